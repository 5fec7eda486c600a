#include "ui/program/ProgramList.h"
#include "ui/widgets/MeasuredLabel.h"
#include "ui/widgets/PanelTable.h"

#include <QDir>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace m350::ui {

ProgramList::ProgramList(QWidget* parent) : QWidget(parent) {
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    header_ = new MeasuredLabel(this);
    header_->setObjectName("programHeader");
    header_->setTextInteractionFlags(Qt::NoTextInteraction);
    table_ = makePanelTable(this, 3, "programFiles", 24);
    table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    footer_ = new MeasuredLabel(this);
    footer_->setObjectName("programFooter");
    column->addWidget(header_);
    column->addWidget(table_, 1);
    column->addWidget(footer_);
    retranslate();
}

QString ProgramList::diskName(ProgramFiles::Disk disk) {
    switch (disk) {
    case ProgramFiles::Disk::Local: return tr("Local Disk(O)", "msg 959");
    case ProgramFiles::Disk::User: return tr("U Disk(N)", "msg 960");
    case ProgramFiles::Disk::System: return tr("System disk (macro libraries)");
    }
    return {};
}

void ProgramList::retranslate() {
    table_->setHorizontalHeaderLabels({tr("Name", "msg 80"), tr("Size", "msg 81"), tr("Modify time", "msg 82")});
    if (!folder_.isEmpty()) {
        showFolder(disk_, folder_, sort_);
    }
}

void ProgramList::showFolder(ProgramFiles::Disk disk, const QString& folder, ProgramFiles::Sort sort) {
    const QString keep = disk == disk_ && folder == folder_ ? selectedName() : QString();
    disk_ = disk;
    folder_ = folder;
    sort_ = sort;
    entries_ = ProgramFiles::list(folder, disk, sort);
    const QLocale locale;
    { // the fitted columns measured once, at the end of this block
        const TableFill filling(table_);
        table_->setRowCount(static_cast<int>(entries_.size()));
        for (int row = 0; row < entries_.size(); ++row) {
            const ProgramFiles::Entry& e = entries_[row];
            auto* size = new QTableWidgetItem(locale.formattedDataSize(e.size, 1, QLocale::DataSizeTraditionalFormat));
            size->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            table_->setItem(row, 0, new QTableWidgetItem(e.name));
            table_->setItem(row, 1, size);
            table_->setItem(row, 2, new QTableWidgetItem(e.modified.toString(QStringLiteral("yyyy-MM-dd HH:mm"))));
        }
    }
    header_->setText(QStringLiteral("%1    %2 %3").arg(diskName(disk), tr("Cur Path:", "msg 952"),
                                                      QDir::toNativeSeparators(folder)));
    const QString sortWord = sort == ProgramFiles::Sort::Suffix ? tr("EXT", "msg 757")
                             : sort == ProgramFiles::Sort::Date ? tr("DATE", "msg 758")
                                                                : tr("NAME", "msg 756");
    footer_->setText(QStringLiteral("%1 %2    %3 %4")
                         .arg(tr("Free Space:", "msg 951"),
                              locale.formattedDataSize(ProgramFiles::freeBytes(folder), 1,
                                                       QLocale::DataSizeTraditionalFormat),
                              tr("Sort:", "msg 759"), sortWord));
    if (!keep.isEmpty()) {
        select(keep);
    }
    if (table_->currentRow() < 0 && !entries_.isEmpty()) {
        table_->selectRow(0);
    }
}

void ProgramList::refresh() { showFolder(disk_, folder_, sort_); }

void ProgramList::moveSelection(int step) {
    if (entries_.isEmpty()) {
        return;
    }
    int row = std::clamp(table_->currentRow() + step, 0, static_cast<int>(entries_.size()) - 1);
    table_->selectRow(row);
}

void ProgramList::select(const QString& name) {
    for (int row = 0; row < entries_.size(); ++row) {
        if (entries_[row].name == name) {
            table_->selectRow(row);
            return;
        }
    }
}

QString ProgramList::selectedName() const {
    int row = table_->currentRow();
    return row >= 0 && row < entries_.size() ? entries_[row].name : QString();
}

QString ProgramList::selectedPath() const {
    QString name = selectedName();
    return name.isEmpty() ? QString() : QDir(folder_).filePath(name);
}

QStringList ProgramList::names() const {
    QStringList out;
    for (const ProgramFiles::Entry& e : entries_) {
        out << e.name;
    }
    return out;
}

} // namespace m350::ui
