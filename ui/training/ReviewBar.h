#pragma once

#include <QString>
#include <QWidget>

#include <array>

class QKeyEvent;
class QLabel;
class QPushButton;
class QTimer;

namespace m350::ui {

struct OperatorAction;
class ReviewPlayback;

// The trainer's review bar under the panel: the attempt's time, the action to come, play/pause,
// one block at a time, the speed (1x-50x) and which view the review shows. It owns the playback's
// pace: while playing, a 60 Hz timer lets speed/60 s of the attempt pass each tick. Its keys keep
// clear of the panel's (F1-F6 softkeys, F7 training, F9-F12 the cycle keys): Space play/pause,
// '.' one block, '+' / '-' the speed, F8 the view.
class ReviewBar : public QWidget {
    Q_OBJECT
public:
    static constexpr std::array<int, 6> kSpeeds{1, 2, 5, 10, 20, 50};
    static constexpr int kTickMs = 16; // ~60 Hz

    explicit ReviewBar(ReviewPlayback& playback, QWidget* parent = nullptr);

    // One tick of the timer: speed/60 s of the attempt (what the timer calls; tests call it too).
    void tick();
    void setPlaying(bool playing);
    void togglePlay() { setPlaying(!playing_); }
    bool playing() const { return playing_; }
    // One block (pauses first).
    void step();
    int speed() const { return kSpeeds[static_cast<std::size_t>(speedIndex_)]; }
    void setSpeed(int speed); // one of kSpeeds (else the nearest below)
    void faster();
    void slower();
    // The review's keys (Space . + = - F8): true when the key was one of them.
    bool key(const QKeyEvent& event);
    // The name of the view shown, on the view button.
    void setViewName(const QString& name);
    // What the bar says once the attempt has played to its end (the verdict), instead of the next action.
    void setEndText(const QString& text);

    QString timeText() const;
    QString nextText() const;
    QTimer* timer() const { return timer_; }
    void retranslate();

    // What an action does, in the panel's language ("F1", "key MDI", "types \"T2\"", "fault IN11 stuck").
    static QString describe(const OperatorAction& action);

signals:
    void played();        // time passed or a block was stepped: the views follow
    void viewRequested(); // F8 or the view button

protected:
    void changeEvent(QEvent* event) override;

private:
    ReviewPlayback& playback_;
    QTimer* timer_;
    QPushButton* play_;
    QPushButton* step_;
    QPushButton* slower_;
    QPushButton* faster_;
    QPushButton* view_;
    QLabel* speed_;
    QLabel* time_;
    QLabel* next_;
    int speedIndex_ = 0;
    bool playing_ = false;
    QString viewName_;
    QString endText_;
};

} // namespace m350::ui
