#include "core/macro/VariableMap.h"

#include <algorithm>

namespace m350::macro {

namespace {

// Work-offset slots shared by both dialects' numbering.
constexpr int kSlotG92 = 0;  // M350 #800-#804 (FANUC: none)
constexpr int kSlotCommon = 8; // M350 #840-#844, FANUC EXT #5201-#5205
constexpr int kFirstRetained = 500; // FANUC: common variables from #500 on survive power-off

} // namespace

void VariableMap::add(int first, int last, VariableKind kind, bool readOnly, int indexBase) {
    ranges_.push_back({first, last, kind, readOnly, indexBase});
    lastNumber_ = std::max(lastNumber_, last);
    if (first > kDenseLast) {
        high_.push_back(ranges_.size() - 1);
        return;
    }
    for (int n = first; n <= std::min(last, kDenseLast); ++n) {
        lookup_[static_cast<std::size_t>(n)] = static_cast<std::uint16_t>(ranges_.size());
    }
}

VariableMap::VariableMap(const gcode::Dialect& dialect, const VariableLayout& layout)
    : lookup_(kDenseLast + 1, 0), dialectName_(dialect.name) {
    using K = VariableKind;
    // Later entries override earlier ones where they overlap.
    if (dialect.id == gcode::DialectId::M350) {
        add(0, 49, K::Local);
        add(50, 499, K::Common);
        add(500, 1499, K::Parameter, false, 0); // parameter N is #(N+500)
        for (int slot = 0; slot <= kSlotCommon; ++slot) {
            add(800 + slot * 5, 804 + slot * 5, K::WorkOffset, false, slot * 8);
        }
        for (int slot = 1; slot <= 6; ++slot) {
            add(850 + (slot - 1) * 5, 854 + (slot - 1) * 5, K::WorkPosition, true, slot * 8);
        }
        add(880, 884, K::MachinePosition, false); // a write sets the axis's machine position (and un-homes it)
        add(885, 889, K::WorkPosition, true, kSlotG92 * 8);
        add(1500, 2999, K::System);
        add(1503, 1503, K::Message);
        add(1505, 1505, K::Dialog);
        add(1515, 1519, K::Homed, false, 0);
        add(1520, 1543, K::Input, true, 1);
        add(1552, 1572, K::Output, false, 1);
        // G31's result per axis (#1920-#1924, 2 = the signal came) is written back to 0 by probing
        // macros before the next probe; the trigger positions (#1925-#1929) only the probe sets
        add(1920, 1924, K::ProbeResult, false, 0);
        add(1925, 1929, K::ProbeResult, true, 5); // index 5-9: X..B after the five results
        // stored like any system value, named here because the Probe page and O505 share them:
        // #1970-#1989 the tools of a multi-tool setting (0 = none), #1993 1 while it runs
        add(1970, 1989, K::System);
        add(1993, 1993, K::System);
        add(1995, 1995, K::AxisCount, true); // "Current Max Axis Number"
        // a simulator extra: FANUC's macro alarm, so our tool-setting macros stop a run with an
        // alarm where the firmware's only leave a message (the M350 has no variable above #2999)
        add(3000, 3000, K::Alarm);
        add(2990, 2990, K::SpindleLoad, true); // a simulator extra, as FANUC's #1032 below
    } else {
        // numbers run to six digits (the 30i's); which of them exist is the machine's
        lastNumber_ = VariableLayout::kLastVariable;
        add(0, 0, K::Null, true);
        add(1, 33, K::Local);
        // the machine's common variables: those from #500 on are kept at power-off (variables.toml)
        for (const VariableRange& r : layout.commonRanges(dialect)) {
            commonText_ += (commonText_.empty() ? "#" : ", #") + std::to_string(r.first) +
                           (r.last > r.first ? "-#" + std::to_string(r.last) : std::string());
            if (r.first < kFirstRetained) {
                add(r.first, std::min(r.last, kFirstRetained - 1), K::Common);
            }
            if (r.last >= kFirstRetained) {
                add(std::max(r.first, kFirstRetained), r.last, K::Retained);
            }
        }
        // the interface signals, as the machine folder's [interface_signals] wires them (a PMC may
        // copy the spindle load register, the article's R1212-R1213, to G54-G55: #1032)
        add(1000, 1015, K::InterfaceInput, true, 0);
        add(1032, 1032, K::InterfaceInputs, true, 0);
        add(1100, 1115, K::InterfaceOutput, false, 0);
        add(1132, 1133, K::InterfaceOutputs, false, 0);
        add(2001, 2400, K::ToolOffset, false, 1);
        add(3000, 3000, K::Alarm);
        add(3001, 3002, K::System);
        add(3003, 3004, K::OperationControl, false, 3);
        add(3006, 3006, K::StopMessage);
        add(3011, 3012, K::System);
        add(3901, 3902, K::System);
        add(4001, 4022, K::ModalGroup, true, 1);
        add(4102, 4130, K::ModalWord, true, 102);
        add(5001, 5005, K::BlockEnd, true);
        add(5021, 5025, K::MachinePosition, true);
        add(5041, 5045, K::WorkPosition, true, -1); // -1: the active system
        add(5061, 5065, K::SkipPosition, true);
        add(5201, 5205, K::WorkOffset, false, kSlotCommon * 8);
        for (int slot = 1; slot <= 6; ++slot) {
            add(5201 + slot * 20, 5205 + slot * 20, K::WorkOffset, false, slot * 8);
        }
        // G54.1 Pn, axis a (0 X .. 4 B): #7001 + 20(n-1) + a for P1-P48, and on a control with more
        // systems (the 30i's 300) #14001 + 20(n-1) + a for all of them
        const int systems = layout.workSystems(dialect);
        for (int n = 1; n <= systems; ++n) {
            const int slot = kFirstAdditionalSlot + n - 1;
            if (n <= 48) {
                add(7001 + 20 * (n - 1), 7005 + 20 * (n - 1), K::WorkOffset, false, slot * 8);
            }
            if (systems > 48) {
                add(14001 + 20 * (n - 1), 14005 + 20 * (n - 1), K::WorkOffset, false, slot * 8);
            }
        }
    }
}

std::vector<VariableRange> VariableMap::rangesOf(VariableKind kind) const {
    std::vector<VariableRange> out;
    for (const Range& r : ranges_) {
        if (r.kind == kind) {
            out.push_back({r.first, r.last});
        }
    }
    return out;
}

VariableInfo VariableMap::describe(int number) const {
    if (number < 0 || number > lastNumber_) {
        return {};
    }
    std::size_t r = 0;
    if (number <= kDenseLast) {
        r = lookup_[static_cast<std::size_t>(number)];
    } else {
        for (std::size_t i : high_) {
            if (number >= ranges_[i].first && number <= ranges_[i].last) {
                r = i + 1;
            }
        }
    }
    if (r == 0) {
        return {};
    }
    const Range& range = ranges_[r - 1u];
    int index = range.indexBase;
    if (range.kind == VariableKind::WorkPosition && range.indexBase < 0) {
        index = -8 + (number - range.first); // active system, axis
    } else {
        index += number - range.first;
    }
    return {range.kind, range.readOnly, index};
}

std::string_view kindName(VariableKind kind) {
    switch (kind) {
    case VariableKind::Undefined: return "undefined";
    case VariableKind::Null: return "null (#0, always vacant)";
    case VariableKind::Local: return "local";
    case VariableKind::Common: return "common";
    case VariableKind::Retained: return "retained common";
    case VariableKind::Parameter: return "parameter";
    case VariableKind::WorkOffset: return "work offset";
    case VariableKind::MachinePosition: return "machine position";
    case VariableKind::WorkPosition: return "work position";
    case VariableKind::BlockEnd: return "block end position";
    case VariableKind::SkipPosition: return "skip position";
    case VariableKind::ProbeResult: return "G31 result";
    case VariableKind::ActiveWorkSystem: return "active work system";
    case VariableKind::Message: return "status-line message";
    case VariableKind::Dialog: return "operator dialog";
    case VariableKind::Input: return "input";
    case VariableKind::Output: return "output";
    case VariableKind::Homed: return "homed flag";
    case VariableKind::AxisCount: return "axis count";
    case VariableKind::InterfaceInput: return "interface input";
    case VariableKind::InterfaceInputs: return "interface inputs, 16 bits";
    case VariableKind::InterfaceOutput: return "interface output";
    case VariableKind::InterfaceOutputs: return "interface outputs";
    case VariableKind::OperationControl: return "automatic operation control";
    case VariableKind::Alarm: return "alarm";
    case VariableKind::StopMessage: return "stop with message";
    case VariableKind::ModalGroup: return "modal group";
    case VariableKind::ModalWord: return "modal word";
    case VariableKind::ToolOffset: return "tool offset";
    case VariableKind::SpindleLoad: return "spindle load % x 100";
    case VariableKind::System: return "system";
    }
    return "undefined";
}

std::string_view kindChinese(VariableKind kind) {
    switch (kind) {
    case VariableKind::Undefined: return "未定义";
    case VariableKind::Null: return "空变量(#0，始终为空)";
    case VariableKind::Local: return "局部变量";
    case VariableKind::Common: return "公共变量";
    case VariableKind::Retained: return "保持型公共变量";
    case VariableKind::Parameter: return "参数";
    case VariableKind::WorkOffset: return "工件坐标偏置";
    case VariableKind::MachinePosition: return "机床坐标";
    case VariableKind::WorkPosition: return "工件坐标";
    case VariableKind::BlockEnd: return "程序段终点坐标";
    case VariableKind::SkipPosition: return "跳转位置";
    case VariableKind::ProbeResult: return "G31结果";
    case VariableKind::ActiveWorkSystem: return "当前工件坐标系";
    case VariableKind::Message: return "状态栏信息";
    case VariableKind::Dialog: return "操作员对话框";
    case VariableKind::Input: return "输入";
    case VariableKind::Output: return "输出";
    case VariableKind::Homed: return "回零标志";
    case VariableKind::AxisCount: return "轴数";
    case VariableKind::InterfaceInput: return "接口输入";
    case VariableKind::InterfaceInputs: return "接口输入(16位)";
    case VariableKind::InterfaceOutput: return "接口输出";
    case VariableKind::InterfaceOutputs: return "接口输出";
    case VariableKind::OperationControl: return "自动运行控制";
    case VariableKind::Alarm: return "报警";
    case VariableKind::StopMessage: return "停止并显示信息";
    case VariableKind::ModalGroup: return "模态组";
    case VariableKind::ModalWord: return "模态字";
    case VariableKind::ToolOffset: return "刀具偏置";
    case VariableKind::SpindleLoad: return "主轴负载% x 100";
    case VariableKind::System: return "系统变量";
    }
    return "未定义";
}

Message VariableMap::undefinedWords(int number) const {
    if (!commonText_.empty() && ((number >= 100 && number <= 999) || number >= 20000)) {
        return message("variable_undefined_common", {std::to_string(number), std::string(dialectName_), commonText_});
    }
    return message("variable_undefined", {std::to_string(number), std::string(dialectName_)});
}

std::string VariableMap::describeWords(int number) const {
    const std::string english = describeText(number);
    const VariableKind kind = describe(number).kind;
    // the same text with the kind's name in Chinese: "#1001 (input IN01)" -> "#1001 (输入 IN01)"
    std::string chinese = english;
    const std::string_view name = kindName(kind);
    if (const std::size_t at = chinese.find(name); at != std::string::npos) {
        chinese.replace(at, name.size(), kindChinese(kind));
    }
    return bilingual(english, chinese);
}

std::string VariableMap::undefinedText(int number) const {
    std::string text = "#" + std::to_string(number) + " does not exist in the " + std::string(dialectName_) + " dialect";
    if (!commonText_.empty() && ((number >= 100 && number <= 999) || number >= 20000)) {
        text += " (this machine's common variables are " + commonText_ + ": machine.toml [variables] common)";
    }
    return text;
}

std::string VariableMap::describeText(int number) const {
    VariableInfo info = describe(number);
    std::string text = "#" + std::to_string(number) + " (" + std::string(kindName(info.kind));
    switch (info.kind) {
    case VariableKind::Parameter: text += " " + std::to_string(info.index); break;
    case VariableKind::Input: text += " IN" + std::string(info.index < 10 ? "0" : "") + std::to_string(info.index); break;
    case VariableKind::Output: text += " OUT" + std::string(info.index < 10 ? "0" : "") + std::to_string(info.index); break;
    case VariableKind::InterfaceInput: text += " UI0" + std::string(info.index < 10 ? "0" : "") + std::to_string(info.index); break;
    case VariableKind::InterfaceOutput: text += " UO0" + std::string(info.index < 10 ? "0" : "") + std::to_string(info.index); break;
    default: break;
    }
    return text + ")";
}

} // namespace m350::macro
