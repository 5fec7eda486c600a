#include "core/training/ExerciseMachine.h"

#include "core/config/MachineConfig.h"
#include "core/config/RackForks.h"
#include "core/files/AtomicFile.h"
#include "core/files/MachineFileRead.h"
#include "core/params/ParameterNumbers.h"
#include "core/params/ParamsFileWriter.h"

#include <filesystem>
#include <sstream>
#include <variant>

namespace m350::training {

namespace fs = std::filesystem;

namespace {

std::optional<Message> rewrite(const fs::path& file, const std::string& text) {
    if (auto why = files::writeFileAtomically(file.string(), text)) {
        return message("exercise_write_failed", {bilingual(*why)});
    }
    return std::nullopt;
}

// `text` with line `line` (1-based) replaced, the file's line ends kept.
std::optional<std::string> withLine(const std::string& text, int line, const std::string& replacement) {
    std::string out;
    std::size_t at = 0;
    for (int n = 1; at <= text.size(); ++n) {
        std::size_t end = text.find('\n', at);
        const bool last = end == std::string::npos;
        std::string current = text.substr(at, last ? std::string::npos : end - at);
        const bool crlf = !current.empty() && current.back() == '\r';
        if (n == line) {
            if (last && current.empty()) {
                return std::nullopt; // past the end
            }
            current = replacement + (crlf ? "\r" : "");
        }
        out += current;
        if (last) {
            return n >= line ? std::optional<std::string>(out) : std::nullopt;
        }
        out += '\n';
        at = end + 1;
    }
    return std::nullopt;
}

// The exercise's parameters change what the controller believes, not the iron: a linear rack whose
// forks stand where the bundled parameters say keeps them there ([magazine] forks written into the
// attempt's machine.toml), so that a pocket parameter set wrong misses its fork as on the machine;
// a servo disc keeps its change station likewise ([magazine] station, params 808, 809, 807).
std::optional<Message> freezeForks(const fs::path& source, const fs::path& target) {
    auto loaded = config::loadMachineFolder(source.string());
    const auto* bundled = std::get_if<config::MachineConfig>(&loaded);
    if (!bundled) {
        return std::nullopt; // a folder that does not load says so when the attempt loads it
    }
    const config::MagazineConfig& magazine = bundled->magazine;
    std::string forks;
    if (magazine.device == config::MagazineConfig::Device::LinearRack && magazine.forks.empty()) {
        forks = "forks = [";
        for (const Eigen::Vector3d& at : config::rackForks(magazine, bundled->parameters)) {
            forks += (forks.back() == '[' ? "[" : ", [") + params::tomlNumber(at.x()) + ", " + params::tomlNumber(at.y()) +
                     ", " + params::tomlNumber(at.z()) + "]";
        }
        forks += "] # where the forks stand (the exercise changes only the parameters)\n";
    } else if (magazine.device == config::MagazineConfig::Device::ServoDisc && !magazine.station) {
        const params::ParameterTable& p = bundled->parameters;
        forks = "station = [" + params::tomlNumber(p.get(param::kChangeFrontX)) + ", " +
                params::tomlNumber(p.get(param::kChangeFrontY)) + ", " + params::tomlNumber(p.get(param::kChangeZDown)) +
                "] # where the disc's change station stands (the exercise changes only the parameters)\n";
    } else {
        return std::nullopt;
    }
    const fs::path file = target / "machine.toml";
    std::string text;
    if (auto why = files::readMachineFile(file, text)) {
        return message("exercise_read_failed", {file.string(), bilingual(*why)});
    }
    const std::size_t header = text.find("\n[magazine]");
    const std::size_t lineEnd = header == std::string::npos ? std::string::npos : text.find('\n', header + 1);
    if (lineEnd == std::string::npos) {
        return std::nullopt;
    }
    text.insert(lineEnd + 1, forks);
    return rewrite(file, text);
}

// A bundled machine may name a library of the machine folder beside it (m350-servo-disc's
// `../m350-linear16/slib-m.nc`): that file and its folder's machine.toml go beside the attempt's
// folder too, so the copy loads as the bundled folder does.
std::optional<Message> copySiblingLibraries(const fs::path& source, const fs::path& target) {
    auto loaded = config::loadMachineFolder(source.string());
    const auto* bundled = std::get_if<config::MachineConfig>(&loaded);
    if (!bundled) {
        return std::nullopt; // a folder that does not load says so when the attempt loads it
    }
    std::error_code error;
    const fs::path self = fs::weakly_canonical(source, error);
    for (const config::LibraryFile& library : bundled->libraries) {
        const fs::path file = fs::weakly_canonical(library.path, error);
        const fs::path sibling = file.parent_path();
        if (error || sibling == self || sibling.parent_path() != self.parent_path()) {
            continue;
        }
        const fs::path into = target.parent_path() / sibling.filename();
        fs::create_directories(into, error);
        for (const fs::path& copied : {file, sibling / "machine.toml"}) {
            if (!error) {
                fs::copy_file(copied, into / copied.filename(), fs::copy_options::overwrite_existing, error);
            }
        }
        if (error) {
            return message("exercise_copy_failed", {file.string(), into.string(), error.message()});
        }
    }
    return std::nullopt;
}

} // namespace

std::optional<Message> prepareExerciseMachine(const Exercise& exercise, const std::string& machinesFolder,
                                              const std::string& into) {
    const fs::path source = fs::path(machinesFolder) / exercise.machine;
    const fs::path target(into);
    std::error_code error;
    fs::create_directories(target, error);
    if (!error) {
        fs::copy(source, target, fs::copy_options::recursive | fs::copy_options::overwrite_existing, error);
    }
    if (error) {
        return message("exercise_copy_failed", {source.string(), target.string(), error.message()});
    }
    if (auto failed = copySiblingLibraries(source, target)) {
        return failed;
    }
    if (!exercise.parameters.empty()) {
        if (auto failed = freezeForks(source, target)) {
            return failed;
        }
        const fs::path params = target / "params.toml";
        std::string text;
        if (fs::exists(params)) {
            if (auto why = files::readMachineFile(params, text)) {
                return message("exercise_read_failed", {params.string(), bilingual(*why)});
            }
        }
        if (auto failed = rewrite(params, params::setTomlNumbers(text, "params", exercise.parameters))) {
            return failed;
        }
    }
    for (const LineChange& change : exercise.lines) {
        const fs::path file = target / change.file;
        std::string text;
        if (auto why = files::readMachineFile(file, text)) {
            return message("exercise_read_failed", {file.string(), bilingual(*why)});
        }
        std::optional<std::string> changed = withLine(text, change.line, change.text);
        if (!changed) {
            return message("exercise_line_past_end", {change.file, std::to_string(change.line)});
        }
        if (auto failed = rewrite(file, *changed)) {
            return failed;
        }
    }
    for (const std::string& name : exercise.files) {
        fs::copy_file(fs::path(exercise.folder) / name, target / name, fs::copy_options::overwrite_existing, error);
        if (error) {
            return message("exercise_copy_failed", {(fs::path(exercise.folder) / name).string(), target.string(), error.message()});
        }
    }
    // the Program page's 本地程序 disk: a program the trainee loads with NC读取 and runs with START
    for (const std::string& name : exercise.programs) {
        fs::create_directories(target / "programs", error);
        if (!error) {
            fs::copy_file(fs::path(exercise.folder) / name, target / "programs" / name, fs::copy_options::overwrite_existing, error);
        }
        if (error) {
            return message("exercise_copy_failed", {(fs::path(exercise.folder) / name).string(), (target / "programs").string(),
                                                    error.message()});
        }
    }
    return std::nullopt;
}

} // namespace m350::training
