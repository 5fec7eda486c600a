// libFuzzer target: one whole program file, bytes as read from disk (UTF-8 or GBK, any line ends),
// decoded and parsed in both dialects with the static checks of Parser::finish.
#include "core/gcode/Dialect.h"
#include "core/gcode/Parser.h"
#include "core/gcode/Program.h"
#include "core/gcode/SourceText.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

namespace {

void parseIn(const m350::gcode::Dialect& dialect, const m350::gcode::SourceText& source) {
    m350::gcode::Program program;
    m350::gcode::Parser parser(dialect);
    parser.addFile(program, source.path, source.text, m350::gcode::FileRole::Main,
                   std::string(m350::gcode::encodingName(source.encoding)));
    parser.finish(program);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    auto decoded = m350::gcode::decodeSource("fuzz.nc", bytes);
    if (const auto* source = std::get_if<m350::gcode::SourceText>(&decoded)) {
        parseIn(m350::gcode::Dialect::m350(), *source);
        parseIn(m350::gcode::Dialect::fanuc(), *source);
    }
    return 0;
}
