#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>

namespace m350::macro {

// How a code calls its program: as G65 does (a new level of locals, the block's other words its
// arguments #1-#26) or as M98 does (no arguments; the block's other words run first).
enum class CallKind : std::uint8_t { Macro, Subprogram };

struct CodeCall {
    std::int32_t program = 0;
    CallKind kind = CallKind::Subprogram;
    // An address call (FANUC parameters 6090/6091): the common variable that receives the
    // address's value (#146, #147); 0 for a G or M code.
    int valueVariable = 0;
    // What configured it, as messages name it: "machine.toml:13:1: [codes] M6 = 9001".
    std::string origin;
};

// The codes that call a program on this machine, whatever configured them: machine.toml's [codes]
// and the FANUC parameters 6050-6091 fill this one table (config/CallCodeParameters.h), which the
// executor and `check` read.
class CallCodes {
  public:
    // Adds a G or M code (letter 'G' or 'M'). When the code calls a program already, nothing
    // changes and the entry it clashes with is returned.
    std::optional<CodeCall> add(char letter, int code, CodeCall call);
    // An address letter A-Z that calls a program whatever its value (FANUC 6090/6091).
    std::optional<CodeCall> addAddress(char letter, CodeCall call);

    const CodeCall* find(char letter, int code) const;
    const CodeCall* address(char letter) const;
    // The address letters that call, as bits (letter - 'A'), so a block's letters meet them in one test.
    std::uint32_t addressLetters() const { return addressLetters_; }
    bool empty() const { return codes_.empty() && addressLetters_ == 0; }
    const std::map<std::pair<char, int>, CodeCall>& codes() const { return codes_; }

  private:
    std::map<std::pair<char, int>, CodeCall> codes_;
    std::map<char, CodeCall> addresses_;
    std::uint32_t addressLetters_ = 0;
};

} // namespace m350::macro
