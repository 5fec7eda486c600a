#pragma once

#include "ui/actions/OperatorAction.h"
#include "ui/replay/Replay.h"
#include "ui/session/PanelSnapshot.h"

#include <QString>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace m350::ui {

class MainWindow;
class MachineSession;

// A recorded attempt played again under a trainer's hand (the review): time passes in the frames
// playReplay gives it (at most 1/60 s, the last one ending on the next action's `t`), so however
// the trainer splits it (speeds, pauses, steps), the machine sees the same frames and the same
// actions at the same moments as the headless grader's and ends as it does. The actions (the
// exercise's faults among them: injectFaults) go through the panel's dispatcher.
class ReviewPlayback {
public:
    // `actions` end with the hand-in's time (a time mark when the attempt's last action is earlier).
    ReviewPlayback(MainWindow& window, MachineSession& session, std::vector<OperatorAction> actions,
                   std::vector<ReplayPlace> places, QString path);

    double now() const { return now_; }
    double end() const { return actions_.empty() ? 0.0 : actions_.back().t; }
    bool finished() const { return next_ >= actions_.size() || !error_.isEmpty(); }
    // The action still to come (null: none), and how many were played.
    const OperatorAction* nextAction() const { return next_ < actions_.size() ? &actions_[next_] : nullptr; }
    std::size_t played() const { return next_; }
    // Why the review stopped short (a `load` a replay may not do, at file:line:column), else empty.
    const QString& error() const { return error_; }

    // Lets up to `seconds` of the attempt's time pass, each action played when its time comes; a
    // frame that does not fit waits for the next call. Returns the time that passed.
    double play(double seconds);
    // One block: frames pass until the block the controller executes changes (or the attempt
    // ends). True when it changed.
    bool stepBlock();

    // The block the controller executes: file, line and how many blocks the run has executed.
    struct Block {
        std::string file;
        std::uint32_t line = 0;
        std::uint64_t blocks = 0;
        bool operator==(const Block&) const = default;
    };
    static Block blockOf(const PanelSnapshot& snapshot);
    Block block() const;

private:
    // Frames up to `budget` s; `stop` (when given) is asked after every frame and action.
    double run(double budget, const std::function<bool()>& stop);
    void playNext();

    MainWindow& window_;
    MachineSession& session_;
    std::vector<OperatorAction> actions_;
    std::vector<ReplayPlace> places_;
    QString path_;
    std::size_t next_ = 0;
    double now_ = 0.0;
    double owed_ = 0.0; // time asked for that did not make a whole frame yet
    QString error_;
};

} // namespace m350::ui
