#include "ui/pages/RecordPage.h"

#include "ui/i18n/Language.h"
#include "ui/pages/PageId.h"
#include "ui/pages/PanelContext.h"
#include "ui/widgets/MeasuredLabel.h"

#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QVBoxLayout>

namespace m350::ui {

namespace {

QString duration(double seconds) {
    auto total = static_cast<long long>(std::max(0.0, seconds));
    return QStringLiteral("%1:%2:%3")
        .arg(total / 3600, 2, 10, QLatin1Char('0'))
        .arg(total / 60 % 60, 2, 10, QLatin1Char('0'))
        .arg(total % 60, 2, 10, QLatin1Char('0'));
}

} // namespace

RecordPage::RecordPage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    setObjectName("recordPage");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(8, 8, 8, 8);
    record_ = new MeasuredLabel(this);
    record_->setObjectName("workRecord");
    record_->setStyleSheet(QStringLiteral("font-size: 13pt;"));
    column->addWidget(record_);
    column->addStretch(1);
    retranslate();
}

QString RecordPage::title() const { return tr("Work Record", "msg 322"); }

void RecordPage::retranslate() {
    if (auto s = context().snapshot()) {
        render(*s);
    }
}

QVector<Page::Softkey> RecordPage::softkeys() const {
    return {{tr("Clear Record", "msg 548"), true, {}}, {tr("To U Disk", "msg 549"), true, {}}, {}, {}, {}, {}};
}

void RecordPage::softkey(int number) {
    if (number == 1) {
        context().ask(tr("Confirm to delete the working record?", "msg 875"), [this](bool yes) {
            if (yes) {
                context().session().clearWorkRecord();
            }
        });
    } else if (number == 2) {
        exportRecord();
    }
}

void RecordPage::exportRecord() {
    const config::MachineFolder folder = context().folderFiles();
    const QString path = QString::fromStdString(folder.pathOf(config::FolderFile::WorkRecord).string());
    const QByteArray text = recordText().toUtf8() + '\n';
    const std::string_view bytes(text.constData(), static_cast<std::size_t>(text.size()));
    if (auto error = folder.write(config::FolderFile::WorkRecord, bytes)) {
        context().notify(tr("%1: cannot write: %2").arg(path, QString::fromStdString(error->in(Language::messageLanguage()))));
        return;
    }
    context().notify(tr("Working record saved to %1").arg(path));
}

bool RecordPage::key(const QString& name) {
    if (name == QLatin1String("ESC")) {
        emit navigate(PageId::monitor);
        return true;
    }
    return false;
}

void RecordPage::render(const PanelSnapshot& snapshot) {
    const WorkRecord& r = snapshot.workRecord;
    QStringList lines{
        tr("Current file:", "msg 876") + QLatin1Char(' ') + (r.file.isEmpty() ? QStringLiteral("-") : QFileInfo(r.file).fileName()),
        tr("Total No.", "msg 47") + QStringLiteral(": ") + QString::number(snapshot.status.totalCount),
        tr("Finished No.:", "msg 878") + QLatin1Char(' ') + QString::number(snapshot.status.pieceCount),
        tr("Time per:", "msg 879") + QLatin1Char(' ') + duration(r.lastPiece),
        tr("Total time:", "msg 880") + QLatin1Char(' ') + duration(r.total),
        tr("Start date:", "msg 881") + QLatin1Char(' ') + (r.startedAt.isEmpty() ? QStringLiteral("-") : r.startedAt)};
    record_->setText(lines.join(QLatin1Char('\n')));
}

QString RecordPage::recordText() const { return record_->text(); }

QJsonObject RecordPage::state() const { return {{"work_record", record_->text()}}; }

} // namespace m350::ui
