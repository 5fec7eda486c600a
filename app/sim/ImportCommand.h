#pragma once

#include "core/common/Message.h"

#include <string>

namespace m350::sim {

// `m350-sim import BACKUP_DIR --into MACHINE_DIR`: makes a machine folder from a copy of an M350's
// system disk (core/backup/BackupImport). The report goes to stderr and import-report.txt in
// `language`, one JSON object to stdout (its texts in English, for scripts):
// status, alarm (the error, as the other commands give it), what was written, copied and skipped,
// what to review, what the simulator cannot model. Exit status 0, or 2 for a damaged or missing
// backup, a machine folder that is not empty, or a failed write (nothing is written then).
int runImport(const std::string& backupDir, const std::string& intoDir, MessageLanguage language);

} // namespace m350::sim
