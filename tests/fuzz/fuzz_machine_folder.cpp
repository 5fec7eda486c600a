// libFuzzer target: the machine-folder readers. The first byte picks the file ('0' is kFiles[0],
// round again past the end), the rest is its content. It is written into a private copy of a bundled
// machine folder (m350-linear16 for most files, fanuc-ts27r for the FANUC tool files), the folder
// is loaded, and the file is put back as it was for the next input.
#include "core/config/MachineConfig.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

struct FolderFile {
    const char* name;
    const char* machine; // the bundled folder the other files come from
};

constexpr std::array<FolderFile, 10> kFiles{{
    {"machine.toml", "m350-linear16"},
    {"params.toml", "m350-linear16"},
    {"offsets.toml", "m350-linear16"},
    {"variables.toml", "fanuc-ts27r"},
    {"tool.tbl", "fanuc-ts27r"},
    {"toollife.txt", "fanuc-ts27r"},
    {"spindle-load.toml", "fanuc-ts27r"},
    {"modbus.toml", "m350-linear16"},
    {"machine.toml", "fanuc-ts27r"},
    {"params.toml", "fanuc-ts27r"},
}};

// A copy of each bundled machine in a temporary folder, made once; removed at exit.
class Folders {
public:
    Folders() {
        std::string pattern = (fs::temp_directory_path() / "m350-fuzz-XXXXXX").string();
        if (mkdtemp(pattern.data()) == nullptr) {
            std::perror("mkdtemp");
            std::abort();
        }
        root_ = pattern;
        for (const char* machine : {"m350-linear16", "fanuc-ts27r"}) {
            fs::copy(fs::path(M350_MACHINES_DIR) / machine, root_ / machine, fs::copy_options::recursive);
        }
    }
    ~Folders() {
        std::error_code ignored;
        fs::remove_all(root_, ignored);
    }
    fs::path folder(const char* machine) const { return root_ / machine; }

private:
    fs::path root_;
};

bool readWhole(const fs::path& path, std::string& bytes) {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return static_cast<bool>(in) || in.eof();
}

void writeWhole(const fs::path& path, const char* data, std::size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(data, static_cast<std::streamsize>(size));
    if (!out.flush()) {
        std::perror(path.c_str());
        std::abort();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const Folders folders;
    if (size == 0) {
        return 0;
    }
    const FolderFile& file = kFiles[static_cast<std::uint8_t>(data[0] - '0') % kFiles.size()];
    const fs::path folder = folders.folder(file.machine);
    const fs::path path = folder / file.name;
    std::string original;
    const bool existed = fs::exists(path) && readWhole(path, original);
    writeWhole(path, reinterpret_cast<const char*>(data) + 1, size - 1);
    (void)m350::config::loadMachineFolder(folder.string());
    if (existed) {
        writeWhole(path, original.data(), original.size());
    } else {
        fs::remove(path);
    }
    return 0;
}
