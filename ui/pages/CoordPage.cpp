#include "ui/pages/CoordPage.h"

#include "ui/i18n/PanelText.h"
#include "ui/pages/CompactDro.h"
#include "ui/pages/PanelContext.h"
#include "ui/widgets/MeasuredLabel.h"
#include "ui/widgets/WrappedLabel.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace m350::ui {

namespace {

constexpr int kWorkSystemParameter = 78; // #578: 0 = G92, 1-6 = G54-G59
constexpr int kCommonSlot = 8;
constexpr int kCommonOffsetVariable = 840; // #840-#844: the common offset X..5th
const int kSlots[] = {0, 1, 2, 3, 4, 5, 6, kCommonSlot}; // the table's rows

} // namespace

CoordPage::CoordPage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    setObjectName("coordPage");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(4, 4, 4, 4);
    table_ = new QTableWidget(static_cast<int>(std::size(kSlots)), 5, this);
    table_->setObjectName("workOffsets");
    table_->setFocusPolicy(Qt::NoFocus);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->verticalHeader()->setDefaultSectionSize(24);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    for (int row = 0; row < table_->rowCount(); ++row) {
        for (int col = 0; col < 5; ++col) {
            auto* item = new QTableWidgetItem;
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            table_->setItem(row, col, item);
        }
    }
    step_ = new MeasuredLabel(this);
    step_->setObjectName("coordStep");
    help_ = new WrappedLabel(this);
    help_->setObjectName("pageHelp");
    column->addWidget(table_, 1);
    column->addWidget(step_);
    column->addWidget(help_);
    retranslate();
}

QString CoordPage::title() const { return tr("Coord Set", "msg 319"); }

void CoordPage::retranslate() {
    QStringList rows;
    for (int slot : kSlots) {
        rows << (slot == kCommonSlot ? tr("Offset", "msg 87")
                 : slot == 0         ? tr("G92", "msg 232")
                                     : QStringLiteral("G%1").arg(53 + slot));
    }
    table_->setVerticalHeaderLabels(rows);
    help_->setText(tr("1:[Knob]Move the cursor,[Enter]modify.", "msg 997") + QLatin1Char('\n') +
                   tr("2:[Deeper] and [Move Up]Modified Z ext-offset.", "msg 998"));
    if (auto s = context().snapshot()) {
        render(*s);
    }
}

QVector<Page::Softkey> CoordPage::softkeys() const {
    QString fourth = tr("Clear 4th", "msg 507");
    QString fifth = tr("Clear 5th", "msg 508");
    if (auto s = context().snapshot()) {
        fourth = PanelText::withAxisName(fourth, 3, s->status);
        fifth = PanelText::withAxisName(fifth, 4, s->status);
    }
    return {{tr("Select Coord", "msg 500"), true, {}}, {tr("Clear X", "msg 501"), true, {}},
            {tr("Clear Y", "msg 502"), true, {}},      {tr("Clear Z", "msg 503"), true, {}},
            {tr("Z Step", "msg 504"), true, {}},       {tr("Deeper", "msg 505"), true, {}},
            {tr("Move up", "msg 506"), true, {}},      {fourth, shown_[3], {}},
            {fifth, shown_[4], {}}, {}, {}, {}};
}

void CoordPage::softkey(int number) {
    switch (number) {
    case 1:
        context().askText(tr("Select the work system: 0 = G92, 1-6 = G54-G59"), {}, [this](std::optional<QString> text) {
            bool ok = false;
            int slot = text ? text->trimmed().toInt(&ok) : -1;
            if (text && (!ok || slot < 0 || slot > 6)) {
                context().notify(tr("Is not G54-G59 coordinate!", "msg 987"));
            } else if (text) {
                context().session().setParameter(kWorkSystemParameter, slot);
            }
        });
        break;
    case 2: setAxis(0); break;
    case 3: setAxis(1); break;
    case 4: setAxis(2); break;
    case 5:
        context().askText(tr("Z Step:", "msg 999"), QString::number(zStep_), [this](std::optional<QString> text) {
            bool ok = false;
            double step = text ? text->trimmed().toDouble(&ok) : 0.0;
            if (text && (!ok || step <= 0.0 || step > 100.0)) {
                context().notify(tr("Step distance must be a number from 0.001 to 100"));
            } else if (text) {
                zStep_ = step;
                if (auto s = context().snapshot()) {
                    render(*s);
                }
            }
        });
        break;
    case 6: moveCommonZ(-zStep_); break; // deeper: the work zero, and so every cut, goes down
    case 7: moveCommonZ(zStep_); break;
    case 8: setAxis(3); break;
    case 9: setAxis(4); break;
    default: break;
    }
}

