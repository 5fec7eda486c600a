#include "ui/pages/LogPage.h"
#include "ui/widgets/PanelTable.h"
#include "ui/widgets/WrappedLabel.h"

#include "ui/pages/PanelContext.h"

#include <QHeaderView>
#include <QJsonArray>
#include <QTableWidget>
#include <QVBoxLayout>

namespace m350::ui {

LogPage::LogPage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    setObjectName("logPage");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(4, 4, 4, 4);
    table_ = makePanelTable(this, 2, "systemLog");
    // the time column is fitted by fill (as ResizeToContents fits it), from the rows it adds: Qt
    // measured all 500 rows again after every entry
    table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Fixed);
    table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
    column->addWidget(table_);
    problem_ = new WrappedLabel(this);
    problem_->setObjectName("logProblem");
    problem_->hide();
    column->addWidget(problem_);
    retranslate();
}

QString LogPage::title() const { return tr("System Log", "msg 304"); }

void LogPage::retranslate() {
    table_->setHorizontalHeaderLabels({tr("Time", "msg 100"), tr("Event", "msg 101")});
    shown_ = nullptr;
    if (auto s = context().snapshot()) {
        render(*s);
    }
}

// Built on each call: the words follow the language in force.
QHash<QString, QString> LogPage::eventTable() {
    QHash<QString, QString> w;
    w["start_work"] = tr("Start working", "msg 112");
    w["resume"] = tr("Resume", "msg 113");
    w["pause"] = tr("Pause", "msg 114");
    w["mdi"] = tr("MDI", "msg 129");
    w["hook"] = tr("Hook file run");
    w["probe"] = tr("Probe", "msg 108");
    w["home_all"] = tr("Home All Axes", "msg 107");
    w["home_axis"] = tr("Axis mach zero", "msg 119");
    w["zero_all"] = tr("All axis clear", "msg 120");
    w["coord_set"] = tr("Axis Coord set", "msg 118");
    w["go_work_zero"] = tr("All axes go to zero", "msg 115");
    w["middle"] = tr("Axes Middle", "msg 109");
    w["simulate"] = tr("Start Simulating", "msg 111");
    w["simulation_over"] = tr("SL over", "msg 125");
    w["select_file"] = tr("Select file", "msg 110");
    w["start_line"] = tr("Line start", "msg 126");
    w["break_run"] = tr("Break run", "msg 128");
    w["reset"] = tr("RESET", "msg 22");
    w["estop"] = tr("ESP", "msg 749");
    w["alarm"] = tr("ERROR", "msg 23");
    w["param"] = tr("Parameter changed");
    w["param_guest"] = tr("Parameter changed (Guest)");
    w["param_operator"] = tr("Parameter changed (Operator)");
    w["param_admin"] = tr("Parameter changed (Admin)");
    w["param_super"] = tr("Parameter changed (Super)");
    w["passwords_locked"] = tr("passwords.toml cannot be trusted: only Guest opens until it is repaired");
    w["passwords_reset"] = tr("Passwords reset to their defaults (m350-sim reset-passwords)");
    w["variable"] = tr("Variable changed");
    w["output"] = tr("Output switched");
    w["fault"] = tr("Simulator: input fault");
    w["level"] = tr("User level changed");
    w["work_record_cleared"] = tr("Clear Record", "msg 548");
    w["tool_table"] = tr("Tool table changed");
    w["touch_off"] = tr("Tool touched off");
    w["tool_number"] = tr("Set target tool No.:", "msg 883");
    w["tool_life_reset"] = tr("Tool life reset");
    w["dprnt"] = tr("DPRNT output");
    w["dprnt_limit"] = tr("DPRNT output reached its limit; dprnt.txt keeps the first and the last records");
    w["dprnt_missed"] = tr("DPRNT records not logged (sent faster than the log takes them)");
    return w;
}

QString LogPage::eventWords(const std::string& event) {
    QString key = QString::fromStdString(event);
    return eventTable().value(key, key);
}

QVector<Page::Softkey> LogPage::softkeys() const { return {{}, {}, {}, {}, {}, {}}; }

void LogPage::softkey(int) {}

