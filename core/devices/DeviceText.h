#pragma once

// How the devices name what they report: "X110.000 Y5.000 Z-80.000", "T2", "pocket 3".
#include <Eigen/Core>

#include <cstdio>
#include <string>

namespace m350::devices::text {

inline std::string position(const Eigen::Vector3d& p) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "X%.3f Y%.3f Z%.3f", p.x(), p.y(), p.z());
    return buffer;
}

inline std::string millimetres(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3f", v);
    return buffer;
}

// A tool or pocket number as a message argument (the pattern says "T%1", "pocket %1").
inline std::string number(int n) {
    return std::to_string(n);
}

inline std::string tool(int t) {
    return "T" + std::to_string(t);
}

inline std::string pocket(int k) {
    return "pocket " + std::to_string(k);
}

} // namespace m350::devices::text
