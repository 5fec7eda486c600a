#pragma once

#include "core/common/HeadTail.h"

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

    void add(std::string text);
    // The kept messages in order; when some were left out, one line between the first and the last
    // says how many.
    std::vector<std::string> list() const;
    std::uint64_t omitted() const { return kept_.omitted(); }

private:
    std::vector<std::string> first_;
    HeadTail<std::string> kept_{kKeepFirst, kKeepLast};
};

} // namespace m350::controller
