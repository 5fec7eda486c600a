#include "ui/pages/ParamPage.h"
#include "ui/pages/ParameterText.h"
#include "ui/widgets/PanelTable.h"

#include "ui/i18n/PanelText.h"
#include "ui/pages/LevelPrompt.h"
#include "ui/pages/PanelContext.h"
#include "ui/session/UserAccess.h"
#include "ui/widgets/MeasuredLabel.h"
#include "ui/widgets/WrappedLabel.h"

#include <QApplication>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonObject>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <variant>

namespace m350::ui {

namespace {

enum Column { Number, Note, Value, Unit, ColumnCount };
constexpr int kUnitMinWidth = 62;
constexpr int kUnitMaxWidth = 110;
constexpr int kFirstVariable = 50;
constexpr int kLastVariable = 499;
constexpr int kShownValue = Qt::UserRole; // the value an item's text was written for


} // namespace

ParamPage::ParamPage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    setObjectName("paramPage");
    const auto& loaded = params::ParameterCatalogue::bundled();
    if (const auto* catalogue = std::get_if<params::ParameterCatalogue>(&loaded)) {
        catalogue_ = *catalogue;
        pages_.emplace(*catalogue_);
    } else {
        catalogueError_ = QString::fromStdString(std::get<std::string>(loaded));
    }
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(4, 4, 4, 4);
    auto* header = new QHBoxLayout;
    tabs_ = new MeasuredLabel(this);
    tabs_->setObjectName("paramTabs");
    tabs_->setTextFormat(Qt::RichText);
    group_ = new MeasuredLabel(this);
    group_->setObjectName("paramGroup");
    group_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    header->addWidget(tabs_);
    header->addWidget(group_, 1);
    column->addLayout(header);
    auto* row = new QHBoxLayout;
    table_ = makePanelTable(this, ColumnCount, "paramTable");
    table_->horizontalHeader()->setSectionResizeMode(Note, QHeaderView::Stretch);
    table_->setColumnWidth(Number, 44);
    table_->setColumnWidth(Value, 100);
    table_->setColumnWidth(Unit, 62);
    // the panel's own (proportional, CJK) face: the names are long and the tables' monospace one cuts them short
    table_->setStyleSheet(QStringLiteral("QTableWidget { font-family: \"%1\"; font-size: 11pt; }")
                              .arg(QApplication::font().family()));
    connect(table_, &QTableWidget::currentCellChanged, this, [this] { fillInfo(); });
    info_ = new WrappedLabel(this);
    info_->setObjectName("paramInfo");
    info_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    info_->setFixedWidth(205);
    info_->setTextFormat(Qt::PlainText);
    row->addWidget(table_, 1);
    row->addWidget(info_);
    column->addLayout(row, 1);
    if (pages_) {
        select(1); // the factory tab's 机床参数, the firmware's first page
    }
    retranslate();
}

QString ParamPage::title() const { return tr("Param", "msg 302"); }

QVector<Page::Softkey> ParamPage::softkeys() const {
    const bool ready = pages_.has_value();
    const QString why = catalogueError_;
    return {{tr("Param List", "msg 384"), ready, why},
            {tr("Search", "msg 385"), ready, why},
            {tr("Param Backup", "msg 386"), ready, why},
            {tr("Param Restore", "msg 387"), ready, why},
            {tr("#50-#499", "msg 388"), true, {}},
            {},
            {tr("Factory(N)", "msg 949"), ready, why},
            {tr("User(O)", "msg 950"), ready, why},
            {tr("User level"), true, {}},
            {},
            {},
            {}};
}

void ParamPage::softkey(int number) {
    switch (number) {
    case 1:
        if (variables_) {
            showVariables(false);
        } else {
            key(QStringLiteral("RIGHT"));
        }
        break;
    case 2: search(); break;
    case 3: backup(); break;
    case 4: restore(); break;
    case 5: showVariables(!variables_); break;
    case 7: showTab(Tab::Factory); break;
    case 8: showTab(Tab::User); break;
    case 9: LevelPrompt::askLevel(context()); break;
    default: break;
    }
}

