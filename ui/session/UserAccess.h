#pragma once

#include "core/config/MachineFolder.h"
#include "core/config/PasswordsFile.h"
#include "core/params/ParameterPages.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QString>

#include <optional>

namespace m350::ui {

// Who is at the panel: 访客 Guest, 操作员 Operator, 管理员 Admin or 超级管理 Super, and the passwords
// that open each level. The panel starts as a guest. Passwords are kept hashed (PBKDF2-HMAC-SHA256
// with a salt per level) in the machine folder's passwords.toml (config/PasswordsFile.h), one line
// per level that has been changed through 密码设置; a level not in the file opens with its default
// password (README). A passwords.toml that cannot be trusted (corrupt, not a file) opens no level
// above Guest: problem() says why, until the highest level sets new passwords or
// `m350-sim reset-passwords` writes the file anew.
class UserAccess {
    Q_DECLARE_TR_FUNCTIONS(m350::ui::UserAccess)

public:
    using Level = params::UserLevel;
    static constexpr int kMinimumLength = 6; // msg 918: fewer than 6 characters are refused

    explicit UserAccess(const QString& folder);

    Level level() const { return level_; }
    // 请输入[操作员]及以上密码: the password of `wanted` or of any higher level opens `wanted`, or
    // that higher level when it is its password. Guest needs none. False (level unchanged) otherwise.
    bool login(Level wanted, const QString& password);
    // 密码设置: the current level's password becomes `password`, saved at once. nullopt, or why not
    // (translated: a guest has no password, fewer than 6 characters, the file could not be written).
    std::optional<QString> changePassword(const QString& password);

    // Why no level above Guest opens (the file's place and fault), empty when the file is sound.
    const QString& problem() const { return problem_; }

    static QString defaultPassword(Level level);
    static QString levelName(Level level); // 访客 操作员 管理员 超级管理, translated

private:
    bool opens(Level level, const QString& password) const;
    void load();
    std::optional<QString> save() const;

    config::MachineFolder folder_; // passwords.toml is written through it
    Level level_ = Level::Guest;
    config::Passwords stored_;
    QString problem_;
};

} // namespace m350::ui
