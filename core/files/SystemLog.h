#pragma once

#include "core/common/Message.h"

#include <cstddef>
#include <string>
#include <vector>

namespace m350::files {

// One row of the 系统日志 page: when, what (a stable key the panel translates: "start_work",
// "pause", "alarm" ...), and the detail (a file, an axis, an alarm's text).
struct LogEntry {
    std::string time;   // "2026-11-23 19:50:01", the caller's clock
    std::string event;
    std::string detail;
};

// The machine folder's system log (`system-log.tsv`, one tab-separated entry a line). Appending
// adds one line (one synced write); when the file holds twice `keep` entries it is rewritten
// atomically with the newest `keep`, so it stays bounded and a crash never loses what was logged
// before. A last line without its line end (an append killed mid-write) is skipped when read.
class SystemLog {
public:
    explicit SystemLog(std::string path, std::size_t keep = 2000);

    // Reads the file (a missing file is an empty log). Lines that are not three fields are
    // skipped and counted in `skipped`. A failure says why in `error`, by message id (the OS's
    // own words nested as it gives them).
    bool load(Message* error, std::size_t* skipped = nullptr);
    bool append(LogEntry entry, Message* error);
    const std::vector<LogEntry>& entries() const { return entries_; }
    const std::string& path() const { return path_; }

private:
    bool compact(Message* error);
    std::string path_;
    std::size_t keep_;
    std::vector<LogEntry> entries_;
    bool tornTail_ = false; // the file ends in a line cut short: the next append rewrites it whole
};

} // namespace m350::files
