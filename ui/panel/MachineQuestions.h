#pragma once

#include "ui/session/PanelSnapshot.h"

#include <string>

namespace m350::ui {

class MachineSession;
class PanelContext;
class PromptBox;

// What the machine asks the operator through the panel's question box, each once for the moment
// that raises it: a macro's #1505 dialog, the tool in the spindle after a stop in a change (msg
// 883), the password a refused parameter write needs, and the homing question after power-on
// (msg 140). It keeps which of them it has asked.
class MachineQuestions {
public:
    MachineQuestions(MachineSession& session, PanelContext& context, PromptBox& prompt)
        : session_(session), context_(context), prompt_(prompt) {}

    void ask(const PanelSnapshot& snapshot);

private:
    void macroDialog(const PanelSnapshot& s);
    void toolNumber(const PanelSnapshot& s);
    void rights(const PanelSnapshot& s);
    void homing(const PanelSnapshot& s);
    bool firstAskedAt(const Alarm& alarm, std::string& askedAt) const;

    MachineSession& session_;
    PanelContext& context_;
    PromptBox& prompt_;
    std::string dialogShown_;
    std::string toolPromptAlarm_;   // the alarm the tool number prompt was last asked at
    std::string rightsPromptAlarm_; // the parameter write refused that the password was last asked at
    bool homingAsked_ = false;
};

} // namespace m350::ui