void CoordPage::setAxis(int axis) {
    if (!shown_[static_cast<std::size_t>(axis)]) {
        return;
    }
    auto s = context().snapshot();
    const QString name = s ? PanelText::axis(axis, s->status) : PanelText::axis(axis);
    context().askText(name + tr("Axis Abs pos:", "msg 93"), QStringLiteral("0"),
                      [this, axis](std::optional<QString> text) {
                          bool ok = false;
                          double value = text ? text->trimmed().toDouble(&ok) : 0.0;
                          if (text && !ok) {
                              context().notify(tr("Not a number: %1").arg(*text));
                          } else if (text) {
                              context().session().setWorkPosition(axis, value);
                          }
                      });
}

void CoordPage::moveCommonZ(double by) {
    auto s = context().snapshot();
    if (!s) {
        return;
    }
    double z = s->status.workOffsets[kCommonSlot](2);
    context().session().setVariable(kCommonOffsetVariable + 2, z + by);
}

bool CoordPage::key(const QString& name) {
    if (name == QLatin1String("ESC")) {
        emit navigate(PageId::monitor);
        return true;
    }
    return false;
}

void CoordPage::render(const PanelSnapshot& snapshot) {
    const controller::PanelStatus& s = snapshot.status;
    bool axesChanged = false;
    QStringList headings;
    for (int axis = 0; axis < 5; ++axis) {
        const auto a = static_cast<std::size_t>(axis);
        axesChanged = axesChanged || shown_[a] != s.axisShown[a];
        shown_[a] = s.axisShown[a];
        table_->setColumnHidden(axis, !shown_[a]);
        headings << QStringLiteral("%1 (%2)").arg(PanelText::axis(axis, s), PanelText::axisUnit(axis, s));
    }
    if (headings.join(QLatin1Char('|')) != names_) {
        names_ = headings.join(QLatin1Char('|'));
        table_->setHorizontalHeaderLabels(headings);
        axesChanged = true;
    }
    for (int row = 0; row < table_->rowCount(); ++row) {
        const int slot = kSlots[row];
        const bool active = slot == s.workSystem;
        for (int axis = 0; axis < 5; ++axis) {
            QTableWidgetItem* item = table_->item(row, axis);
            item->setText(droText(s.workOffsets[static_cast<std::size_t>(slot)](axis)).trimmed());
            item->setForeground(active ? QColor(240, 208, 96) : QColor(232, 236, 240));
        }
    }
    step_->setText(tr("Z Step:", "msg 999") + QStringLiteral(" %1").arg(zStep_, 0, 'f', 3));
    if (axesChanged) {
        emit softkeysChanged();
    }
}

QString CoordPage::offsetText(int slot, int axis) const {
    for (int row = 0; row < table_->rowCount(); ++row) {
        if (kSlots[row] == slot) {
            return table_->item(row, axis)->text();
        }
    }
    return {};
}

QString CoordPage::columnText(int axis) const {
    const QTableWidgetItem* item = table_->horizontalHeaderItem(axis);
    return item ? item->text() : QString();
}
bool CoordPage::columnShown(int axis) const { return !table_->isColumnHidden(axis); }

QJsonObject CoordPage::state() const { return {{"coord_z_step", zStep_}}; }

} // namespace m350::ui
