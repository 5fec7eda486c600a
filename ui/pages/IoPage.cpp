#include "ui/pages/IoPage.h"
#include "ui/widgets/MeasuredLabel.h"
#include "ui/widgets/PanelTable.h"

#include "core/controller/ParameterWrites.h"
#include "core/params/IoPorts.h"
#include "core/params/ParameterNumbers.h"
#include "ui/i18n/PanelText.h"
#include "ui/pages/LevelPrompt.h"
#include "ui/pages/PanelContext.h"
#include "ui/widgets/WrappedLabel.h"

#include <QGridLayout>
#include <QHeaderView>
#include <QJsonArray>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace m350::ui {

namespace {

enum Column { Lamp, Name, Enable, Pin, Polarity, ColumnCount };

QLabel* lamp(QWidget* parent, const QString& text) {
    auto* label = new MeasuredLabel(text, parent);
    label->setAlignment(Qt::AlignCenter);
    label->setMinimumWidth(40);
    label->setStyleSheet(QStringLiteral("background:#1b2029;color:#9fb4d0;border:1px solid #3a4250;"));
    return label;
}

void light(QLabel* label, bool on) {
    if (label->property("lit").toBool() == on && label->property("lit").isValid()) {
        return;
    }
    label->setProperty("lit", on);
    label->setStyleSheet(on ? QStringLiteral("background:#30c030;color:#000;border:1px solid #80ff80;")
                            : QStringLiteral("background:#1b2029;color:#9fb4d0;border:1px solid #3a4250;"));
}

int pinOf(const params::ParameterTable& p, int parameter) { return static_cast<int>(p.get(parameter)); }

} // namespace

IoPage::IoPage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    setObjectName("ioPage");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(4, 4, 4, 4);
    table_ = makePanelTable(this, ColumnCount, "ioPorts");
    table_->horizontalHeader()->setSectionResizeMode(Name, QHeaderView::Stretch);
    column->addWidget(table_, 1);
    auto* lamps = new QGridLayout;
    lamps->setSpacing(2);
    inputsTitle_ = new MeasuredLabel(this);
    outputsTitle_ = new MeasuredLabel(this);
    lamps->addWidget(inputsTitle_, 0, 0, 1, 12);
    for (int pin = 1; pin <= 24; ++pin) {
        QLabel* l = lamp(this, QStringLiteral("IN%1").arg(pin, 2, 10, QLatin1Char('0')));
        l->setObjectName(QStringLiteral("lampIN%1").arg(pin, 2, 10, QLatin1Char('0')));
        inputs_[static_cast<std::size_t>(pin - 1)] = l;
        lamps->addWidget(l, 1 + (pin - 1) / 12, (pin - 1) % 12);
    }
    lamps->addWidget(outputsTitle_, 3, 0, 1, 12);
    for (int pin = 1; pin <= 21; ++pin) {
        QLabel* l = lamp(this, QStringLiteral("OUT%1").arg(pin, 2, 10, QLatin1Char('0')));
        l->setObjectName(QStringLiteral("lampOUT%1").arg(pin, 2, 10, QLatin1Char('0')));
        outputs_[static_cast<std::size_t>(pin - 1)] = l;
        lamps->addWidget(l, 4 + (pin - 1) / 12, (pin - 1) % 12);
    }
    column->addLayout(lamps);
    watch_ = new WrappedLabel(this);
    watch_->setObjectName("ioWatch");
    column->addWidget(watch_);
    retranslate();
}

QString IoPage::title() const { return tr("IO", "msg 303"); }

void IoPage::retranslate() {
    table_->setHorizontalHeaderLabels({tr("Stat", "msg 493"), tr("Port Name", "msg 130"), tr("Enable", "msg 131"),
                                       tr("Pin No.", "msg 132"), tr("Polarity", "msg 133")});
    inputsTitle_->setText(tr("Inputs IN01-IN24"));
    outputsTitle_->setText(tr("Outputs OUT01-OUT21"));
    wiring_.clear(); // names change with the language: rebuild on the next snapshot
    if (auto s = context().snapshot()) {
        render(*s);
    }
}

QVector<Page::Softkey> IoPage::softkeys() const {
    const QString extra = tr("Simulator only: a fault a trainer puts on the selected input");
    const QString none = tr("The IO test screens drive real hardware; the simulator has none");
    return {{tr("Out Open", "msg 396"), true, {}},
            {tr("Out Close", "msg 397"), true, {}},
            {},
            {tr("Change Polarity", "msg 399"), true, {}},
            {},
            {tr("Test", "msg 401"), false, none},
            {tr("Sim: stuck 0"), true, extra},
            {tr("Sim: stuck 1"), true, extra},
            {tr("Sim: slow 2 s"), true, extra},
            {tr("Sim: bouncing"), true, extra},
            {tr("Sim: clear fault"), true, extra},
            {tr("Sim: press"), true, tr("Simulator only: the selected input reads its active level for 0.3 s, as a key pressed")}};
}