bool ParamPage::key(const QString& name) {
    if (name == QLatin1String("UP") || name == QLatin1String("DOWN")) {
        int row = table_->currentRow() + (name == QLatin1String("UP") ? -1 : 1);
        if (table_->rowCount() > 0) {
            table_->selectRow(std::clamp(row, 0, table_->rowCount() - 1));
        }
        return true;
    }
    if ((name == QLatin1String("LEFT") || name == QLatin1String("RIGHT")) && pages_ && !variables_) {
        // the groups of the current tab, in a ring
        const auto& categories = pages_->categories();
        const int step = name == QLatin1String("LEFT") ? -1 : 1;
        const int count = static_cast<int>(categories.size());
        int next = static_cast<int>(category_);
        do {
            next = (next + step + count) % count;
        } while (categories[static_cast<std::size_t>(next)].tab != tab());
        showCategory(static_cast<std::size_t>(next));
        return true;
    }
    if (name == QLatin1String("ENTER")) {
        edit();
        return true;
    }
    if (name == QLatin1String("ESC") && variables_) {
        showVariables(false);
        return true;
    }
    return false;
}

bool ParamPage::typed(const QString& text) {
    if (text.compare(QLatin1String("N"), Qt::CaseInsensitive) == 0) {
        showTab(Tab::Factory);
    } else if (text.compare(QLatin1String("O"), Qt::CaseInsensitive) == 0) {
        showTab(Tab::User);
    } else {
        return false;
    }
    return true;
}

ParamPage::Tab ParamPage::tab() const {
    return pages_ ? pages_->categories()[category_].tab : Tab::Factory;
}

void ParamPage::showTab(Tab tab) {
    if (!pages_) {
        return;
    }
    showVariables(false);
    const auto& categories = pages_->categories();
    for (std::size_t c = 0; c < categories.size(); ++c) {
        if (categories[c].tab == tab) {
            showCategory(c);
            return;
        }
    }
}

bool ParamPage::select(int number) {
    auto at = pages_ ? pages_->locate(number) : std::nullopt;
    if (!at) {
        return false;
    }
    showVariables(false);
    if (at->category != category_ || table_->rowCount() == 0) {
        showCategory(at->category);
    }
    table_->selectRow(static_cast<int>(at->row));
    return true;
}

void ParamPage::showCategory(std::size_t category) {
    category_ = category;
    const auto& numbers = pages_->categories()[category].numbers;
    table_->clearContents();
    const bool chinese = PanelText::chinese();
    const SnapshotPtr snapshot = context().snapshot();
    { // the fitted columns measured once, at the end of this block
        const TableFill filling(table_);
        table_->setRowCount(static_cast<int>(numbers.size()));
        for (int row = 0; row < table_->rowCount(); ++row) {
            // each item whole before it goes in, its value too: a change to an item in the table is
            // one more signal to the view (a group's rows were four signals each more than needed)
            const params::ParameterInfo& info = *catalogue_->find(numbers[static_cast<std::size_t>(row)]);
            auto* note = new QTableWidgetItem(ParameterText::localName(info.nameZh, info.nameEn, chinese));
            note->setToolTip(note->text());
            auto* value = new QTableWidgetItem;
            value->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            if (snapshot) {
                const double shown = snapshot->status.parameters.get(info.number);
                value->setData(kShownValue, shown);
                value->setText(ParameterText::value(info, shown));
            }
            auto* unit = new QTableWidgetItem(QString::fromStdString(info.unit));
            unit->setToolTip(unit->text());
            table_->setItem(row, Number, new QTableWidgetItem(QString::number(info.number)));
            table_->setItem(row, Note, note);
            table_->setItem(row, Value, value);
            table_->setItem(row, Unit, unit);
        }
    }
    // the unit column is as wide as this group's longest unit ("pulse/mm", "mm/s^2"), the name
    // column takes the rest and shows a cut name in full as its tooltip
    // (measured at a group's first showing: F7 / F8 go through the groups again and again)
    unitWidths_.resize(pages_->categories().size(), 0);
    if (unitWidths_[category] == 0) {
        table_->resizeColumnToContents(Unit);
        unitWidths_[category] = std::clamp(table_->columnWidth(Unit), kUnitMinWidth, kUnitMaxWidth);
    }
    table_->setColumnWidth(Unit, unitWidths_[category]);
    table_->selectRow(0);
    showCaptions();
    if (snapshot) {
        render(*snapshot);
    }
}

