#include "ui/pages/ToolTablePage.h"

#include "core/tools/ToolTableFile.h"
#include "core/tools/ToolTableText.h"
#include "ui/pages/PageId.h"
#include "ui/pages/PanelContext.h"
#include "ui/widgets/PanelTable.h"

#include <QJsonArray>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace m350::ui {

namespace {

QString optionalNumber(const std::optional<double>& v) {
    return v ? QString::fromStdString(tools::tableNumber(*v)) : QString();
}

} // namespace

ToolTablePage::ToolTablePage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    setObjectName("toolTablePage");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(4, 4, 4, 4);
    header_ = addPanelLabel(column, this, "toolTableHeader", false);
    table_ = addPanelTable(column, this, kColumns, "toolTable");
    table_->setSelectionBehavior(QAbstractItemView::SelectItems); // the field Enter edits
    info_ = addPanelLabel(column, this, "toolTableInfo", true);
    help_ = addPanelLabel(column, this, "pageHelp", true);
    retranslate();
}

QString ToolTablePage::title() const { return tr("Tool Table"); }

QString ToolTablePage::typeName(tools::ToolType type) {
    switch (type) {
    case tools::ToolType::Flat: return tr("Flat end mill");
    case tools::ToolType::Ball: return tr("Ball nose");
    case tools::ToolType::Bull: return tr("Bull nose");
    case tools::ToolType::Drill: return tr("Drill");
    case tools::ToolType::Tap: return tr("Tap");
    case tools::ToolType::Chamfer: return tr("Chamfer");
    case tools::ToolType::Engrave: return tr("Engraver");
    case tools::ToolType::Face: return tr("Face mill");
    case tools::ToolType::Reamer: return tr("Reamer");
    case tools::ToolType::Probe: return tr("Touch probe");
    case tools::ToolType::Other: return tr("Other");
    }
    return {};
}

QString ToolTablePage::columnTitle(Column column) const {
    switch (column) {
    case Column::Tool: return tr("Tool");
    case Column::Pocket: return tr("Pocket");
    case Column::Z: return tr("Z offset");
    case Column::Diameter: return tr("Diameter");
    case Column::Rpm: return tr("Max rpm");
    case Column::Teeth: return tr("Teeth");
    case Column::Type: return tr("Type");
    case Column::Comment: return tr("Comment");
    }
    return {};
}

void ToolTablePage::retranslate() {
    QStringList titles;
    for (int c = 0; c < kColumns; ++c) {
        titles << columnTitle(static_cast<Column>(c));
    }
    table_->setHorizontalHeaderLabels(titles);
    help_->setText(tr("UP/DOWN: tool, LEFT/RIGHT: field, ENTER: edit. Touch Off: with the tool loaded and its tip "
                      "on a known height, enter that work Z; the tool's Z offset changes so the display reads it.") +
                   QLatin1Char('\n') +
                   tr("The table is the machine folder's tool.tbl in LinuxCNC's format; rpm, teeth and type are kept "
                      "in the comment as {rpm=... teeth=... type=...}."));
    shown_.reset();
    if (auto s = context().snapshot()) {
        render(*s);
    }
}

QVector<Page::Softkey> ToolTablePage::softkeys() const {
    const bool any = !rows_.empty();
    return {{tr("Modify"), any, any ? QString() : tr("The table is empty")},
            {tr("New", "msg 328"), true, {}},
            {tr("Del", "msg 325"), any, any ? QString() : tr("The table is empty")},
            {tr("Touch Off"), true, {}},
            {tr("Import"), true, {}},
            {tr("Export"), true, {}},
            {tr("Tool Life"), true, {}}, // Shift+F1: the tool life groups (ToolLifePage)
            {tr("Breakage Monitor"), true, {}}, // Shift+F2: the spindle load monitor (BreakageMonitorPage)
            {},
            {},
            {},
            {}};
}

void ToolTablePage::softkey(int number) {
    switch (number) {
    case 1: edit(); break;
    case 2: addTool(); break;
    case 3: removeSelected(); break;
    case 4: touchOff(); break;
    case 5: importTable(); break;
    case 6: exportTable(); break;
    case 7: emit navigate(PageId::toolLife); break;
    case 8: emit navigate(PageId::breakage); break;
    default: break;
    }
}

