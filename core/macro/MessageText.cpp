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

namespace {

std::string shortNumber(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.3f", v);
    std::string text = buffer;
    while (text.back() == '0') {
        text.pop_back();
    }
    if (text.back() == '.') {
        text.pop_back();
    }
    return text == "-0" ? "0" : text;
}

} // namespace

std::string expandVariableFields(std::string_view text, const std::function<std::optional<double>(int)>& read) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        std::size_t close = text[i] == '{' && i + 2 < text.size() && text[i + 1] == '#' ? text.find('}', i) : text.npos;
        int number = 0;
        bool digits = close != text.npos && close > i + 2 && close - i - 2 <= 4;
        for (std::size_t k = i + 2; digits && k < close; ++k) {
            digits = text[k] >= '0' && text[k] <= '9';
            number = number * 10 + (text[k] - '0');
        }
        if (!digits) {
            out.push_back(text[i]);
            continue;
        }
        std::optional<double> value = read(number);
        out += value ? shortNumber(*value) : "vacant";
        i = close;
    }
    return out;
}

} // namespace m350::macro
