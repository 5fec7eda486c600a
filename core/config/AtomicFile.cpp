#include "core/config/AtomicFile.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace m350::config {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kChunk = 64 * 1024;

std::string failure(const fs::path& file, const char* what) {
    return file.string() + ": " + what + ": " + std::strerror(errno);
}

// Closes the descriptor on every path out of writeFileAtomically.
class Descriptor {
public:
    explicit Descriptor(int fd) : fd_(fd) {}
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    ~Descriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    int get() const { return fd_; }
    bool close() {
        int fd = fd_;
        fd_ = -1;
        return ::close(fd) == 0;
    }

private:
    int fd_;
};

std::optional<std::string> writeAll(int fd, const fs::path& temp, std::string_view content,
                                    const AtomicWriteHooks& hooks) {
    std::size_t done = 0;
    while (done < content.size()) {
        std::size_t size = std::min(kChunk, content.size() - done);
        ssize_t n = ::write(fd, content.data() + done, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return failure(temp, "cannot write");
        done += static_cast<std::size_t>(n);
        if (hooks.afterChunk) hooks.afterChunk(done);
    }
    return std::nullopt;
}

} // namespace

fs::path atomicTempPath(const fs::path& path) {
    return path.parent_path() / ("." + path.filename().string() + ".tmp");
}

std::optional<std::string> writeFileAtomically(const fs::path& path, std::string_view content,
                                               const AtomicWriteHooks& hooks) {
    fs::path temp = atomicTempPath(path);
    mode_t mode = 0644;
    struct stat existing {};
    if (::stat(path.c_str(), &existing) == 0) mode = existing.st_mode & 07777;
    Descriptor file(::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, mode));
    if (file.get() < 0) return failure(temp, "cannot create");
    if (auto error = writeAll(file.get(), temp, content, hooks)) {
        ::unlink(temp.c_str());
        return error;
    }
    if (::fsync(file.get()) != 0 || !file.close()) {
        std::string error = failure(temp, "cannot sync");
        ::unlink(temp.c_str());
        return error;
    }
    if (hooks.beforeRename) hooks.beforeRename();
    if (::rename(temp.c_str(), path.c_str()) != 0) {
        std::string error = failure(path, "cannot replace");
        ::unlink(temp.c_str());
        return error;
    }
    return syncFolder(path.parent_path().empty() ? fs::path(".") : path.parent_path());
}

std::optional<std::string> syncFolder(const fs::path& folder) {
    Descriptor directory(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (directory.get() < 0 || ::fsync(directory.get()) != 0) return failure(folder, "cannot sync the folder");
    return std::nullopt;
}

} // namespace m350::config
