#include "core/files/OutputFile.h"

#include "core/files/AtomicFile.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace m350::files {

namespace fs = std::filesystem;

namespace {

Message failure(const fs::path& file, const char* id, int error) {
    return message(id, {file.string(), std::strerror(error)});
}

std::optional<Message> passedOn(const std::optional<Message>& why) {
    return why ? std::optional<Message>(message("output_write_failed", {bilingual(*why)})) : std::nullopt;
}

} // namespace

OutputFile::OutputFile(fs::path target, fs::path temp) : target_(std::move(target)), temp_(std::move(temp)) {}

// A link is written through: the file it leads to is replaced, the link stays a link.
fs::path OutputFile::writtenPath(const fs::path& target) {
    std::error_code ec;
    if (!fs::is_symlink(target, ec)) {
        return target;
    }
    const fs::path real = fs::weakly_canonical(fs::absolute(target, ec), ec);
    return ec ? target : real;
}

std::variant<std::unique_ptr<OutputFile>, Message> OutputFile::open(const fs::path& named) {
    const fs::path target = writtenPath(named);
    struct stat existing {};
    const bool exists = ::stat(target.c_str(), &existing) == 0;
    if (exists && S_ISDIR(existing.st_mode)) {
        return message("output_cannot_write_folder", {named.string()});
    }
    if (exists && !S_ISREG(existing.st_mode)) {
        std::unique_ptr<OutputFile> direct(new OutputFile(target, {}));
        direct->stream_.open(target, std::ios::binary);
        if (!direct->stream_) {
            return failure(named, "output_cannot_open", errno);
        }
        return direct;
    }
    auto created = createTempBeside(target, exists ? existing.st_mode & 07777 : 0644);
    if (auto* error = std::get_if<Message>(&created)) {
        return message("output_write_failed", {bilingual(*error)});
    }
    const TempFile temp = std::get<TempFile>(created);
    ::close(temp.descriptor);
    std::unique_ptr<OutputFile> file(new OutputFile(target, temp.path));
    file->stream_.open(temp.path, std::ios::binary | std::ios::trunc);
    if (!file->stream_) {
        return failure(target, "output_cannot_open", errno);
    }
    return file;
}

OutputFile::~OutputFile() {
    if (!committed_ && !temp_.empty()) {
        stream_.close();
        ::unlink(temp_.c_str());
    }
}

std::optional<Message> OutputFile::commit() {
    errno = 0;
    stream_.flush();
    if (!stream_) {
        return failure(target_, "output_cannot_write", errno != 0 ? errno : EIO);
    }
    stream_.close();
    if (!stream_) {
        return failure(target_, "output_cannot_write", errno != 0 ? errno : EIO);
    }
    if (temp_.empty()) {
        committed_ = true;
        return std::nullopt;
    }
    const int fd = ::open(temp_.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0 || ::fsync(fd) != 0) {
        const int error = errno;
        if (fd >= 0) ::close(fd);
        return failure(target_, "output_cannot_sync", error);
    }
    ::close(fd);
    if (::rename(temp_.c_str(), target_.c_str()) != 0) {
        return failure(target_, "output_cannot_replace", errno);
    }
    committed_ = true;
    for (const fs::path& stale : staleTempFiles(target_)) {
        ::unlink(stale.c_str());
    }
    return passedOn(syncFolder(target_.parent_path().empty() ? fs::path(".") : target_.parent_path()));
}

std::optional<Message> writeOutputFile(const fs::path& target, std::string_view content) {
    auto opened = OutputFile::open(target);
    if (auto* error = std::get_if<Message>(&opened)) {
        return *error;
    }
    OutputFile& file = *std::get<std::unique_ptr<OutputFile>>(opened);
    errno = 0;
    file.stream().write(content.data(), static_cast<std::streamsize>(content.size()));
    if (!file.stream()) { // a large content fails here, not at the flush: say this errno
        return failure(target, "output_cannot_write", errno != 0 ? errno : EIO);
    }
    return file.commit();
}

} // namespace m350::files
