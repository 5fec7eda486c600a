#include "core/params/IoPorts.h"

#include "core/common/Numeric.h"

#include <algorithm>
#include <iterator>
#include <cstdio>

namespace m350::params {
namespace {

constexpr int kInputPins = 24; // IN01-IN24

// The IO page's functions (parameter catalogue, group "IO"): short names for messages.
constexpr IoFunction kFunctions[] = {
    {500, true, "X servo alarm", "X轴驱动器报警"},
    {503, true, "Y servo alarm", "Y轴驱动器报警"},
    {506, true, "Z servo alarm", "Z轴驱动器报警"},
    {509, true, "4th servo alarm", "4th轴驱动器报警"},
    {512, true, "5th servo alarm", "5th轴驱动器报警"},
    {515, true, "X- limit", "X轴负向限位"},
    {518, true, "Y- limit", "Y轴负向限位"},
    {521, true, "Z- limit", "Z轴负向限位"},
    {524, true, "4th- limit", "4th轴负向限位"},
    {527, true, "5th- limit", "5th轴负向限位"},
    {530, true, "X+ limit", "X轴正向限位"},
    {533, true, "Y+ limit", "Y轴正向限位"},
    {536, true, "Z+ limit", "Z轴正向限位"},
    {539, true, "4th+ limit", "4th轴正向限位"},
    {542, true, "5th+ limit", "5th轴正向限位"},
    {545, true, "X home switch", "X轴零点"},
    {548, true, "Y home switch", "Y轴零点"},
    {551, true, "Z home switch", "Z轴零点"},
    {554, true, "4th home switch", "4th轴零点"},
    {557, true, "5th home switch", "5th轴零点"},
    {575, true, "fixed tool setter", "固定对刀"},
    {578, true, "floating tool setter", "浮动对刀"},
    {581, true, "extern key 1", "扩展按键1"},
    {584, true, "extern key 2", "扩展按键2"},
    {587, true, "extern key 3", "扩展按键3"},
    {590, true, "extern key 4", "扩展按键4"},
    {593, true, "extern key 5", "扩展按键5"},
    {596, true, "extern key 6", "扩展按键6"},
    {599, true, "extern START", "外部启动"},
    {602, true, "extern PAUSE", "外部暂停"},
    {605, true, "extern E-stop", "外部急停"},
    {620, true, "spindle stopped", "主轴停止检测"},
    {623, true, "tool released", "刀具松开检测"},
    {626, true, "tool clamped", "刀具锁紧检测"},
    {629, true, "magazine out", "刀库推出检测"},
    {632, true, "dust cover", "除尘罩检测"},
    {635, true, "inverter alarm", "变频器报警"},
    {638, true, "custom alarm 1", "自定义报警1"},
    {641, true, "custom alarm 2", "自定义报警2"},
    {644, true, "custom alarm 3", "自定义报警3"},
    {647, true, "custom alarm 4", "自定义报警4"},
    {650, true, "custom alarm 5", "自定义报警5"},
    {697, true, "magazine in", "刀库收回检测"},
    {715, false, "spindle forward", "主轴正转"},
    {718, false, "spindle reverse", "主轴反转"},
    {721, false, "spindle speed step 1", "主轴多段数1"},
    {724, false, "spindle speed step 2", "主轴多段数2"},
    {727, false, "spindle speed step 3", "主轴多段数3"},
    {730, false, "coolant", "冷却"},
    {733, false, "lubrication", "润滑"},
    {736, false, "alarm lamp", "系统报警灯"},
    {739, false, "run lamp", "系统运行灯"},
    {742, false, "brake", "系统抱闸"},
    {745, false, "ready lamp", "系统准备好指示灯"},
    {750, false, "tool release", "刀具松开/锁紧"},
    {753, false, "magazine out", "刀库推出/收回"},
    {756, false, "front locating cylinder", "前定位气缸"},
    {759, false, "vacuum pump", "真空泵"},
    {762, false, "dust cover open", "除尘罩打开/关闭"},
    {765, false, "push cylinder", "推料气缸"},
    {768, false, "vacuum cleaner", "吸尘器"},
    {771, false, "left locating cylinder", "左定位气缸"},
    {774, false, "vacuum valve", "真空阀"},
    {777, false, "multi-process cylinder 1", "多工序气缸1"},
    {780, false, "multi-process cylinder 2", "多工序气缸2"},
    {783, false, "multi-process cylinder 3", "多工序气缸3"},
    {786, false, "multi-process cylinder 4", "多工序气缸4"},
    {789, false, "coolant 1", "1号冷却液"},
    {792, false, "coolant 2", "2号冷却液"},
};

std::string portName(const char* prefix, int pin) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%s%02d", prefix, pin);
    return buffer;
}

std::optional<PortAssignment> onPin(const ParameterTable& parameters, int pin, bool input) {
    for (const IoFunction& f : kFunctions) {
        if (f.input != input) {
            continue;
        }
        PortAssignment a = portAssignment(parameters, f.parameter);
        if (a.wired() && a.pin == pin) {
            return a;
        }
    }
    return std::nullopt;
}

} // namespace

std::span<const IoFunction> ioFunctions() {
    return kFunctions;
}

const IoFunction* ioFunction(int parameter) {
    auto it = std::find_if(std::begin(kFunctions), std::end(kFunctions),
                           [parameter](const IoFunction& f) { return f.parameter == parameter; });
    return it == std::end(kFunctions) ? nullptr : &*it;
}

PortAssignment portAssignment(const ParameterTable& parameters, int functionParameter) {
    PortAssignment a;
    a.function = ioFunction(functionParameter);
    a.pin = saturatingInt(parameters.get(functionParameter));
    a.enabled = parameters.get(functionParameter + 1) != 0.0;
    a.activeLevel = parameters.get(functionParameter + 2) != 0.0 ? 1 : 0;
    return a;
}

std::optional<PortAssignment> wiredInput(const ParameterTable& parameters, int functionParameter) {
    PortAssignment a = portAssignment(parameters, functionParameter);
    if (!a.wired() || a.pin > kInputPins) {
        return std::nullopt;
    }
    return a;
}

std::optional<PortAssignment> inputOnPin(const ParameterTable& parameters, int pin) {
    return onPin(parameters, pin, true);
}

std::optional<PortAssignment> outputOnPin(const ParameterTable& parameters, int pin) {
    return onPin(parameters, pin, false);
}

std::string inputName(int pin) {
    return portName("IN", pin);
}

std::string outputName(int pin) {
    return portName("OUT", pin);
}

std::string describeInput(const ParameterTable& parameters, int pin, bool chinese) {
    auto a = inputOnPin(parameters, pin);
    return inputName(pin) +
           (a ? std::string(" (") + (chinese ? a->function->nameZh : a->function->nameEn) + ")" : std::string());
}

} // namespace m350::params
