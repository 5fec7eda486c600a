#include "core/controller/LibraryCache.h"

#include <utility>
#include <variant>

namespace m350::controller {

std::shared_ptr<const gcode::ParsedLibraries> LibraryCache::get(const gcode::Dialect& dialect,
                                                                 const std::vector<File>& files) {
    const std::chrono::system_clock::time_point now = now_();
    std::vector<files::FileStamp> stamps;
    stamps.reserve(files.size());
    bool unchanged = parsed_ && dialect == dialect_ && files == files_ && stamps_.size() == files.size();
    for (std::size_t i = 0; i < files.size(); ++i) {
        stamps.push_back(files::FileStamp::of(files[i].path, now));
        unchanged = unchanged && stamps_[i].settled && stamps[i].sameFile(stamps_[i]);
    }
    if (unchanged) { // an MDI line joins the libraries without reading them
        return parsed_;
    }
    ++reads_;
    std::vector<gcode::SourceText> sources;
    sources.reserve(files.size());
    for (const File& file : files) {
        auto source = gcode::readSourceFile(file.path);
        if (!std::holds_alternative<gcode::SourceText>(source)) {
            return nullptr;
        }
        sources.push_back(std::get<gcode::SourceText>(std::move(source)));
    }
    bool same = parsed_ && dialect == dialect_ && files == files_;
    for (std::size_t i = 0; same && i < files.size(); ++i) {
        same = sources[i].text == texts_[i] && sources[i].encoding == encodings_[i];
    }
    if (!same) {
        parsed_ = parse(dialect, files, sources);
    }
    stamps_ = std::move(stamps);
    return parsed_;
}

std::shared_ptr<const gcode::ParsedLibraries> LibraryCache::parse(const gcode::Dialect& dialect,
                                                                  const std::vector<File>& files,
                                                                  const std::vector<gcode::SourceText>& sources) {
    ++parses_;
    auto parsed = std::make_shared<gcode::ParsedLibraries>();
    gcode::Parser parser(dialect);
    for (std::size_t i = 0; i < files.size(); ++i) {
        add(parser, parsed->program, files[i], sources[i]);
    }
    parsed->diagnostics = parser.diagnostics();
    parsed->joinable = !parser.leftFindingsOut() && parsed->program.files.size() == files.size();
    for (const gcode::Diagnostic& d : parsed->diagnostics) {
        parsed->joinable = parsed->joinable && !d.unreadable; // a file refused or cut short
    }
    dialect_ = dialect;
    files_ = files;
    texts_.clear();
    encodings_.clear();
    for (const gcode::SourceText& source : sources) {
        texts_.emplace_back(source.text);
        encodings_.push_back(source.encoding);
    }
    return parsed;
}

bool LibraryCache::addFile(gcode::Parser& parser, gcode::Program& program, const File& file,
                           std::vector<gcode::Diagnostic>& diagnostics) {
    auto source = gcode::readSourceFile(file.path);
    if (auto* error = std::get_if<gcode::SourceReadError>(&source)) {
        diagnostics.push_back(gcode::diagnosticOf(*error));
        return false;
    }
    add(parser, program, file, std::get<gcode::SourceText>(source));
    return true;
}

void LibraryCache::add(gcode::Parser& parser, gcode::Program& program, const File& file, const gcode::SourceText& source) {
    const std::size_t first = program.units.size();
    parser.addSource(program, source, file.role);
    if (file.firstUnitNumber >= 0 && first < program.units.size() && program.units[first].number < 0) {
        program.units[first].number = file.firstUnitNumber;
        program.indexUnit(static_cast<std::uint32_t>(first));
    }
}

} // namespace m350::controller
