#include "ui/panel/KeyPad.h"

#include "ui/panel/HandwheelWidget.h"

#include <QEvent>
#include <QGridLayout>
#include <QPushButton>
#include <QVBoxLayout>

#include <cmath>

namespace m350::ui {

namespace {

// Rows of keys as they sit on the panel, top to bottom.
const QVector<QStringList>& keyRows() {
    static const QVector<QStringList> rows{
        {"MONITOR", "PROGRAM", "PARAM", "IO", "LOG", "SYSTEM"},
        {"MDI", "PROBE", "CONT_STEP_MPG", "MPG_RUN", "HIGH_LOW", "STEP_INPUT"},
        {"STEP_0.001", "STEP_0.01", "STEP_0.1", "STEP_1", "EXT_START", "ESTOP"},
        {"JOG_X+", "JOG_Y+", "JOG_Z+", "JOG_A+", "JOG_B+", "START"},
        {"JOG_X-", "JOG_Y-", "JOG_Z-", "JOG_A-", "JOG_B-", "PAUSE"},
        {"FRO_100", "FRO_UP", "FRO_DOWN", "SRO_100", "SRO_UP", "SRO_DOWN"},
        {"SPINDLE", "M3", "M4", "M5", "RESET"},
        {"K1", "K2", "K3", "K4", "K5", "K6"},
        {"K7", "M8", "M9", "M10", "M11", "M19"},
    };
    return rows;
}

bool isJogKey(const QString& key) { return key.startsWith(QLatin1String("JOG_")); }

} // namespace

KeyPad::KeyPad(Sink sink, QWidget* parent) : QWidget(parent), sink_(std::move(sink)) {
    setObjectName("keyPad");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(2, 2, 2, 2);
    column->setSpacing(3);
    auto* grid = new QGridLayout;
    grid->setSpacing(2);
    int row = 0;
    for (const QStringList& keys : keyRows()) {
        int col = 0;
        for (const QString& key : keys) {
            grid->addWidget(addKey(key, this), row, col++, 1, key == QLatin1String("RESET") ? 2 : 1);
        }
        ++row;
    }
    column->addLayout(grid, 3);
    wheel_ = new HandwheelWidget(sink_, this);
    wheel_->setMaximumHeight(210);
    column->addWidget(wheel_, 2);
    retranslate();
}

QPushButton* KeyPad::addKey(const QString& key, QWidget* parent) {
    auto* button = new QPushButton(parent);
    button->setObjectName(QStringLiteral("key_") + key);
    button->setFocusPolicy(Qt::NoFocus);
    button->setMinimumSize(40, 36);
    button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    if (isJogKey(key)) {
        // a jog key moves while it is held, as on the panel
        connect(button, &QPushButton::pressed, this, [this, key] { sink_(OperatorAction::keyDown(key)); });
        connect(button, &QPushButton::released, this, [this, key] { sink_(OperatorAction::keyUp(key)); });
    } else {
        connect(button, &QPushButton::clicked, this, [this, key] { sink_(OperatorAction::key(key)); });
    }
    buttons_.insert(key, button);
    return button;
}

void KeyPad::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
    }
    QWidget::changeEvent(event);
}

