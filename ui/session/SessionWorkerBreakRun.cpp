// 断点加工 through the session: start the loaded file at a line, resume at the paused block, and
// the break point the machine folder keeps for 断电断点加工 (a file `breakpoint`: the program's
// path on one line, the line number on the next, written atomically).
#include "ui/session/SessionWorker.h"

#include "core/controller/Controller.h"
#include "ui/i18n/Language.h"

#include <QDateTime>
#include <QFile>

namespace m350::ui {

using controller::Controller;

void SessionWorker::startAtLine(int line) {
    lastError_.clear();
    if (busy()) {
        refuse(tr("A program is running: wait for it, or PAUSE / RESET first"));
        return;
    }
    if (programFile_.isEmpty()) {
        refuse(tr("No program loaded: load one on the Program page"));
        return;
    }
    if (line <= 0) {
        refuse(tr("Line %1 is not in the program").arg(line));
        return;
    }
    if (!loadCurrentFile()) {
        return;
    }
    Message why;
    startedAt("start_line", controller_->breakRun().startAtLine(static_cast<std::uint32_t>(line), &why), why);
}

void SessionWorker::resumeAtPause() {
    lastError_.clear();
    if (!fileLoaded_) {
        refuse(tr("No paused run to resume (PAUSE, then RESET)"));
        return;
    }
    Message why;
    startedAt("break_run", controller_->breakRun().resumeAtPause(&why), why);
}

void SessionWorker::powerResume() {
    lastError_.clear();
    BreakPoints kept = breakPointFile_.points(controller_->breakRun(), folder_);
    if (kept.keptLine <= 0) {
        refuse(tr("No break point is kept in the machine folder"));
        return;
    }
    if (busy()) {
        refuse(tr("A program is running: wait for it, or PAUSE / RESET first"));
        return;
    }
    if (kept.keptFile != programFile_) {
        programFile_ = kept.keptFile;
        fileLoaded_ = false;
    }
    if (!loadCurrentFile()) {
        return;
    }
    Message why;
    startedAt("break_run", controller_->breakRun().startAtLine(static_cast<std::uint32_t>(kept.keptLine), &why), why);
}

void SessionWorker::startedAt(const char* event, bool started, const Message& why) {
    if (!started) {
        refuse(QString::fromStdString(why.in(Language::messageLanguage())));
        return;
    }
    activity_ = Activity::Auto;
    log_->record(event, programFile_);
    workRecord_.file = programFile_;
    if (workRecord_.startedAt.isEmpty()) {
        workRecord_.startedAt = QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
    }
    publish();
}

void SessionWorker::keepBreakPoint() {
    if (auto problem = breakPointFile_.keep(controller_->breakRun(), folder_)) {
        lastError_ = *problem;
    }
}

} // namespace m350::ui
