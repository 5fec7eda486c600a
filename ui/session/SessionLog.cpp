#include "ui/session/SessionLog.h"

#include "core/config/MachineFolder.h"
#include "ui/i18n/Language.h"

#include <QDateTime>

namespace m350::ui {

SessionLog::SessionLog(const std::string& machineFolder)
    : log_(config::MachineFolder(machineFolder).pathOf(config::FolderFile::SystemLog).string()) {
    Message error;
    if (!log_.load(&error)) {
        loadProblem_ = error;
    }
    entries_ = std::make_shared<const LogTail>(log_.entries(), kOffered);
}

void SessionLog::record(const char* event, const QString& detail) {
    files::LogEntry entry{QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")).toStdString(),
                           event, detail.toStdString()};
    Message error;
    if (log_.append(std::move(entry), &error)) {
        appendProblem_.reset();
    } else {
        appendProblem_ = error;
    }
    entries_ = std::make_shared<const LogTail>(entries_->with(log_.entries().back(), kOffered));
}

QString SessionLog::problem() const {
    const std::optional<Message>& problem = appendProblem_ ? appendProblem_ : loadProblem_;
    return problem ? QString::fromStdString(problem->in(Language::messageLanguage())) : QString();
}

} // namespace m350::ui
