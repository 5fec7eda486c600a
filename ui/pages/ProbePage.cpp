#include "ui/pages/ProbePage.h"

#include "ui/pages/CompactDro.h"
#include "ui/pages/PanelContext.h"
#include "ui/widgets/MeasuredLabel.h"
#include "ui/widgets/WrappedLabel.h"

#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QJsonArray>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace m350::ui {

namespace {

constexpr int kThickness = 129;    // 浮动对刀仪厚度
constexpr int kSetterX = 135;      // 135-137: 固定对刀仪 X Y Z (machine)
constexpr int kTeachXYProgram = 506; // slib-probe.nc: XY位置教导 into params 135, 136
constexpr int kTeachZProgram = 507;  // Z位置教导 into param 137
constexpr int kToolOffset = 930;   // 930-945: T1..T16 Z offset
constexpr int kCapacity = 801;
constexpr int kVirtualTools = 803;
constexpr int kSelectedTools = 1970; // #1970-#1989: the tools of a multi-tool setting
constexpr int kToolSlots = 20;
constexpr int kTargetTool = 1504;    // #1504: the tool T.nc changes to
constexpr int kProbeMode = 1502;     // #1502: 0 floating, 1 first fixed setting, 2 fixed again
constexpr int kSelectable = 16;

QString number(double value) { return QString::number(value, 'f', 3); }

} // namespace

ProbePage::ProbePage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    setObjectName("probePage");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(4, 4, 4, 4);
    column->setSpacing(2);
    auto* top = new QHBoxLayout;
    auto* fieldBox = new QGroupBox(this);
    auto* fields = new QGridLayout(fieldBox);
    fields->setColumnMinimumWidth(1, 90);
    // rows as close as the controller's: the page fits its 800x480 screen with the selection grid
    fields->setVerticalSpacing(0);
    fields->setContentsMargins(6, 2, 6, 2);
    int row = 0;
    for (const char* name : {"coord", "tool", "thickness", "x", "y", "z"}) {
        auto* caption = new MeasuredLabel(this);
        auto* value = new MeasuredLabel(this);
        value->setObjectName(QStringLiteral("probe_") + name);
        value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        value->setProperty("dro", false);
        fields->addWidget(caption, row, 0);
        fields->addWidget(value, row, 1);
        captions_.insert(name, caption);
        fields_.insert(name, value);
        ++row;
    }
    fields->setRowStretch(row, 1);
    offsetsBox_ = new QGroupBox(this);
    auto* offsets = new QGridLayout(offsetsBox_);
    offsets->setHorizontalSpacing(18);
    offsets->setVerticalSpacing(0);
    offsets->setContentsMargins(6, 2, 6, 2);
    for (int tool = 1; tool <= kSelectable; ++tool) {
        auto* label = new MeasuredLabel(this);
        label->setObjectName(QStringLiteral("probeOffsetT%1").arg(tool));
        label->setStyleSheet(QStringLiteral("font-family: 'DejaVu Sans Mono', monospace;"));
        offsets_[static_cast<std::size_t>(tool - 1)] = label;
        offsets->addWidget(label, (tool - 1) % 8, (tool - 1) / 8);
    }
    top->addWidget(fieldBox, 1);
    top->addWidget(offsetsBox_, 1);
    column->addLayout(top);
    dro_ = new CompactDro(this);
    column->addWidget(dro_);
    gridBox_ = new QWidget(this);
    gridBox_->setObjectName("probeSelection");
    auto* gridLayout = new QGridLayout(gridBox_);
    gridLayout->setContentsMargins(0, 2, 0, 2);
    gridLayout->setVerticalSpacing(2);
    gridTitle_ = new MeasuredLabel(gridBox_);
    gridLayout->addWidget(gridTitle_, 0, 0, 1, 8);
    for (int tool = 1; tool <= kSelectable; ++tool) {
        auto* b = new QPushButton(QStringLiteral("T%1").arg(tool), gridBox_);
        b->setObjectName(QStringLiteral("probeSelectT%1").arg(tool));
        b->setCheckable(true);
        b->setFocusPolicy(Qt::NoFocus);
        connect(b, &QPushButton::clicked, this, [this, tool](bool on) {
            selected_[static_cast<std::size_t>(tool - 1)] = on;
            cursor_ = tool - 1;
            refreshGrid();
        });
        grid_[static_cast<std::size_t>(tool - 1)] = b;
        gridLayout->addWidget(b, 1 + (tool - 1) / 8, (tool - 1) % 8);
    }
    gridBox_->hide();
    column->addWidget(gridBox_);
    progress_ = new WrappedLabel(this);
    progress_->setObjectName("probeProgress");
    column->addWidget(progress_);
    help_ = new WrappedLabel(this);
    help_->setObjectName("pageHelp");
    column->addWidget(help_, 1, Qt::AlignBottom);
    retranslate();
}

QString ProbePage::title() const { return tr("Probe", "msg 6"); }

