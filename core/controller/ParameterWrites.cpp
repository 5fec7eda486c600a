#include "core/controller/ParameterWrites.h"

#include <cmath>
#include <variant>

namespace m350::controller {

params::UserLevel ParameterWrites::required(int number) {
    const auto& bundled = params::ParameterCatalogue::bundled();
    const auto* catalogue = std::get_if<params::ParameterCatalogue>(&bundled);
    const params::ParameterInfo* info = catalogue ? catalogue->find(number) : nullptr;
    return params::ParameterPages::requiredLevel(info ? info->group : params::ParameterPages::kUnlistedGroup);
}

std::string ParameterWrites::levelWords(params::UserLevel level) {
    switch (level) {
    case params::UserLevel::Guest: return bilingual("Guest", "访客");
    case params::UserLevel::Operator: return bilingual("Operator", "操作员");
    case params::UserLevel::Admin: return bilingual("Admin", "管理员");
    case params::UserLevel::Super: return bilingual("Super", "超级管理");
    }
    return {};
}

std::optional<Message> ParameterWrites::refusal(int number, params::UserLevel level) {
    const params::UserLevel needed = required(number);
    if (level >= needed) {
        return std::nullopt;
    }
    return message("parameter_rights", {std::to_string(number), levelWords(needed), levelWords(level)});
}

std::vector<ParameterWrites::Change> ParameterWrites::take(const params::ParameterTable& table) {
    std::vector<Change> changes;
    if (table.version() == seenVersion_) {
        return changes;
    }
    for (int number = 0; number < params::ParameterTable::kCount; ++number) {
        const double before = seen_.get(number);
        const double after = table.get(number);
        if (before == after || (std::isnan(before) && std::isnan(after))) {
            continue;
        }
        auto writer = writers_.find(number);
        Change change{number, before, after, level_, Writer::Machine, {}};
        if (writer != writers_.end()) {
            change.writer = writer->second.first;
            change.place = writer->second.second;
        }
        changes.push_back(std::move(change));
        seen_.set(number, after);
    }
    writers_.clear();
    seenVersion_ = table.version();
    return changes;
}

} // namespace m350::controller