void KeyPad::retranslate() {
    const QMap<QString, QString> labels{
        {"MONITOR", tr("Monitor", "msg 300")}, {"PROGRAM", tr("Program", "msg 301")},
        {"PARAM", tr("Param", "msg 302")},     {"IO", tr("IO", "msg 303")},
        {"LOG", tr("Log")},  {"SYSTEM", tr("System")},
        {"MDI", tr("MDI")},                    {"PROBE", tr("Probe", "msg 313")},
        {"CONT_STEP_MPG", tr("CONT\nSTEP MPG")}, {"MPG_RUN", tr("MPG RUN")},
        {"HIGH_LOW", tr("Hi/Lo")},             {"STEP_INPUT", tr("Step...")},
        {"STEP_0.001", "0.001"},               {"STEP_0.01", "0.01"},
        {"STEP_0.1", "0.1"},                   {"STEP_1", "1"},
        {"EXT_START", tr("Ext START")},        {"ESTOP", tr("E-STOP")},
        {"START", tr("START")},                {"PAUSE", tr("PAUSE")},
        {"RESET", tr("RESET")},                {"FRO_100", tr("FRO\n100%")},
        {"FRO_UP", tr("FRO\n+10%")},            {"FRO_DOWN", tr("FRO\n-10%")},
        {"SRO_100", tr("SRO\n100%")},           {"SRO_UP", tr("SRO\n+10%")},
        {"SRO_DOWN", tr("SRO\n-10%")},          {"SPINDLE", tr("Spindle")},
    }; // the others (M3, K1 ...) are labelled with their names
    for (auto it = buttons_.begin(); it != buttons_.end(); ++it) {
        QString key = it.key();
        if (isJogKey(key)) {
            QString axis = key.mid(4, 1);
            axis = axis == QLatin1String("A") ? QStringLiteral("4th") : axis == QLatin1String("B") ? QStringLiteral("5th") : axis;
            it.value()->setText(axis + key.right(1));
        } else {
            it.value()->setText(labels.value(key, key));
        }
    }
    const QString later = tr("This page comes with the panel's part 2");
    for (auto it = pageKeys().begin(); it != pageKeys().end(); ++it) {
        bool there = availablePages_.contains(it.value());
        buttons_.value(it.key())->setEnabled(there);
        buttons_.value(it.key())->setToolTip(there ? QString() : later);
    }
}

void KeyPad::setAvailablePages(const QStringList& ids) {
    availablePages_ = ids;
    retranslate();
}

const QMap<QString, QString>& KeyPad::pageKeys() {
    static const QMap<QString, QString> keys{{"MONITOR", "monitor"}, {"PROGRAM", "program"}, {"PARAM", "param"},
                                             {"IO", "io"},           {"LOG", "log"},         {"SYSTEM", "system"},
                                             {"MDI", "mdi"},         {"PROBE", "probe"}};
    return keys;
}

const QStringList& KeyPad::mCodeKeys() {
    static const QStringList keys{"M3", "M4", "M5", "M8", "M9", "M10", "M11", "M19"};
    return keys;
}

const QStringList& KeyPad::userKeys() {
    static const QStringList keys{"K1", "K2", "K3", "K4", "K5", "K6", "K7"};
    return keys;
}

void KeyPad::render(const PanelSnapshot& snapshot) {
    const controller::PanelStatus& s = snapshot.status;
    auto lamp = [this](const char* key, bool on) {
        QPushButton* b = buttons_.value(key);
        if (b->property("lamp").toBool() != on) {
            b->setProperty("lamp", on);
            b->setStyleSheet({}); // re-polish for the lamp property
        }
    };
    lamp("MPG_RUN", s.guide);
    lamp("START", s.run == controller::PanelStatus::Run::Running);
    lamp("PAUSE", s.run == controller::PanelStatus::Run::Hold);
    lamp("SPINDLE", s.spindle != machine::SpindleState::Stop);
    lamp("HIGH_LOW", s.jogHighSpeed);
    lamp("CONT_STEP_MPG", true);
    for (const char* step : {"STEP_0.001", "STEP_0.01", "STEP_0.1", "STEP_1"}) {
        double value = QString::fromLatin1(step).mid(5).toDouble();
        lamp(step, std::abs(s.jogStep - value) < 1e-9);
    }
    for (int axis = 3; axis < machine::kAxisCount; ++axis) {
        QString name = QStringLiteral("JOG_") + QChar("XYZAB"[axis]);
        buttons_.value(name + "+")->setEnabled(s.axisShown[static_cast<std::size_t>(axis)]);
        buttons_.value(name + "-")->setEnabled(s.axisShown[static_cast<std::size_t>(axis)]);
    }
    wheel_->render(snapshot);
}

} // namespace m350::ui
