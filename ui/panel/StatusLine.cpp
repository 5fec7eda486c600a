#include "ui/panel/StatusLine.h"

#include "ui/panel/PanelMode.h"
#include "ui/session/UserAccess.h"
#include "ui/widgets/MeasuredLabel.h"

#include <QDateTime>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>

#include <cstring>

namespace m350::ui {

namespace {

QLabel* field(QWidget* parent, const char* name, int minimumWidth) {
    auto* label = new MeasuredLabel(parent);
    label->setObjectName(name);
    label->setMinimumWidth(minimumWidth);
    label->setAlignment(Qt::AlignCenter);
    return label;
}

} // namespace

StatusLine::StatusLine(QWidget* parent) : QWidget(parent) {
    setObjectName("statusLine");
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->setSpacing(4);
    mode_ = field(this, "modeField", 64);
    state_ = field(this, "stateField", 64);
    file_ = field(this, "fileField", 120);
    file_->setAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    page_ = field(this, "pageField", 90);
    level_ = field(this, "levelField", 64);
    clock_ = field(this, "clockField", 150);
    layout->addWidget(mode_);
    layout->addWidget(state_);
    layout->addWidget(file_, 1);
    layout->addWidget(page_);
    layout->addWidget(level_);
    layout->addWidget(clock_);
}

void StatusLine::render(const PanelSnapshot& snapshot, const QString& pageId, const QString& pageTitle) {
    PanelText::State state = displayedState(snapshot);
    mode_->setText(PanelText::mode(displayedMode(snapshot, pageId)));
    state_->setText(PanelText::state(state));
    const char* level = state == PanelText::State::Error || state == PanelText::State::Alarm ? "bad"
                        : state == PanelText::State::Ready                                  ? "ok"
                                                                                            : "busy";
    if (!stateLevel_ || std::strcmp(level, stateLevel_) != 0) { // a re-polish costs more than the rest of the line
        stateLevel_ = level;
        state_->setProperty("level", level);
        state_->setStyleSheet({}); // re-polish for the property
    }
    QString file = snapshot.status.mdi ? QStringLiteral("MDI") : QFileInfo(snapshot.programFile).fileName();
    file_->setText(file);
    page_->setText(pageTitle);
    level_->setText(UserAccess::levelName(snapshot.userLevel));
    // the local time once a second: its conversion asks the time zone file each time
    if (const qint64 second = QDateTime::currentSecsSinceEpoch(); second != clockSecond_) {
        clockSecond_ = second;
        clock_->setText(QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")));
    }
}

QString StatusLine::modeText() const { return mode_->text(); }
QString StatusLine::stateText() const { return state_->text(); }
QString StatusLine::levelText() const { return level_->text(); }

} // namespace m350::ui
