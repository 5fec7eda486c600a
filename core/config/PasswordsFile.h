#pragma once

#include "core/common/Message.h"
#include "core/config/MachineFolder.h"
#include "core/params/ParameterPages.h"

#include <array>
#include <optional>
#include <string>
#include <variant>

namespace m350::config {

// passwords.toml, the panel's 密码设置: one line per level whose password was changed,
// `operator = "SALT:HASH"` (hex, either case; PBKDF2-HMAC-SHA256, hashed by the panel). A level
// the file does not name opens with its published default; a level it names never does.
struct StoredPassword {
    std::string salt; // bytes
    std::string hash; // bytes, kHashBytes of them
};

struct Passwords {
    static constexpr std::size_t kHashBytes = 32; // SHA-256
    std::array<std::optional<StoredPassword>, 4> levels{}; // by params::UserLevel; Guest's stays empty
    // The level's key in the file ("operator", "admin", "super"); nullptr for Guest.
    static const char* key(params::UserLevel level);
};

// Why passwords.toml cannot be trusted: not a regular file (a folder, FIFO, device, a link to
// one), larger than a machine file can be, not TOML, or a line that is not a level with a salt and
// a hash. The panel then opens no level above Guest until the file is repaired (README).
struct PasswordsProblem {
    Message message; // "FILE:LINE:COL: why" or "FILE: why", by id
};

// The folder's passwords.toml read through files::parseTomlFile (the machine folder's regular-file
// and size check): Passwords (every level at its default when there is no file), or the problem.
std::variant<Passwords, PasswordsProblem> readPasswords(const MachineFolder& folder);

// The file's text for `passwords`.
std::string formatPasswords(const Passwords& passwords);

// The explicit reset (`m350-sim reset-passwords`): passwords.toml written anew with no level, so
// every level opens with its default password again. nullopt on success, else why.
std::optional<Message> resetPasswords(const MachineFolder& folder);

} // namespace m350::config
