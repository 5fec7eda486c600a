#include "ui/session/ToolDataFiles.h"

#include "ui/i18n/Language.h"

#include "core/config/MachineFolder.h"
#include "core/controller/ToolTableEdits.h"
#include "core/tools/ToolLifeManager.h"

namespace m350::ui {

void ToolDataFiles::keep(const controller::ToolTableEdits& table, const SaveTable& saveTable, tools::ToolLifeManager& life,
                         const config::MachineFolder& folder) {
    keepTable(table, saveTable, folder);
    keepLife(life, folder);
}

void ToolDataFiles::keepTable(const controller::ToolTableEdits& table, const SaveTable& saveTable,
                              const config::MachineFolder& folder) {
    const tools::ToolData::Mark mark = table.mark();
    if (!folder.path().empty() && table.changed() && !(failedTableMark_ && *failedTableMark_ == mark)) {
        if (auto error = saveTable()) {
            tableProblem_ = QString::fromStdString(error->in(Language::messageLanguage()));
            failedTableMark_ = mark;
        } else {
            tableProblem_.clear();
            failedTableMark_.reset();
        }
    }
    if (!shownTableMark_ || !(*shownTableMark_ == mark)) {
        table_ = std::make_shared<const tools::ToolTable>(table.table());
        shownTableMark_ = mark;
    }
}

// Counting changes the data every 4 s of cutting.
void ToolDataFiles::keepLife(tools::ToolLifeManager& life, const config::MachineFolder& folder) {
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
