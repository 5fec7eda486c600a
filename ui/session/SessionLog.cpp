#include "ui/session/SessionLog.h"

#include "core/config/MachineFolder.h"

#include <QDateTime>

namespace m350::ui {

SessionLog::SessionLog(const std::string& machineFolder)
    : log_(config::MachineFolder(machineFolder).pathOf(config::FolderFile::SystemLog).string()) {
    std::string error;
    if (!log_.load(&error)) {
        problem_ = QString::fromStdString(error);
    }
    entries_ = std::make_shared<const std::vector<files::LogEntry>>(log_.entries());
}

void SessionLog::record(const char* event, const QString& detail) {
    files::LogEntry entry{QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")).toStdString(),
                           event, detail.toStdString()};
    std::string error;
    if (!log_.append(std::move(entry), &error)) {
        problem_ = QString::fromStdString(error);
    }
    entries_ = std::make_shared<const std::vector<files::LogEntry>>(log_.entries());
}

} // namespace m350::ui
