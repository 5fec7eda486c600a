#pragma once

#include "core/params/ParameterCatalogue.h"

#include <cstddef>
#include <optional>
#include <unordered_map>
#include <vector>

namespace m350::params {

// The panel's user levels (访客 / 操作员 / 管理员 / 超级管理), lowest first.
enum class UserLevel { Guest = 0, Operator = 1, Admin = 2, Super = 3 };

// How the Param page (参数管理) lays the catalogue out, and who may change what.
//
// Two tabs: 用户参数(O) holds the groups an operator tunes day to day (manual, process, coordinate,
// spindle, probe, MPG, external, tools); 厂商参数(N) the machine builder's (machine, IO, home, hard
// and soft limits, backlash, system, the input and output port tables) and, last, the parameters no
// firmware page lists (group 0, and 18: the T1/T2 process form). The CAM-teach forms (1000 and up)
// belong to the CAM screens, not to this page, and lie beyond the parameter table.
//
// The level a change needs follows the tab, since the firmware's -p flag is known only as "set on 38
// mostly factory-level items" and not per parameter: user-tab groups need 操作员 Operator, factory
// groups 管理员 Admin, the unlisted ones 超级管理 Super. A guest changes nothing.
class ParameterPages {
public:
    enum class Tab { Factory, User };
    static constexpr int kUnlistedGroup = -1; // group 0 and 18 together, on the factory tab

    struct Category {
        int group = 0; // the catalogue's group (the firmware's -m), or kUnlistedGroup
        Tab tab = Tab::User;
        std::vector<int> numbers; // in the catalogue's (the firmware's page) order
    };
    struct Location {
        std::size_t category = 0;
        std::size_t row = 0;
    };

    explicit ParameterPages(const ParameterCatalogue& catalogue);

    const std::vector<Category>& categories() const { return categories_; }
    // Where parameter `number` is listed; nullopt for a number the page does not list.
    std::optional<Location> locate(int number) const;

    static Tab tabOf(int group);
    static UserLevel requiredLevel(int group);

private:
    std::vector<Category> categories_;
    std::unordered_map<int, Location> index_;
};

} // namespace m350::params