bool LogPage::key(const QString& name) {
    if (name == QLatin1String("ENTER")) {
        // a long entry (an alarm with its place, a parameter change) ends cut off in its cell:
        // Enter shows the selected one whole in the question box
        const int row = table_->currentRow();
        if (row >= 0 && table_->item(row, 1)) {
            context().ask(table_->item(row, 0)->text() + QStringLiteral("\n") + eventText(row), [](bool) {});
        }
        return true;
    }
    if (name != QLatin1String("UP") && name != QLatin1String("DOWN")) {
        return false;
    }
    int row = table_->currentRow() + (name == QLatin1String("UP") ? -1 : 1);
    if (table_->rowCount() > 0) {
        table_->selectRow(std::clamp(row, 0, table_->rowCount() - 1));
    }
    return true;
}

void LogPage::render(const PanelSnapshot& snapshot) {
    if (snapshot.log && (snapshot.log.get() != shown_ || snapshot.log->added() != shownAdded_)) {
        fill(snapshot);
    }
    const QString problem = snapshot.logProblem.isEmpty() ? QString() : tr("The System Log is not saved: %1").arg(snapshot.logProblem);
    if (problem_->text() != problem) {
        problem_->setText(problem);
        problem_->setVisible(!problem.isEmpty());
    }
}

void LogPage::fill(const PanelSnapshot& snapshot) {
    const LogTail& entries = *snapshot.log; // the newest (SessionLog::kOffered): the file keeps more
    const QHash<QString, QString> words = eventTable();
    const int count = static_cast<int>(entries.size());
    // The entries since the list shown go on top and the oldest beyond the list leave at the
    // bottom; the rows between keep their items. The cursor keeps its row, as a refill kept it.
    const std::uint64_t newer = entries.added() - shownAdded_;
    const bool onTop = shown_ != nullptr && entries.added() >= shownAdded_ && newer < entries.size() &&
                       table_->rowCount() == shownRows_;
    shown_ = snapshot.log.get();
    shownAdded_ = entries.added();
    shownRows_ = count;
    const TableFill filling(table_); // the fitted columns measured once, when it goes
    const int current = table_->currentRow();
    int fresh = count;
    if (onTop) {
        fresh = static_cast<int>(newer);
        for (int row = 0; row < fresh; ++row) {
            table_->insertRow(0);
        }
    }
    table_->setRowCount(count);
    for (int row = 0; row < fresh; ++row) {
        const files::LogEntry& e = entries[entries.size() - 1 - static_cast<std::size_t>(row)];
        QString key = QString::fromStdString(e.event);
        QString text = words.value(key, key);
        if (!e.detail.empty()) {
            text += QStringLiteral(": ") + QString::fromStdString(e.detail);
        }
        auto* event = new QTableWidgetItem(text);
        if (e.event == "alarm" || e.event == "estop") {
            event->setForeground(QColor(255, 120, 120));
        }
        table_->setItem(row, 0, new QTableWidgetItem(QString::fromStdString(e.time)));
        table_->setItem(row, 1, event);
    }
    fitTimeColumn(onTop ? table_->columnWidth(0) : 0, fresh);
    if (onTop && current >= 0 && current < count && table_->currentRow() != current) {
        table_->selectRow(current);
    }
}

// As wide as ResizeToContents makes it: its header and its widest time, one pixel more for the
// grid, within the header's bounds. `width`: what the rows kept need; the first `fresh` rows are new.
void LogPage::fitTimeColumn(int width, int fresh) {
    for (int row = 0; row < fresh; ++row) {
        width = std::max(width, table_->sizeHintForIndex(table_->model()->index(row, 0)).width() + (table_->showGrid() ? 1 : 0));
    }
    const QHeaderView* header = table_->horizontalHeader();
    width = std::clamp(std::max(width, header->sectionSizeHint(0)), header->minimumSectionSize(), header->maximumSectionSize());
    if (table_->columnWidth(0) != width) {
        table_->setColumnWidth(0, width);
    }
}

int LogPage::rows() const { return table_->rowCount(); }
QString LogPage::eventText(int row) const { return table_->item(row, 1) ? table_->item(row, 1)->text() : QString(); }

QJsonObject LogPage::state() const {
    QJsonArray newest;
    for (int row = 0; row < std::min(rows(), 20); ++row) {
        newest.append(eventText(row));
    }
    return {{"log_newest", newest}, {"log_problem", problem_->text()}};
}

} // namespace m350::ui
