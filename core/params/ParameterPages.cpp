#include "core/params/ParameterPages.h"

#include "core/params/ParameterTable.h"

#include <algorithm>
#include <array>

namespace m350::params {

namespace {

constexpr std::array kUserGroups = {2, 3, 4, 5, 8, 11, 12, 14};
constexpr std::array kFactoryGroups = {1, 6, 7, 9, 10, 13, 15, 16, 17};
constexpr int kProcessFormGroup = 18;

bool unlisted(int group) { return group == 0 || group == kProcessFormGroup; }

} // namespace

ParameterPages::Tab ParameterPages::tabOf(int group) {
    return std::find(kUserGroups.begin(), kUserGroups.end(), group) != kUserGroups.end() ? Tab::User
                                                                                         : Tab::Factory;
}

UserLevel ParameterPages::requiredLevel(int group) {
    if (group == kUnlistedGroup || unlisted(group)) return UserLevel::Super;
    return tabOf(group) == Tab::User ? UserLevel::Operator : UserLevel::Admin;
}

ParameterPages::ParameterPages(const ParameterCatalogue& catalogue) {
    auto add = [&](int group, auto accepts) {
        Category category{group, tabOf(group), {}};
        for (const ParameterInfo& p : catalogue.all())
            if (accepts(p.group) && ParameterTable::valid(p.number)) category.numbers.push_back(p.number);
        if (!category.numbers.empty()) categories_.push_back(std::move(category));
    };
    for (int group : kUserGroups) add(group, [group](int g) { return g == group; });
    for (int group : kFactoryGroups) add(group, [group](int g) { return g == group; });
    add(kUnlistedGroup, unlisted);
    for (std::size_t c = 0; c < categories_.size(); ++c)
        for (std::size_t row = 0; row < categories_[c].numbers.size(); ++row)
            index_.emplace(categories_[c].numbers[row], Location{c, row});
}

std::optional<ParameterPages::Location> ParameterPages::locate(int number) const {
    auto it = index_.find(number);
    if (it == index_.end()) return std::nullopt;
    return it->second;
}

} // namespace m350::params
