#pragma once

#include "core/common/Message.h"

#include <CLI/CLI.hpp>

#include <string>

namespace m350::sim {

// A usage error of m350-sim's own (a --param, --input, --fault, --break value it refuses), by
// message id: m350-sim says it in the --lang language. To CLI11 (and m350-hmi, which shares the
// option parsers) it is a ValidationError with the English text, as before.
class UsageError : public CLI::ValidationError {
public:
    UsageError(std::string option, Message words)
        : CLI::ValidationError(option, words.english()), option_(std::move(option)), words_(std::move(words)) {}

    // "--param: 'x' is not a number", as CLI11 says a ValidationError
    std::string text(MessageLanguage language) const { return option_ + ": " + words_.in(language); }

private:
    std::string option_;
    Message words_;
};

} // namespace m350::sim
