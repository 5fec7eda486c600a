#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace m350 {

// The language a message is said in: the firmware's (zh_CN) or English.
enum class MessageLanguage : std::uint8_t { English, Chinese };

// Words the core says to the operator by a stable id, as the firmware's string table works: the
// id names a row of translations/messages.tsv (its English and Chinese pattern, %1.. for the
// arguments), the arguments are language-neutral (numbers, positions, file names). The core
// reports english(); the panel and `m350-sim --lang` say it in their language by the id.
struct Message {
    std::string id;
    std::vector<std::string> arguments;

    std::string english() const;
    std::string in(MessageLanguage language) const;

    // Compares the English (what tests and the CLI's JSON see).
    friend bool operator==(const Message& m, std::string_view text) { return m.english() == text; }
};

std::ostream& operator<<(std::ostream& out, const Message& m);

// A message by id: throws std::logic_error for an id the table does not have, so a typo fails the
// first test that reaches it.
Message message(std::string_view id, std::vector<std::string> arguments = {});

// An argument that is words after all (an input's function: "tool released", 松刀到位), in both
// languages; english() and in() take the one they say.
std::string bilingual(std::string_view english, std::string_view chinese);
// A whole message as an argument of another (the reason a deeper layer gave: "compensated arc: %1"),
// said in the language the outer one is.
std::string bilingual(const Message& words);
std::string argumentIn(const std::string& argument, MessageLanguage language);

// One row of the table.
struct MessagePattern {
    std::string id;
    std::string english;
    std::string chinese;
};

const std::vector<MessagePattern>& messagePatterns();
const MessagePattern* findMessagePattern(std::string_view id);
// The pattern with %1..%9 replaced by the arguments in order; the id's English words fill in when
// the table has no such id (a message from a newer core).
std::string messageText(std::string_view id, const std::vector<std::string>& arguments, MessageLanguage language);
// "zh_CN" or "en" (what --lang takes); nullopt-like false for anything else.
bool parseMessageLanguage(std::string_view name, MessageLanguage& language);

} // namespace m350
