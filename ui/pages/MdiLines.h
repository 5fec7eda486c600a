#pragma once

#include <QString>
#include <QStringList>

namespace m350::ui {

// The MDI page's six lines, kept in the machine folder as the M350 keeps them: the file
// `mdiblock`, six records of 120 bytes, each a line padded with NULs. Written atomically.
class MdiLines {
public:
    static constexpr int kCount = 6;
    static constexpr int kRecordBytes = 120;

    // Reads `folder`/mdiblock; a missing file gives six empty lines. UTF-8 or GBK.
    static QStringList load(const QString& folder, QString* error = nullptr);
    // False (and why) when the folder cannot be written or a line is longer than a record.
    static bool save(const QString& folder, const QStringList& lines, QString* error);
    static QString path(const QString& folder);
};

} // namespace m350::ui
