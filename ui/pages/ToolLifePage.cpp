#include "ui/pages/ToolLifePage.h"

#include "ui/pages/PanelContext.h"
#include "ui/widgets/PanelTable.h"

#include <QBrush>
#include <QFont>
#include <QJsonArray>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace m350::ui {

namespace {

QString amount(tools::LifeKind kind, int units) { return QString::fromStdString(tools::lifeAmountText(kind, units)); }

} // namespace

ToolLifePage::ToolLifePage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    setObjectName("toolLifePage");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(4, 4, 4, 4);
    header_ = addPanelLabel(column, this, "toolLifeHeader", false);
    note_ = addPanelLabel(column, this, "toolLifeNote", true);
    table_ = addPanelTable(column, this, kColumns, "toolLifeTable");
    info_ = addPanelLabel(column, this, "toolLifeInfo", true);
    help_ = addPanelLabel(column, this, "pageHelp", true);
    retranslate();
}

QString ToolLifePage::title() const { return tr("Tool Life"); }

QString ToolLifePage::columnTitle(Column column) const {
    switch (column) {
    case Column::Group: return tr("Group");
    case Column::Kind: return tr("Life type");
    case Column::Life: return tr("Life");
    case Column::Tool: return tr("Tool");
    case Column::H: return QStringLiteral("H");
    case Column::D: return QStringLiteral("D");
    case Column::Used: return tr("Used");
    case Column::Remaining: return tr("Remaining");
    case Column::State: return tr("State");
    }
    return {};
}

void ToolLifePage::retranslate() {
    QStringList titles;
    for (int c = 0; c < kColumns; ++c) {
        titles << columnTitle(static_cast<Column>(c));
    }
    table_->setHorizontalHeaderLabels(titles);
    help_->setText(tr("UP/DOWN: tool (and its group). Reset Life: the group's tools start again from 0 used. "
                      "Minutes count cutting feed only (no rapids, dwells, holds or tool changes), in whole 4 s "
                      "units, shown as min:s. @ in use, # life reached."));
    if (shown_) {
        fill(); // the words of the cells (life type, state) in the new language
    }
    if (auto s = context().snapshot()) {
        render(*s);
    }
}

QVector<Page::Softkey> ToolLifePage::softkeys() const {
    const bool any = !rows_.empty();
    return {{tr("Reset Life"), any, any ? QString() : tr("No tool life groups")},
            {},
            {},
            {},
            {},
            {tr("Tool Table"), true, {}}};
}

void ToolLifePage::softkey(int number) {
    if (number == 1) {
        resetSelectedGroup();
    } else if (number == 6) {
        emit navigate(PageId::tools);
    }
}

bool ToolLifePage::key(const QString& name) {
    if (name == QLatin1String("UP") || name == QLatin1String("DOWN")) {
        select(currentRow_ + (name == QLatin1String("UP") ? -1 : 1));
    } else if (name == QLatin1String("ESC")) {
        emit navigate(PageId::tools);
    } else {
        return false;
    }
    return true;
}

void ToolLifePage::render(const PanelSnapshot& snapshot) {
    problem_ = snapshot.toolLifeProblem;
    tWordChangesTool_ = snapshot.tWordChangesTool;
    if (snapshot.toolLife && snapshot.toolLife != shown_) {
        shown_ = snapshot.toolLife;
        fill();
    }
    header_->setText(headerText());
    const int first = shown_ ? shown_->ignoreNumber + 1 : 101;
    note_->setText(tWordChangesTool_
                       ? tr("Simulator extra: the M350 itself has no tool life management. Here T%1+n selects group "
                            "n (T%2 = group 1) and the T word changes the tool, as M06 does on FANUC.")
                             .arg(first - 1)
                             .arg(first)
                       : tr("FANUC 0i: T%1 selects group 1 (the ignore number plus the group); M06 ends the counting "
                            "of the old tool and starts it for the selected one.")
                             .arg(first));
    info_->setText(infoText());
}

void ToolLifePage::fill() {
    rows_.clear();
    for (const tools::LifeGroupView& group : shown_->groups) {
        for (const tools::LifeToolView& tool : group.tools) {
            rows_.push_back({&group, &tool, &tool == &group.tools.front()});
        }
    }
    { // the fitted columns measured once, at the end of this block
        const TableFill filling(table_);
        table_->setRowCount(static_cast<int>(rows_.size()));
        QFont bold = table_->font();
        bold.setBold(true);
        for (int row = 0; row < static_cast<int>(rows_.size()); ++row) {
            const bool inUse = rowHighlighted(row);
            for (int c = 0; c < kColumns; ++c) {
                auto* item = new QTableWidgetItem(cellText(row, static_cast<Column>(c)));
                if (c != static_cast<int>(Column::State) && c != static_cast<int>(Column::Kind)) {
                    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                }
                if (inUse) {
                    item->setBackground(QBrush(QColor(30, 110, 60)));
                    item->setForeground(QBrush(Qt::white));
                    item->setFont(bold);
                } else if (rows_[static_cast<std::size_t>(row)].tool->expired && c >= static_cast<int>(Column::Tool)) {
                    item->setForeground(QBrush(QColor(255, 120, 120)));
                }
                table_->setItem(row, c, item);
            }
        }
    }
    select(currentRow_);
    emit softkeysChanged();
}

