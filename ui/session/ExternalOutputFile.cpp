#include "ui/session/ExternalOutputFile.h"

#include "ui/i18n/Language.h"
#include "ui/session/SessionLog.h"

#include "core/config/MachineFolder.h"
#include "core/controller/ExternalDevices.h"

#include <QCoreApplication>

#include <string_view>

namespace m350::ui {

namespace {

// dprnt.txt is written whole (up to the output's limit, 64 MiB by default): while a program keeps
// sending, at most once a second, and when the run is over.
constexpr qint64 kSaveIntervalMs = 1000;

// A record may hold several lines (BPRNT's end-of-block code, a DPRNT of text with line ends).
void logRecordLines(SessionLog& log, std::string_view record) {
    while (!record.empty()) {
        const std::size_t end = record.find_first_of("\r\n");
        const std::string_view line = record.substr(0, end);
        if (!line.empty()) {
            log.record("dprnt", QString::fromUtf8(line.data(), static_cast<qsizetype>(line.size())));
        }
        record = end == std::string_view::npos ? std::string_view() : record.substr(end + 1);
    }
}

// 64 MiB, 2 KiB or 1000 B: the limit as the log's detail (which, like every detail, is data, not
// words of the panel's language).
std::string readableSize(std::uint64_t bytes) {
    if (bytes % (1u << 20) == 0) {
        return std::to_string(bytes >> 20) + " MiB";
    }
    return bytes % 1024 == 0 ? std::to_string(bytes >> 10) + " KiB" : std::to_string(bytes) + " B";
}

} // namespace

std::optional<QString> ExternalOutputFile::keep(controller::ExternalDevices& devices, SessionLog& log,
                                                const config::MachineFolder& folder, bool running) {
    const controller::ExternalDevices::NewRecords fresh = devices.takeNewRecords();
    if (fresh.missed > 0) {
        log.record("dprnt_missed", QString::number(fresh.missed));
    }
    for (const std::string& record : fresh.records) {
        logRecordLines(log, record);
    }
    if (!capLogged_ && devices.outputCapped()) {
        capLogged_ = true;
        log.record("dprnt_limit", QString::fromStdString(readableSize(limit_)));
    }
    unsaved_ = unsaved_ || fresh.missed > 0 || !fresh.records.empty();
    if (!running || !saved_.isValid() || saved_.elapsed() >= kSaveIntervalMs) {
        return save(devices, folder);
    }
    return std::nullopt;
}

std::optional<QString> ExternalOutputFile::save(const controller::ExternalDevices& devices, const config::MachineFolder& folder) {
    if (!unsaved_ || folder.path().empty()) {
        return std::nullopt;
    }
    unsaved_ = false;
    saved_.start();
    if (auto problem = folder.write(config::FolderFile::ExternalOutput, devices.received())) {
        return QCoreApplication::translate("m350::ui::ExternalOutputFile", "File save failed!", "msg 907") + QStringLiteral(" ") +
               QString::fromStdString(problem->in(Language::messageLanguage()));
    }
    return std::nullopt;
}

} // namespace m350::ui
