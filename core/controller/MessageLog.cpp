#include "core/controller/MessageLog.h"

namespace m350::controller {

void MessageLog::add(std::string text) {
    kept_.add(first_, Entry{std::move(text), {}}, 1);
}

void MessageLog::add(std::string text, const Message& words) {
    kept_.add(first_, Entry{std::move(text), words}, 1);
}

std::vector<std::string> MessageLog::list() const {
    std::vector<std::string> out;
    for (const Entry& entry : first_) {
        out.push_back(entry.text);
    }
    if (kept_.omitted() > 0) {
        out.push_back(omittedLine().english());
    }
    for (const auto& kept : kept_.tail()) {
        out.push_back(kept.piece.text);
    }
    return out;
}

std::vector<Message> MessageLog::words() const {
    std::vector<Message> out;
    for (const Entry& entry : first_) {
        out.push_back(entry.words);
    }
    if (kept_.omitted() > 0) {
        out.push_back(omittedLine());
    }
    for (const auto& kept : kept_.tail()) {
        out.push_back(kept.piece.words);
    }
    return out;
}

Message MessageLog::omittedLine() const {
    return message("messages_omitted",
                   {std::to_string(kept_.omitted()), std::to_string(kKeepFirst), std::to_string(kKeepLast)});
}

} // namespace m350::controller
