#pragma once

#include "core/gcode/Diagnostic.h"
#include "core/gcode/MappedFile.h"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace m350::gcode {

enum class TextEncoding { Utf8, Gbk };

std::string_view encodingName(TextEncoding encoding);

// A program file as the parser sees it.
struct SourceText {
    std::string path;
    std::string_view text;  // UTF-8, BOM removed, CRLF kept as is; points into `storage`
    TextEncoding encoding = TextEncoding::Utf8;
    // What `text` points into: the file mapped into memory (a UTF-8 file is parsed where it lies,
    // neither copied nor zero-filled first: a 200,000-line program is several megabytes), or the
    // text decoded from GBK.
    std::shared_ptr<const void> storage;
    // The mapped file when `text` lies in it (UTF-8): the parser may then let go of pages it has
    // read and re-read them later.
    std::shared_ptr<const MappedFile> mapping;
};

struct SourceReadError {
    std::string path;
    std::string message;
    std::uint32_t line = 0; // of the first byte that is neither UTF-8 nor GBK; 0 when the file could not be read
    std::uint32_t column = 0;
    // The message by id (core/common/Message.h), for the panel and `m350-sim --lang`.
    std::string messageId{};
    std::vector<std::string> messageArguments{};

    static SourceReadError of(std::string path, const Message& words, std::uint32_t line = 0, std::uint32_t column = 0) {
        return SourceReadError{std::move(path), words.english(), line, column, words.id, words.arguments};
    }
};


// The error as a diagnostic: placed at the bad byte (or 0:0), marked unreadable.
Diagnostic diagnosticOf(const SourceReadError& error);

// The largest file read whole into memory (a library, a GBK file, a file that cannot be mapped):
// parsed, such files take many times their size.
inline constexpr std::uintmax_t kMostSourceBytes = std::uintmax_t{256} * 1024 * 1024;
// The largest UTF-8 program file: it stays mapped, and the parser keeps only what jumps, loops and
// calls need (see BlockList), so its size is bounded by block numbers, not by memory.
inline constexpr std::uintmax_t kMostProgramBytes = std::uintmax_t{4} * 1024 * 1024 * 1024 - 1;
// Above this a mapped UTF-8 program is kept in memory only in part (Parser::addSource).
inline constexpr std::uintmax_t kProgramKeptWholeUpTo = std::uintmax_t{64} * 1024 * 1024;

// Maps the file (reads it where mapping is not possible) and decodes it as decodeSource does.
// Folders, FIFOs, devices, files above kMostProgramBytes and files above kMostSourceBytes that
// are not mapped UTF-8 are refused with a message.
std::variant<SourceText, SourceReadError> readSourceFile(const std::string& path);

// Strips a UTF-8 BOM, accepts strictly valid UTF-8 (pure ASCII included) as
// Utf8, otherwise decodes as GBK (via GB18030, a superset). If neither fits,
// the error names the 1-based line and byte column of the first bad byte.
std::variant<SourceText, SourceReadError> decodeSource(std::string path, std::string_view bytes);

}  // namespace m350::gcode