void ProbePage::retranslate() {
    captions_["coord"]->setText(tr("Coord:", "msg 991"));
    captions_["tool"]->setText(tr("Cur Tool:", "msg 992"));
    captions_["thickness"]->setText(tr("THK Of Probe:", "msg 993"));
    captions_["x"]->setText(tr("Fixed Probe X:", "msg 994"));
    captions_["y"]->setText(tr("Fixed Probe Y:", "msg 995"));
    captions_["z"]->setText(tr("Fixed Probe Z:", "msg 996"));
    offsetsBox_->setTitle(tr("Tool Z offsets (params 930-945)"));
    gridTitle_->setText(tr("Multi-tool selection:", "msg 864"));
    help_->setText(tr("1:Before operate [Floating Probe],Pls move tool above the block and set Param 129;", "msg 984") +
                   QLatin1Char('\n') +
                   tr("2:[Fixed Probe]Input the cutter No.,record the offset of Z axis after tool change;", "msg 985") +
                   QLatin1Char('\n') +
                   tr("3:[Mult Probe] Probe several tools at one time.select the Tools and press [Mult Probe];",
                      "msg 986"));
    if (auto s = context().snapshot()) {
        render(*s);
    }
}

QVector<Page::Softkey> ProbePage::softkeys() const {
    return {{tr("Floating Probe", "msg 468"), true, {}}, {tr("Tool Table"), true, {}},
            {tr("Fixed Probe", "msg 470"), true, {}},    {tr("Mult Probe", "msg 471"), true, {}},
            {tr("XY Teach", "msg 472"), true, {}},       {tr("Z Teach", "msg 473"), true, {}}};
}

void ProbePage::softkey(int number) {
    switch (number) {
    case 1: floating(); break;
    case 2: emit navigate(PageId::tools); break;
    case 3: fixed(); break;
    case 4: multi(); break;
    case 5: teach(true); break;
    case 6: teach(false); break;
    default: break;
    }
}

void ProbePage::floating() {
    context().ask(tr("Tool is above the probe sensor?", "msg 982"), [this](bool yes) {
        if (yes) {
            context().session().runMdi({QStringLiteral("#1502=0"), QStringLiteral("M98 P502")}, Activity::Probe);
        }
    });
}

void ProbePage::fixed() {
    auto s = context().snapshot();
    QString current = s ? QString::number(s->status.tool) : QString();
    context().askText(tr("Enter the tool number:", "msg 863"), current, [this](std::optional<QString> text) {
        if (!text) {
            return;
        }
        bool ok = false;
        int tool = text->trimmed().toInt(&ok);
        auto s = context().snapshot();
        if (!ok || tool <= 0 || !s) {
            context().notify(tr("The current tool No. is 0, this operation is invalid!", "msg 858"));
            return;
        }
        const params::ParameterTable& p = s->status.parameters;
        int most = static_cast<int>(p.get(kCapacity)) + (p.get(kVirtualTools) != 0.0 ? 20 : 0);
        if (tool > most) {
            context().notify(tr("Exceeded the maximum!", "msg 884"));
            return;
        }
        fixedFor(tool);
    });
}

// Mode 1 (first fixed setting) also fixes the work Z relative to the setter, so it needs a work
// Z zero already set; mode 2 records only the tool's Z offset. Another tool is changed to first
// (T.nc with #1504, or its T word), then probe.nc runs (or M98 P502) with #1502 set.
void ProbePage::fixedFor(int tool) {
    context().ask(tr("Is the workpiece zero set for the Z axis?", "msg 983"), [this, tool](bool zeroSet) {
        auto s = context().snapshot();
        QVector<MachineSession::HookStep> steps;
        if (s && s->status.tool != tool) {
            steps.push_back({config::Hook::ToolWord, {{kTargetTool, tool}}, {QStringLiteral("T%1").arg(tool)}});
        }
        const int mode = zeroSet ? 1 : 2;
        steps.push_back({config::Hook::Probe, {{kProbeMode, mode}},
                         {QStringLiteral("#1502=%1").arg(mode), QStringLiteral("M98 P502")}});
        if (!zeroSet) {
            context().notify(tr("Pls determine the Z-axis workpiece zero!", "msg 869"));
        }
        context().session().runHooks(steps, Activity::Probe);
    });
}

void ProbePage::multi() {
    if (!selecting_) {
        showGrid(true);
        return;
    }
    // the chosen tools in #1970-#1989 (0: none), then mulprobe.nc (or M98 P505)
    std::map<int, double> tools;
    int count = 0;
    for (int tool = 1; tool <= kSelectable; ++tool) {
        if (selected_[static_cast<std::size_t>(tool - 1)]) {
            tools[kSelectedTools + count++] = tool;
        }
    }
    if (count == 0) {
        context().notify(tr("Select the tools first (arrows move, Enter selects)"));
        return;
    }
    for (int slot = count; slot < kToolSlots; ++slot) {
        tools[kSelectedTools + slot] = 0;
    }
    MachineSession::HookStep step{config::Hook::MultiProbe, tools, {QStringLiteral("M98 P%1").arg(kMultiToolProgram)}};
    context().ask(tr("One Key probe for the selected tool?", "msg 866"), [this, step](bool yes) {
        if (yes) {
            showGrid(false);
            context().session().runHooks({step}, Activity::Probe);
        }
    });
}

