#pragma once

#include <QString>

#include <optional>

namespace m350::ui {

// The panel writes into its machine folder (MDI lines, later parameters and offsets), so it never
// runs on the bundled folder itself: the desktop keeps its own copy of the default machine in
// the user's data folder, made on first start; a replay or a screenshot uses a throwaway copy.
std::optional<QString> copyBundledMachine(const QString& intoDirectory, QString* error);
std::optional<QString> userMachineFolder(QString* error);

} // namespace m350::ui
