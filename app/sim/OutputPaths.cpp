#include "app/sim/OutputPaths.h"

#include "core/config/MachineFolder.h"
#include "core/files/OutputGuard.h"

#include <filesystem>
#include <utility>
#include <vector>

namespace m350::sim {

namespace fs = std::filesystem;

std::string externalOutputPath(const SimOptions& o) {
    if (o.outputFile) {
        return *o.outputFile;
    }
    return o.command == SimOptions::Command::Run ? (fs::path(o.program).parent_path() / "dprnt.txt").string()
                                                 : std::string("dprnt.txt");
}

std::optional<Message> outputNamingAnInput(const SimOptions& o, const config::MachineConfig& machine) {
    std::vector<std::pair<std::string, std::string>> outputs; // option, path
    if (o.traceFile) {
        outputs.emplace_back("--trace", *o.traceFile);
    }
    outputs.emplace_back(o.outputFile ? "--dprnt" : bilingual("the DPRNT output", "DPRNT输出"), externalOutputPath(o));
    if (o.toolsOut) {
        outputs.emplace_back("--tools-out", *o.toolsOut);
    }
    std::vector<files::GuardedPath> inputs; // what, path
    if (!o.program.empty()) {
        inputs.push_back({bilingual("the program of this run", "本次运行的程序"), o.program});
    }
    for (const config::LibraryFile& library : machine.libraries) {
        inputs.push_back({bilingual("a library of this run", "本次运行的程序库"), library.path});
    }
    if (o.toolTableFile) {
        inputs.push_back({bilingual("the --tool-table file of this run", "本次运行的--tool-table文件"), *o.toolTableFile});
    }
    std::error_code ec;
    for (const fs::directory_entry& entry : fs::directory_iterator(machine.folder, ec)) {
        if (entry.is_regular_file(ec) && entry.path().filename() != config::MachineFolder::fileName(config::FolderFile::ExternalOutput)) {
            // dprnt.txt: an output
            inputs.push_back({bilingual("a file of the machine folder of this run", "本次运行的机床文件夹中的文件"), entry.path()});
        }
    }
    for (const auto& [option, output] : outputs) {
        if (auto refused = files::refusedOutput(option, output, inputs)) {
            return refused;
        }
    }
    return std::nullopt;
}

} // namespace m350::sim
