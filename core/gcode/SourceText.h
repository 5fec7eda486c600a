#pragma once

#include "core/common/LargeAllocation.h"

#include <string>
#include <string_view>
#include <variant>

namespace m350::gcode {

enum class TextEncoding { Utf8, Gbk };

std::string_view encodingName(TextEncoding encoding);

// A file's bytes. A 200,000-line program is several megabytes: LargeAllocator gives them huge
// pages where the system has them.
using SourceBytes = std::basic_string<char, std::char_traits<char>, LargeAllocator<char>>;

// A program file as the parser sees it.
struct SourceText {
    std::string path;
    SourceBytes text;  // UTF-8, BOM removed, CRLF kept as is
    TextEncoding encoding = TextEncoding::Utf8;
};

struct SourceReadError {
    std::string path;
    std::string message;
};

// Reads the file's bytes and passes them to decodeSource.
std::variant<SourceText, SourceReadError> readSourceFile(const std::string& path);

// Strips a UTF-8 BOM, accepts strictly valid UTF-8 (pure ASCII included) as
// Utf8, otherwise decodes as GBK (via GB18030, a superset). If neither fits,
// the error names the 1-based line and byte column of the first bad byte.
std::variant<SourceText, SourceReadError> decodeSource(std::string path, std::string_view bytes);
// The same, taking over `bytes`: valid UTF-8 becomes the text without a copy.
std::variant<SourceText, SourceReadError> decodeSourceBuffer(std::string path, SourceBytes bytes);

}  // namespace m350::gcode
