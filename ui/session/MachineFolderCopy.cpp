#include "ui/session/MachineFolderCopy.h"

#include "core/config/MachineConfig.h"

#include <QDir>
#include <QFile>
#include <QStandardPaths>

namespace m350::ui {

namespace {

QString bundledDefault() {
    return QDir(QString::fromStdString(config::bundledMachinesDirectory())).filePath(config::kDefaultMachine);
}

bool copyFolder(const QString& from, const QString& to, QString* error) {
    QDir source(from);
    if (!source.exists()) {
        *error = QStringLiteral("%1: the bundled machine folder is missing").arg(from);
        return false;
    }
    if (!QDir().mkpath(to)) {
        *error = QStringLiteral("%1: cannot create the folder").arg(to);
        return false;
    }
    for (const QString& name : source.entryList(QDir::Files)) {
        QString target = QDir(to).filePath(name);
        if (!QFile::exists(target) && !QFile::copy(source.filePath(name), target)) {
            *error = QStringLiteral("%1: cannot copy %2").arg(to, name);
            return false;
        }
        QFile::setPermissions(target, QFile::permissions(target) | QFileDevice::WriteOwner);
    }
    return true;
}

} // namespace

std::optional<QString> copyBundledMachine(const QString& intoDirectory, QString* error) {
    QString target = QDir(intoDirectory).filePath(config::kDefaultMachine);
    if (!copyFolder(bundledDefault(), target, error)) {
        return std::nullopt;
    }
    return target;
}

std::optional<QString> userMachineFolder(QString* error) {
    QString data = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    if (data.isEmpty()) {
        *error = QStringLiteral("no folder for the panel's data (set HOME, or pass --config DIR)");
        return std::nullopt;
    }
    return copyBundledMachine(QDir(data).filePath(QStringLiteral("machines")), error);
}

} // namespace m350::ui
