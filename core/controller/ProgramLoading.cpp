// Loading what runs: a program file, MDI lines or a hook, parsed with the machine's libraries,
// and the executor that runs it.
#include "core/controller/Controller.h"
#include "core/config/CallCodeParameters.h"

#include "core/gcode/Parser.h"
#include "core/gcode/SourceText.h"

namespace m350::controller {

bool Controller::load(const gcode::SourceText& source, gcode::FileRole role) {
    // Each load replaces the program (a panel loads one file after another, MDI line after line);
    // the machine, the variables and the magazine carry on.
    executor_.reset();
    breakRun_.forgetPause();
    hook_.reset();
    breakage_.restartMonitor();
    program_ = gcode::Program{};
    diagnostics_.clear();
    parseWithLibraries(program_, source, role, diagnostics_);
    if (gcode::hasBlockingError(diagnostics_)) {
        return false;
    }
    executor_ = newExecutor();
    for (auto [number, value] : settings_.variables) {
        macro::VariableInfo info = store_.map().describe(number);
        if (macro::VariableStore::ownsKind(info.kind)) {
            store_.write(info, number, macro::Value::of(value));
        } else {
            writeSystem(info, number, value, {});
        }
    }
    return true;
}

// The file, then the hook programs that programs call (ALL_T.nc for M101), then the machine's
// libraries: what a run of that file needs. The libraries come parsed from libraries_ while their
// files read as they did.
void Controller::parseWithLibraries(gcode::Program& program, const gcode::SourceText& source, gcode::FileRole role,
                                    std::vector<gcode::Diagnostic>& diagnostics) const {
    const gcode::Dialect dialect = config::parsingDialect(config_);
    gcode::Parser parser(dialect);
    parser.setDropChunksAbove(static_cast<std::size_t>(settings_.programKeptWholeUpTo));
    const std::vector<LibraryCache::File> files = librariesFor(source.path);
    if (auto parsed = settings_.reuseParsedLibraries ? libraries_.get(dialect, files) : nullptr) {
        parser.startOn(program, std::move(parsed));
    }
    parser.addSource(program, source, role);
    if (!parser.joinLibraries(program)) {
        for (const LibraryCache::File& file : files) {
            LibraryCache::addFile(parser, program, file, diagnostics);
        }
    }
    parser.finish(program);
    diagnostics.insert(diagnostics.end(), parser.diagnostics().begin(), parser.diagnostics().end());
}

std::unique_ptr<macro::Executor> Controller::newExecutor() {
    macro::Executor::Options options;
    options.callCodes = config_.callCodes;
    options.peripherals = &devices_;
    return std::make_unique<macro::Executor>(program_, *config_.dialect, store_, *this, interp_, options);
}

bool Controller::loadFile(const std::string& path) {
    mdi_ = false;
    auto source = gcode::readSourceFile(path);
    if (auto* error = std::get_if<gcode::SourceReadError>(&source)) {
        diagnostics_.push_back(gcode::diagnosticOf(*error));
        return false;
    }
    return load(std::get<gcode::SourceText>(source), gcode::FileRole::Main);
}

bool Controller::loadMdi(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) {
        text += line;
        text += '\n';
    }
    mdi_ = true;
    return load(gcode::SourceText{"MDI", text, gcode::TextEncoding::Utf8, nullptr, nullptr}, gcode::FileRole::Mdi);
}

} // namespace m350::controller
