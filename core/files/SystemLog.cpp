#include "core/files/SystemLog.h"

#include "core/files/AtomicFile.h"
#include "core/files/MachineFileRead.h"
#include "core/files/ScratchFolder.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <unistd.h>

namespace m350::files {

namespace {

// A field never holds the tab or line end that separate fields and entries.
std::string clean(std::string text) {
    std::replace_if(text.begin(), text.end(), [](char c) { return c == '\t' || c == '\n' || c == '\r'; }, ' ');
    return text;
}

std::string line(const LogEntry& e) { return e.time + '\t' + e.event + '\t' + e.detail + '\n'; }

} // namespace

SystemLog::SystemLog(std::string path, std::size_t keep) : path_(std::move(path)), keep_(std::max<std::size_t>(keep, 1)) {}

bool SystemLog::load(Message* error, std::size_t* skipped) {
    entries_.clear();
    tornTail_ = false;
    std::size_t bad = 0;
    std::error_code ec;
    if (!std::filesystem::exists(path_, ec) && !std::filesystem::is_symlink(path_, ec)) {
        return true; // no log yet
    }
    std::string whole;
    if (auto why = readMachineFile(path_, whole)) {
        *error = message("syslog_cannot_read", {path_, bilingual(*why)});
        return false;
    }
    std::istringstream in(std::move(whole));
    std::string text;
    while (std::getline(in, text)) {
        if (in.eof()) {
            // no line end: an append cut short (the process was killed mid-write); the next append
            // rewrites the log without it
            tornTail_ = true;
            ++bad;
            break;
        }
        std::istringstream fields(text);
        LogEntry e;
        if (!std::getline(fields, e.time, '\t') || !std::getline(fields, e.event, '\t') || e.time.empty() ||
            e.event.empty()) {
            ++bad;
            continue;
        }
        std::getline(fields, e.detail);
        entries_.push_back(std::move(e));
    }
    if (in.bad()) {
        *error = message("syslog_read_failed", {path_});
        return false;
    }
    if (skipped) {
        *skipped = bad;
    }
    return true;
}

bool SystemLog::append(LogEntry entry, Message* error) {
    entry.time = clean(std::move(entry.time));
    entry.event = clean(std::move(entry.event));
    entry.detail = clean(std::move(entry.detail));
    entries_.push_back(entry);
    if (entries_.size() >= 2 * keep_ || tornTail_) {
        return compact(error);
    }
    // One write of the whole line to the file's end, synced: a kill leaves the line whole or cut
    // short, and a cut line is dropped when the log is read.
    const std::string text = line(entry);
    const int fd = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
    bool written = fd >= 0 && ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size()) &&
                   syncUnlessScratch(fd, path_);
    int failure = written ? 0 : errno;
    if (fd >= 0 && ::close(fd) != 0) {
        failure = written ? errno : failure;
        written = false;
    }
    if (!written) {
        *error = message("syslog_cannot_append", {path_, std::strerror(failure)});
        return false;
    }
    return true;
}

bool SystemLog::compact(Message* error) {
    if (entries_.size() > keep_) {
        entries_.erase(entries_.begin(), entries_.end() - static_cast<std::ptrdiff_t>(keep_));
    }
    std::string content;
    for (const LogEntry& e : entries_) {
        content += line(e);
    }
    if (auto why = writeFileAtomically(path_, content)) {
        *error = message("syslog_cannot_rewrite", {path_, bilingual(*why)});
        return false;
    }
    tornTail_ = false;
    return true;
}

} // namespace m350::files