void IoPage::softkey(int number) {
    switch (number) {
    case 1: switchOutput(true); break;
    case 2: switchOutput(false); break;
    case 4: {
        int parameter = selectedFunction();
        if (parameter == 0) {
            context().notify(tr("Select a port first (UP/DOWN)"));
            return;
        }
        // the port tables are factory parameters: the level the Param page asks for them (issue 26)
        if (!LevelPrompt::require(context(), controller::ParameterWrites::required(parameter + 2),
                                  [this] { softkey(4); })) {
            return;
        }
        auto s = context().snapshot();
        double level = s ? s->status.parameters.get(parameter + 2) : 1.0;
        context().session().setParameter(parameter + 2, level != 0.0 ? 0.0 : 1.0);
        break;
    }
    case 7: forceSelected(MachineSession::Fault::Stuck, 0); break;
    case 8: forceSelected(MachineSession::Fault::Stuck, 1); break;
    case 9: forceSelected(MachineSession::Fault::Slow, 0); break;
    case 10: forceSelected(MachineSession::Fault::Bouncing, 0); break;
    case 11: forceSelected(MachineSession::Fault::None, 0); break;
    case 12: pressSelected(); break;
    default: break;
    }
}

void IoPage::switchOutput(bool on) {
    int row = table_->currentRow();
    if (row < 0 || rows_[row].input) {
        context().notify(tr("Select an output port first (UP/DOWN)"));
        return;
    }
    auto s = context().snapshot();
    if (!s) {
        return;
    }
    const params::ParameterTable& p = s->status.parameters;
    int pin = pinOf(p, rows_[row].parameter);
    int active = static_cast<int>(p.get(rows_[row].parameter + 2));
    const int level = on ? active : 1 - active;
    const int tool = s->status.tool;
    if (on && rows_[row].parameter == param::kDrawbarOutput && tool > 0) {
        // the tool in the spindle falls out when the drawbar lets go: the operator says so first
        context().ask(tr("T%1 is in the spindle: releasing the drawbar drops it. Release it?").arg(tool),
                      [this, pin, level](bool yes) {
                          if (yes) {
                              context().session().setOutput(pin, level);
                          }
                      });
        return;
    }
    context().session().setOutput(pin, level);
}

void IoPage::forceSelected(MachineSession::Fault fault, int level) {
    int row = table_->currentRow();
    if (row < 0 || !rows_[row].input) {
        context().notify(tr("Select an input port first (UP/DOWN)"));
        return;
    }
    auto s = context().snapshot();
    int pin = s ? pinOf(s->status.parameters, rows_[row].parameter) : 0;
    constexpr double kSlowSeconds = 2.0;
    constexpr double kBounceSeconds = 0.05;
    double seconds = fault == MachineSession::Fault::Slow ? kSlowSeconds : kBounceSeconds;
    context().session().forceInput(pin, fault, level, seconds);
}

// A key wired to the input (an external key, extern START) pressed once: its active level a moment.
void IoPage::pressSelected() {
    int row = table_->currentRow();
    if (row < 0 || !rows_[row].input) {
        context().notify(tr("Select an input port first (UP/DOWN)"));
        return;
    }
    auto s = context().snapshot();
    if (!s) {
        return;
    }
    const params::ParameterTable& p = s->status.parameters;
    constexpr double kPressSeconds = 0.3;
    context().session().forceInput(pinOf(p, rows_[row].parameter), MachineSession::Fault::Pressed,
                                   static_cast<int>(p.get(rows_[row].parameter + 2)), kPressSeconds);
}

bool IoPage::key(const QString& name) {
    if (name != QLatin1String("UP") && name != QLatin1String("DOWN")) {
        return false;
    }
    if (rows_.isEmpty()) {
        return true;
    }
    int row = table_->currentRow() + (name == QLatin1String("UP") ? -1 : 1);
    table_->selectRow(std::clamp(row, 0, static_cast<int>(rows_.size()) - 1));
    return true;
}

int IoPage::selectedFunction() const {
    int row = table_->currentRow();
    return row >= 0 && row < rows_.size() ? rows_[row].parameter : 0;
}

