#include "ui/training/TrainingStartPage.h"

#include "ui/widgets/PanelTable.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace m350::ui {

TrainingStartPage::TrainingStartPage(QWidget* parent) : QWidget(parent) {
    setObjectName("trainingStart");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(6, 6, 6, 6);
    heading_ = addPanelLabel(column, this, "trainingHeading", false);
    table_ = addPanelTable(column, this, 4, "trainingExercises");
    text_ = addPanelLabel(column, this, "trainingText", true);
    text_->setMinimumHeight(90);
    text_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
}

void TrainingStartPage::show(const std::vector<training::Exercise>& exercises, const TrainingProgress& progress,
                             const QString& trainee, MessageLanguage language) {
    heading_->setText(tr("Training: %1").arg(trainee));
    table_->setHorizontalHeaderLabels({tr("Exercise"), tr("Level"), tr("Status"), tr("Best time")});
    const int keep = selected();
    TableFill fill(table_);
    table_->setRowCount(static_cast<int>(exercises.size()));
    for (std::size_t i = 0; i < exercises.size(); ++i) {
        const training::Exercise& e = exercises[i];
        const QString name = QString::fromStdString(e.name);
        const TrainingProgress::Entry* done = progress.find(trainee, name);
        const QString status = !done ? tr("not tried") : done->passed ? tr("passed") : tr("failed (%1 tries)").arg(done->tries);
        const QString best = done && done->bestTime
                                 ? QStringLiteral("%1:%2").arg(static_cast<int>(*done->bestTime) / 60).arg(static_cast<int>(*done->bestTime) % 60, 2, 10, QLatin1Char('0'))
                                 : QStringLiteral("-");
        const QStringList cells{QString::fromStdString(e.title.in(language)), QString::number(e.level), status, best};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            table_->setItem(static_cast<int>(i), c, item);
        }
    }
    select(keep < 0 ? 0 : keep);
}

int TrainingStartPage::selected() const { return table_->currentRow(); }

void TrainingStartPage::select(int row) {
    if (table_->rowCount() > 0) {
        table_->setCurrentCell(std::clamp(row, 0, table_->rowCount() - 1), 0);
    }
}

void TrainingStartPage::move(int by) { select(selected() + by); }

void TrainingStartPage::showText(const QString& text) { text_->setText(text); }

QString TrainingStartPage::text() const { return text_->text(); }

} // namespace m350::ui
