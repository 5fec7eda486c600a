#pragma once

#include "core/common/Message.h"
#include "core/gcode/Dialect.h"
#include "core/macro/VariableLayout.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace m350::macro {

// What a variable number is, in one dialect. The catalogue of every range either dialect defines;
// the executor dispatches on the kind, the UI and the CLI describe variables from it.
enum class VariableKind : std::uint8_t {
    Undefined,       // no such variable: reading or writing it is an alarm
    Null,            // FANUC #0: always vacant, read-only
    Local,           // per call level
    Common,          // FANUC #100-#199 or as the machine declares below #500 (cleared at reset), M350 #50-#499
    Retained,        // FANUC #500-#999 and the machine's declared ranges from #500 on, kept in the machine folder
    Parameter,       // M350 #500-#1499: parameter (n - 500)
    WorkOffset,      // M350 #800-#844, FANUC #5221.., G54.1 Pn #7001.. and #14001..: coordinate system offsets
    MachinePosition, // M350 #880-#884, FANUC #5021-#5025 (waits for motion)
    WorkPosition,    // M350 #850-#879, FANUC #5041-#5045 (waits for motion)
    BlockEnd,        // FANUC #5001-#5005: end point of the last block, in work coordinates
    SkipPosition,    // FANUC #5061-#5065
    ProbeResult,     // M350 #1920-#1929 (G31 result and trigger position)
    ActiveWorkSystem,// M350 #578 (0 = G92, 1..6 = G54..G59)
    Message,         // M350 #1503 status-line message
    Dialog,          // M350 #1505 operator dialog
    Input,           // M350 #1520+k-1 = INk (read-only)
    Output,          // M350 #1552+k-1 = OUTk
    Homed,           // M350 #1515-#1519
    AxisCount,       // M350 #1995: how many axes the machine has (3-5, from its parameters; read-only)
    InterfaceInput,  // FANUC #1000-#1015: the interface inputs UI000-UI015 (read-only)
    InterfaceInputs, // FANUC #1032: UI000-UI015 as one 16-bit number (read-only)
    InterfaceOutput, // FANUC #1100-#1115: the interface outputs UO000-UO015
    InterfaceOutputs,// FANUC #1132 (UO000-UO015, 16 bits), #1133 (UO100-UO131, 32 bits)
    OperationControl,// FANUC #3003 (single block, completion wait), #3004 (feed hold, override, exact stop)
    Alarm,           // FANUC #3000: writing raises an alarm with the comment as message
    StopMessage,     // FANUC #3006: stop with a message
    ModalGroup,      // FANUC #4001-#4022
    ModalWord,       // FANUC #4107-#4120 (D E F H M N O S T ...)
    ToolOffset,      // FANUC #2001-#2400: tool offset memory 1-400
    SpindleLoad,     // M350 #2990 (a simulator extra, as FANUC's #1032): spindle load % x 100, read-only
    System           // other system values, kept as plain storage
};

struct VariableInfo {
    VariableKind kind = VariableKind::Undefined;
    bool readOnly = false;
    int index = 0; // parameter number, port, axis, group ... depending on kind
};

class VariableMap {
public:
    explicit VariableMap(const gcode::Dialect& dialect, const VariableLayout& layout = {});

    // Variables the macro layer stores lie below this or in a machine's declared common ranges.
    static constexpr int kMaxVariable = 9999;
    // The slot in the work offsets (interp::WorkOffsets) of G54.1 P1; Pn is this + n - 1.
    static constexpr int kFirstAdditionalSlot = 9;

    VariableInfo describe(int number) const;
    std::string describeText(int number) const;
    // What the alarm and `check` say of a number that is no variable here.
    std::string undefinedText(int number) const;
    // The same by message id; describeText() in both languages, as a message's argument.
    Message undefinedWords(int number) const;
    std::string describeWords(int number) const;
    // What a #[expression] may reach before it is no variable number at all: M350 #9999, FANUC
    // #999999 (the 30i's six digits), whether or not this machine has a variable there.
    int lastNumber() const { return lastNumber_; }
    // The ranges of one kind, in the order they were added (VariableStore clears the common ones).
    std::vector<VariableRange> rangesOf(VariableKind kind) const;

private:
    struct Range {
        int first;
        int last;
        VariableKind kind;
        bool readOnly;
        int indexBase; // index = number - first + indexBase
    };
    static constexpr int kDenseLast = 19999; // through the 30i's G54.1 P300 (#19981-#19985)
    void add(int first, int last, VariableKind kind, bool readOnly = false, int indexBase = 0);

    std::vector<Range> ranges_;
    std::vector<std::uint16_t> lookup_; // variable number up to kDenseLast -> range index + 1 (0 = undefined)
    std::vector<std::size_t> high_;     // indices into ranges_ of ranges above kDenseLast
    int lastNumber_ = kMaxVariable;
    std::string_view dialectName_;
    std::string commonText_; // FANUC: "#100-#199, #500-#999", the machine's common variables
};

std::string_view kindName(VariableKind kind);

} // namespace m350::macro
