#include "ui/pages/MonitorPage.h"

#include "ui/i18n/PanelText.h"
#include "ui/pages/CompactDro.h"
#include "ui/widgets/DroLabel.h"
#include "ui/pages/PanelContext.h"
#include "ui/pages/ProgramWindow.h"
#include "ui/session/HookSteps.h"
#include "ui/widgets/MeasuredLabel.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

#include <cmath>

namespace m350::ui {

namespace {

constexpr int kSpindleInterface = 79; // 0 analog, 1 pulse/direction (servo), 2 multi-speed

QString clock(double seconds) {
    auto total = static_cast<long long>(std::max(0.0, seconds));
    return QStringLiteral("%1:%2:%3")
        .arg(total / 3600, 2, 10, QLatin1Char('0'))
        .arg(total / 60 % 60, 2, 10, QLatin1Char('0'))
        .arg(total % 60, 2, 10, QLatin1Char('0'));
}

QString workSystemName(int slot) { return QString::fromStdString(controller::workSystemName(slot)); }

const QStringList& infoNames() {
    static const QStringList names{"coord", "fro", "sro", "sjr", "feed", "spindle", "tool", "total", "pieces", "time", "jog"};
    return names;
}

} // namespace

MonitorPage::MonitorPage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    setObjectName("monitorPage");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(4, 4, 4, 4);
    auto* row = new QHBoxLayout;
    auto* dro = new QGridLayout;
    dro->setHorizontalSpacing(10);
    dro->setVerticalSpacing(2); // the rows' room goes to the digits (DroLabel), 800x480 included
    axisHeader_ = new MeasuredLabel(this);
    machineHeader_ = new MeasuredLabel(this);
    workHeader_ = new MeasuredLabel(this);
    for (QLabel* header : {axisHeader_, machineHeader_, workHeader_}) {
        header->setObjectName("droHeader");
        header->setAlignment(Qt::AlignCenter);
    }
    dro->addWidget(axisHeader_, 0, 0);
    dro->addWidget(machineHeader_, 0, 1);
    dro->addWidget(workHeader_, 0, 2);
    for (int axis = 0; axis < 5; ++axis) {
        axisName_[axis] = new MeasuredLabel(this);
        axisName_[axis]->setObjectName(QStringLiteral("droAxis%1").arg(axis));
        machine_[axis] = new DroLabel(this);
        machine_[axis]->setObjectName(QStringLiteral("droMachine%1").arg(axis));
        work_[axis] = new DroLabel(this);
        work_[axis]->setObjectName(QStringLiteral("droWork%1").arg(axis));
        for (QLabel* value : {machine_[axis], work_[axis]}) {
            value->setProperty("dro", true);
            value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        }
        unit_[axis] = new MeasuredLabel(this);
        unit_[axis]->setObjectName(QStringLiteral("droUnit%1").arg(axis));
        unit_[axis]->setProperty("droUnit", true);
        axisName_[axis]->setProperty("droAxis", true);
        dro->addWidget(axisName_[axis], axis + 1, 0);
        dro->addWidget(machine_[axis], axis + 1, 1);
        dro->addWidget(work_[axis], axis + 1, 2);
        dro->addWidget(unit_[axis], axis + 1, 3);
    }
    dro->setRowStretch(6, 1);
    dro->setColumnStretch(1, 1); // the coordinates take the room the row gives the DRO
    dro->setColumnStretch(2, 1);
    auto* info = new QGridLayout;
    info->setVerticalSpacing(1);
    int line = 0;
    for (const QString& name : infoNames()) {
        auto* caption = new MeasuredLabel(this);
        caption->setObjectName("infoCaption");
        info->addWidget(caption, line, 0);
        info->addWidget(infoLabel(name), line, 1);
        captions_.insert(name, caption);
        ++line;
    }
    info->setRowStretch(line, 1);
    // the program window sits under the coordinates, beside the overrides and counters
    auto* left = new QVBoxLayout;
    left->addLayout(dro);
    program_ = new ProgramWindow(context.machineFolder(), this);
    left->addWidget(program_, 1); // what the DRO leaves: more of the program around its block
    row->addLayout(left, 3);
    row->addLayout(info, 2);
    column->addLayout(row, 1);
    modal_ = new MeasuredLabel(this);
    modal_->setObjectName("modalLine");
    column->addWidget(modal_);
    retranslate();
}

QLabel* MonitorPage::infoLabel(const QString& name) {
    auto* label = new MeasuredLabel(this);
    label->setObjectName(QStringLiteral("info_") + name);
    label->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    values_.insert(name, label);
    return label;
}

QString MonitorPage::title() const { return tr("Monitor", "msg 300"); }

