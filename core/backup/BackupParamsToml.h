#pragma once

#include "core/backup/ControllerBackup.h"
#include "core/params/ParameterCatalogue.h"

#include <array>
#include <string>
#include <vector>

namespace m350::backup {

// params.toml from a backup's `setting`: all 1000 parameters in number order, each named in a
// comment (an IO triple's enable and level members by their function), and those that differ
// from `default_setting` marked "factory: V". All, not only the changed ones: a parameter missing
// from params.toml loads as 0, not as its factory value, and an owner reads the whole list.
struct ImportedParams {
    std::string text;
    std::vector<int> changed;     // differ from default_setting (empty without it)
    std::vector<Message> outOfRange; // values the panel would refuse, kept as the controller had them
};
ImportedParams formatImportedParams(const ControllerBackup& backup, const params::ParameterCatalogue& catalogue);

// offsets.toml from `coordinate`: G92, G54-G59, G52 and common, [X, Y, Z, A, B] each, in the
// format the bundled machines use.
std::string formatImportedOffsets(const std::array<double, kCoordinateCount>& coordinate);

} // namespace m350::backup
