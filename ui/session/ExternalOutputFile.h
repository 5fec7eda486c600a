#pragma once

#include <QElapsedTimer>
#include <QString>

#include <cstdint>
#include <optional>

namespace m350::config {
class MachineFolder;
}
namespace m350::controller {
class ExternalDevices;
}

namespace m350::ui {

class SessionLog;

// The external output device of a FANUC machine (POPEN / DPRNT / BPRNT / PCLOS) on the panel: what
// it received goes into the machine folder's dprnt.txt, as `m350-sim` writes it beside a program,
// and each record into the system log, where an operator sees it. The records come from the
// controller one by one (ExternalDevices::takeNewRecords), so the log goes on past the output's
// limit, where dprnt.txt keeps only the first and the last of them.
class ExternalOutputFile {
public:
    explicit ExternalOutputFile(std::uint64_t limit) : limit_(limit) {}

    // Logs the records that came since the last call; writes dprnt.txt when the run is over
    // (`running` false) or a second after the last write. Why the file was not written, if so.
    std::optional<QString> keep(controller::ExternalDevices& devices, SessionLog& log, const config::MachineFolder& folder,
                                bool running);
    // Writes dprnt.txt when records came since it was last written.
    std::optional<QString> save(const controller::ExternalDevices& devices, const config::MachineFolder& folder);

private:
    std::uint64_t limit_;
    bool unsaved_ = false; // records came since dprnt.txt was last written
    bool capLogged_ = false;
    QElapsedTimer saved_;
};

} // namespace m350::ui
