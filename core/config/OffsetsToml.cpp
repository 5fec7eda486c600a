#include "core/config/OffsetsToml.h"

#include "core/config/MachineFolder.h"
#include "core/config/TomlReading.h"

#include <string>
#include <utility>

namespace m350::config {

namespace fs = std::filesystem;

namespace {

using namespace toml_reading;

} // namespace

void loadOffsets(const fs::path& folder, MachineConfig& config) {
    fs::path file = folder / MachineFolder::fileName(FolderFile::Offsets);
    if (!fs::exists(file)) {
        return;
    }
    toml::table t = parseToml(file);
    warnUnknownKeys(file, t, {"G92", "G54", "G55", "G56", "G57", "G58", "G59", "G52", "common"}, config);
    static constexpr std::pair<const char*, int> slots[] = {{"G92", 0}, {"G54", 1}, {"G55", 2}, {"G56", 3},
                                                            {"G57", 4}, {"G58", 5}, {"G59", 6}, {"G52", 7},
                                                            {"common", 8}};
    for (auto [name, slot] : slots) {
        if (const toml::node* given = t.get(name); given && !given->is_array()) {
            fail(file, message("config_axes_list", {name}), given->source());
        }
        if (auto axes = t[name].as_array()) {
            if (axes->size() > 5) {
                fail(file, message("config_axes_too_many", {name}), axes->source());
            }
            for (std::size_t i = 0; i < axes->size(); ++i) {
                config.offsets[static_cast<std::size_t>(slot)][i] = numberValue(file, *axes->get(i), name);
            }
            if (axes->size() < 3) {
                config.warn(warningAt(file, axes->source(),
                                      axes->size() == 1 ? message("config_axes_one", {name})
                                                        : message("config_axes_few", {name, std::to_string(axes->size())})));
            }
        }
    }
}

} // namespace m350::config
