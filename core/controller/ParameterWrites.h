#pragma once

#include "core/common/Message.h"
#include "core/params/ParameterPages.h"
#include "core/params/ParameterTable.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace m350::controller {

// Who may change which parameter, and the record of every change (issue 26). What the operator
// types at the panel (MDI lines, the program that runs, the panel's own edits) needs the level the
// Param page asks for the parameter (ParameterPages::requiredLevel); the machine's own macros
// (libraries, hook files) write what they write. Every change, whoever made it, is taken out of
// the table by take() so that the panel's System Log lists it with the level in force.
class ParameterWrites {
public:
    // Who changed a parameter: the operator's program or MDI line, the panel's own edit (Param
    // page, touch off, teach), or the machine (its macros, hook files, the firmware's counters).
    enum class Writer : std::uint8_t { Machine, Program, Panel };
    struct Change {
        int number = 0;
        double before = 0.0;
        double after = 0.0;
        params::UserLevel level = params::UserLevel::Super;
        Writer writer = Writer::Machine;
        std::string place; // "mdi.nc:1", "slib-g.nc:120" for a program's write; empty otherwise
    };

    explicit ParameterWrites(const params::ParameterTable& table) : seen_(table) {}

    // The level at the panel. Without a panel (m350-sim, a Controller alone) it is Super.
    void setLevel(params::UserLevel level) { level_ = level; }
    params::UserLevel level() const { return level_; }
    // The level the Param page needs to change `number`; Super for one it does not list.
    static params::UserLevel required(int number);
    // The refusal (msg 934's words, the parameter, the level it needs and the level now) when the
    // operator's code writes `number` above the level; nullopt when it may.
    std::optional<Message> refusal(int number) const { return refusal(number, level_); }
    static std::optional<Message> refusal(int number, params::UserLevel level);
    static std::string levelWords(params::UserLevel level); // bilingual: Guest / 访客 ...

    // Who is about to write `number` (kept until take() sees the change); a change nobody noted
    // is the machine's.
    void note(int number, Writer writer, std::string place = {}) { writers_[number] = {writer, std::move(place)}; }
    // The changes since the last call: the table compared with what it held then.
    std::vector<Change> take(const params::ParameterTable& table);

private:
    params::UserLevel level_ = params::UserLevel::Super;
    params::ParameterTable seen_;
    std::uint64_t seenVersion_ = 0;
    std::map<int, std::pair<Writer, std::string>> writers_;
};

} // namespace m350::controller
