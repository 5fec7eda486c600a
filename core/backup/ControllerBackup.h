#pragma once

#include "core/common/Message.h"

#include "core/params/ParameterCatalogue.h"
#include "core/params/ParameterTable.h"

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace m350::backup {

// A copy of an M350's system disk (SYSDISK, what the panel's 系统备份 writes to a USB stick), as
// read for an import. The controller keeps its data in binary files:
//   setting          1000 little-endian float64, index = parameter number (required)
//   default_setting  the factory values, same layout (optional: marks what the owner changed)
//   coordinate       45 float64 = #800-#844: G92, G54-G59, G52, the common offset, 5 axes each
//   mdiblock         the six MDI lines, 120 bytes each, NUL-padded (GBK)
// (each found in any case),
// and its macros and hook files as .nc text. Everything else (bitmaps, kernel modules, logs,
// string tables, fonts, the firmware) means nothing to the simulator and is only listed.
inline constexpr int kCoordinateCount = 45;
inline constexpr std::size_t kMdiBlockBytes = 6 * 120;

struct BackupFile {
    std::string name;             // relative to the backup folder, '/' between folders
    std::filesystem::path source; // where it lies in the backup: read (mapped) and copied streaming
};

struct SkippedFile {
    std::string name;
    Message reason; // by id: said in the report's language
};

struct ControllerBackup {
    params::ParameterTable setting;
    std::optional<params::ParameterTable> defaultSetting;
    std::optional<std::array<double, kCoordinateCount>> coordinate;
    std::optional<std::string> mdiblock; // the raw bytes
    std::vector<BackupFile> programs;    // every .nc file, sorted by name
    std::vector<SkippedFile> skipped;    // sorted by name
};

struct BackupError {
    std::string file;
    Message message; // by id: said in the CLI's --lang and the panel's language
};

// Reads the backup folder. A missing `setting`, or a binary file of the wrong size or holding a
// value no controller stores (nan, infinity, a magnitude no parameter or offset has: what bytes
// that are not float64 decode to), is an error naming the file, the byte offset and the
// parameter or offset; nothing else is read then.
std::variant<ControllerBackup, BackupError> readControllerBackup(const std::filesystem::path& folder,
                                                                 const params::ParameterCatalogue* catalogue);

// A file of the backup's top folder by its name in any case (a copy through a FAT-formatted USB
// stick may have changed it: SLIB-G.NC), or nullptr.
const BackupFile* findProgram(const ControllerBackup& backup, std::string_view name);
bool sameNameAnyCase(std::string_view a, std::string_view b);

// Why a value read from a float64 table is refused, or nullopt when it is a plausible value.
std::optional<Message> implausibleValue(double value);

} // namespace m350::backup
