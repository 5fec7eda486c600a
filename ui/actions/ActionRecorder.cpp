#include "ui/actions/ActionRecorder.h"

#include "core/files/AtomicFile.h"
#include "core/files/OutputFile.h"
#include "ui/i18n/Language.h"

#include <QJsonDocument>

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace m350::ui {

namespace {

QString systemError(int error) { return QString::fromLocal8Bit(std::strerror(error)); }

} // namespace

ActionRecorder::~ActionRecorder() {
    blockSignals(true); // whoever listened may be gone already
    stop();
}

bool ActionRecorder::start(const QString& path, QString* error) {
    stop();
    error_.clear();
    path_ = path;
    target_ = files::OutputFile::writtenPath(path.toStdString());
    struct stat existing {};
    const bool exists = ::stat(target_.c_str(), &existing) == 0;
    if (exists && S_ISDIR(existing.st_mode)) {
        *error = tr("%1: cannot write: %2").arg(path, tr("it is a folder"));
        return false;
    }
    if (exists && !S_ISREG(existing.st_mode)) {
        fd_ = ::open(target_.c_str(), O_WRONLY | O_CLOEXEC);
        if (fd_ < 0) {
            *error = tr("%1: cannot write: %2").arg(path, systemError(errno));
            return false;
        }
        return true;
    }
    auto created = files::createTempBeside(target_, exists ? existing.st_mode & 07777 : 0644);
    if (auto* why = std::get_if<Message>(&created)) {
        *error = QString::fromStdString(why->in(Language::messageLanguage())); // it names the file
        return false;
    }
    fd_ = std::get<files::TempFile>(created).descriptor;
    temp_ = std::get<files::TempFile>(created).path;
    return true;
}

bool ActionRecorder::publish() {
    if (temp_.empty()) {
        return true;
    }
    if (::rename(temp_.c_str(), target_.c_str()) != 0) {
        fail(tr("%1: cannot write: %2").arg(path_, systemError(errno)));
        return false;
    }
    temp_.clear();
    return true;
}

bool ActionRecorder::writeLine(const QByteArray& line) {
    qsizetype done = 0;
    while (done < line.size()) {
        const ssize_t n = ::write(fd_, line.constData() + done, static_cast<std::size_t>(line.size() - done));
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            fail(tr("%1: cannot write: %2").arg(path_, systemError(n < 0 ? errno : EIO)));
            return false;
        }
        done += n;
    }
    return true;
}

void ActionRecorder::fail(const QString& why) {
    if (error_.isEmpty()) {
        error_ = why;
    }
    if (fd_ >= 0) {
        ::close(fd_);
        fd_ = -1;
    }
    if (!temp_.empty()) {
        ::unlink(temp_.c_str());
        temp_.clear();
    }
    emit failed(why);
}

QString ActionRecorder::stop() {
    if (fd_ < 0) {
        return error_;
    }
    const bool device = temp_.empty() && [this] {
        struct stat s {};
        return ::fstat(fd_, &s) == 0 && !S_ISREG(s.st_mode);
    }();
    if (!device && ::fsync(fd_) != 0) {
        fail(tr("%1: cannot write: %2").arg(path_, systemError(errno)));
        return error_;
    }
    if (!publish()) {
        return error_;
    }
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) {
        error_ = tr("%1: cannot write: %2").arg(path_, systemError(errno));
        emit failed(error_);
    }
    return error_;
}

void ActionRecorder::record(const OperatorAction& action) {
    if (fd_ < 0) {
        return;
    }
    OperatorAction stamped = action;
    // the clock as it is, not rounded to the millisecond: a handwheel turn lasts its `seconds` up to
    // the next one, and a gap made longer by rounding would let the 试切 override ramp down between
    // turns in the replay (it ramps down five times faster than up: the run would crawl)
    stamped.t = clock_();
    writeExtra(format_ ? format_(stamped) : QJsonDocument(stamped.toJson()).toJson(QJsonDocument::Compact) + '\n');
}

bool ActionRecorder::writeExtra(const QByteArray& line) {
    if (fd_ < 0 || line.isEmpty()) {
        return false;
    }
    // each line goes straight to the file: a session can end at any moment
    return writeLine(line) && publish();
}

} // namespace m350::ui