bool ToolTablePage::key(const QString& name) {
    const int row = table_->currentRow();
    const int column = static_cast<int>(column_);
    if (name == QLatin1String("UP") || name == QLatin1String("DOWN")) {
        select(row + (name == QLatin1String("UP") ? -1 : 1), column_);
    } else if (name == QLatin1String("LEFT") || name == QLatin1String("RIGHT")) {
        const int next = std::clamp(column + (name == QLatin1String("LEFT") ? -1 : 1), 0, kColumns - 1);
        select(row, static_cast<Column>(next));
    } else if (name == QLatin1String("ENTER")) {
        edit();
    } else if (name == QLatin1String("ESC")) {
        emit navigate(PageId::probe);
    } else {
        return false;
    }
    return true;
}

void ToolTablePage::render(const PanelSnapshot& snapshot) {
    problem_ = snapshot.toolTableProblem;
    if (snapshot.toolTable && snapshot.toolTable != shown_) {
        shown_ = snapshot.toolTable;
        fill();
    }
    header_->setText(tr("Cur Tool:", "msg 992") + QStringLiteral(" T%1    tool.tbl: ").arg(snapshot.status.tool) +
                     tr("%1 tools").arg(rows_.size()));
    info_->setText(infoText());
}

void ToolTablePage::fill() {
    rows_ = shown_->entries();
    { // the fitted columns measured once, at the end of this block
        const TableFill filling(table_);
        table_->setRowCount(static_cast<int>(rows_.size()));
        for (int row = 0; row < static_cast<int>(rows_.size()); ++row) {
            for (int c = 0; c < kColumns; ++c) {
                auto* item = new QTableWidgetItem(cellText(row, static_cast<Column>(c)));
                if (c != static_cast<int>(Column::Comment) && c != static_cast<int>(Column::Type)) {
                    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                }
                table_->setItem(row, c, item);
            }
        }
    }
    auto kept = std::find_if(rows_.begin(), rows_.end(), [this](const tools::ToolEntry& e) { return e.tool == currentTool_; });
    select(kept != rows_.end() ? static_cast<int>(kept - rows_.begin()) : 0, column_);
    emit softkeysChanged();
}

QString ToolTablePage::cellText(int row, Column column) const {
    if (row < 0 || row >= static_cast<int>(rows_.size())) {
        return {};
    }
    const tools::ToolEntry& e = rows_[static_cast<std::size_t>(row)];
    switch (column) {
    case Column::Tool: return QString::number(e.tool);
    case Column::Pocket: return QString::number(e.pocket);
    case Column::Z: return e.offsets[tools::kZ] ? QString::number(*e.offsets[tools::kZ], 'f', 3) : QString();
    case Column::Diameter: return optionalNumber(e.diameter);
    case Column::Rpm: return optionalNumber(e.maxRpm);
    case Column::Teeth: return e.teeth ? QString::number(*e.teeth) : QString();
    case Column::Type: return e.type ? typeName(*e.type) : QString();
    case Column::Comment: return QString::fromStdString(e.comment);
    }
    return {};
}

void ToolTablePage::select(int row, Column column) {
    column_ = column;
    if (rows_.empty()) {
        currentTool_ = 0;
        return;
    }
    row = std::clamp(row, 0, static_cast<int>(rows_.size()) - 1);
    currentTool_ = rows_[static_cast<std::size_t>(row)].tool;
    table_->setCurrentCell(row, static_cast<int>(column));
    info_->setText(infoText());
}

int ToolTablePage::rowCount() const { return static_cast<int>(rows_.size()); }

int ToolTablePage::selectedTool() const { return rows_.empty() ? 0 : currentTool_; }

std::optional<tools::ToolEntry> ToolTablePage::selectedEntry() const {
    for (const tools::ToolEntry& e : rows_) {
        if (e.tool == currentTool_) {
            return e;
        }
    }
    return std::nullopt;
}

QString ToolTablePage::infoText() const {
    QString text;
    if (auto entry = selectedEntry()) {
        text = QStringLiteral("tool.tbl: ") + QString::fromStdString(tools::formatToolEntry(*entry));
    }
    if (!problem_.isEmpty()) {
        text += (text.isEmpty() ? QString() : QStringLiteral("\n")) + tr("tool.tbl not saved: %1").arg(problem_);
    }
    return text;
}

QJsonObject ToolTablePage::state() const {
    QJsonArray rows;
    for (const tools::ToolEntry& e : rows_) {
        rows.append(QString::fromStdString(tools::formatToolEntry(e)));
    }
    return {{"tool_table", rows}, {"tool_table_selected", selectedTool()}, {"tool_table_field", columnTitle(column_)}};
}

} // namespace m350::ui
