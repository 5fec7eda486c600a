#include "core/files/AtomicFile.h"

#include "core/files/FileDescriptor.h"
#include "core/files/ScratchFolder.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <unordered_map>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace m350::files {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kChunk = 64 * 1024;

// What failed on `file` (a message id) and the OS's reason in its own words.
Message failure(const fs::path& file, const char* id) { return message(id, {file.string(), std::strerror(errno)}); }

std::optional<Message> writeAll(int fd, const fs::path& temp, std::string_view content,
                                    const AtomicWriteHooks& hooks) {
    std::size_t done = 0;
    while (done < content.size()) {
        std::size_t size = std::min(kChunk, content.size() - done);
        ssize_t n = ::write(fd, content.data() + done, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return failure(temp, "file_cannot_write_os");
        done += static_cast<std::size_t>(n);
        if (hooks.afterChunk) hooks.afterChunk(done);
    }
    return std::nullopt;
}

} // namespace

std::variant<TempFile, Message> createTempBeside(const fs::path& target, unsigned mode) {
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::string pattern =
        (folder / ("." + target.filename().string() + "." + std::to_string(::getpid()) + ".XXXXXX")).string();
    const int fd = ::mkostemp(pattern.data(), O_CLOEXEC);
    if (fd < 0) {
        return failure(target, "file_cannot_create_beside");
    }
    ::fchmod(fd, static_cast<mode_t>(mode));
    return TempFile{fd, pattern};
}

std::vector<fs::path> staleTempFiles(const fs::path& target) {
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    const std::string prefix = "." + target.filename().string() + ".";
    std::vector<fs::path> stale;
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) {
            continue;
        }
        const std::string rest = name.substr(prefix.size()); // PID.XXXXXX, or "tmp" (the one shared name of old)
        const std::size_t dot = rest.find('.');
        if (rest == "tmp") {
            stale.push_back(it->path());
            continue;
        }
        if (dot == 0 || dot == std::string::npos || rest.size() - dot != 7 ||
            rest.find_first_not_of("0123456789") != dot) {
            continue; // not a temp file of ours
        }
        const long pid = std::strtol(rest.c_str(), nullptr, 10);
        const bool writerAlive = pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
        if (!writerAlive) {
            stale.push_back(it->path());
        }
    }
    return stale;
}

namespace {

// A file of the scratch folder is rewritten where it is: a crash loses the folder anyway, and a
// replay of many MDI lines spent a third of its file time on the temp file, the rename and the
// search for stale temp files. Only a plain file with one name (or none yet) is: a link goes on
// being replaced, not written through. The file also stays open between writes (a replay
// rewrites mdi.nc and the MDI lines at every line run; opening, truncating and closing were most
// of such a write): its handle is used again only while the name still leads to the same file.
class ScratchHandles {
public:
    ScratchHandles() = default;
    ScratchHandles(const ScratchHandles&) = delete;
    ScratchHandles& operator=(const ScratchHandles&) = delete;
    ~ScratchHandles() { forgetAll(); }

    // The kept handle of `path` if it is still the file `now` describes, else -1 (and forgotten).
    int find(const std::string& path, const struct stat* now) {
        auto it = open_.find(path);
        if (it == open_.end()) {
            return -1;
        }
        struct stat kept {};
        if (now && ::fstat(it->second, &kept) == 0 && kept.st_dev == now->st_dev && kept.st_ino == now->st_ino) {
            return it->second;
        }
        ::close(it->second);
        open_.erase(it);
        return -1;
    }
    void keep(const std::string& path, int fd) {
        if (open_.size() >= kMostKept) {
            forgetAll();
        }
        open_.emplace(path, fd);
    }
    void forget(const std::string& path) { find(path, nullptr); }
    std::mutex& mutex() { return mutex_; }

private:
    void forgetAll() {
        for (const auto& [path, fd] : open_) {
            ::close(fd);
        }
        open_.clear();
    }
    static constexpr std::size_t kMostKept = 32;
    std::mutex mutex_;
    std::unordered_map<std::string, int> open_;
};

ScratchHandles& scratchHandles() {
    static ScratchHandles handles;
    return handles;
}

std::optional<std::optional<Message>> writeScratchInPlace(const fs::path& path, std::string_view content,
                                                              const AtomicWriteHooks& hooks) {
    if (hooks.beforeRename || !inScratchFolder(path)) {
        return std::nullopt;
    }
    struct stat existing {};
    const bool exists = ::lstat(path.c_str(), &existing) == 0;
    if (exists && (!S_ISREG(existing.st_mode) || existing.st_nlink != 1)) {
        return std::nullopt;
    }
    ScratchHandles& handles = scratchHandles();
    const std::lock_guard lock(handles.mutex());
    int fd = handles.find(path.string(), exists ? &existing : nullptr);
    if (fd < 0) {
        fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
        if (fd < 0) {
            return std::nullopt; // the careful way says what is wrong
        }
        handles.keep(path.string(), fd);
    }
    // from the start, then cut to the new length; an empty rewrite still marks the file modified
    if (::lseek(fd, 0, SEEK_SET) != 0) {
        handles.forget(path.string());
        return std::optional<Message>(failure(path, "file_cannot_write_os"));
    }
    if (auto error = writeAll(fd, path, content, hooks)) {
        handles.forget(path.string());
        return error;
    }
    if (::ftruncate(fd, static_cast<off_t>(content.size())) != 0 || (content.empty() && ::futimens(fd, nullptr) != 0)) {
        handles.forget(path.string());
        return std::optional<Message>(failure(path, "file_cannot_write_os"));
    }
    return std::optional<Message>();
}

} // namespace

std::optional<Message> writeFileAtomically(const fs::path& path, std::string_view content,
                                               const AtomicWriteHooks& hooks) {
    if (auto done = writeScratchInPlace(path, content, hooks)) {
        return *done;
    }
    mode_t mode = 0644;
    struct stat existing {};
    if (::stat(path.c_str(), &existing) == 0) mode = existing.st_mode & 07777;
    auto created = createTempBeside(path, mode);
    if (auto* error = std::get_if<Message>(&created)) return *error;
    const fs::path temp = std::get<TempFile>(created).path;
    FileDescriptor file(std::get<TempFile>(created).descriptor);
    if (auto error = writeAll(file.get(), temp, content, hooks)) {
        ::unlink(temp.c_str());
        return error;
    }
    if (!syncUnlessScratch(file.get(), path) || !file.close()) {
        Message error = failure(temp, "file_cannot_sync");
        ::unlink(temp.c_str());
        return error;
    }
    if (hooks.beforeRename) hooks.beforeRename();
    if (::rename(temp.c_str(), path.c_str()) != 0) {
        Message error = failure(path, "file_cannot_replace");
        ::unlink(temp.c_str());
        return error;
    }
    for (const fs::path& stale : staleTempFiles(path)) {
        ::unlink(stale.c_str());
    }
    return syncFolder(path.parent_path().empty() ? fs::path(".") : path.parent_path());
}

std::optional<Message> syncFolder(const fs::path& folder) {
    if (inScratchFolder(folder)) {
        return std::nullopt;
    }
    FileDescriptor directory(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (directory.get() < 0 || ::fsync(directory.get()) != 0) return failure(folder, "file_cannot_sync_folder");
    return std::nullopt;
}

} // namespace m350::files
