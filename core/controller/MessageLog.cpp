#include "core/controller/MessageLog.h"

namespace m350::controller {

void MessageLog::add(std::string text) {
    kept_.add(first_, std::move(text), 1);
}

std::vector<std::string> MessageLog::list() const {
    std::vector<std::string> out = first_;
    if (kept_.omitted() > 0) {
        out.push_back("… " + std::to_string(kept_.omitted()) + " more messages omitted (the first " +
                      std::to_string(kKeepFirst) + " and the last " + std::to_string(kKeepLast) + " are kept) …");
    }
    for (const auto& kept : kept_.tail()) {
        out.push_back(kept.piece);
    }
    return out;
}

} // namespace m350::controller
