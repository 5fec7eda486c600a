// The external output device of a FANUC machine (POPEN / DPRNT / BPRNT / PCLOS) on the panel: what
// it received goes into the machine folder's dprnt.txt, as `m350-sim` writes it beside a program,
// and each record into the system log, where an operator sees it. The records come from the
// controller one by one (externalDevices().takeNewRecords()), so the log goes on past the output's limit, where
// dprnt.txt keeps only the first and the last of them.
#include "ui/session/SessionWorker.h"

#include "core/controller/Controller.h"
#include "ui/i18n/Language.h"

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

void SessionWorker::keepExternalOutput() {
    const controller::ExternalDevices::NewRecords fresh = controller_->externalDevices().takeNewRecords();
    if (fresh.missed > 0) {
        log_->record("dprnt_missed", QString::number(fresh.missed));
    }
    for (const std::string& record : fresh.records) {
        logRecordLines(*log_, record);
    }
    if (!externalOutputCapLogged_ && controller_->externalDevices().outputCapped()) {
        externalOutputCapLogged_ = true;
        log_->record("dprnt_limit", QString::fromStdString(readableSize(options_.externalOutputLimit)));
    }
    externalOutputUnsaved_ = externalOutputUnsaved_ || fresh.missed > 0 || !fresh.records.empty();
    if (!busy() || !externalOutputSaved_.isValid() || externalOutputSaved_.elapsed() >= kSaveIntervalMs) {
        saveExternalOutput();
    }
}

void SessionWorker::saveExternalOutput() {
    if (!externalOutputUnsaved_ || folder_.path().empty()) {
        return;
    }
    externalOutputUnsaved_ = false;
    externalOutputSaved_.start();
    if (auto problem = folder_.write(config::FolderFile::ExternalOutput, controller_->externalDevices().received())) {
        lastError_ = tr("File save failed!", "msg 907") + QStringLiteral(" ") + QString::fromStdString(problem->in(Language::messageLanguage()));
    }
}

} // namespace m350::ui
