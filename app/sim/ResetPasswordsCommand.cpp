#include "app/sim/ResetPasswordsCommand.h"

#include "app/sim/ReportJson.h"

#include "core/config/MachineFolder.h"
#include "core/config/PasswordsFile.h"
#include "core/files/SystemLog.h"

#include <ctime>
#include <iostream>

namespace m350::sim {

namespace {

// "2026-11-27 12:30:00", local time, as the panel stamps its log.
std::string now() {
    const std::time_t t = std::time(nullptr);
    std::tm local{};
    localtime_r(&t, &local);
    char text[32];
    return std::string(text, std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", &local));
}

} // namespace

int runResetPasswords(const std::string& folder, MessageLanguage language) {
    const config::MachineFolder store(folder);
    const std::string file = store.pathOf(config::FolderFile::Passwords).string();
    if (auto error = config::resetPasswords(store)) {
        std::cerr << "m350-sim: reset-passwords: " << error->in(language) << '\n';
        nlohmann::json j = errorJson("file_error", error->english(), file);
        j["alarm"]["message_id"] = error->id;
        std::cout << dump(j) << '\n';
        return 2;
    }
    files::SystemLog log(store.pathOf(config::FolderFile::SystemLog).string());
    Message error;
    if (!log.load(&error) || !log.append({now(), "passwords_reset", file}, &error)) {
        std::cerr << "m350-sim: " << message("passwords_log_failed", {bilingual(error)}).in(language) << '\n';
    }
    const Message said = message("passwords_reset", {file});
    std::cerr << said.in(language) << '\n';
    std::cout << dump({{"status", "ok"}, {"passwords", file}, {"message", said.english()}, {"message_id", said.id}})
              << '\n';
    return 0;
}

} // namespace m350::sim
