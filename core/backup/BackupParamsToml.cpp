#include "core/backup/BackupParamsToml.h"

#include "core/params/IoPorts.h"
#include "core/params/ParamsFileWriter.h"

namespace m350::backup {

namespace {

// The comment naming parameter n: its catalogue names, or for the enable and active-level members
// of an IO triple (not catalogued) the function they belong to.
std::string parameterComment(int n, const params::ParameterCatalogue& catalogue) {
    if (const params::ParameterInfo* info = catalogue.find(n)) {
        return info->nameZh + " " + info->nameEn;
    }
    for (int member = 1; member <= 2; ++member) {
        const params::IoFunction* function = params::ioFunction(n - member);
        if (function && catalogue.find(n - member)) {
            const params::ParameterInfo& owner = *catalogue.find(n - member);
            return std::string(member == 1 ? "enable of " : "active level of ") + std::to_string(n - member) + " " +
                   owner.nameZh + " " + owner.nameEn;
        }
    }
    return {};
}

} // namespace

ImportedParams formatImportedParams(const ControllerBackup& backup, const params::ParameterCatalogue& catalogue) {
    ImportedParams out;
    std::string body;
    for (int n = 0; n < params::ParameterTable::kCount; ++n) {
        const double value = backup.setting.get(n);
        std::string line = std::to_string(n) + " = " + params::tomlNumber(value);
        std::string comment = parameterComment(n, catalogue);
        if (backup.defaultSetting && backup.defaultSetting->get(n) != value) {
            out.changed.push_back(n);
            comment += (comment.empty() ? "" : "; ") + std::string("factory: ") + params::tomlNumber(backup.defaultSetting->get(n));
        }
        if (catalogue.find(n)) {
            if (auto problem = catalogue.validate(n, value)) {
                out.outOfRange.push_back(*problem);
            }
        }
        body += line + (comment.empty() ? "" : "  # " + comment) + "\n";
    }
    out.text = "# Parameters imported from a controller backup (its `setting`): all 1000, named (macro variable =\n"
               "# parameter + 500).";
    if (backup.defaultSetting) {
        out.text += " " + std::to_string(out.changed.size()) +
                    " differ from the factory values (`default_setting`): marked \"factory: V\".\n";
    } else {
        out.text += " The backup had no `default_setting`, so no value is compared with the factory's.\n";
    }
    out.text += "[params]\n" + body;
    return out;
}

std::string formatImportedOffsets(const std::array<double, kCoordinateCount>& coordinate) {
    static constexpr const char* systems[] = {"G92", "G54", "G55", "G56", "G57", "G58", "G59", "G52", "common"};
    std::string text = "# Work offsets imported from a controller backup (its `coordinate`, #800-#844), machine\n"
                       "# coordinates [X, Y, Z, A, B]; common is the offset added to every system (公共偏置).\n";
    for (std::size_t slot = 0; slot < std::size(systems); ++slot) {
        text += std::string(systems[slot]) + " = [";
        for (std::size_t axis = 0; axis < 5; ++axis) {
            text += (axis ? ", " : "") + params::tomlNumber(coordinate[slot * 5 + axis]);
        }
        text += "]\n";
    }
    return text;
}

} // namespace m350::backup
