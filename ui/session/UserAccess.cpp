#include "ui/session/UserAccess.h"


#include <QCryptographicHash>
#include <QFile>
#include <QMessageAuthenticationCode>
#include <QRandomGenerator>
#include <QRegularExpression>

namespace m350::ui {

namespace {

constexpr int kRounds = 10000;
constexpr int kSaltBytes = 16;
constexpr std::array<const char*, 4> kKeys = {"guest", "operator", "admin", "super"};

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
    const auto& stored = stored_[index(level)];
    if (!stored) {
        return password == defaultPassword(level);
    }
    return digest(password, stored->salt) == stored->hash;
}

bool UserAccess::login(Level wanted, const QString& password) {
    if (wanted == Level::Guest) {
        level_ = Level::Guest;
        return true;
    }
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
    if (password.size() < kMinimumLength) {
        return tr("The No. of characters < 6,pls input again!", "msg 918");
    }
    QByteArray salt(kSaltBytes, '\0');
    QRandomGenerator::system()->generate(salt.begin(), salt.end());
    auto previous = stored_[index(level_)];
    stored_[index(level_)] = Stored{salt, digest(password, salt)};
    if (auto error = save()) {
        stored_[index(level_)] = previous;
        return tr("File save failed!", "msg 907") + QStringLiteral(" ") + *error;
    }
    return std::nullopt;
}

// One line per changed level: `operator = "SALT:HASH"` (hex). Lines it does not know are skipped, so
// a hand-edited file never locks anyone out of a level whose default still applies.
void UserAccess::load() {
    QFile file(QString::fromStdString(folder_.pathOf(config::FolderFile::Passwords).string()));
    if (!file.open(QIODevice::ReadOnly)) {
        return;
    }
    static const QRegularExpression line(QStringLiteral(R"(^\s*(\w+)\s*=\s*"([0-9a-f]+):([0-9a-f]+)\"\s*$)"));
    for (const QByteArray& text : file.readAll().split('\n')) {
        auto match = line.match(QString::fromUtf8(text));
        if (!match.hasMatch()) {
            continue;
        }
        for (std::size_t level = 1; level < kKeys.size(); ++level) {
            if (match.captured(1) == QLatin1String(kKeys[level])) {
                stored_[level] = Stored{QByteArray::fromHex(match.captured(2).toLatin1()),
                                        QByteArray::fromHex(match.captured(3).toLatin1())};
            }
        }
    }
}

std::optional<QString> UserAccess::save() const {
    std::string text = "# M350 Studio panel passwords (密码设置): PBKDF2-HMAC-SHA256, " + std::to_string(kRounds) +
                       " rounds, \"salt:hash\" in hex. Delete a line to go back to that level's default.\n";
    for (std::size_t level = 1; level < kKeys.size(); ++level) {
        if (stored_[level]) {
            text += std::string(kKeys[level]) + " = \"" + stored_[level]->salt.toHex().toStdString() + ":" +
                    stored_[level]->hash.toHex().toStdString() + "\"\n";
        }
    }
    if (auto error = folder_.write(config::FolderFile::Passwords, text)) {
        return QString::fromStdString(*error);
    }
    return std::nullopt;
}

} // namespace m350::ui