// The machine's O506 (XY) or O507 (Z) stores the position: the trainee sees the macro do it, and
// an axis that is not homed is its alarm.
void ProbePage::teach(bool xy) {
    QString question = xy ? tr("(XY)Mach pos is XY pos of Probe?", "msg 148") : tr("(Z)Mach pos is Z pos of Probe?", "msg 149");
    context().ask(question, [this, xy](bool yes) {
        if (yes) {
            context().session().runMdi({QStringLiteral("M98 P%1").arg(xy ? kTeachXYProgram : kTeachZProgram)},
                                       Activity::Probe);
        }
    });
}

void ProbePage::showGrid(bool on) {
    selecting_ = on;
    // the grid takes the place of the help (its title says what to do) and of the small DRO, so
    // the page keeps the height of the controller's 800x480 screen. What goes, goes first: with all
    // three shown for a moment the window would grow and stay grown
    if (on) {
        help_->hide();
        dro_->hide();
        gridBox_->show();
    } else {
        gridBox_->hide();
        help_->show();
        dro_->show();
    }
    refreshGrid();
}

void ProbePage::refreshGrid() {
    for (int i = 0; i < kSelectable; ++i) {
        QPushButton* b = grid_[static_cast<std::size_t>(i)];
        b->setChecked(selected_[static_cast<std::size_t>(i)]);
        b->setStyleSheet(i == cursor_ ? QStringLiteral("border: 2px solid #f0d060;") : QString());
    }
}

bool ProbePage::key(const QString& name) {
    if (!selecting_) {
        return false;
    }
    if (name == QLatin1String("ESC")) {
        showGrid(false);
    } else if (name == QLatin1String("ENTER")) {
        selected_[static_cast<std::size_t>(cursor_)] = !selected_[static_cast<std::size_t>(cursor_)];
    } else if (name == QLatin1String("LEFT") || name == QLatin1String("RIGHT")) {
        cursor_ = (cursor_ + (name == QLatin1String("LEFT") ? -1 : 1) + kSelectable) % kSelectable;
    } else if (name == QLatin1String("UP") || name == QLatin1String("DOWN")) {
        cursor_ = (cursor_ + 8) % kSelectable;
    } else {
        return false;
    }
    refreshGrid();
    return true;
}

void ProbePage::render(const PanelSnapshot& snapshot) {
    const controller::PanelStatus& s = snapshot.status;
    const params::ParameterTable& p = s.parameters;
    dro_->render(snapshot);
    fields_["coord"]->setText(QString::fromStdString(controller::workSystemName(s.workSystem)));
    fields_["tool"]->setText(QStringLiteral("T%1").arg(s.tool));
    fields_["thickness"]->setText(number(p.get(kThickness)));
    fields_["x"]->setText(number(p.get(kSetterX)));
    fields_["y"]->setText(number(p.get(kSetterX + 1)));
    fields_["z"]->setText(number(p.get(kSetterX + 2)));
    for (int tool = 1; tool <= kSelectable; ++tool) {
        offsets_[static_cast<std::size_t>(tool - 1)]->setText(
            QStringLiteral("T%1 %2").arg(tool, 2, 10, QLatin1Char('0')).arg(p.get(kToolOffset + tool - 1), 10, 'f', 3));
    }
    QString progress;
    if (snapshot.activity == Activity::Probe) {
        progress = tr("Probing: %1:%2").arg(QString::fromStdString(s.file)).arg(s.line);
        if (!s.message.empty()) {
            progress += QStringLiteral("  ") + QString::fromStdString(s.message);
        }
    } else if (!s.message.empty()) {
        progress = QString::fromStdString(s.message);
    }
    progress_->setText(progress);
}

QString ProbePage::fieldText(const QString& name) const { return fields_.value(name) ? fields_.value(name)->text() : QString(); }
QString ProbePage::offsetText(int tool) const { return offsets_[static_cast<std::size_t>(tool - 1)]->text(); }
QString ProbePage::progressText() const { return progress_->text(); }

QJsonObject ProbePage::state() const {
    QJsonArray selected;
    for (int tool = 1; tool <= kSelectable; ++tool) {
        if (selected_[static_cast<std::size_t>(tool - 1)]) {
            selected.append(tool);
        }
    }
    QJsonArray offsets;
    for (const QLabel* label : offsets_) {
        offsets.append(label->text());
    }
    return {{"probe_selecting", selecting_},
            {"probe_selected", selected},
            {"probe_progress", progress_->text()},
            {"probe_offsets", offsets}};
}

} // namespace m350::ui
