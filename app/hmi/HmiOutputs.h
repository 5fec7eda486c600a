#pragma once

#include "app/hmi/HmiOptions.h"

#include <QByteArray>
#include <QString>

#include <optional>
#include <string>

namespace m350::hmi {

// The panel's own outputs (--state, --screenshot, --record) never land on what it reads or owns
// (issue 26, "Nothing lost"): the loaded program, the replay being played, anything inside the
// machine folder; nor on a folder, a socket or a disk; nor two on one file; a screenshot's suffix
// is an image format. Why one is refused (naming the option, the path and why), else nullopt.
// Asked before the panel starts, so a refused run writes nothing.
std::optional<QString> refusedOutput(const HmiOptions& o, const QString& machineFolder);

// The image format --screenshot writes: its suffix's (.png, .jpg ...), PNG for a name without one
// or a device; nullopt for a suffix that is no image format (`--screenshot notes.txt`).
std::optional<QByteArray> screenshotFormat(const std::string& path);

// Writes `bytes` whole (a temp file renamed over a regular file) or into a device as one; why
// not (naming the file), else nullopt.
std::optional<QString> writeOutput(const std::string& path, const QByteArray& bytes);

} // namespace m350::hmi
