#include "ui/program/ProgramFiles.h"

#include "core/config/MachineConfig.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <filesystem>
#include <string_view>

#include <dirent.h>
#include <fcntl.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

namespace m350::ui {

namespace {

constexpr QStringView kForbidden = u"/\\:*?\"<>|";

QString examplesFolder() {
    return QDir(QString::fromStdString(config::bundledMachinesDirectory())).filePath(QStringLiteral("../examples"));
}

} // namespace

QString ProgramFiles::localFolder(const QString& machineFolder, QString* error) {
    QDir machine(machineFolder);
    const QString folder = machine.filePath(QStringLiteral("programs"));
    if (QDir(folder).exists()) {
        return folder;
    }
    if (!machine.mkpath(QStringLiteral("programs"))) {
        *error = QStringLiteral("%1: cannot create the folder").arg(folder);
        return folder;
    }
    QDir examples(examplesFolder());
    for (const QString& name : examples.entryList({QStringLiteral("*.nc")}, QDir::Files)) {
        QString target = QDir(folder).filePath(name);
        QFile::copy(examples.filePath(name), target);
        QFile::setPermissions(target, QFile::permissions(target) | QFileDevice::WriteOwner);
    }
    return folder;
}

QVector<ProgramFiles::Entry> ProgramFiles::list(const QString& folder, Disk disk, Sort sort) {
    // What QDir's Files | Readable listing gave (hidden files left out, links followed, "*.nc" in
    // any case on the system disk), read with one stat a file: the disks are listed again at
    // each F1, and QDir matched every name with a regular expression and asked each file twice.
    QVector<Entry> out;
    DIR* dir = ::opendir(QFile::encodeName(folder).constData());
    if (dir == nullptr) {
        return out;
    }
    const int fd = ::dirfd(dir);
    while (const dirent* entry = ::readdir(dir)) {
        const std::string_view name(entry->d_name);
        if (name.empty() || name.front() == '.') {
            continue;
        }
        if (disk == Disk::System && // the libraries, not machine.toml and the rest
            (name.size() < 3 || ::strncasecmp(name.data() + name.size() - 3, ".nc", 3) != 0)) {
            continue;
        }
        struct stat info {};
        if (::fstatat(fd, entry->d_name, &info, 0) != 0 || !S_ISREG(info.st_mode) || ::faccessat(fd, entry->d_name, R_OK, 0) != 0) {
            continue;
        }
        const qint64 modified = static_cast<qint64>(info.st_mtim.tv_sec) * 1000 + info.st_mtim.tv_nsec / 1000000;
        out.append({QFile::decodeName(entry->d_name), static_cast<qint64>(info.st_size), QDateTime::fromMSecsSinceEpoch(modified)});
    }
    ::closedir(dir);
    auto byName = [](const Entry& a, const Entry& b) { return a.name.compare(b.name, Qt::CaseInsensitive) < 0; };
    switch (sort) {
    case Sort::Name: std::sort(out.begin(), out.end(), byName); break;
    case Sort::Suffix:
        std::sort(out.begin(), out.end(), [&](const Entry& a, const Entry& b) {
            int c = QFileInfo(a.name).suffix().compare(QFileInfo(b.name).suffix(), Qt::CaseInsensitive);
            return c != 0 ? c < 0 : byName(a, b);
        });
        break;
    case Sort::Date: // newest first
        std::sort(out.begin(), out.end(), [&](const Entry& a, const Entry& b) {
            return a.modified != b.modified ? a.modified > b.modified : byName(a, b);
        });
        break;
    }
    return out;
}

ProgramFiles::NameProblem ProgramFiles::checkName(const QString& folder, const QString& name) {
    if (name.trimmed().isEmpty()) {
        return NameProblem::Empty;
    }
    if (name.size() > kMaxName) {
        return NameProblem::TooLong;
    }
    if (name.startsWith(QLatin1Char('.')) || std::any_of(name.begin(), name.end(), [](QChar c) {
            return kForbidden.contains(c) || c.unicode() < 0x20;
        })) {
        return NameProblem::Invalid;
    }
    if (QFileInfo::exists(QDir(folder).filePath(name))) {
        return NameProblem::Exists;
    }
    return NameProblem::None;
}

// std::filesystem::space asks the file system alone (statvfs); QStorageInfo read the whole mount
// table first, at every disk switch of the Program page
qint64 ProgramFiles::freeBytes(const QString& folder) {
    std::error_code error;
    const std::filesystem::space_info space = std::filesystem::space(folder.toStdString(), error);
    return error ? -1 : static_cast<qint64>(space.available);
}

bool ProgramFiles::create(const QString& path, QString* error) {
    QFile file(path);
    if (!file.open(QIODevice::NewOnly | QIODevice::WriteOnly)) {
        *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

bool ProgramFiles::remove(const QString& path, QString* error) {
    QFile file(path);
    if (!file.remove()) {
        *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

bool ProgramFiles::rename(const QString& from, const QString& to, QString* error) {
    QFile file(from);
    if (!file.rename(to)) {
        *error = QStringLiteral("%1: %2").arg(from, file.errorString());
        return false;
    }
    return true;
}

bool ProgramFiles::copy(const QString& from, const QString& to, QString* error) {
    QFile file(from);
    if (!file.copy(to)) {
        *error = QStringLiteral("%1: %2").arg(from, file.errorString());
        return false;
    }
    QFile::setPermissions(to, QFile::permissions(to) | QFileDevice::WriteOwner);
    return true;
}

} // namespace m350::ui
