#pragma once

#include "core/common/Message.h"

#include <string>

namespace m350::sim {

// `m350-sim reset-passwords --config FOLDER`: the explicit repair of a passwords.toml the panel
// cannot trust (config/PasswordsFile.h). The file is written anew with no level, so every level
// opens with its published default again, and the folder's System Log says so. What it did on
// stderr (in `language`) and one JSON object on stdout (status, passwords: the file, message,
// message_id); exit status 0, or 2 when the file cannot be written (alarm file_error).
int runResetPasswords(const std::string& folder, MessageLanguage language);

} // namespace m350::sim
