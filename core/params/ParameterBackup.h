#pragma once

#include "core/common/Message.h"

#include "core/params/ParameterCatalogue.h"
#include "core/params/ParameterTable.h"

#include <filesystem>
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace m350::params {

// 参数备份 / 参数恢复: all 1000 parameters in one TOML file of the machine folder,
//
//     # M350 Studio parameter backup
//     [backup]
//     machine = "m350-linear16"
//     format = 1
//     [params]
//     0 = 50  # 电机起跳速度 Motor starting speed
//     ...
//
// every number 0-999 once, so a restore puts back exactly what was saved (the IO triples' enable
// and level members, which the catalogue does not list, included).
inline constexpr const char* kParameterBackupFile = "params-backup.toml";

std::string formatParameterBackup(const ParameterTable& parameters, const ParameterCatalogue& catalogue,
                                  const std::string& machineName);

struct ParameterRestore {
    std::map<int, double> values;       // all 1000
    std::vector<std::string> outOfRange; // values kept as written though the panel would refuse them
};

// Reads a backup. The file must parse, say `format = 1`, and give every parameter 0-999 exactly
// once as a number; otherwise the error names the file and line ("file:12:5: why"). A value
// outside its catalogued range is restored as written and listed, as params.toml loading does.
std::variant<ParameterRestore, Message> readParameterBackup(const std::filesystem::path& file,
                                                                const ParameterCatalogue& catalogue);

} // namespace m350::params
