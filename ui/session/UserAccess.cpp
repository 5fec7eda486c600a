#include "ui/session/UserAccess.h"

#include "ui/i18n/Language.h"


#include <QCryptographicHash>
#include <QMessageAuthenticationCode>
#include <QRandomGenerator>

namespace m350::ui {

namespace {

constexpr int kRounds = 10000;
constexpr int kSaltBytes = 16;

// PBKDF2-HMAC-SHA256 (RFC 8018) with one output block, the hash's own length.
QByteArray digest(const QString& password, const QByteArray& salt) {
    QMessageAuthenticationCode mac(QCryptographicHash::Sha256, password.toUtf8());
    mac.addData(salt + QByteArray("\0\0\0\1", 4));
    QByteArray u = mac.result();
    QByteArray out = u;
    for (int round = 1; round < kRounds; ++round) {
        mac.reset();
        mac.addData(u);
        u = mac.result();
        for (int i = 0; i < out.size(); ++i) {
            out[i] = static_cast<char>(out[i] ^ u[i]);
        }
    }
    return out;
}

std::size_t index(params::UserLevel level) { return static_cast<std::size_t>(level); }

} // namespace

UserAccess::UserAccess(const QString& folder) : folder_(folder.toStdString()) { load(); }

QString UserAccess::defaultPassword(Level level) {
    switch (level) {
    case Level::Guest: return {};
    case Level::Operator: return QStringLiteral("opr350");
    case Level::Admin: return QStringLiteral("adm350");
    case Level::Super: return QStringLiteral("sup350");
    }
    return {};
}

QString UserAccess::levelName(Level level) {
    switch (level) {
    case Level::Guest: return tr("Guest", "msg 942");
    case Level::Operator: return tr("Operator", "msg 943");
    case Level::Admin: return tr("Admin", "msg 944");
    case Level::Super: return tr("Super", "msg 945");
    }
    return {};
}

bool UserAccess::opens(Level level, const QString& password) const {
    if (!problem_.isEmpty()) {
        return false; // a passwords.toml that cannot be trusted brings no default back
    }
    const auto& stored = stored_.levels[index(level)];
    if (!stored) {
        return password == defaultPassword(level);
    }
    return digest(password, QByteArray::fromStdString(stored->salt)) == QByteArray::fromStdString(stored->hash);
}

bool UserAccess::login(Level wanted, const QString& password) {
    if (wanted == Level::Guest) {
        level_ = Level::Guest;
        return true;
    }
    load(); // a reset or a repair since the panel started counts at once
    for (int level = static_cast<int>(Level::Super); level >= static_cast<int>(wanted); --level) {
        if (opens(static_cast<Level>(level), password)) {
            level_ = static_cast<Level>(level);
            return true;
        }
    }
    return false;
}

std::optional<QString> UserAccess::changePassword(const QString& password) {
    if (level_ == Level::Guest) {
        return tr("Rights is limited,pls shift user's rights:", "msg 934");
    }
    if (!problem_.isEmpty() && level_ != Level::Super) {
        return tr("Rights is limited,pls shift user's rights:", "msg 934"); // only the highest level repairs the file
    }
    if (password.size() < kMinimumLength) {
        return tr("The No. of characters < 6,pls input again!", "msg 918");
    }
    QByteArray salt(kSaltBytes, '\0');
    QRandomGenerator::system()->generate(salt.begin(), salt.end());
    auto previous = stored_.levels[index(level_)];
    stored_.levels[index(level_)] = config::StoredPassword{salt.toStdString(), digest(password, salt).toStdString()};
    if (auto error = save()) {
        stored_.levels[index(level_)] = previous;
        return tr("File save failed!", "msg 907") + QStringLiteral(" ") + *error;
    }
    problem_.clear(); // written whole: the file is sound again
    return std::nullopt;
}

// A file that cannot be trusted keeps what the last sound read knew: the highest level, still
// signed in, then repairs it with every level's password as it was (save() writes them all).
void UserAccess::load() {
    auto read = config::readPasswords(folder_);
    if (auto* problem = std::get_if<config::PasswordsProblem>(&read)) {
        problem_ = QString::fromStdString(problem->message.in(Language::messageLanguage()));
        return;
    }
    stored_ = std::get<config::Passwords>(read);
    problem_.clear();
}

std::optional<QString> UserAccess::save() const {
    if (auto error = folder_.write(config::FolderFile::Passwords, config::formatPasswords(stored_))) {
        return QString::fromStdString(error->in(Language::messageLanguage()));
    }
    return std::nullopt;
}

} // namespace m350::ui
