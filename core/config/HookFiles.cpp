#include "core/config/HookFiles.h"

#include "core/common/Message.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>

#include <dirent.h>

namespace m350::config {

namespace {

using H = Hook;

// In the order of the enum: hookFile() indexes it.
constexpr std::array kHooks{
    HookFile{H::ToolWord, "T", "T.nc", "a T word set from the panel (#1504 = the target tool)", "从面板设定T指令（#1504 = 目标刀号）"},
    HookFile{H::AllTools, "ALL_T", "ALL_T.nc", "M101: every tool in turn", "M101：依次换上每把刀"},
    HookFile{H::HomeAll, "fndzero", "fndzero.nc", "Go Home, all axes (回机械原点)", "回机械原点，全部轴"},
    HookFile{H::HomeX, "fndX", "fndX.nc", "Go Home, X", "回机械原点，X轴"},
    HookFile{H::HomeY, "fndY", "fndY.nc", "Go Home, Y", "回机械原点，Y轴"},
    HookFile{H::HomeZ, "fndZ", "fndZ.nc", "Go Home, Z", "回机械原点，Z轴"},
    HookFile{H::HomeA, "fndA", "fndA.nc", "Go Home, the 4th axis", "回机械原点，第4轴"},
    HookFile{H::HomeB, "fndB", "fndB.nc", "Go Home, the 5th axis", "回机械原点，第5轴"},
    HookFile{H::GoToWorkZero, "gotozero", "gotozero.nc", "Go Work Zero, all axes (回工件原点)", "回工件原点，全部轴"},
    HookFile{H::AbsZero, "abszero", "abszero.nc", "absolute-encoder homing, all axes", "绝对值编码器回零，全部轴"},
    HookFile{H::AbsX, "absX", "absX.nc", "absolute-encoder homing, X", "绝对值编码器回零，X轴"},
    HookFile{H::AbsY, "absY", "absY.nc", "absolute-encoder homing, Y", "绝对值编码器回零，Y轴"},
    HookFile{H::AbsZ, "absZ", "absZ.nc", "absolute-encoder homing, Z", "绝对值编码器回零，Z轴"},
    HookFile{H::AbsA, "absA", "absA.nc", "absolute-encoder homing, the 4th axis", "绝对值编码器回零，第4轴"},
    HookFile{H::AbsB, "absB", "absB.nc", "absolute-encoder homing, the 5th axis", "绝对值编码器回零，第5轴"},
    HookFile{H::Probe, "probe", "probe.nc", "the Probe page's fixed setting (#1502 = 1 first, 2 again)", "对刀页面的固定对刀（先#1502 = 1，再次为2）"},
    HookFile{H::MultiProbe, "mulprobe", "mulprobe.nc", "the Probe page's multi-tool setting (tools in #1970-#1989)", "对刀页面的多刀固定对刀（刀具在#1970-#1989中）"},
    HookFile{H::Pause, "pause", "pause.nc", "PAUSE, M00 or G04 P-1 holding a run", "暂停键、M00或G04 P-1暂停运行时"},
    HookFile{H::Error, "error", "error.nc", "an alarm", "报警时"},
    HookFile{H::PowerOn, "sysstart", "sysstart.nc", "power-on, before the boot homing prompt", "开机时，回零提示之前"},
    HookFile{H::Key1, "key-1", "key-1.nc", "K1 while param 210 = 0", "参数210 = 0时的K1键"},
    HookFile{H::Key2, "key-2", "key-2.nc", "K2 while param 211 = 0", "参数211 = 0时的K2键"},
    HookFile{H::Key3, "key-3", "key-3.nc", "K3 while param 212 = 0", "参数212 = 0时的K3键"},
    HookFile{H::Key4, "key-4", "key-4.nc", "K4 while param 213 = 0", "参数213 = 0时的K4键"},
    HookFile{H::Key5, "key-5", "key-5.nc", "K5 while param 214 = 0", "参数214 = 0时的K5键"},
    HookFile{H::Key6, "key-6", "key-6.nc", "K6 while param 215 = 0", "参数215 = 0时的K6键"},
    HookFile{H::Key7, "key-7", "key-7.nc", "K7 while param 216 = 0", "参数216 = 0时的K7键"},
    HookFile{H::ExtButton, "ext_button", "ext_button.nc", "FUNC K01-K14 (#1996 = M250-M263)", "FUNC K01-K14（#1996 = M250-M263）"},
    HookFile{H::ExtKey1, "extnc0-1", "extnc0-1.nc", "external key 1 while param 272 = 0", "参数272 = 0时的外部按键1"},
    HookFile{H::ExtKey2, "extnc1-1", "extnc1-1.nc", "external key 2 while param 273 = 0", "参数273 = 0时的外部按键2"},
    HookFile{H::ExtKey3, "extnc2-1", "extnc2-1.nc", "external key 3 while param 274 = 0", "参数274 = 0时的外部按键3"},
    HookFile{H::ExtKey4, "extnc3-1", "extnc3-1.nc", "external key 4 while param 275 = 0", "参数275 = 0时的外部按键4"},
    HookFile{H::ExtKey5, "extnc4-1", "extnc4-1.nc", "external key 5 while param 276 = 0", "参数276 = 0时的外部按键5"},
    HookFile{H::ExtKey6, "extnc5-1", "extnc5-1.nc", "external key 6 while param 277 = 0", "参数277 = 0时的外部按键6"},
    HookFile{H::M3, "M3", "M3.nc", "the M3 key", "M3键"},
    HookFile{H::M4, "M4", "M4.nc", "the M4 key", "M4键"},
    HookFile{H::M5, "M5", "M5.nc", "the M5 key", "M5键"},
    HookFile{H::M8, "M8", "M8.nc", "the M8 key", "M8键"},
    HookFile{H::M9, "M9", "M9.nc", "the M9 key", "M9键"},
    HookFile{H::M10, "M10", "M10.nc", "the M10 key", "M10键"},
    HookFile{H::M11, "M11", "M11.nc", "the M11 key", "M11键"},
    HookFile{H::M19, "M19", "M19.nc", "the M19 key", "M19键"},
    HookFile{H::Mdi, "mdi", kMdiProgramFile, "the MDI program kept beside mdiblock", "mdiblock旁保存的MDI程序"},
    HookFile{H::UserLibrary, "slibuser", "slibuser.nc", "user G-code handlers O9100-O9199 (G100-G199)", "用户G代码处理程序O9100-O9199（G100-G199）", false},
};

constexpr bool inEnumOrder() {
    for (std::size_t i = 0; i < kHooks.size(); ++i) {
        if (static_cast<std::size_t>(kHooks[i].hook) != i) {
            return false;
        }
    }
    return true;
}
static_assert(inEnumOrder(), "kHooks must list the hooks in the order of the enum");

bool sameIgnoringCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

std::optional<Hook> offset(Hook first, int index, int count) {
    if (index < 0 || index >= count) {
        return std::nullopt;
    }
    return static_cast<Hook>(static_cast<int>(first) + index);
}

} // namespace

std::span<const HookFile> hookFiles() { return kHooks; }

const HookFile& hookFile(Hook hook) { return kHooks[static_cast<std::size_t>(hook)]; }

const HookFile* findHook(std::string_view name) {
    if (name.size() > 3 && sameIgnoringCase(name.substr(name.size() - 3), ".nc")) {
        name.remove_suffix(3);
    }
    for (const HookFile& hook : kHooks) {
        if (sameIgnoringCase(hook.name, name)) {
            return &hook;
        }
    }
    return nullptr;
}

std::string runsWhenWords(const HookFile& hook) { return bilingual(hook.runsWhen, hook.runsWhenZh); }

std::string runnableHookNames() {
    std::string names;
    for (const HookFile& hook : kHooks) {
        if (hook.runnable) {
            names += names.empty() ? "" : ", ";
            names += hook.name;
        }
    }
    return names;
}

std::optional<std::string> hookPath(const std::string& folder, Hook hook) {
    namespace fs = std::filesystem;
    if (folder.empty()) {
        return std::nullopt;
    }
    const std::string_view fileName = hookFile(hook).fileName;
    std::error_code ec;
    fs::path exact = fs::path(folder) / fileName;
    if (fs::is_regular_file(exact, ec)) {
        return exact.string();
    }
    // A hook in another case ("FNDZERO.NC" from a backup): the names are compared as readdir gives
    // them, since a program load and an MDI line ask for the hooks a folder lacks every time.
    DIR* dir = ::opendir(folder.c_str());
    if (dir == nullptr) {
        return std::nullopt;
    }
    std::optional<std::string> found;
    while (const dirent* entry = ::readdir(dir)) {
        if (sameIgnoringCase(entry->d_name, fileName)) {
            const fs::path candidate = fs::path(folder) / entry->d_name;
            if (fs::is_regular_file(candidate, ec)) {
                found = candidate.string();
                break;
            }
        }
    }
    ::closedir(dir);
    return found;
}

std::optional<Hook> homeAxisHook(int axis) { return offset(Hook::HomeX, axis, 5); }
std::optional<Hook> absoluteAxisHook(int axis) { return offset(Hook::AbsX, axis, 5); }
std::optional<Hook> goHomeHook(std::optional<int> axis, bool absoluteEncoders) {
    if (!axis) {
        return absoluteEncoders ? Hook::AbsZero : Hook::HomeAll;
    }
    return absoluteEncoders ? absoluteAxisHook(*axis) : homeAxisHook(*axis);
}
std::optional<Hook> userKeyHook(int key) { return offset(Hook::Key1, key - 1, 7); }
std::optional<Hook> externKeyHook(int key) { return offset(Hook::ExtKey1, key - 1, 6); }

std::optional<Hook> mCodeKeyHook(int code) {
    const std::string name = "M" + std::to_string(code);
    for (auto h = static_cast<std::size_t>(Hook::M3); h <= static_cast<std::size_t>(Hook::M19); ++h) {
        if (kHooks[h].name == name) {
            return kHooks[h].hook;
        }
    }
    return std::nullopt;
}

} // namespace m350::config
