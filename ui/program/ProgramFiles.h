#pragma once

#include <QDateTime>
#include <QString>
#include <QVector>

namespace m350::ui {

// The Program page's disks and what it does to their files. The M350 has 本地程序(O), its own
// flash, and U盘程序(N), the USB stick; here the local disk is `programs/` in the machine folder
// (made on first use, with the bundled examples in it), the U disk a folder of the user's
// (--programs DIR, else the home folder), and a third, the system disk, holds the machine's macro
// libraries (slib-g.nc, slib-m.nc) for the editor.
class ProgramFiles {
public:
    enum class Disk { Local, User, System };
    enum class Sort { Name = 0, Suffix = 1, Date = 2 }; // parameter 149
    struct Entry {
        QString name;
        qint64 size = 0;
        QDateTime modified;
    };
    enum class NameProblem { None, Empty, TooLong, Invalid, Exists };
    static constexpr int kMaxName = 32; // characters, as the panel's file system takes them

    static QString localFolder(const QString& machineFolder, QString* error);
    static QVector<Entry> list(const QString& folder, Disk disk, Sort sort);
    static NameProblem checkName(const QString& folder, const QString& name);
    static qint64 freeBytes(const QString& folder);
    // Each returns false with a reason.
    static bool create(const QString& path, QString* error);
    static bool remove(const QString& path, QString* error);
    static bool rename(const QString& from, const QString& to, QString* error);
    static bool copy(const QString& from, const QString& to, QString* error);
};

} // namespace m350::ui
