#pragma once

#include "ui/session/PanelSnapshot.h"

#include <QWidget>

class QLabel;

namespace m350::ui {

// The top line of the screen: mode, state, the loaded file, the page's name, the user level, date
// and time.
class StatusLine : public QWidget {
    Q_OBJECT
public:
    explicit StatusLine(QWidget* parent = nullptr);
    void render(const PanelSnapshot& snapshot, const QString& pageId, const QString& pageTitle);
    QString modeText() const;
    QString stateText() const;
    QString levelText() const;

private:
    QLabel* mode_;
    QLabel* state_;
    const char* stateLevel_ = nullptr; // the "level" property state_ was last polished with
    QLabel* file_;
    QLabel* page_;
    QLabel* level_; // 访客 / 操作员 / 管理员 / 超级管理
    QLabel* clock_;
    qint64 clockSecond_ = -1; // the second the clock shows
};

} // namespace m350::ui