QString ToolLifePage::stateText(const tools::LifeToolView& tool) const {
    // FANUC's marks stay as they are in every language
    if (tool.inUse) {
        return tool.expired ? QStringLiteral("@# ") + tr("In use, life reached") : QStringLiteral("@ ") + tr("In use");
    }
    if (tool.expired) {
        return QStringLiteral("# ") + tr("Life reached");
    }
    return tool.selected ? tr("Selected, waits for the tool change") : tr("Waiting");
}

QString ToolLifePage::cellText(int row, Column column) const {
    if (row < 0 || row >= static_cast<int>(rows_.size())) {
        return {};
    }
    const Row& r = rows_[static_cast<std::size_t>(row)];
    const tools::LifeGroupView& g = *r.group;
    const tools::LifeToolView& t = *r.tool;
    switch (column) {
    case Column::Group: return r.firstOfGroup ? QString::number(g.number) : QString();
    case Column::Kind:
        return r.firstOfGroup ? (g.kind == tools::LifeKind::Count ? tr("Count") : tr("Minutes")) : QString();
    case Column::Life: return r.firstOfGroup ? amount(g.kind, g.lifeUnits) : QString();
    case Column::Tool: return QStringLiteral("T%1").arg(t.tool);
    case Column::H: return QString::number(t.h);
    case Column::D: return QString::number(t.d);
    case Column::Used: return amount(g.kind, t.used);
    case Column::Remaining: return amount(g.kind, t.remaining);
    case Column::State: return stateText(t);
    }
    return {};
}

bool ToolLifePage::rowHighlighted(int row) const {
    return row >= 0 && row < static_cast<int>(rows_.size()) && rows_[static_cast<std::size_t>(row)].tool->inUse;
}

void ToolLifePage::select(int row) {
    if (rows_.empty()) {
        currentRow_ = 0;
        return;
    }
    currentRow_ = std::clamp(row, 0, static_cast<int>(rows_.size()) - 1);
    table_->setCurrentCell(currentRow_, 0);
}

int ToolLifePage::rowCount() const { return static_cast<int>(rows_.size()); }

int ToolLifePage::selectedGroup() const {
    return rows_.empty() ? 0 : rows_[static_cast<std::size_t>(currentRow_)].group->number;
}

QString ToolLifePage::headerText() const {
    if (!shown_) {
        return {};
    }
    const tools::LifeView& v = *shown_;
    QString inUse = v.inUse ? tr("In use: group %1 T%2").arg(v.inUse->group).arg(v.inUse->tool) : tr("In use: none");
    return tr("Ignore No. %1").arg(v.ignoreNumber) + QStringLiteral("    ") +
           tr("Capacity: %1 groups x %2 tools").arg(v.capacity.groups).arg(v.capacity.toolsPerGroup) +
           QStringLiteral("    ") + inUse;
}

QString ToolLifePage::infoText() const {
    QStringList lines;
    if (shown_ && shown_->groups.empty()) {
        lines << tr("No tool life groups. Enter them in a program or MDI: G10 L3, then P<group> L<life> Q<1 count | "
                    "2 minutes> and T<tool> H<h> D<d> blocks, then G11. They are kept in toollife.txt.");
    }
    QStringList spent;
    for (const tools::LifeGroupView& g : shown_ ? shown_->groups : std::vector<tools::LifeGroupView>{}) {
        if (g.allExpired) {
            spent << QString::number(g.number);
        }
    }
    if (!spent.isEmpty()) {
        lines << tr("Every tool has reached its life in group %1: selecting it is an alarm.").arg(spent.join(", "));
    }
    if (shown_ && shown_->unreadLines > 0) {
        lines << tr("toollife.txt: %1 line(s) could not be read; they are kept in the file as comments.")
                     .arg(shown_->unreadLines);
    }
    if (!problem_.isEmpty()) {
        lines << tr("toollife.txt not saved: %1").arg(problem_);
    }
    return lines.join(QLatin1Char('\n'));
}

void ToolLifePage::resetSelectedGroup() {
    const int group = selectedGroup();
    if (group == 0) {
        return;
    }
    context().ask(tr("Reset the tool life of group %1: every tool's used life back to 0?").arg(group),
                  [this, group](bool yes) {
                      if (yes) {
                          context().session().resetToolLife(group);
                      }
                  });
}

QJsonObject ToolLifePage::state() const {
    QJsonArray rows;
    for (int row = 0; row < rowCount(); ++row) {
        QStringList cells;
        for (int c = 0; c < kColumns; ++c) {
            cells << cellText(row, static_cast<Column>(c));
        }
        rows.append(cells.join(QLatin1Char('|')));
    }
    return {{"tool_life", rows}, {"tool_life_group", selectedGroup()}};
}

} // namespace m350::ui
