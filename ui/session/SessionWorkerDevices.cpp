// The external output device of a FANUC machine (POPEN / DPRNT / BPRNT / PCLOS) on the panel: what
// it received goes into the machine folder's dprnt.txt, as `m350-sim` writes it beside a program,
// and each record into the system log, where an operator sees it.
#include "ui/session/SessionWorker.h"

#include "core/config/OutputFile.h"
#include "core/controller/Controller.h"

#include <filesystem>

namespace m350::ui {

namespace {

constexpr const char* kExternalOutputFile = "dprnt.txt";

} // namespace

void SessionWorker::keepExternalOutput() {
    const std::string& received = controller_->externalOutput();
    if (received.size() <= externalOutputKept_) {
        return;
    }
    std::string_view fresh = std::string_view(received).substr(externalOutputKept_);
    externalOutputKept_ = received.size();
    while (!fresh.empty()) {
        const std::size_t end = fresh.find_first_of("\r\n");
        std::string_view record = fresh.substr(0, end);
        if (!record.empty()) {
            log_->record("dprnt", QString::fromUtf8(record.data(), static_cast<qsizetype>(record.size())));
        }
        fresh = end == std::string_view::npos ? std::string_view() : fresh.substr(end + 1);
    }
    if (!folder_.empty()) {
        const auto file = std::filesystem::path(folder_) / kExternalOutputFile;
        if (auto problem = config::writeOutputFile(file, received)) {
            lastError_ = tr("File save failed!", "msg 907") + QStringLiteral(" ") + QString::fromStdString(*problem);
        }
    }
}

} // namespace m350::ui
