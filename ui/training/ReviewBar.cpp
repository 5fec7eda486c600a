#include "ui/training/ReviewBar.h"

#include "ui/actions/OperatorAction.h"
#include "ui/training/ReviewPlayback.h"
#include "ui/widgets/MeasuredLabel.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QPushButton>
#include <QTimer>

#include <algorithm>

namespace m350::ui {

namespace {

QPushButton* reviewButton(QWidget* parent, const char* name) {
    auto* button = new QPushButton(parent);
    button->setObjectName(QLatin1String(name));
    button->setFocusPolicy(Qt::NoFocus); // Space stays the bar's key, never a button's click
    return button;
}

} // namespace

ReviewBar::ReviewBar(ReviewPlayback& playback, QWidget* parent) : QWidget(parent), playback_(playback) {
    setObjectName("reviewBar");
    setAttribute(Qt::WA_StyledBackground);
    timer_ = new QTimer(this);
    timer_->setInterval(kTickMs);
    connect(timer_, &QTimer::timeout, this, &ReviewBar::tick);
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(4, 2, 4, 2);
    row->setSpacing(4);
    play_ = reviewButton(this, "reviewPlay");
    step_ = reviewButton(this, "reviewStep");
    slower_ = reviewButton(this, "reviewSlower");
    faster_ = reviewButton(this, "reviewFaster");
    view_ = reviewButton(this, "reviewView");
    speed_ = new MeasuredLabel(this);
    speed_->setObjectName("reviewSpeed");
    speed_->setAlignment(Qt::AlignCenter);
    speed_->setMinimumWidth(speed_->fontMetrics().horizontalAdvance(QStringLiteral("50x ")));
    time_ = new MeasuredLabel(this);
    time_->setObjectName("reviewTime");
    next_ = new MeasuredLabel(this);
    next_->setObjectName("reviewNext");
    next_->setTextFormat(Qt::PlainText);
    next_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred); // a long text is cut, never widens the window
    row->addWidget(play_);
    row->addWidget(step_);
    row->addWidget(slower_);
    row->addWidget(speed_);
    row->addWidget(faster_);
    row->addWidget(time_);
    row->addWidget(next_, 1);
    row->addWidget(view_);
    connect(play_, &QPushButton::clicked, this, &ReviewBar::togglePlay);
    connect(step_, &QPushButton::clicked, this, &ReviewBar::step);
    connect(slower_, &QPushButton::clicked, this, &ReviewBar::slower);
    connect(faster_, &QPushButton::clicked, this, &ReviewBar::faster);
    connect(view_, &QPushButton::clicked, this, &ReviewBar::viewRequested);
    retranslate();
}

void ReviewBar::tick() {
    if (playback_.finished()) {
        setPlaying(false);
        return;
    }
    playback_.play(speed() / 60.0);
    if (playback_.finished()) {
        setPlaying(false);
    }
    retranslate();
    emit played();
}

void ReviewBar::setPlaying(bool playing) {
    playing = playing && !playback_.finished();
    if (playing == playing_) {
        return;
    }
    playing_ = playing;
    if (playing_) {
        timer_->start();
    } else {
        timer_->stop();
    }
    retranslate();
}

void ReviewBar::step() {
    setPlaying(false);
    if (playback_.finished()) {
        return;
    }
    playback_.stepBlock();
    retranslate();
    emit played();
}

void ReviewBar::setSpeed(int speed) {
    speedIndex_ = 0;
    for (std::size_t i = 0; i < kSpeeds.size(); ++i) {
        if (kSpeeds[i] <= speed) {
            speedIndex_ = static_cast<int>(i);
        }
    }
    retranslate();
}

void ReviewBar::faster() {
    speedIndex_ = std::min(speedIndex_ + 1, static_cast<int>(kSpeeds.size()) - 1);
    retranslate();
}

void ReviewBar::slower() {
    speedIndex_ = std::max(speedIndex_ - 1, 0);
    retranslate();
}

bool ReviewBar::key(const QKeyEvent& event) {
    if (event.modifiers() & (Qt::ControlModifier | Qt::AltModifier)) {
        return false; // Ctrl and Alt with + and - are the panel's overrides
    }
    switch (event.key()) {
    case Qt::Key_Space: togglePlay(); return true;
    case Qt::Key_Period: step(); return true;
    case Qt::Key_Plus:
    case Qt::Key_Equal: faster(); return true;
    case Qt::Key_Minus: slower(); return true;
    case Qt::Key_F8: emit viewRequested(); return true;
    default: return false;
    }
}

void ReviewBar::setViewName(const QString& name) {
    viewName_ = name;
    retranslate();
}

void ReviewBar::setEndText(const QString& text) {
    endText_ = text;
    retranslate();
}

QString ReviewBar::timeText() const {
    return tr("%1 / %2 s").arg(playback_.now(), 0, 'f', 1).arg(playback_.end(), 0, 'f', 1);
}

QString ReviewBar::nextText() const {
    if (!playback_.error().isEmpty()) {
        return playback_.error();
    }
    const OperatorAction* next = playback_.nextAction();
    if (!next) {
        return endText_.isEmpty() ? tr("End of the attempt") : endText_;
    }
    if (next->kind == OperatorAction::Kind::Wait && next->t >= playback_.end()) { // the time mark the hand-in adds
        return tr("Next: %1 s hand in").arg(next->t, 0, 'f', 1);
    }
    return tr("Next: %1 s %2").arg(next->t, 0, 'f', 1).arg(describe(*next));
}

QString ReviewBar::describe(const OperatorAction& action) {
    using Kind = OperatorAction::Kind;
    switch (action.kind) {
    case Kind::Key: return tr("key %1").arg(action.name);
    case Kind::KeyDown: return tr("key %1 held").arg(action.name);
    case Kind::KeyUp: return tr("key %1 let go").arg(action.name);
    case Kind::Softkey:
        return action.softkey > 6 ? QStringLiteral("Shift+F%1").arg(action.softkey - 6) : QStringLiteral("F%1").arg(action.softkey);
    case Kind::Text: return tr("types \"%1\"").arg(action.text);
    case Kind::Wheel: return tr("handwheel %1 detents").arg(action.wheel.detents);
    case Kind::Page: return tr("page %1").arg(action.name);
    case Kind::Force: return tr("fault IN%1 %2").arg(action.force.input).arg(action.force.fault);
    case Kind::Language: return tr("language %1").arg(action.name);
    case Kind::Load: return tr("load %1").arg(action.name);
    case Kind::Wait: return tr("time passes");
    }
    return {};
}

void ReviewBar::retranslate() {
    play_->setText(playing_ ? tr("Pause (Space)") : tr("Play (Space)"));
    step_->setText(tr("Block (.)"));
    slower_->setText(QStringLiteral("-"));
    faster_->setText(QStringLiteral("+"));
    speed_->setText(QStringLiteral("%1x").arg(speed()));
    view_->setText(tr("%1 (F8)").arg(viewName_));
    time_->setText(timeText());
    next_->setText(nextText());
}

void ReviewBar::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
    }
    QWidget::changeEvent(event);
}

} // namespace m350::ui
