#include "core/gcode/Program.h"

#include <algorithm>
#include <string>

namespace m350::gcode {

namespace {
int rolePriority(FileRole role) {
    return (role == FileRole::Main || role == FileRole::Mdi) ? 0 : 1;
}
} // namespace

void Program::indexUnit(std::uint32_t unitIndex) {
    const ProgramUnit& unit = units[unitIndex];
    if (unit.number >= 0) {
        unitsByNumber_[unit.number].push_back(unitIndex);
    }
}

void Program::indexUnitsOf(const Program& part, std::uint32_t firstUnit) {
    for (const auto& [number, partUnits] : part.unitsByNumber_) {
        std::vector<std::uint32_t>& here = unitsByNumber_[number];
        for (std::uint32_t unit : partUnits) {
            here.push_back(firstUnit + unit);
        }
    }
}

std::optional<std::uint32_t> Program::findUnit(std::int32_t number) const {
    auto it = unitsByNumber_.find(number);
    if (it == unitsByNumber_.end()) {
        return std::nullopt;
    }
    const auto& candidates = it->second;
    auto best = std::min_element(candidates.begin(), candidates.end(), [this](std::uint32_t a, std::uint32_t b) {
        return rolePriority(files[units[a].file].role) < rolePriority(files[units[b].file].role);
    });
    return *best;
}

std::optional<std::uint32_t> Program::findHandler(std::int32_t number, FileRole libraryRole) const {
    auto it = unitsByNumber_.find(number);
    if (it == unitsByNumber_.end()) {
        return std::nullopt;
    }
    std::optional<std::uint32_t> found;
    for (std::uint32_t unit : it->second) {
        FileRole role = files[units[unit].file].role;
        if (rolePriority(role) == 0) {
            return unit; // the user's own definition overrides the library's
        }
        if (role == libraryRole && !found) {
            found = unit;
        }
    }
    return found;
}

std::optional<std::uint32_t> Program::mainUnit() const {
    for (std::uint32_t i = 0; i < units.size(); ++i) {
        if (rolePriority(files[units[i].file].role) == 0) {
            return i;
        }
    }
    return std::nullopt;
}

std::optional<std::uint32_t> Program::findLabel(std::uint32_t unit, std::int32_t label, std::uint32_t from) const {
    return units[unit].labels.find(label, from);
}

Diagnostic Program::suspectMessage(std::uint32_t block) const {
    const SourceLocation& at = blocks[block].location;
    if (blocks.changedOnDisk(block)) {
        return diagnostic(Severity::Error, DiagnosticKind::Lint, files[at.file].name, at.line, 0,
                          message("program_changed_on_disk", {files[at.file].name, std::to_string(at.line)}));
    }
    auto found = suspects.find(block);
    return found != suspects.end()
               ? found->second
               : diagnostic(Severity::Error, DiagnosticKind::Lint, files[at.file].name, at.line, 0, message("suspect_line"));
}

std::uint32_t Program::unitOfBlock(std::uint32_t block) const {
    auto it = std::upper_bound(units.begin(), units.end(), block,
                               [](std::uint32_t b, const ProgramUnit& u) { return b < u.begin; });
    return static_cast<std::uint32_t>(std::distance(units.begin(), it) - 1);
}

} // namespace m350::gcode
