#include "core/config/SystemLog.h"

#include "core/config/AtomicFile.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace m350::config {

namespace {

// A field never holds the tab or line end that separate fields and entries.
std::string clean(std::string text) {
    std::replace_if(text.begin(), text.end(), [](char c) { return c == '\t' || c == '\n' || c == '\r'; }, ' ');
    return text;
}

std::string line(const LogEntry& e) { return e.time + '\t' + e.event + '\t' + e.detail + '\n'; }

} // namespace

SystemLog::SystemLog(std::string path, std::size_t keep) : path_(std::move(path)), keep_(std::max<std::size_t>(keep, 1)) {}

bool SystemLog::load(std::string* error, std::size_t* skipped) {
    entries_.clear();
    std::size_t bad = 0;
    std::ifstream in(path_);
    if (!in) {
        std::error_code ec;
        if (!std::filesystem::exists(path_, ec)) {
            return true; // no log yet
        }
        *error = path_ + ": cannot read the system log";
        return false;
    }
    std::string text;
    while (std::getline(in, text)) {
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
        *error = path_ + ": cannot read";
        return false;
    }
    if (skipped) {
        *skipped = bad;
    }
    return true;
}

bool SystemLog::append(LogEntry entry, std::string* error) {
    entry.time = clean(std::move(entry.time));
    entry.event = clean(std::move(entry.event));
    entry.detail = clean(std::move(entry.detail));
    entries_.push_back(entry);
    if (entries_.size() >= 2 * keep_) {
        return compact(error);
    }
    std::ofstream out(path_, std::ios::app);
    out << line(entry);
    out.flush();
    if (!out) {
        *error = path_ + ": cannot append to the system log";
        return false;
    }
    return true;
}

bool SystemLog::compact(std::string* error) {
    entries_.erase(entries_.begin(), entries_.end() - static_cast<std::ptrdiff_t>(keep_));
    std::string content;
    for (const LogEntry& e : entries_) {
        content += line(e);
    }
    if (auto why = writeFileAtomically(path_, content)) {
        *error = *why;
        return false;
    }
    return true;
}

} // namespace m350::config
