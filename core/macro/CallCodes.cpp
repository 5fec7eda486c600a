#include "core/macro/CallCodes.h"

namespace m350::macro {

std::optional<CodeCall> CallCodes::add(char letter, int code, CodeCall call) {
    auto [it, added] = codes_.try_emplace({letter, code}, std::move(call));
    return added ? std::nullopt : std::optional<CodeCall>(it->second);
}

std::optional<CodeCall> CallCodes::addAddress(char letter, CodeCall call) {
    auto [it, added] = addresses_.try_emplace(letter, std::move(call));
    if (!added) {
        return it->second;
    }
    addressLetters_ |= 1u << static_cast<unsigned>(letter - 'A');
    return std::nullopt;
}

const CodeCall* CallCodes::find(char letter, int code) const {
    auto it = codes_.find({letter, code});
    return it == codes_.end() ? nullptr : &it->second;
}

const CodeCall* CallCodes::address(char letter) const {
    if (letter < 'A' || letter > 'Z' || (addressLetters_ >> static_cast<unsigned>(letter - 'A') & 1u) == 0) {
        return nullptr;
    }
    return &addresses_.at(letter);
}

} // namespace m350::macro
