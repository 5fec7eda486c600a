#include "core/backup/ControllerBackup.h"

#include "core/files/MachineFileRead.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

namespace m350::backup {

namespace fs = std::filesystem;

namespace {

// Beyond these a value is not a parameter or an offset but bytes that are not float64: a file of
// 32-bit numbers, text, or a big-endian copy decodes to magnitudes like 1e-310 or 1e+200.
constexpr double kLargestPlausible = 1e12;
constexpr double kSmallestPlausible = 1e-12;

struct Failure {
    BackupError error;
};

[[noreturn]] void fail(const fs::path& file, Message words) {
    throw Failure{{file.string(), std::move(words)}};
}

// A data file's bytes: a folder, FIFO or device (a link to one) is said as what it is, an
// unreadable file with the system's reason, never read as "not found" or as empty.
std::string readBytes(const fs::path& file) {
    std::string bytes;
    if (auto why = files::readMachineFile(file, bytes)) {
        fail(file, message("backup_cannot_read", {bilingual(*why)}));
    }
    return bytes;
}

double littleEndianDouble(const char* bytes) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, bytes, sizeof bits);
    if constexpr (std::endian::native == std::endian::big) {
        std::uint64_t swapped = 0;
        for (int i = 0; i < 8; ++i) {
            swapped = (swapped << 8) | ((bits >> (8 * i)) & 0xffu);
        }
        bits = swapped;
    }
    return std::bit_cast<double>(bits);
}

// The name of value `index` of a table in messages, in both languages (bilingual()): "parameter 129
// (浮动对刀仪厚度 Floating tool set thickness)" / 参数129（浮动对刀仪厚度）, or "#805 (G54 X)".
using IndexName = std::string (*)(int index, const params::ParameterCatalogue* catalogue);

std::string parameterName(int index, const params::ParameterCatalogue* catalogue) {
    std::string english = "parameter " + std::to_string(index);
    std::string chinese = "参数" + std::to_string(index);
    if (const params::ParameterInfo* info = catalogue ? catalogue->find(index) : nullptr) {
        english += " (" + info->nameZh + " " + info->nameEn + ")";
        chinese += "（" + info->nameZh + "）";
    }
    return bilingual(english, chinese);
}

std::string offsetName(int index, const params::ParameterCatalogue*) {
    static constexpr const char* systems[] = {"G92", "G54", "G55", "G56", "G57", "G58", "G59", "G52", "common offset"};
    static constexpr const char* systemsZh[] = {"G92", "G54", "G55", "G56", "G57", "G58", "G59", "G52", "公共偏置"};
    static constexpr const char* axes[] = {"X", "Y", "Z", "4th", "5th"};
    static constexpr const char* axesZh[] = {"X", "Y", "Z", "第4轴", "第5轴"};
    const std::string number = "#" + std::to_string(800 + index);
    return bilingual(number + " (" + systems[index / 5] + " " + axes[index % 5] + ")",
                     number + "（" + systemsZh[index / 5] + " " + axesZh[index % 5] + "）");
}

std::vector<double> readTable(const fs::path& file, std::size_t count, const std::string& what, IndexName name,
                              const params::ParameterCatalogue* catalogue) {
    const std::string bytes = readBytes(file);
    const std::size_t expected = count * sizeof(double);
    if (bytes.size() != expected) {
        std::vector<std::string> arguments{std::to_string(bytes.size()), what, std::to_string(count),
                                           std::to_string(expected)};
        if (bytes.size() < expected) {
            arguments.push_back(name(static_cast<int>(bytes.size() / 8), catalogue));
        }
        fail(file, message(bytes.size() < expected ? "backup_truncated" : "backup_wrong_size", std::move(arguments)));
    }
    std::vector<double> values(count);
    for (std::size_t i = 0; i < count; ++i) {
        values[i] = littleEndianDouble(bytes.data() + i * sizeof(double));
        if (auto why = implausibleValue(values[i])) {
            fail(file, message("backup_damaged",
                               {std::to_string(i * sizeof(double)), name(static_cast<int>(i), catalogue), bilingual(*why)}));
        }
    }
    return values;
}

params::ParameterTable parameterTable(const std::vector<double>& values) {
    params::ParameterTable table;
    for (int n = 0; n < params::ParameterTable::kCount; ++n) {
        table.set(n, values[static_cast<std::size_t>(n)]);
    }
    return table;
}

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

bool isElf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    char magic[4] = {};
    return in.read(magic, 4) && std::memcmp(magic, "\x7f" "ELF", 4) == 0;
}

// Why a file of the system disk is not copied into the machine folder.
Message skipReason(const fs::path& file) {
    const std::string ext = lowercase(file.extension().string());
    const std::string stem = lowercase(file.stem().string());
    if (ext == ".bmp" || ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".gif" || ext == ".ico") {
        return message("import_skip_image");
    }
    if (ext == ".ko") {
        return message("import_skip_module");
    }
    if (ext == ".ttf" || ext == ".ttc" || ext == ".otf" || ext == ".fnt" || ext == ".fon" || ext == ".bdf" ||
        ext == ".pcf") {
        return message("import_skip_font");
    }
    if (ext == ".log" || stem.find("log") != std::string::npos) {
        return message("import_skip_log");
    }
    if (ext.empty() && (stem == "eng" || stem == "chs" || stem == "cht" || stem == "rus")) {
        return message("import_skip_strings", {"resources/firmware-ui-strings.tsv"});
    }
    if (ext == ".so" || isElf(file)) {
        return message("import_skip_program");
    }
    return message("import_skip_unused");
}

