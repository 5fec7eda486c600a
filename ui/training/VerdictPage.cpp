#include "ui/training/VerdictPage.h"

#include "ui/widgets/PanelTable.h"

#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace m350::ui {

VerdictPage::VerdictPage(QWidget* parent) : QWidget(parent) {
    setObjectName("trainingVerdict");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(6, 6, 6, 6);
    summary_ = addPanelLabel(column, this, "verdictSummary", true);
    table_ = addPanelTable(column, this, 4, "verdictChecks");
    reason_ = addPanelLabel(column, this, "verdictReason", true);
    reason_->setMinimumHeight(60);
    reason_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
}

void VerdictPage::show(const training::Verdict& verdict, const QString& title, MessageLanguage language) {
    checks_ = verdict.checks;
    language_ = language;
    const QString time = QStringLiteral("%1:%2").arg(static_cast<int>(verdict.timeUsed) / 60).arg(static_cast<int>(verdict.timeUsed) % 60, 2, 10, QLatin1Char('0'));
    summary_->setText((verdict.passed ? tr("PASSED: %1") : tr("FAILED: %1")).arg(title) + QStringLiteral("   ") +
                      tr("score %1/100, time %2, hints %3").arg(verdict.score).arg(time).arg(verdict.hintsUsed) +
                      (verdict.timedOut ? QStringLiteral("   ") + tr("time out") : QString()));
    summary_->setProperty("level", verdict.passed ? "ok" : "alarm");
    table_->setHorizontalHeaderLabels({tr("Check"), tr("Result"), tr("Measured"), tr("Expected")});
    TableFill fill(table_);
    table_->setRowCount(static_cast<int>(checks_.size()));
    for (std::size_t i = 0; i < checks_.size(); ++i) {
        const training::CheckResult& c = checks_[i];
        const QStringList cells{QString::fromStdString(c.id), c.passed ? tr("passed") : tr("failed"),
                                QString::fromStdString(c.measured), QString::fromStdString(c.expected)};
        for (int col = 0; col < cells.size(); ++col) {
            table_->setItem(static_cast<int>(i), col, new QTableWidgetItem(cells[col]));
        }
    }
    const auto failed = std::find_if(checks_.begin(), checks_.end(), [](const auto& c) { return !c.passed; });
    table_->setCurrentCell(failed == checks_.end() ? 0 : static_cast<int>(failed - checks_.begin()), 0);
    showReason();
}

int VerdictPage::selected() const { return table_->currentRow(); }

void VerdictPage::move(int by) {
    if (table_->rowCount() > 0) {
        table_->setCurrentCell(std::clamp(selected() + by, 0, table_->rowCount() - 1), 0);
        showReason();
    }
}

training::CheckTarget VerdictPage::target() const {
    const int row = selected();
    if (row < 0 || row >= static_cast<int>(checks_.size()) || checks_[static_cast<std::size_t>(row)].passed) {
        return {};
    }
    return checks_[static_cast<std::size_t>(row)].target;
}

QString VerdictPage::summary() const { return summary_->text(); }

void VerdictPage::showReason() {
    const int row = selected();
    if (row < 0 || row >= static_cast<int>(checks_.size())) {
        reason_->clear();
        return;
    }
    const training::CheckResult& c = checks_[static_cast<std::size_t>(row)];
    QString where;
    switch (c.target.kind) {
    case training::CheckTarget::Kind::Parameter: where = tr("parameter %1").arg(c.target.number); break;
    case training::CheckTarget::Kind::Output: where = tr("output OUT%1").arg(c.target.number, 2, 10, QLatin1Char('0')); break;
    case training::CheckTarget::Kind::Tool: where = tr("tool T%1").arg(c.target.number); break;
    case training::CheckTarget::Kind::Line: where = QStringLiteral("%1:%2").arg(QString::fromStdString(c.target.file)).arg(c.target.line); break;
    case training::CheckTarget::Kind::None: break;
    }
    reason_->setText(c.passed ? tr("This check passed.")
                              : QString::fromStdString(c.reason.in(language_)) +
                                    (where.isEmpty() ? QString() : QStringLiteral("\n") + tr("F5 opens %1 in the panel.").arg(where)));
}

} // namespace m350::ui
