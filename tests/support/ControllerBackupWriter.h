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
