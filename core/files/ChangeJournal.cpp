#include "core/files/ChangeJournal.h"

#include "core/files/LastGoodCopy.h"
#include "core/files/MachineFileRead.h"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

namespace m350::files {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kHeader = "m350 change";
constexpr std::string_view kEnd = "end";
constexpr std::uintmax_t kMostJournalBytes = 64 * 1024;

// FNV-1a: a checksum that a pending file cut short or left from another change fails.
std::string checksum(std::string_view bytes) {
    std::uint64_t hash = 14695981039346656037ull;
    for (unsigned char c : bytes) {
        hash = (hash ^ c) * 1099511628211ull;
    }
    char out[17];
    std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(hash));
    return out;
}

struct JournalEntry {
    std::string name;
    std::uintmax_t size = 0;
    std::string checksum;
};

fs::path folderOf(const fs::path& journal) {
    return journal.parent_path().empty() ? fs::path(".") : journal.parent_path();
}

bool matches(const fs::path& file, const JournalEntry& entry) {
    std::string text;
    return !readMachineFile(file, text, entry.size) && text.size() == entry.size && checksum(text) == entry.checksum;
}

// The entries of a whole journal, or why it is not one.
std::optional<Message> parseJournal(const std::string& text, std::vector<JournalEntry>& entries) {
    std::istringstream in(text);
    std::string line;
    if (!std::getline(in, line) || line != kHeader) {
        return message("journal_not_ours");
    }
    while (std::getline(in, line)) {
        if (line == kEnd) {
            return entries.empty() ? std::optional<Message>(message("journal_no_file")) : std::nullopt;
        }
        std::istringstream fields(line);
        JournalEntry entry;
        if (!(fields >> entry.name >> entry.size >> entry.checksum) || entry.name.find('/') != std::string::npos ||
            entry.name == "." || entry.name == "..") {
            return message("journal_bad_line", {std::to_string(entries.size() + 2)});
        }
        entries.push_back(std::move(entry));
    }
    return message("journal_no_end");
}

void removePending(std::span<const ChangedFile> files) {
    for (const ChangedFile& file : files) {
        ::unlink(pendingPath(file.path).c_str());
    }
}

} // namespace

fs::path pendingPath(const fs::path& file) {
    fs::path pending = file;
    pending += ".pending";
    return pending;
}

std::optional<Message> finishInterruptedChange(const fs::path& journal, std::span<const fs::path> candidates) {
    struct stat info {};
    if (::lstat(journal.c_str(), &info) != 0) {
        if (errno != ENOENT) {
            return message("journal_os", {journal.string(), std::strerror(errno)});
        }
        for (const fs::path& file : candidates) {
            // a change that never happened: its journal was not written
            ::unlink(pendingPath(file).c_str());
        }
        return std::nullopt;
    }
    std::string text;
    if (auto why = readMachineFile(journal, text, kMostJournalBytes)) {
        return message("journal_unreadable", {journal.string(), bilingual(*why)});
    }
    std::vector<JournalEntry> entries;
    if (auto why = parseJournal(text, entries)) {
        return message("journal_refused", {journal.string(), bilingual(*why)});
    }
    const fs::path folder = folderOf(journal);
    for (const JournalEntry& entry : entries) {
        const fs::path target = folder / entry.name;
        const fs::path pending = pendingPath(target);
        std::error_code ec;
        if (fs::exists(fs::symlink_status(pending, ec))) {
            if (!matches(pending, entry)) {
                return message("journal_pending_differs", {pending.string(), journal.string()});
            }
            if (::rename(pending.c_str(), target.c_str()) != 0) {
                return message("journal_cannot_finish", {target.string(), std::strerror(errno)});
            }
        } else if (!matches(target, entry)) {
            return message("journal_neither", {target.string(), journal.string()});
        }
    }
    if (auto error = syncFolder(folder)) {
        return error;
    }
    if (::unlink(journal.c_str()) != 0) {
        return message("file_cannot_remove", {journal.string(), std::strerror(errno)});
    }
    return syncFolder(folder);
}

std::optional<Message> writeTogether(const fs::path& journal, std::span<const ChangedFile> files,
                                         const AtomicWriteHooks& hooks) {
    std::vector<fs::path> paths;
    for (const ChangedFile& file : files) {
        paths.push_back(file.path);
    }
    if (auto error = finishInterruptedChange(journal, paths)) {
        return error;
    }
    std::string record = std::string(kHeader) + '\n';
    for (const ChangedFile& file : files) {
        const fs::path pending = pendingPath(file.path);
        if (auto error = writeFileAtomically(pending, file.content)) {
            removePending(files);
            return error;
        }
        struct stat target {};
        if (::stat(file.path.c_str(), &target) == 0) {
            ::chmod(pending.c_str(), target.st_mode & 07777); // the file keeps its permissions
        }
        record += file.path.filename().string() + ' ' + std::to_string(file.content.size()) + ' ' +
                  checksum(file.content) + '\n';
    }
    record += std::string(kEnd) + '\n';
    AtomicWriteHooks journalHooks;
    journalHooks.afterChunk = hooks.afterChunk;
    journalHooks.beforeRename = hooks.beforeRename;
    if (auto error = writeFileAtomically(journal, record, journalHooks)) {
        removePending(files);
        return error;
    }
    // the change has happened: from here a crash is finished by the next load
    for (std::size_t i = 0; i < files.size(); ++i) {
        if (::rename(pendingPath(files[i].path).c_str(), files[i].path.c_str()) != 0) {
            return message("file_cannot_replace", {files[i].path.string(), std::strerror(errno)});
        }
        if (i + 1 < files.size() && hooks.betweenFiles) {
            hooks.betweenFiles();
        }
    }
    if (auto error = syncFolder(folderOf(journal))) {
        return error;
    }
    for (const ChangedFile& file : files) {
        if (file.keepLastGood) {
            if (auto error = writeFileAtomically(lastGoodPath(file.path), file.content)) {
                return error;
            }
        }
    }
    if (::unlink(journal.c_str()) != 0) {
        return message("file_cannot_remove", {journal.string(), std::strerror(errno)});
    }
    return syncFolder(folderOf(journal));
}

} // namespace m350::files
