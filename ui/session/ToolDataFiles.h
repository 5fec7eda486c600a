#pragma once

#include "core/tools/ToolData.h"
#include "core/tools/ToolLifeView.h"

#include <QString>

#include "core/common/Message.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

namespace m350::config {
class MachineFolder;
}
namespace m350::controller {
class ToolTableEdits;
}
namespace m350::tools {
class ToolLifeManager;
}

namespace m350::ui {

// The tool data as the snapshots show it and as the machine folder keeps it: every change of the
// tool table (the tool pages' edits, G10 L1, a macro's #1430, the Param page's 930) is saved to
// tool.tbl, every change of the tool life counts to toollife.txt, before the next snapshot. A
// save that failed is said, and tried again only when the data changes again, not at every frame.
class ToolDataFiles {
public:
    // The table's save (controller::saveToolTable: with the parameters params.toml lists).
    using SaveTable = std::function<std::optional<Message>()>;

    // Saves what changed since the last call and makes new views of it.
    void keep(const controller::ToolTableEdits& table, const SaveTable& saveTable, tools::ToolLifeManager& life,
              const config::MachineFolder& folder);

    std::shared_ptr<const tools::ToolTable> table() const { return table_; }
    const QString& tableProblem() const { return tableProblem_; } // why tool.tbl was not saved
    std::shared_ptr<const tools::LifeView> life() const { return life_; }
    const QString& lifeProblem() const { return lifeProblem_; } // why toollife.txt was not saved

private:
    void keepTable(const controller::ToolTableEdits& table, const SaveTable& saveTable, const config::MachineFolder& folder);
    void keepLife(tools::ToolLifeManager& life, const config::MachineFolder& folder);

    std::shared_ptr<const tools::ToolTable> table_;
    std::optional<tools::ToolData::Mark> shownTableMark_;
    std::optional<tools::ToolData::Mark> failedTableMark_;
    QString tableProblem_;
    std::shared_ptr<const tools::LifeView> life_;
    std::optional<std::uint64_t> shownLifeRevision_;
    std::optional<std::uint64_t> failedLifeRevision_;
    QString lifeProblem_;
};

} // namespace m350::ui
