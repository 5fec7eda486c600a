#include "core/config/PasswordsFile.h"

#include "core/files/Toml.h"

#include <filesystem>

namespace m350::config {

namespace fs = std::filesystem;

namespace {

std::string placeOf(const std::string& file, const toml::source_region& where) {
    return file + ":" + std::to_string(where.begin.line) + ":" + std::to_string(where.begin.column);
}

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// Hex text to bytes; nullopt for an odd length, an empty text or a character that is no digit.
std::optional<std::string> fromHex(std::string_view text) {
    if (text.empty() || text.size() % 2 != 0) {
        return std::nullopt;
    }
    std::string bytes;
    for (std::size_t i = 0; i < text.size(); i += 2) {
        const int high = hexDigit(text[i]);
        const int low = hexDigit(text[i + 1]);
        if (high < 0 || low < 0) {
            return std::nullopt;
        }
        bytes.push_back(static_cast<char>(high * 16 + low));
    }
    return bytes;
}

std::string toHex(const std::string& bytes) {
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string text;
    for (unsigned char c : bytes) {
        text.push_back(kDigits[c >> 4]);
        text.push_back(kDigits[c & 15]);
    }
    return text;
}

constexpr std::array<params::UserLevel, 3> kProtected{params::UserLevel::Operator, params::UserLevel::Admin,
                                                      params::UserLevel::Super};

} // namespace

const char* Passwords::key(params::UserLevel level) {
    switch (level) {
    case params::UserLevel::Guest: return nullptr;
    case params::UserLevel::Operator: return "operator";
    case params::UserLevel::Admin: return "admin";
    case params::UserLevel::Super: return "super";
    }
    return nullptr;
}

std::variant<Passwords, PasswordsProblem> readPasswords(const MachineFolder& folder) {
    const fs::path path = folder.pathOf(FolderFile::Passwords);
    const std::string file = path.string();
    std::error_code ec;
    const fs::file_status link = fs::symlink_status(path, ec);
    if (link.type() == fs::file_type::not_found) {
        return Passwords{}; // never changed: every level at its default
    }
    if (ec) {
        return PasswordsProblem{message("passwords_unreadable", {file, ec.message()})};
    }
    toml::table table;
    try {
        table = files::parseTomlFile(file);
    } catch (const files::UnreadableToml& e) {
        return PasswordsProblem{message("folder_cannot_read", {placeOf(file, e.source()), bilingual(e.reason())})};
    } catch (const toml::parse_error& e) {
        return PasswordsProblem{message("passwords_toml", {placeOf(file, e.source()), std::string(e.description())})};
    }
    Passwords passwords;
    for (auto&& [name, node] : table) {
        std::optional<params::UserLevel> level;
        for (params::UserLevel candidate : kProtected) {
            if (name.str() == Passwords::key(candidate)) {
                level = candidate;
            }
        }
        if (!level) {
            return PasswordsProblem{message("passwords_no_level", {placeOf(file, name.source()), std::string(name.str())})};
        }
        const std::optional<std::string> text = node.value<std::string>();
        const std::size_t colon = text ? text->find(':') : std::string::npos;
        std::optional<std::string> salt = colon != std::string::npos ? fromHex(text->substr(0, colon)) : std::nullopt;
        std::optional<std::string> hash = colon != std::string::npos ? fromHex(text->substr(colon + 1)) : std::nullopt;
        if (!salt || !hash || hash->size() != Passwords::kHashBytes) {
            return PasswordsProblem{message("passwords_bad_hash", {placeOf(file, node.source()), std::string(name.str()),
                                                                   std::to_string(Passwords::kHashBytes)})};
        }
        passwords.levels[static_cast<std::size_t>(*level)] = StoredPassword{std::move(*salt), std::move(*hash)};
    }
    return passwords;
}

std::string formatPasswords(const Passwords& passwords) {
    std::string text = "# M350 Studio panel passwords (密码设置): PBKDF2-HMAC-SHA256, \"salt:hash\" in hex.\n"
                       "# A level named here opens with its own password only; `m350-sim reset-passwords` brings "
                       "back the defaults.\n";
    for (params::UserLevel level : kProtected) {
        if (const auto& stored = passwords.levels[static_cast<std::size_t>(level)]) {
            text += std::string(Passwords::key(level)) + " = \"" + toHex(stored->salt) + ":" + toHex(stored->hash) + "\"\n";
        }
    }
    return text;
}

std::optional<Message> resetPasswords(const MachineFolder& folder) {
    std::error_code ec;
    if (fs::is_directory(fs::symlink_status(folder.pathOf(FolderFile::Passwords), ec))) {
        return message("passwords_is_folder", {folder.pathOf(FolderFile::Passwords).string()});
    }
    if (auto error = folder.write(FolderFile::Passwords, formatPasswords(Passwords{}))) {
        return message("passwords_write_failed", {bilingual(*error)});
    }
    return std::nullopt;
}

} // namespace m350::config
