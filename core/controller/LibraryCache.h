#pragma once

#include "core/files/FileStamp.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Diagnostic.h"
#include "core/gcode/ParsedLibraries.h"
#include "core/gcode/Parser.h"
#include "core/gcode/SourceText.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace m350::controller {

// The machine's library files (and the ALL_T.nc hook) parsed once and kept while every file reads
// as it did: each MDI line and each program load joins them to its main file
// (gcode::Parser::joinLibraries) instead of parsing them again. A file is read and compared whole
// with the text that was parsed, so an edit on disk is always seen, whatever its size or time
// stamps say; only a file whose stat is as it was when it last read the same, and was settled then
// (files::FileStamp: changed well before that read), is not read again.
class LibraryCache {
public:
    using Clock = std::chrono::system_clock::time_point (*)();
    explicit LibraryCache(Clock now = &std::chrono::system_clock::now) : now_(now) {}

    struct File {
        std::string path;
        gcode::FileRole role = gcode::FileRole::Library;
        // ALL_T.nc: the M handler number its unnamed first program takes (M101 runs it); -1 otherwise.
        std::int32_t firstUnitNumber = -1;
        bool operator==(const File&) const = default;
    };

    // The files parsed with `dialect`, in that order; parsed again when the dialect, the list or a
    // file's text changed. Null when a file cannot be read: the caller adds the files one by one
    // (addFile) and so says why.
    std::shared_ptr<const gcode::ParsedLibraries> get(const gcode::Dialect& dialect, const std::vector<File>& files);

    // Reads and adds one file as a program load always did; false (and the read error in
    // `diagnostics`) when it cannot be read.
    static bool addFile(gcode::Parser& parser, gcode::Program& program, const File& file,
                        std::vector<gcode::Diagnostic>& diagnostics);

    // How many times the libraries were parsed (tests: a second load must not parse them).
    std::uint64_t parses() const { return parses_; }
    // How many times the files were read (tests: settled files are not read again).
    std::uint64_t reads() const { return reads_; }

private:
    static void add(gcode::Parser& parser, gcode::Program& program, const File& file, const gcode::SourceText& source);
    std::shared_ptr<const gcode::ParsedLibraries> parse(const gcode::Dialect& dialect, const std::vector<File>& files,
                                                        const std::vector<gcode::SourceText>& sources);

    gcode::Dialect dialect_;
    std::vector<File> files_;
    std::vector<std::string> texts_;     // as parsed, by file
    std::vector<gcode::TextEncoding> encodings_;
    std::shared_ptr<const gcode::ParsedLibraries> parsed_;
    std::vector<files::FileStamp> stamps_; // by file, taken before the read that matched texts_
    Clock now_;
    std::uint64_t parses_ = 0;
    std::uint64_t reads_ = 0;
};

} // namespace m350::controller
