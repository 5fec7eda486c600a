#pragma once

#include "core/files/SystemLog.h"
#include "ui/session/LogTail.h"

#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace m350::ui {

using LogEntries = std::shared_ptr<const LogTail>;

// The session's side of the 系统日志: every operation and alarm, stamped with the wall clock,
// appended to the machine folder's log, and offered to snapshots as an immutable list of the
// newest kOffered entries (what the System Log page shows), replaced (not changed) when an entry
// arrives: the file keeps more. The list shares its blocks with the one before (LogTail): copying
// the whole list at every entry cost a session of many MDI lines dearly.
class SessionLog {
public:
    static constexpr std::size_t kOffered = 500;

    explicit SessionLog(const std::string& machineFolder);
    // Event keys: see LogPage for their words (start_work, resume, pause, mdi, home_all ...).
    void record(const char* event, const QString& detail = {});
    LogEntries entries() const { return entries_; }
    // Why the log could not be read or its last entry not be written, in the panel's language;
    // empty when the last entry was written (a full disk that has room again).
    QString problem() const;

private:
    files::SystemLog log_;
    LogEntries entries_;
    std::optional<Message> loadProblem_;
    std::optional<Message> appendProblem_;
};

} // namespace m350::ui
