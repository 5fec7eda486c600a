#include "ui/panel/MachineQuestions.h"

#include "core/controller/ParameterWrites.h"
#include "ui/i18n/AlarmText.h"
#include "ui/pages/LevelPrompt.h"
#include "ui/pages/PanelContext.h"
#include "ui/panel/PromptBox.h"
#include "ui/session/MachineSession.h"

#include <QCoreApplication>

namespace m350::ui {

void MachineQuestions::ask(const PanelSnapshot& s) {
    macroDialog(s);
    toolNumber(s);
    rights(s);
    homing(s);
}

// Whether a question not yet asked at `alarm` (its message and line, kept in `askedAt`) may be
// asked now, the question box being free; it counts as asked from here on.
bool MachineQuestions::firstAskedAt(const Alarm& alarm, std::string& askedAt) const {
    const std::string at = alarm.message + ":" + std::to_string(alarm.line);
    if (at == askedAt || prompt_.active()) {
        return false;
    }
    askedAt = at;
    return true;
}

// A macro's #1505 dialog: the run waits until the operator answers it.
void MachineQuestions::macroDialog(const PanelSnapshot& s) {
    if (!s.status.dialog) {
        dialogShown_.clear();
        return;
    }
    if (*s.status.dialog == dialogShown_ && prompt_.active()) {
        return;
    }
    dialogShown_ = *s.status.dialog;
    prompt_.ask(QString::fromStdString(*s.status.dialog), false, {},
                [this](std::optional<QString> answer) { session_.answerDialog(answer.has_value()); });
}

// After a stop in a change the controller does not know the spindle's tool: at the E-stop, and
// again at each change it refuses, the operator is asked to enter it (the firmware's msg 883).
void MachineQuestions::toolNumber(const PanelSnapshot& s) {
    if (!s.status.toolUnsure || !s.status.alarm) {
        toolPromptAlarm_.clear();
        return;
    }
    if (!firstAskedAt(*s.status.alarm, toolPromptAlarm_)) {
        return;
    }
    const QString question = AlarmText::message(*s.status.toolUnsure) + QStringLiteral("\n") +
                             QCoreApplication::translate("m350::ui::MainWindow", "Set target tool No.:", "msg 883");
    prompt_.ask(question, true, QString::number(s.status.tool), [this](std::optional<QString> answer) {
        bool number = false;
        const int tool = answer ? answer->trimmed().toInt(&number) : -1;
        if (number && tool >= 0) {
            session_.setSpindleToolNumber(tool);
        }
    });
}

// The operator's MDI line or program wrote a parameter above the user level: the run stopped with
// the refusal, and the password of the level it needs is asked as the Param page asks it.
void MachineQuestions::rights(const PanelSnapshot& s) {
    if (!s.status.alarm || s.status.alarm->code != AlarmCode::RightsLimited || s.status.alarm->messageArguments.empty()) {
        rightsPromptAlarm_.clear();
        return;
    }
    if (!firstAskedAt(*s.status.alarm, rightsPromptAlarm_)) {
        return;
    }
    const int parameter = QString::fromStdString(s.status.alarm->messageArguments.front()).toInt();
    LevelPrompt::require(context_, controller::ParameterWrites::required(parameter), {});
}

// After power-on (sysstart.nc) the panel asks once whether to home every axis.
void MachineQuestions::homing(const PanelSnapshot& s) {
    if (!s.homingPrompt || homingAsked_) {
        return;
    }
    homingAsked_ = true;
    // the words keep the translations' MainWindow context, where the panel has always had them
    context_.ask(QCoreApplication::translate("m350::ui::MainWindow", "Go to home?", "msg 140"), [this](bool yes) {
        if (yes) {
            session_.home({});
        }
    });
}

} // namespace m350::ui
