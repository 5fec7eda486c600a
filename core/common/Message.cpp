#include "core/common/Message.h"

#include <ostream>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

namespace m350 {

// translations/messages.tsv, compiled in by CMake (core/CMakeLists.txt) in pieces of whole lines,
// the last nullptr: one source for the core's English, the CLI's and the panel's Chinese.
extern const char* const kMessageTableTsv[];

namespace {

std::vector<MessagePattern> readTable() {
    std::vector<MessagePattern> table;
    std::string whole;
    for (const char* const* part = kMessageTableTsv; *part; ++part) {
        whole += *part;
    }
    std::string_view text(whole);
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
        if (line.empty() || line.front() == '#') {
            continue;
        }
        const std::size_t tab1 = line.find('\t');
        const std::size_t tab2 = tab1 == std::string_view::npos ? tab1 : line.find('\t', tab1 + 1);
        if (tab2 == std::string_view::npos) {
            throw std::logic_error("translations/messages.tsv: a row needs id, English and Chinese: " + std::string(line));
        }
        table.push_back({std::string(line.substr(0, tab1)), std::string(line.substr(tab1 + 1, tab2 - tab1 - 1)),
                         std::string(line.substr(tab2 + 1))});
    }
    return table;
}

constexpr char kBilingual = '\x1f'; // between an argument's English and its Chinese

std::string fill(const std::string& pattern, const std::vector<std::string>& arguments, MessageLanguage language) {
    std::string out;
    out.reserve(pattern.size() + 32);
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] == '%' && i + 1 < pattern.size() && pattern[i + 1] >= '1' && pattern[i + 1] <= '9') {
            const auto n = static_cast<std::size_t>(pattern[i + 1] - '1');
            out += n < arguments.size() ? argumentIn(arguments[n], language) : std::string("?");
            ++i;
        } else {
            out += pattern[i];
        }
    }
    return out;
}

} // namespace

std::string bilingual(std::string_view english, std::string_view chinese) {
    return std::string(english) + kBilingual + std::string(chinese);
}

std::string bilingual(const Message& words) {
    return bilingual(words.english(), words.in(MessageLanguage::Chinese));
}

std::string argumentIn(const std::string& argument, MessageLanguage language) {
    const std::size_t split = argument.find(kBilingual);
    if (split == std::string::npos) {
        return argument;
    }
    return language == MessageLanguage::Chinese ? argument.substr(split + 1) : argument.substr(0, split);
}

const std::vector<MessagePattern>& messagePatterns() {
    static const std::vector<MessagePattern> table = readTable();
    return table;
}

const MessagePattern* findMessagePattern(std::string_view id) {
    // looked up for every alarm and status line shown: hundreds of ids, searched by hash
    static const std::unordered_map<std::string_view, const MessagePattern*> byId = [] {
        std::unordered_map<std::string_view, const MessagePattern*> index;
        for (const MessagePattern& pattern : messagePatterns()) {
            index.emplace(pattern.id, &pattern); // the first of a repeated id, as the search found
        }
        return index;
    }();
    const auto found = byId.find(id);
    return found == byId.end() ? nullptr : found->second;
}

std::string messageText(std::string_view id, const std::vector<std::string>& arguments, MessageLanguage language) {
    const MessagePattern* pattern = findMessagePattern(id);
    if (pattern == nullptr) {
        std::string text(id);
        for (const std::string& argument : arguments) {
            text += " " + argumentIn(argument, language);
        }
        return text;
    }
    return fill(language == MessageLanguage::Chinese ? pattern->chinese : pattern->english, arguments, language);
}

std::string Message::english() const {
    return messageText(id, arguments, MessageLanguage::English);
}

std::string Message::in(MessageLanguage language) const {
    return messageText(id, arguments, language);
}

Message message(std::string_view id, std::vector<std::string> arguments) {
    if (findMessagePattern(id) == nullptr) {
        throw std::logic_error("no message '" + std::string(id) + "' in translations/messages.tsv");
    }
    return Message{std::string(id), std::move(arguments)};
}

std::ostream& operator<<(std::ostream& out, const Message& m) {
    return out << m.english();
}

bool parseMessageLanguage(std::string_view name, MessageLanguage& language) {
    if (name == "zh_CN") {
        language = MessageLanguage::Chinese;
        return true;
    }
    if (name == "en") {
        language = MessageLanguage::English;
        return true;
    }
    return false;
}

} // namespace m350
