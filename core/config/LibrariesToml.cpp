#include "core/config/LibrariesToml.h"

#include "core/config/HookFiles.h"
#include "core/config/TomlReading.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <string>
#include <vector>

namespace m350::config {

namespace fs = std::filesystem;

namespace {

using namespace toml_reading;

// slibuser.nc, the user's G-code handlers (O9100-O9199 = G100-G199), is loaded beside slib-g.nc
// as the M350 does, whether or not machine.toml lists it.
void addUserLibrary(const fs::path& folder, MachineConfig& config) {
    auto path = hookPath(folder.string(), Hook::UserLibrary);
    if (!path) {
        return;
    }
    std::error_code ec;
    for (const LibraryFile& library : config.libraries) {
        if (fs::equivalent(library.path, *path, ec)) {
            return;
        }
    }
    config.libraries.push_back({*path, gcode::FileRole::GLibrary});
}

bool libraryInside(const fs::path& path, const fs::path& folder) {
    std::error_code ec;
    const fs::path real = fs::weakly_canonical(path, ec);
    const fs::path within = ec ? fs::path() : fs::weakly_canonical(folder, ec);
    if (ec || real.empty() || within.empty()) {
        return false;
    }
    const fs::path relative = real.lexically_relative(within);
    return !relative.empty() && *relative.begin() != "..";
}

// Where a library may lie once `..` and every symlink are resolved: the machine folder, the
// bundled machine folders (the program's own, which share slib-g.nc and slib-probe.nc), and the
// folder the user names in M350_LIBRARIES. A copied folder must not make the simulator read (and
// echo in its messages) any other file of this computer.
std::vector<fs::path> libraryFolders(const fs::path& folder) {
    std::vector<fs::path> folders{folder, bundledMachinesDirectory()};
    if (const char* named = std::getenv(kLibrariesVariable); named && *named) {
        folders.emplace_back(named);
    }
    return folders;
}

// A program file (.nc) of a machine folder beside this one (`../m350-linear16/slib-m.nc` in a copy
// of the bundled machines): its folder holds a machine.toml and shares this folder's parent.
bool inSiblingMachineFolder(const fs::path& path, const fs::path& folder) {
    std::error_code ec;
    const fs::path real = fs::weakly_canonical(path, ec);
    const fs::path self = ec ? fs::path() : fs::weakly_canonical(folder, ec);
    if (ec || real.empty() || self.empty()) {
        return false;
    }
    std::string extension = real.extension().string();
    for (char& c : extension) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    const fs::path sibling = real.parent_path();
    return extension == ".nc" && sibling.parent_path() == self.parent_path() &&
           fs::is_regular_file(sibling / "machine.toml", ec);
}

} // namespace

void readLibraries(const fs::path& folder, const fs::path& file, const toml::table& machine, MachineConfig& config) {
    const toml::table& t = machine;
    auto addLibrary = [&](const toml::node& node, gcode::FileRole role) {
        auto name = node.value<std::string>();
        if (!name) {
            fail(file, message("config_library_not_name"), node.source());
        }
        fs::path path = folder / *name;
        const std::vector<fs::path> allowed = libraryFolders(folder);
        if (std::none_of(allowed.begin(), allowed.end(), [&](const fs::path& f) { return libraryInside(path, f); }) &&
            !inSiblingMachineFolder(path, folder)) {
            fail(file, message("config_library_outside", {*name, folder.string(), kLibrariesVariable}), node.source());
        }
        std::error_code ec;
        const fs::file_status status = fs::status(path, ec);
        if (!fs::exists(status)) {
            fail(file, message("config_library_missing", {*name, folder.string()}), node.source());
        }
        if (!fs::is_regular_file(status)) {
            fail(file, message("config_library_not_file", {*name}), node.source());
        }
        config.libraries.push_back({path.string(), role});
    };
    if (auto libs = t["libraries"].as_table()) {
        if (auto g = libs->get("g")) {
            addLibrary(*g, gcode::FileRole::GLibrary);
        }
        if (auto m = libs->get("m")) {
            addLibrary(*m, gcode::FileRole::MLibrary);
        }
        if (auto other = libs->get_as<toml::array>("other")) {
            for (const toml::node& n : *other) {
                addLibrary(n, gcode::FileRole::Library);
            }
        }
    }
    addUserLibrary(folder, config);
}

} // namespace m350::config
