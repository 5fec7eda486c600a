#pragma once

#include "core/common/HeadTail.h"
#include "core/common/Message.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace m350::controller {

// The messages of a run (#3006 texts, dialogs, what run() did for the absent operator), bounded: a
// program that posts a message on every pass of an endless loop keeps the first kKeepFirst and
// the last kKeepLast, and counts the ones between.
class MessageLog {
public:
    static constexpr std::size_t kKeepFirst = 2000;
    static constexpr std::size_t kKeepLast = 2000;

    // A line of the program's own words (a #3006 text), said as it is in every language.
    void add(std::string text);
    // A line the controller says, by message id: its English is the text.
    void add(std::string text, const Message& words);
    // The kept messages in order; when some were left out, one line between the first and the last
    // says how many.
    std::vector<std::string> list() const;
    // The same lines by message id, in the same order (an empty id: the program's words, list()'s text).
    std::vector<Message> words() const;
    std::uint64_t omitted() const { return kept_.omitted(); }

private:
    Message omittedLine() const;

    struct Entry {
        std::string text;
        Message words;
    };
    std::vector<Entry> first_;
    HeadTail<Entry> kept_{kKeepFirst, kKeepLast};
};

} // namespace m350::controller