void ParamPage::showVariables(bool on) {
    if (on == variables_) {
        return;
    }
    variables_ = on;
    context().session().watchVariables(on);
    table_->setColumnHidden(Note, on);
    table_->setColumnHidden(Unit, on);
    if (!on) {
        showCategory(category_);
        emit softkeysChanged();
        return;
    }
    table_->clearContents();
    { // the fitted columns measured once, at the end of this block
        const TableFill filling(table_);
        table_->setRowCount(kLastVariable - kFirstVariable + 1);
        for (int row = 0; row < table_->rowCount(); ++row) {
            auto* value = new QTableWidgetItem;
            value->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            table_->setItem(row, Number, new QTableWidgetItem(QStringLiteral("#%1").arg(kFirstVariable + row)));
            table_->setItem(row, Value, value);
        }
    }
    table_->selectRow(0);
    retranslate();
    emit softkeysChanged();
}

int ParamPage::selectedNumber() const {
    int row = table_->currentRow();
    if (row < 0) {
        return -1;
    }
    if (variables_) {
        return kFirstVariable + row;
    }
    return pages_ ? pages_->categories()[category_].numbers[static_cast<std::size_t>(row)] : -1;
}


void ParamPage::retranslate() {
    infoFor_.reset(); // the words again, in the language now in force
    unitWidths_.clear(); // and the units measured again in its font
    table_->setHorizontalHeaderLabels({tr("No.", "msg 83"), tr("Note", "msg 84"), tr("Value", "msg 85"),
                                       tr("Unit", "msg 86")});
    if (!pages_) {
        info_->setText(catalogueError_);
        return;
    }
    showCaptions();
    if (!variables_) {
        const bool chinese = PanelText::chinese();
        const auto& numbers = pages_->categories()[category_].numbers;
        for (int row = 0; row < table_->rowCount(); ++row) {
            const params::ParameterInfo& info = *catalogue_->find(numbers[static_cast<std::size_t>(row)]);
            table_->item(row, Note)->setText(ParameterText::localName(info.nameZh, info.nameEn, chinese));
            table_->item(row, Note)->setToolTip(table_->item(row, Note)->text());
            table_->item(row, Value)->setData(kShownValue, QVariant()); // its words again too
        }
    }
    if (auto s = context().snapshot()) {
        render(*s);
    }
}

// The tab and the group the table shows, above it.
void ParamPage::showCaptions() {
    const QString factory = tr("Factory(N)", "msg 949");
    const QString user = tr("User(O)", "msg 950");
    auto mark = [](const QString& text, bool on) {
        return on ? QStringLiteral("<span style='background:#3e5a8a;'>&nbsp;%1&nbsp;</span>").arg(text)
                  : QStringLiteral("&nbsp;%1&nbsp;").arg(text);
    };
    tabs_->setText(variables_ ? tr("#50-#499", "msg 388")
                              : mark(factory, tab() == Tab::Factory) + QStringLiteral("  ") + mark(user, tab() == Tab::User));
    if (variables_) {
        group_->setText(tr("Macro variables #50-#499, as a program reads them"));
    } else {
        int position = 0, count = 0;
        for (std::size_t c = 0; c < pages_->categories().size(); ++c) {
            if (pages_->categories()[c].tab == tab()) {
                ++count;
                position = c == category_ ? count : position;
            }
        }
        group_->setText(QStringLiteral("◀ %1 (%2/%3) ▶").arg(ParameterText::groupTitle(pages_->categories()[category_].group)).arg(position).arg(count));
    }
}