constexpr const char* kDataFiles[] = {"setting", "default_setting", "coordinate", "mdiblock"};

// `folder`/`name`, or the top-level entry with that name in another case, whatever it is (a
// folder or a link is read by readBytes, which says what it is); nullopt when there is none.
std::optional<fs::path> dataFile(const fs::path& folder, const char* name) {
    std::error_code ec;
    if (fs::exists(fs::symlink_status(folder / name, ec))) {
        return folder / name;
    }
    for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
        if (sameNameAnyCase(entry.path().filename().string(), name)) {
            return entry.path();
        }
    }
    return std::nullopt;
}

// Every .nc file (its bytes) and every other file (why it is skipped), in name order.
void listFiles(const fs::path& folder, ControllerBackup& backup) {
    for (auto it = fs::recursive_directory_iterator(folder); it != fs::recursive_directory_iterator(); ++it) {
        const fs::directory_entry& entry = *it;
        const std::string name = fs::relative(entry.path(), folder).generic_string();
        if (entry.is_symlink()) {
            backup.skipped.push_back({name, message("import_skip_link")});
            continue;
        }
        if (entry.is_directory()) {
            continue;
        }
        if (!entry.is_regular_file()) {
            backup.skipped.push_back({name, message("import_skip_special")});
            continue;
        }
        if (std::any_of(std::begin(kDataFiles), std::end(kDataFiles),
                        [&name](const char* data) { return sameNameAnyCase(name, data); })) {
            continue; // read as data
        }
        if (lowercase(entry.path().extension().string()) == ".nc") {
            backup.programs.push_back({name, entry.path()}); // copied streaming: a .nc may be hundreds of MB
        } else {
            backup.skipped.push_back({name, skipReason(entry.path())});
        }
    }
    std::sort(backup.programs.begin(), backup.programs.end(),
              [](const BackupFile& a, const BackupFile& b) { return a.name < b.name; });
    std::sort(backup.skipped.begin(), backup.skipped.end(),
              [](const SkippedFile& a, const SkippedFile& b) { return a.name < b.name; });
}

} // namespace

bool sameNameAnyCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

const BackupFile* findProgram(const ControllerBackup& backup, std::string_view name) {
    for (const BackupFile& file : backup.programs) {
        if (sameNameAnyCase(file.name, name)) {
            return &file;
        }
    }
    return nullptr;
}

std::optional<Message> implausibleValue(double value) {
    if (std::isnan(value)) {
        return message("backup_value_nan");
    }
    if (std::isinf(value)) {
        return message("backup_value_infinite", {value > 0 ? "infinity" : "-infinity"});
    }
    const double magnitude = std::abs(value);
    if (magnitude > kLargestPlausible || (magnitude != 0.0 && magnitude < kSmallestPlausible)) {
        std::ostringstream text;
        text << value;
        return message("backup_value_implausible", {text.str()});
    }
    return std::nullopt;
}

std::variant<ControllerBackup, BackupError> readControllerBackup(const fs::path& folder,
                                                                 const params::ParameterCatalogue* catalogue) {
    ControllerBackup backup;
    const std::string settingFile = bilingual("a setting file", "setting 文件");
    try {
        if (!fs::is_directory(folder)) {
            fail(folder, message("backup_not_a_folder"));
        }
        const std::optional<fs::path> setting = dataFile(folder, "setting");
        if (!setting) {
            fail(folder / "setting", message("backup_no_setting"));
        }
        backup.setting =
            parameterTable(readTable(*setting, params::ParameterTable::kCount, settingFile, parameterName, catalogue));
        if (const auto defaults = dataFile(folder, "default_setting")) {
            backup.defaultSetting = parameterTable(
                readTable(*defaults, params::ParameterTable::kCount, settingFile, parameterName, catalogue));
        }
        if (const auto coordinate = dataFile(folder, "coordinate")) {
            std::vector<double> offsets =
                readTable(*coordinate, kCoordinateCount, bilingual("a coordinate file", "coordinate 文件"), offsetName,
                          catalogue);
            backup.coordinate.emplace();
            std::copy(offsets.begin(), offsets.end(), backup.coordinate->begin());
        }
        if (const auto mdi = dataFile(folder, "mdiblock")) {
            backup.mdiblock = readBytes(*mdi);
        }
        listFiles(folder, backup);
    } catch (const Failure& f) {
        return f.error;
    } catch (const fs::filesystem_error& e) {
        return BackupError{e.path1().empty() ? folder.string() : e.path1().string(),
                           message("config_system_error", {e.code().message()})};
    }
    return backup;
}

} // namespace m350::backup
