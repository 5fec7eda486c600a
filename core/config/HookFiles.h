#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace m350::config {

// The M350's hook files: small programs on its system disk that the panel and the controller run
// when something happens (a key, a softkey, PAUSE, an alarm, power-on). A machine folder may hold
// any of them; without one the built-in behaviour stays (native homing, the MDI line the key
// stands for). This table is the one place that names their files.
enum class Hook : std::uint8_t {
    ToolWord, // T.nc: a T word set from the panel, #1504 = the target tool
    AllTools, // ALL_T.nc: M101, every tool in turn
    HomeAll,  // fndzero.nc
    HomeX,    // fndX.nc .. fndB.nc: one axis (HomeX + axis)
    HomeY,
    HomeZ,
    HomeA,
    HomeB,
    GoToWorkZero, // gotozero.nc
    AbsZero,      // abszero.nc: absolute-encoder homing of every axis
    AbsX,         // absX.nc .. absB.nc (AbsX + axis)
    AbsY,
    AbsZ,
    AbsA,
    AbsB,
    Probe,      // probe.nc: the Probe page's fixed setting
    MultiProbe, // mulprobe.nc: multi-tool setting over #1970-#1989, #1993
    Pause,      // pause.nc
    Error,      // error.nc
    PowerOn,    // sysstart.nc
    Key1,       // key-1.nc .. key-7.nc (Key1 + k - 1)
    Key2,
    Key3,
    Key4,
    Key5,
    Key6,
    Key7,
    ExtButton, // ext_button.nc: FUNC K01-K14, #1996 = the M code 250-263
    ExtKey1,   // extnc0-1.nc .. extnc5-1.nc: external keys 1-6 (ExtKey1 + k - 1)
    ExtKey2,
    ExtKey3,
    ExtKey4,
    ExtKey5,
    ExtKey6,
    M3, // the panel's M-code keys
    M4,
    M5,
    M8,
    M9,
    M10,
    M11,
    M19,
    Mdi,         // mdi.nc: the MDI program the M350 keeps beside mdiblock
    UserLibrary, // slibuser.nc: user G-code handlers O9100-O9199 (G100-G199), a library
};

// The Mdi hook's file, which the panel writes (config::MachineFolder, FolderFile::MdiProgram).
inline constexpr std::string_view kMdiProgramFile = "mdi.nc";

// M101 runs ALL_T.nc: the M350 changes to every tool in turn.
inline constexpr int kAllToolsMCode = 101;

struct HookFile {
    Hook hook;
    std::string_view name;     // as `m350-sim hook NAME` takes it: "fndzero", "key-3", "T"
    std::string_view fileName; // in the machine folder: "fndzero.nc"
    std::string_view runsWhen; // what runs it, for usage texts
    std::string_view runsWhenZh; // the same in the panel's Chinese
    bool runnable = true;      // false for a library (slibuser.nc), which is loaded, not run
};

std::span<const HookFile> hookFiles();
const HookFile& hookFile(Hook hook);
// By its name, with or without ".nc", in any case ("fndx" is fndX.nc).
const HookFile* findHook(std::string_view name);
// What runs the hook, as a message argument in both languages (core/common/Message.h).
std::string runsWhenWords(const HookFile& hook);
// The names of the hooks `m350-sim hook` runs, comma separated, for usage messages.
std::string runnableHookNames();
// The hook's file in the machine folder: its own name, or the same name in another case (a copy
// through a FAT-formatted USB stick may change it). nullopt when the folder has none.
std::optional<std::string> hookPath(const std::string& folder, Hook hook);

// The hooks of numbered keys and axes; nullopt outside their range.
std::optional<Hook> homeAxisHook(int axis);     // 0 X .. 4 B
std::optional<Hook> absoluteAxisHook(int axis); // 0 X .. 4 B
// The panel's Go Home: all axes (axis nullopt) or one; fndzero.nc / fndX.nc, or with absolute
// servos (param 100 = 1) abszero.nc / absX.nc.
std::optional<Hook> goHomeHook(std::optional<int> axis, bool absoluteEncoders);
std::optional<Hook> userKeyHook(int key);       // K1-K7
std::optional<Hook> externKeyHook(int key);     // external keys 1-6
std::optional<Hook> mCodeKeyHook(int code);     // 3 4 5 8 9 10 11 19

} // namespace m350::config
