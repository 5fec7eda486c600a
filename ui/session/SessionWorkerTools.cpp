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

// A save that failed is tried again when the data changes again, not at every frame.
void SessionWorker::keepToolTable() {
    const tools::ToolData::Mark mark = controller_->toolTableEdits().mark();
    if (!folder_.path().empty() && controller_->toolTableEdits().changed() && !(failedToolMark_ && *failedToolMark_ == mark)) {
        if (auto error = controller::saveToolTable(*controller_, folder_)) {
            toolTableProblem_ = QString::fromStdString(error->in(Language::messageLanguage()));
            failedToolMark_ = mark;
        } else {
            toolTableProblem_.clear();
            failedToolMark_.reset();
        }
    }
    if (!shownToolMark_ || !(*shownToolMark_ == mark)) {
        toolTable_ = std::make_shared<const tools::ToolTable>(controller_->toolTableEdits().table());
        shownToolMark_ = mark;
    }
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

// Counting changes the data every 4 s of cutting: a save that failed is tried again only when
// the data changed since.
void SessionWorker::keepToolLife() {
    tools::ToolLifeManager& life = controller_->toolLife().manager();
    const std::uint64_t revision = life.revision();
    if (!folder_.path().empty() && life.changed() && failedLifeRevision_ != revision) {
        if (auto error = folder_.saveToolLife(life.data())) {
            toolLifeProblem_ = QString::fromStdString(error->in(Language::messageLanguage()));
            failedLifeRevision_ = revision;
        } else {
            toolLifeProblem_.clear();
            failedLifeRevision_.reset();
            life.markSaved();
        }
    }
    if (shownLifeRevision_ != revision) {
        toolLife_ = std::make_shared<const tools::LifeView>(tools::makeLifeView(life));
        shownLifeRevision_ = revision;
    }
}

} // namespace m350::ui
