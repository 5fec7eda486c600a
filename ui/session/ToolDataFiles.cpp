#include "ui/session/ToolDataFiles.h"

#include "ui/i18n/Language.h"

#include "core/config/MachineFolder.h"
#include "core/controller/Controller.h"
#include "core/controller/ToolTableSave.h"

namespace m350::ui {

void ToolDataFiles::keep(controller::Controller& controller, const config::MachineFolder& folder) {
    keepTable(controller, folder);
    keepLife(controller, folder);
}

void ToolDataFiles::keepTable(controller::Controller& controller, const config::MachineFolder& folder) {
    const tools::ToolData::Mark mark = controller.toolTableEdits().mark();
    if (!folder.path().empty() && controller.toolTableEdits().changed() && !(failedTableMark_ && *failedTableMark_ == mark)) {
        if (auto error = controller::saveToolTable(controller, folder)) {
            tableProblem_ = QString::fromStdString(error->in(Language::messageLanguage()));
            failedTableMark_ = mark;
        } else {
            tableProblem_.clear();
            failedTableMark_.reset();
        }
    }
    if (!shownTableMark_ || !(*shownTableMark_ == mark)) {
        table_ = std::make_shared<const tools::ToolTable>(controller.toolTableEdits().table());
        shownTableMark_ = mark;
    }
}

// Counting changes the data every 4 s of cutting.
void ToolDataFiles::keepLife(controller::Controller& controller, const config::MachineFolder& folder) {
    tools::ToolLifeManager& life = controller.toolLife().manager();
    const std::uint64_t revision = life.revision();
    if (!folder.path().empty() && life.changed() && failedLifeRevision_ != revision) {
        if (auto error = folder.saveToolLife(life.data())) {
            lifeProblem_ = QString::fromStdString(error->in(Language::messageLanguage()));
            failedLifeRevision_ = revision;
        } else {
            lifeProblem_.clear();
            failedLifeRevision_.reset();
            life.markSaved();
        }
    }
    if (shownLifeRevision_ != revision) {
        life_ = std::make_shared<const tools::LifeView>(tools::makeLifeView(life));
        shownLifeRevision_ = revision;
    }
}

} // namespace m350::ui
