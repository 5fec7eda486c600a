#pragma once
// The mould-like program of the preview benchmarks (issue 27): G1/G2/G3 lines as a CAM finishing
// pass writes them, in a temporary file made once per size. Shared by the core's PreviewBench and
// the panel's MachineViewBench.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <unistd.h>

namespace m350::bench {

// A raster of 10 mm rows in a 200 x 200 mm pocket: G1 steps with a G2 or G3 half circle of 1 mm
// every third line, Z stepping down a little each row, as a CAM finishing pass looks.
// Written line by line: a 10M-line program is 340 MB, which the benchmark's memory must not hold.
inline void writeMouldProgram(std::ostream& out, std::size_t lines) {
    out << "G90 G17 G54\nG0 X0 Y0 Z5\nG1 Z0 F1500\n";
    char line[96];
    double x = 0.0, y = 0.0, z = 0.0;
    int dir = 1;
    for (std::size_t i = 0; i < lines; ++i) {
        int n = 0;
        if (i % 3 == 2) {
            // a half circle of radius 1 along the row
            const double to = x + 2.0 * dir;
            n = std::snprintf(line, sizeof line, "G%d X%.3f Y%.3f I%.3f J0\n", dir > 0 ? 2 : 3, to, y, double(dir));
            x = to;
        } else {
            if ((x > 200.0 && dir > 0) || (x < 0.0 && dir < 0)) {
                // the next row: this line steps over, the arcs stay in their row (only when moving
                // outward: the check turned back and forth at the edge, so the rows never reversed
                // and the "raster" was a band kilometres long)
                dir = -dir;
                y = y > 200.0 ? 0.0 : y + 0.2;
            }
            x += 0.05 * dir;
            z = -0.001 * double(i % 1000);
            n = std::snprintf(line, sizeof line, "G1 X%.3f Y%.3f Z%.3f\n", x, y, z);
        }
        out.write(line, n);
    }
    out << "G0 Z5\nM30\n";
}

class TempProgram {
public:
    explicit TempProgram(std::size_t lines)
        : path_(std::filesystem::temp_directory_path() /
                ("m350-preview-bench-" + std::to_string(::getpid()) + "-" + std::to_string(lines) + ".nc")) {
        std::ofstream out(path_, std::ios::binary | std::ios::trunc);
        writeMouldProgram(out, lines);
    }
    ~TempProgram() {
        std::error_code ignored;
        std::filesystem::remove(path_, ignored);
    }
    std::string path() const { return path_.string(); }

private:
    std::filesystem::path path_;
};

inline const TempProgram& program(std::size_t lines) {
    static std::map<std::size_t, std::unique_ptr<TempProgram>> files;
    auto& slot = files[lines];
    if (!slot) {
        slot = std::make_unique<TempProgram>(lines);
    }
    return *slot;
}

} // namespace m350::bench
