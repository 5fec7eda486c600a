#include "ui/panel/KeyPad.h"

#include "ui/i18n/PanelText.h"
#include "ui/panel/HandwheelWidget.h"

#include <QEvent>
#include <QGridLayout>
#include <QPushButton>
#include <QVBoxLayout>

#include <cmath>

namespace m350::ui {

namespace {

bool lampOn(const PanelKey& key, const controller::PanelStatus& s) {
    using Lamp = PanelKey::Lamp;
    switch (key.lamp) {
    case Lamp::None: return false;
    case Lamp::Always: return true;
    case Lamp::Running: return s.run == controller::PanelStatus::Run::Running;
    case Lamp::Hold: return s.run == controller::PanelStatus::Run::Hold;
    case Lamp::Spindle: return s.spindle != machine::SpindleState::Stop;
    case Lamp::Guide: return s.guide;
    case Lamp::JogHighSpeed: return s.jogHighSpeed;
    case Lamp::JogStep: return std::abs(s.jogStep - key.argument) < 1e-9;
    }
    return false;
}

} // namespace

KeyPad::KeyPad(Sink sink, QWidget* parent) : QWidget(parent), sink_(std::move(sink)) {
    setObjectName("keyPad");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(2, 2, 2, 2);
    column->setSpacing(3);
    auto* grid = new QGridLayout;
    grid->setSpacing(2);
    for (const PanelKey& key : PanelKey::all()) {
        if (key.place.row >= 0) {
            grid->addWidget(addKey(key), key.place.row, key.place.column, 1, key.place.width);
        }
    }
    column->addLayout(grid, 3);
    wheel_ = new HandwheelWidget(sink_, this);
    wheel_->setMaximumHeight(210);
    column->addWidget(wheel_, 2);
    retranslate();
}

QPushButton* KeyPad::addKey(const PanelKey& key) {
    auto* button = new QPushButton(this);
    button->setObjectName(QStringLiteral("key_") + key.name);
    button->setFocusPolicy(Qt::NoFocus);
    button->setMinimumSize(40, 36);
    button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    const QString name = key.name;
    if (key.role == PanelKey::Role::Jog) {
        // a jog key moves while it is held, as on the panel
        connect(button, &QPushButton::pressed, this, [this, name] { sink_(OperatorAction::keyDown(name)); });
        connect(button, &QPushButton::released, this, [this, name] { sink_(OperatorAction::keyUp(name)); });
    } else {
        connect(button, &QPushButton::clicked, this, [this, name] { sink_(OperatorAction::key(name)); });
    }
    buttons_.insert(name, button);
    shown_.push_back({&key, button, false});
    return button;
}

void KeyPad::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
    }
    QWidget::changeEvent(event);
}

void KeyPad::retranslate() {
    for (const PanelKey& key : PanelKey::all()) {
        if (QPushButton* button = buttons_.value(key.name)) {
            button->setText(key.label.source ? tr(key.label.source, key.label.comment)
                            : key.caption.isEmpty() ? key.name
                                                    : QString(key.caption));
        }
    }
}

void KeyPad::render(const PanelSnapshot& snapshot) {
    const controller::PanelStatus& s = snapshot.status;
    for (Shown& shown : shown_) {
        const PanelKey& key = *shown.key;
        QPushButton* button = shown.button;
        const bool on = lampOn(key, s);
        if (key.lamp != PanelKey::Lamp::None && shown.lamp != on) {
            shown.lamp = on;
            button->setProperty("lamp", on);
            button->setStyleSheet({}); // re-polish for the lamp property
        }
        if (key.role == PanelKey::Role::Jog && key.axis >= 3) {
            // the 4th and 5th keys move the axis the machine has there, under its name (A+, C-)
            const bool shown = s.axisShown[static_cast<std::size_t>(key.axis)];
            const QString text = shown ? PanelText::axis(key.axis, s) + QChar(key.direction > 0 ? '+' : '-')
                                       : QString(key.caption);
            if (button->text() != text) {
                button->setText(text);
            }
            button->setEnabled(shown);
        }
    }
    wheel_->render(snapshot);
}

} // namespace m350::ui
