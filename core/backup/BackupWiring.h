#pragma once

#include "core/common/Message.h"
#include "core/params/ParameterTable.h"

#include <string>
#include <vector>

namespace m350::backup {

// A value the import had to state because no file of the backup gives it: the machine.toml key,
// the value written (may hold words: bilingual, said with argumentIn) and why it needs the owner's eye.
struct ReviewItem {
    std::string key;
    std::string value;
    Message why;
};

// What the import makes of a backup's magazine (param 802 and its geometry) and IO wiring (the
// IO page's triples): the [magazine] table when one of our devices models it, the [[io_links]]
// that let sensors follow their actuators where no device does, and plain statements of what the
// simulator cannot model. Nothing here stops an import: a machine without a magazine device
// still jogs, homes, probes and runs programs.
struct ImportedWiring {
    std::string magazineToml; // "[magazine]\n..." or empty
    std::string linksToml;    // "[[io_links]]\n..." tables, or empty
    Message magazine;         // one line: the type and what became of it
    std::vector<ReviewItem> review;
    std::vector<Message> unsupported;
};

ImportedWiring importWiring(const params::ParameterTable& parameters);

} // namespace m350::backup