bool IoPage::selectFunction(int parameter) {
    for (int row = 0; row < rows_.size(); ++row) {
        if (rows_[row].parameter == parameter) {
            table_->selectRow(row);
            return true;
        }
    }
    return false;
}

void IoPage::rebuildTable(const PanelSnapshot& snapshot) {
    const params::ParameterTable& p = snapshot.status.parameters;
    int selected = selectedFunction();
    rows_.clear();
    for (const params::IoFunction& f : params::ioFunctions()) {
        if (pinOf(p, f.parameter) > 0) {
            rows_.push_back({f.parameter, f.input});
        }
    }
    { // the fitted columns measured once, at the end of this block
        const TableFill filling(table_);
        table_->setRowCount(static_cast<int>(rows_.size()));
        for (int row = 0; row < rows_.size(); ++row) {
            for (int col = 0; col < ColumnCount; ++col) {
                if (!table_->item(row, col)) {
                    table_->setItem(row, col, new QTableWidgetItem);
                }
            }
        }
    }
    if (!selectFunction(selected) && !rows_.isEmpty()) {
        table_->selectRow(0);
    }
}

void IoPage::fillRow(int row, const PanelSnapshot& snapshot) {
    const params::ParameterTable& p = snapshot.status.parameters;
    const params::IoFunction& f = *params::ioFunction(rows_[row].parameter);
    params::PortAssignment port = params::portAssignment(p, f.parameter);
    const int pins = f.input ? machine::kInputCount : machine::kOutputCount;
    const auto index = static_cast<std::size_t>(std::clamp(port.pin, 1, pins) - 1);
    int level = port.pin > pins ? -1 : f.input ? snapshot.status.inputs[index] : snapshot.status.outputs[index];
    bool active = port.enabled && level == port.activeLevel;
    table_->item(row, Lamp)->setText(active ? QStringLiteral("●") : QStringLiteral("○"));
    table_->item(row, Lamp)->setForeground(active ? QColor(80, 230, 80) : QColor(120, 130, 140));
    table_->item(row, Name)->setText(PanelText::chinese() ? QString::fromUtf8(f.nameZh) : QString::fromUtf8(f.nameEn));
    table_->item(row, Enable)->setText(port.enabled ? tr("Yes") : tr("No"));
    table_->item(row, Pin)->setText(QString::fromStdString(f.input ? params::inputName(port.pin) : params::outputName(port.pin)));
    table_->item(row, Polarity)->setText(QString::number(port.activeLevel));
}

void IoPage::render(const PanelSnapshot& snapshot) {
    const controller::PanelStatus& s = snapshot.status;
    QVector<int> wiring;
    for (const params::IoFunction& f : params::ioFunctions()) {
        wiring.push_back(pinOf(s.parameters, f.parameter));
    }
    if (wiring != wiring_) {
        wiring_ = wiring;
        rebuildTable(snapshot);
    }
    for (int row = 0; row < rows_.size(); ++row) {
        fillRow(row, snapshot);
    }
    for (int pin = 1; pin <= 24; ++pin) {
        light(inputs_[static_cast<std::size_t>(pin - 1)], s.inputs[static_cast<std::size_t>(pin - 1)] != 0);
    }
    for (int pin = 1; pin <= 21; ++pin) {
        light(outputs_[static_cast<std::size_t>(pin - 1)], s.outputs[static_cast<std::size_t>(pin - 1)] != 0);
    }
    if (s.sensorWait) {
        watch_->setText(tr("Sensor watchdog: %1 awaited at %2 for %3 s (%4:%5)")
                            .arg(QString::fromStdString(s.sensorWait->input))
                            .arg(s.sensorWait->awaitedLevel)
                            .arg(s.sensorWait->seconds, 0, 'f', 1)
                            .arg(QString::fromStdString(s.sensorWait->file))
                            .arg(s.sensorWait->line));
    } else if (s.alarm && s.alarm->code == AlarmCode::SensorTimeout) {
        watch_->setText(tr("Sensor watchdog: %1").arg(QString::fromStdString(s.alarm->message)));
    } else {
        watch_->clear();
    }
}

bool IoPage::inputLit(int pin) const { return inputs_[static_cast<std::size_t>(pin - 1)]->property("lit").toBool(); }
bool IoPage::outputLit(int pin) const { return outputs_[static_cast<std::size_t>(pin - 1)]->property("lit").toBool(); }
QString IoPage::watchText() const { return watch_->text(); }

QJsonObject IoPage::state() const {
    return {{"io_selected", selectedFunction()}, {"io_watch", watch_->text()}};
}

} // namespace m350::ui