void MonitorPage::retranslate() {
    axisHeader_->setText(tr("Axis", "msg 33"));
    machineHeader_->setText(tr("Mach", "msg 34"));
    workHeader_->setText(tr("Abs", "msg 35"));
    captions_["coord"]->setText(tr("Coord:", "msg 991"));
    captions_["fro"]->setText(tr("FRO", "msg 30"));
    captions_["sro"]->setText(tr("SRO", "msg 31"));
    captions_["sjr"]->setText(tr("SJR", "msg 32"));
    captions_["feed"]->setText(tr("Feed Rate", "msg 36"));
    captions_["tool"]->setText(tr("Cur Tool", "msg 46"));
    captions_["total"]->setText(tr("Total No.", "msg 47"));
    captions_["pieces"]->setText(tr("Cur No.", "msg 48"));
    captions_["time"]->setText(tr("Work Time", "msg 49"));
    captions_["jog"]->setText(tr("INC Distance", "msg 244"));
    program_->retranslate();
    if (auto s = context().snapshot()) {
        render(*s);
    }
}

QVector<Page::Softkey> MonitorPage::softkeys() const {
    auto axisRow = [this](const QStringList& labels) {
        auto s = context().snapshot();
        QVector<Softkey> keys;
        for (int i = 0; i < labels.size(); ++i) {
            bool axisKey = i < 5;
            QString label = axisKey && s ? PanelText::withAxisName(labels[i], i, s->status) : labels[i];
            keys.push_back({label, !axisKey || shown_[static_cast<std::size_t>(i)], {}});
        }
        return keys;
    };
    switch (menu_) {
    case Menu::GoHome:
        return axisRow({tr("X Go Home", "msg 420"), tr("Y Go Home", "msg 421"), tr("Z Go Home", "msg 422"),
                        tr("4th Go Home", "msg 423"), tr("5th Go Home", "msg 424"), tr("All Go Home", "msg 425")});
    case Menu::GoWorkZero:
        return axisRow({tr("X Go Zero", "msg 432"), tr("Y Go Zero", "msg 433"), tr("Z Go Zero", "msg 434"),
                        tr("4th Go Zero", "msg 435"), tr("5th Go Zero", "msg 436"), tr("All Go Zero", "msg 437")});
    case Menu::Clear:
        return axisRow({tr("Clear X", "msg 444"), tr("Clear Y", "msg 445"), tr("Clear Z", "msg 446"),
                        tr("Clear 4th", "msg 447"), tr("Clear 5th", "msg 448"), tr("Clear All", "msg 449")});
    case Menu::Main: break;
    }
    return {{tr("Simulation", "msg 312"), true, {}},
            {tr("Probe", "msg 313"), true, {}},
            {tr("Go Work Zero", "msg 314"), true, {}},
            {tr("Go Home", "msg 315"), true, {}},
            {tr("Clear", "msg 316"), true, {}},
            {tr("Break Run", "msg 317"), true, {}},
            {tr("Manual", "msg 318"), true, {}},
            {tr("Coord Set", "msg 319"), true, {}},
            {tr("MDI", "msg 320"), true, {}},
            {tr("Middle", "msg 321"), true, {}},
            {tr("Work Record", "msg 322"), true, {}},
            {tr("Sort Proces", "msg 323"), false, tr("Not in the simulator")}};
}

void MonitorPage::openMenu(Menu menu) {
    menu_ = menu;
    emit softkeysChanged();
}

void MonitorPage::softkey(int number) {
    if (menu_ != Menu::Main) {
        axisCommand(number);
        return;
    }
    switch (number) {
    case 1: emit navigate(PageId::graphics); break;
    case 2: emit navigate(PageId::probe); break;
    case 3: openMenu(Menu::GoWorkZero); break;
    case 4: openMenu(Menu::GoHome); break;
    case 5: openMenu(Menu::Clear); break;
    case 6: emit navigate(PageId::breakRun); break;
    case 7: emit navigate(PageId::custom); break;
    case 8: emit navigate(PageId::coord); break;
    case 9: emit navigate(PageId::mdi); break;
    case 10: emit navigate(PageId::middle); break;
    case 11: emit navigate(PageId::record); break;
    default: break;
    }
}

// F1-F5 one axis, F6 all of them.
void MonitorPage::axisCommand(int number) {
    if (number < 1 || number > 6) {
        return;
    }
    QVector<int> axes;
    if (number == 6) {
        for (int axis = 0; axis < 5; ++axis) {
            if (shown_[static_cast<std::size_t>(axis)]) {
                axes.push_back(axis);
            }
        }
    } else {
        axes.push_back(number - 1);
    }
    MachineSession& session = context().session();
    switch (menu_) {
    case Menu::GoHome: session.home(number == 6 ? QVector<int>{} : axes); break;
    case Menu::Clear: session.zeroAxes(axes); break;
    case Menu::GoWorkZero:
        if (number == 6) {
            session.runHooks({goToWorkZeroStep(axes)}, Activity::Mdi); // gotozero.nc when the folder has it
        } else {
            session.runMdi({QStringLiteral("G90 G00 %1 0").arg(QChar("XYZAB"[axes.front()]))}, Activity::Mdi);
        }
        break;
    case Menu::Main: break;
    }
}

