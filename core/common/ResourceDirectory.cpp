#include "core/common/ResourceDirectory.h"

#include <filesystem>
#include <system_error>

namespace m350 {

namespace {

std::string findResourceDirectory() {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        // M350_RESOURCES_FROM_BIN: the install's data folder relative to its bin folder
        // (GNUInstallDirs, set in core/CMakeLists.txt), usually ../share/m350-studio.
        const fs::path installed = (exe.parent_path() / M350_RESOURCES_FROM_BIN).lexically_normal();
        if (fs::is_directory(installed / "machines", ec)) {
            return installed.string();
        }
    }
    return M350_RESOURCE_DIR;
}

} // namespace

std::string resourceDirectory() {
    static const std::string directory = findResourceDirectory();
    return directory;
}

} // namespace m350
