#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace m350::testing {

// A copy of an M350's system disk as a test makes it: the controller's binary files (`setting`,
// `default_setting`, `coordinate`, `mdiblock`) in their own layouts, and .nc libraries and hook
// files written for the tests in the factory's style (nothing copied from a controller).
struct ControllerBackupWriter {
    std::array<double, 1000> setting{};
    std::array<double, 1000> defaults{};
    std::array<double, 45> coordinate{};
    std::array<std::string, 6> mdiLines;       // bytes as the panel stores them (GBK)
    std::map<std::string, std::string> files;  // name -> bytes: .nc files and the files to skip
    bool withDefaults = true, withCoordinate = true, withMdi = true;

    // A small router: a servo disc (magazine type 4, which the import cannot model) of 6 pockets,
    // home switches, fixed and floating setters, a clamp on OUT01/IN11, offsets in G54, G55 and
    // the common offset, three MDI lines (one GBK comment), slib-g.nc with O20000 (T) and O502 (one pass on the fixed setter),
    // slib-m.nc with O10006 (M6), T.nc, a GBK pause.nc, and bitmaps, a module, logs and a
    // string table that the import skips.
    static ControllerBackupWriter smallRouter();

    // An owner's dual-Y gantry router as its system disk holds it: soft limits on (param 155),
    // home switches for X, Y, Z (NPN) searched by the library's O501 with a long G31, the 4th motor
    // driving the gantry's second side as Y (param 491 = 1), lubrication on OUT09 (params 733-735,
    // 94) and coolant on OUT08, no magazine, param 969 at the factory's 0 (outside its range).
    // slib-g.nc holds O501; slib-m.nc the M30 handler O10030 (M5M9M11, the counters); fndzero.nc
    // homes Z, X, Y by O501 and gives A Y's position; key-2.nc lubricates the guides (M10, M11);
    // key-3.nc sets the work Z on the floating block, clearing #1922 between its probes.
    static ControllerBackupWriter dualYGantry();

    void writeTo(const std::filesystem::path& folder) const;
};

// n little-endian float64, as the controller writes `setting` and `coordinate`.
std::string float64File(const double* values, std::size_t count);
// The six lines, 120 bytes each, NUL-padded.
std::string mdiBlock(const std::array<std::string, 6>& lines);
std::string readFile(const std::filesystem::path& file);
// "浮动对刀" and the like as GBK bytes, written out so the tests need no converter.
inline const std::string kGbkPause = "\xd4\xdd\xcd\xa3";  // 暂停
inline const std::string kGbkTest = "\xb2\xe2\xca\xd4";   // 测试

} // namespace m350::testing