bool MonitorPage::key(const QString& name) {
    if (name == QLatin1String("ESC") && menu_ != Menu::Main) {
        openMenu(Menu::Main);
        return true;
    }
    return false;
}

void MonitorPage::render(const PanelSnapshot& snapshot) {
    const controller::PanelStatus& s = snapshot.status;
    bool axesChanged = false;
    QString names;
    for (int axis = 0; axis < 5; ++axis) {
        const auto index = static_cast<std::size_t>(axis);
        bool shown = s.axisShown[index];
        axesChanged = axesChanged || shown != shown_[index];
        shown_[index] = shown;
        names += PanelText::axis(axis, s);
        for (QLabel* label : {axisName_[index], machine_[index], work_[index], unit_[index]}) {
            label->setVisible(shown);
        }
        // the homed marker: a filled circle beside a homed axis, as the panel's home icon
        axisName_[index]->setText(PanelText::axis(axis, s) +
                                  (s.homed[index] ? QStringLiteral(" ●") : QStringLiteral(" ○")));
        unit_[index]->setText(PanelText::axisUnit(axis, s));
        axisName_[index]->setToolTip(s.homed[index] ? tr("Homed") : tr("Not homed"));
        machine_[index]->setText(droText(s.machine(axis)));
        work_[index]->setText(droText(s.work(axis)));
    }
    if (axesChanged || names != names_) {
        names_ = names;
        emit softkeysChanged();
    }
    values_["coord"]->setText(workSystemName(s.workSystem));
    // 试切: the wheel sets the feed override, and the state shows which way it drives the program
    if (s.guide) {
        const QString way = s.guideDirection > 0   ? PanelText::state(PanelText::State::Forward)
                            : s.guideDirection < 0 ? PanelText::state(PanelText::State::Reverse)
                                                   : QString();
        values_["fro"]->setText(QStringLiteral("%1%  %2").arg(s.guideOverride, 0, 'f', 0).arg(way).trimmed());
    } else {
        values_["fro"]->setText(QStringLiteral("%1%").arg(s.feedOverride, 0, 'f', 0));
    }
    values_["sro"]->setText(QStringLiteral("%1%").arg(s.spindleOverride, 0, 'f', 0));
    values_["sjr"]->setText(QStringLiteral("%1%").arg(s.jogOverride, 0, 'f', 0));
    values_["feed"]->setText(QStringLiteral("%1").arg(s.feed, 0, 'f', 0));
    const int type = static_cast<int>(s.parameters.get(kSpindleInterface));
    captions_["spindle"]->setText(type == 1   ? tr("Servo S", "msg 38")
                                  : type == 2 ? tr("Mult S", "msg 39")
                                              : tr("Analog S", "msg 37"));
    values_["spindle"]->setText(QStringLiteral("%1  %2").arg(s.spindleRpm, 0, 'f', 0).arg(PanelText::spindle(s.spindle)));
    // after a stop in a change the controller is unsure of the tool until the operator enters it
    values_["tool"]->setText((s.toolUnsure ? QStringLiteral("T%1 ?") : QStringLiteral("T%1")).arg(s.tool));
    values_["total"]->setText(QString::number(s.totalCount));
    values_["pieces"]->setText(QString::number(s.pieceCount));
    values_["time"]->setText(clock(s.runSeconds));
    values_["jog"]->setText(QStringLiteral("%1  %2").arg(s.jogStep, 0, 'f', 3).arg(s.jogHighSpeed ? tr("High", "msg 873") : tr("Low", "msg 872")));
    modal_->setText(QString::fromStdString(s.modalLine));
    program_->render(snapshot);
}

QString MonitorPage::machineText(int axis) const { return machine_[static_cast<std::size_t>(axis)]->text().trimmed(); }
QString MonitorPage::workText(int axis) const { return work_[static_cast<std::size_t>(axis)]->text().trimmed(); }
QString MonitorPage::axisText(int axis) const { return axisName_[static_cast<std::size_t>(axis)]->text(); }
QString MonitorPage::unitText(int axis) const { return unit_[static_cast<std::size_t>(axis)]->text(); }
bool MonitorPage::axisVisible(int axis) const { return !axisName_[static_cast<std::size_t>(axis)]->isHidden(); }
QString MonitorPage::infoText(const QString& name) const { return values_.value(name) ? values_.value(name)->text() : QString(); }

QJsonObject MonitorPage::state() const {
    static const char* const menus[] = {"main", "go_home", "go_work_zero", "clear"};
    return {{"monitor_menu", QString::fromLatin1(menus[static_cast<int>(menu_)])}};
}

} // namespace m350::ui
