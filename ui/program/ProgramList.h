#pragma once

#include "ui/program/ProgramFiles.h"

#include <QWidget>

class QLabel;
class QTableWidget;

namespace m350::ui {

// The Program page's file list: which disk, 当前路径, the files (名称 / 大小 / 修改时间) with a
// selection bar, 磁盘剩余空间 and the sort order (param 149).
class ProgramList : public QWidget {
    Q_OBJECT
public:
    explicit ProgramList(QWidget* parent = nullptr);

    void showFolder(ProgramFiles::Disk disk, const QString& folder, ProgramFiles::Sort sort);
    void refresh(); // the folder again (after a change on disk)
    void retranslate();
    void moveSelection(int step);
    void select(const QString& name);
    QString selectedName() const;
    QString selectedPath() const;
    QStringList names() const;
    ProgramFiles::Disk disk() const { return disk_; }
    const QString& folder() const { return folder_; }
    static QString diskName(ProgramFiles::Disk disk);

private:
    QLabel* header_;
    QTableWidget* table_;
    QLabel* footer_;
    ProgramFiles::Disk disk_ = ProgramFiles::Disk::Local;
    ProgramFiles::Sort sort_ = ProgramFiles::Sort::Name;
    QString folder_;
    QVector<ProgramFiles::Entry> entries_;
};

} // namespace m350::ui
