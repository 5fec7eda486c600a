#include "core/macro/MessageText.h"

#include <cstdio>

namespace m350::macro {

std::string formatMessageText(std::string_view text, const double (&values)[4]) {
    std::string out;
    int next = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '%') {
            out.push_back(text[i]);
            continue;
        }
        if (i + 1 < text.size() && text[i + 1] == '%') {
            out.push_back('%');
            ++i;
            continue;
        }
        // %.Nf with one digit of precision, as the panel's texts use
        if (i + 3 < text.size() && text[i + 1] == '.' && text[i + 2] >= '0' && text[i + 2] <= '9' &&
            text[i + 3] == 'f' && next < 4) {
            char buffer[64];
            std::snprintf(buffer, sizeof buffer, "%.*f", text[i + 2] - '0', values[next++]);
            out += buffer;
            i += 3;
            continue;
        }
        out.push_back('%');
    }
    return out;
}

} // namespace m350::macro
