// The tool table side of the session: the page's edits, an imported tool.tbl, touch off, and
// keeping the machine folder's tool.tbl in step with the tool data however it changed; likewise
// the tool life data (toollife.txt) and its view.
#include "ui/session/SessionWorker.h"

#include "core/controller/Controller.h"
#include "core/controller/ToolTableSave.h"
#include "core/tools/ToolData.h"
#include "ui/i18n/AlarmText.h"
#include "ui/i18n/Language.h"

namespace m350::ui {

void SessionWorker::putTool(const tools::ToolEntry& entry) {
    lastError_.clear();
    Message why;
    if (!controller_->toolTableEdits().putTool(entry, &why)) {
        refuse(QString::fromStdString(why.in(Language::messageLanguage())));
        return;
    }
    log_->record("tool_table", QStringLiteral("T%1").arg(entry.tool));
    publish();
}

void SessionWorker::removeTool(int tool) {
    lastError_.clear();
    Message why;
    if (!controller_->toolTableEdits().removeTool(tool, &why)) {
        refuse(QString::fromStdString(why.in(Language::messageLanguage())));
        return;
    }
    log_->record("tool_table", QStringLiteral("T%1 -").arg(tool));
    publish();
}

void SessionWorker::replaceToolTable(const tools::ToolTable& table, const QString& from) {
    lastError_.clear();
    Message why;
    if (!controller_->toolTableEdits().replaceTable(table, &why)) {
        refuse(QString::fromStdString(why.in(Language::messageLanguage())));
        return;
    }
    log_->record("tool_table", from);
    publish();
}

void SessionWorker::touchOffTool(double workZ) {
    lastError_.clear();
    // on the M350 the tool's Z is a parameter (930+): the level the Param page asks for it
    const int tool = controller_->panelStatus().tool;
    const params::ParameterTable& parameters = controller_->config().parameters;
    if (const std::optional<int> z = controller_->dialect().id == gcode::DialectId::M350
                                         ? tools::m350ZParameter(tool, parameters)
                                         : std::nullopt) {
        if (auto refused = controller::ParameterWrites::refusal(*z, userLevel_)) {
            refuse(AlarmText::message(Alarm::of(AlarmCode::RightsLimited, *refused)));
            return;
        }
        controller_->notePanelWrite(*z);
    }
    Message why;
    if (!controller_->toolTableEdits().touchOffTool(workZ, &why)) {
        refuse(QString::fromStdString(why.in(Language::messageLanguage())));
        return;
    }
    log_->record("touch_off", QStringLiteral("T%1 Z = %2").arg(controller_->panelStatus().tool).arg(workZ, 0, 'f', 3));
    publish();
}

void SessionWorker::resetToolLife(int group) {
    lastError_.clear();
    Message why;
    if (!controller_->toolLife().resetGroup(group, &why)) {
        refuse(QString::fromStdString(why.in(Language::messageLanguage())));
        return;
    }
    log_->record("tool_life_reset", QStringLiteral("P%1").arg(group)); // the group as G10 L3 names it
    publish();
}

} // namespace m350::ui