void ParamPage::render(const PanelSnapshot& snapshot) {
    shown_ = context().snapshot();
    if (variables_) {
        for (int row = 0; row < table_->rowCount() && row < snapshot.userVariables.size(); ++row) {
            double v = snapshot.userVariables[row];
            table_->item(row, Value)->setText(std::isnan(v) ? QStringLiteral("<vacant>") : QString::number(v, 'f', 4));
        }
    } else if (pages_) {
        fillValues(snapshot);
    }
    fillInfo();
}

// A value's text is written again only when the value changed (the item keeps the value it shows):
// the parameters seldom change, and their words cost translations at every snapshot.
void ParamPage::fillValues(const PanelSnapshot& snapshot) {
    const auto& numbers = pages_->categories()[category_].numbers;
    for (int row = 0; row < table_->rowCount(); ++row) {
        const int number = numbers[static_cast<std::size_t>(row)];
        const double value = snapshot.status.parameters.get(number);
        QTableWidgetItem* item = table_->item(row, Value);
        if (const QVariant shown = item->data(kShownValue); shown.isValid() && shown.toDouble() == value) {
            continue;
        }
        item->setData(kShownValue, value);
        item->setText(ParameterText::value(*catalogue_->find(number), value));
    }
}

void ParamPage::fillInfo() {
    int number = selectedNumber();
    const params::UserLevel level = context().session().userLevel();
    const InfoFor infoFor{number, variables_, level, category_};
    if (infoFor_ == infoFor) {
        return;
    }
    infoFor_ = infoFor;
    const QString current = tr("(now: %1)").arg(UserAccess::levelName(level));
    if (variables_ || number < 0 || !pages_) {
        if (variables_) {
            info_->setText(tr("User:", "msg 940") + QStringLiteral(" ") + UserAccess::levelName(params::UserLevel::Operator) +
                           QStringLiteral(" ") + current + QStringLiteral("\n\n") +
                           tr("Enter sets the selected variable, as a macro's #%1 = value would.").arg(number));
        }
        return;
    }
    const params::ParameterInfo& info = *catalogue_->find(number);
    const int group = pages_->categories()[category_].group;
    QStringList lines;
    lines << tr("User:", "msg 940") + QStringLiteral(" ") +
                 UserAccess::levelName(params::ParameterPages::requiredLevel(group)) + QStringLiteral(" ") + current;
    lines << tr("Param List:", "msg 941") + QStringLiteral(" ") + ParameterText::groupTitle(group);
    lines << tr("Details:", "msg 946") + QStringLiteral(" ") + ParameterText::localName(info.nameZh, info.nameEn) + QStringLiteral(" (") +
                 ParameterText::localName(info.nameEn, info.nameZh) + QStringLiteral(")");
    lines << QStringLiteral("  ") + tr("macro #%1, factory value %2").arg(number + 500).arg(info.defaultValue);
    lines << tr("Active:", "msg 947") + QStringLiteral(" ") + tr("Immediately", "msg 913");
    lines << tr("Range:", "msg 948") + QStringLiteral(" ") + ParameterText::range(info);
    info_->setText(lines.join(QLatin1Char('\n')));
}

QString ParamPage::valueText(int row) const {
    auto* item = table_->item(row, Value);
    return item ? item->text() : QString();
}

QString ParamPage::infoText() const { return info_->text(); }

QJsonObject ParamPage::state() const {
    static const char* const levels[] = {"guest", "operator", "admin", "super"};
    QJsonObject out{{"param_view", variables_ ? "variables" : "params"},
                    {"param_selected", selectedNumber()},
                    {"param_value", valueText(table_->currentRow())},
                    {"user_level", levels[static_cast<int>(context().session().userLevel())]}};
    if (pages_ && !variables_) {
        out["param_tab"] = tab() == Tab::Factory ? "factory" : "user";
        out["param_group"] = pages_->categories()[category_].group;
    }
    return out;
}

} // namespace m350::ui
