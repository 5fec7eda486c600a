#pragma once

#include <QString>

namespace m350::ui {

class Page;
class PanelPrompt;

// What the panel offers the dispatcher: its pages, its softkeys, its question box, its language
// and the step-distance question of the STEP_INPUT key. MainWindow is the panel that implements it;
// the dispatcher needs no more of the window than this.
class PanelScreen {
public:
    virtual bool showPage(const QString& id) = 0; // false: no such page
    virtual Page* currentPage() const = 0;
    virtual void pressSoftkey(int number) = 0; // 1-12
    virtual PanelPrompt* prompt() const = 0;
    virtual void setLanguage(const QString& language) = 0;
    virtual void askJogStep() = 0;
    // The handwheel's switches: axis 0..4, or step 1 10 100; -1 leaves that switch as it is.
    virtual void switchWheel(int axis, int step) = 0;

protected:
    ~PanelScreen() = default;
};

} // namespace m350::ui
