#include "core/files/MachineFileRead.h"

#include "core/files/FileDescriptor.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace m350::files {

namespace fs = std::filesystem;

namespace {

Message notRegular(mode_t mode) {
    return message(S_ISDIR(mode)                      ? "machine_file_folder"
                   : S_ISFIFO(mode)                   ? "machine_file_fifo"
                   : S_ISCHR(mode) || S_ISBLK(mode)   ? "machine_file_device"
                   : S_ISSOCK(mode)                   ? "machine_file_socket"
                                                      : "machine_file_special");
}

Message tooBig(std::uintmax_t bytes, std::uintmax_t most) {
    return message("machine_file_too_big", {std::to_string(bytes), std::to_string(most / (1024 * 1024))});
}

// What the OS said (its own words, as strerror gives them), framed in the language said.
Message osSaid(int error) { return message("machine_file_os", {std::strerror(error)}); }

} // namespace

std::optional<Message> readMachineFile(const fs::path& file, std::string& text, std::uintmax_t mostBytes) {
    text.clear();
    // stat before open: a device is refused without being opened at all
    struct stat info {};
    if (::stat(file.c_str(), &info) != 0) {
        return osSaid(errno);
    }
    if (!S_ISREG(info.st_mode)) {
        return notRegular(info.st_mode);
    }
    // O_NONBLOCK: should the file be swapped for a FIFO after the stat, opening it does not wait
    const FileDescriptor fd(::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK));
    if (fd.get() < 0) {
        return osSaid(errno);
    }
    if (::fstat(fd.get(), &info) != 0) {
        return osSaid(errno);
    }
    if (!S_ISREG(info.st_mode)) {
        return notRegular(info.st_mode);
    }
    const auto size = static_cast<std::uintmax_t>(info.st_size);
    if (size > mostBytes) {
        return tooBig(size, mostBytes);
    }
    text.resize(static_cast<std::size_t>(size));
    std::size_t done = 0;
    for (;;) {
        if (done == text.size()) {
            if (done > mostBytes) {
                text.clear();
                return tooBig(done, mostBytes);
            }
            // it may have grown since the fstat: read on, in steps, up to the bound
            text.resize(text.size() + 64 * 1024);
        }
        const ssize_t n = ::read(fd.get(), text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n < 0) {
            const Message why = osSaid(errno);
            text.clear();
            return why;
        }
        if (n == 0) {
            break;
        }
        done += static_cast<std::size_t>(n);
    }
    text.resize(done);
    if (done > mostBytes) {
        text.clear();
        return tooBig(done, mostBytes);
    }
    return std::nullopt;
}

} // namespace m350::files
