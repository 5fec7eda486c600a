#include "tests/diff/Rs274Canon.h"

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <regex>
#include <sstream>
#include <utility>

namespace m350::testing {

namespace {

// The numbers in a call's arguments, which rs274 separates by commas, spaces or both.
std::vector<double> numbersIn(const std::string& arguments) {
    std::vector<double> numbers;
    std::string token;
    auto flush = [&] {
        if (!token.empty()) {
            char* end = nullptr;
            double value = std::strtod(token.c_str(), &end);
            if (end != token.c_str() && *end == '\0') {
                numbers.push_back(value);
            }
            token.clear();
        }
    };
    for (char c : arguments) {
        if (c == ',' || c == ' ' || c == '\t') {
            flush();
        } else {
            token += c;
        }
    }
    flush();
    return numbers;
}

enum class Plane { XY, XZ, YZ };

class CanonReader {
  public:
    void read(const std::string& line) {
        static const std::regex call(R"(^\s*\d+\s+\S+\s+([A-Z][A-Z0-9_]*)\((.*)\)\s*$)");
        std::smatch m;
        if (!std::regex_match(line, m, call)) {
            return; // not a canonical call (rs274 prints nothing else on stdout, but be lenient)
        }
        const std::string name = m[1];
        const std::string arguments = m[2];
        if (name == "COMMENT" || name == "MESSAGE") {
            return; // free text: its numbers mean nothing here
        }
        const std::vector<double> n = numbersIn(arguments);
        if (name == "USE_LENGTH_UNITS") {
            readUnits(arguments, line);
        } else if (name == "SET_G5X_OFFSET" && n.size() >= 4) {
            g5x_ = scaled(n, 1);
        } else if (name == "SET_G92_OFFSET" && n.size() >= 3) {
            g92_ = scaled(n, 0);
        } else if (name == "USE_TOOL_LENGTH_OFFSET" && n.size() >= 3) {
            tool_ = scaled(n, 0);
        } else if (name == "SET_XY_ROTATION") {
            if (n.empty()) {
                problem("a rotation without an angle", line);
            } else {
                rotation_ = n[0] * std::numbers::pi / 180.0;
            }
        } else if (name == "SELECT_PLANE") {
            readPlane(arguments, line);
        } else if ((name == "STRAIGHT_TRAVERSE" || name == "STRAIGHT_FEED") && n.size() >= 3) {
            move(name == "STRAIGHT_TRAVERSE" ? "rapid" : "feed", scaled(n, 0), line);
        } else if (name == "ARC_FEED" && n.size() >= 6) {
            arc(n, line);
        } else if (name == "PROGRAM_END") {
            run_.programEnded = true;
        } else if (name == "STRAIGHT_PROBE" || name == "RIGID_TAP" || name == "NURBS_FEED" ||
                   name.find("SPLINE") != std::string::npos) {
            problem("motion call not followed", line);
        } else if (name == "SET_G5X_OFFSET" || name == "SET_G92_OFFSET" || name == "USE_TOOL_LENGTH_OFFSET" ||
                   name == "STRAIGHT_TRAVERSE" || name == "STRAIGHT_FEED" || name == "ARC_FEED") {
            problem("too few numbers", line);
        }
    }

    CanonRun take() { return std::move(run_); }

  private:
    Point scaled(const std::vector<double>& n, std::size_t first) const {
        return {n[first] * scale_, n[first + 1] * scale_, n[first + 2] * scale_};
    }

    void readUnits(const std::string& arguments, const std::string& line) {
        if (arguments.find("CANON_UNITS_MM") != std::string::npos) {
            scale_ = 1.0;
        } else if (arguments.find("CANON_UNITS_INCHES") != std::string::npos) {
            scale_ = 25.4;
        } else if (arguments.find("CANON_UNITS_CM") != std::string::npos) {
            scale_ = 10.0;
        } else {
            problem("unknown length unit", line);
        }
    }

    void readPlane(const std::string& arguments, const std::string& line) {
        if (arguments == "CANON_PLANE_XY") {
            plane_ = Plane::XY;
        } else if (arguments == "CANON_PLANE_XZ") {
            plane_ = Plane::XZ;
        } else if (arguments == "CANON_PLANE_YZ") {
            plane_ = Plane::YZ;
        } else {
            problem("plane not followed", line);
        }
    }

    // The indices into X Y Z of the plane's first and second axis and of its normal.
    std::array<std::size_t, 3> planeAxes() const {
        switch (plane_) {
        case Plane::XZ:
            return {2, 0, 1};
        case Plane::YZ:
            return {1, 2, 0};
        case Plane::XY:
            break;
        }
        return {0, 1, 2};
    }

    void arc(const std::vector<double>& n, const std::string& line) {
        const auto [first, second, normal] = planeAxes();
        Point end{};
        end[first] = n[0] * scale_;
        end[second] = n[1] * scale_;
        end[normal] = n[5] * scale_;
        const Point start = last_;
        move("arc", end, line);
        const Point& to = run_.moves.back().machine;
        Point centre = end;
        centre[first] = n[2] * scale_;
        centre[second] = n[3] * scale_;
        centre = toMachine(centre);
        const double cFirst = centre[first];
        const double cSecond = centre[second];
        const int turns = static_cast<int>(std::lround(n[4]));
        if (turns == 0) {
            problem("an arc of 0 turns", line);
            return;
        }
        constexpr double kTurn = 2 * std::numbers::pi;
        const double a0 = std::atan2(start[second] - cSecond, start[first] - cFirst);
        const double a1 = std::atan2(to[second] - cSecond, to[first] - cFirst);
        double sweep = std::fmod(turns > 0 ? a1 - a0 : a0 - a1, kTurn);
        if (sweep < 0) {
            sweep += kTurn;
        }
        if (std::hypot(to[first] - start[first], to[second] - start[second]) < 1e-3) {
            sweep = kTurn; // ends where it starts: rounding may leave a hair either side of 0
        }
        sweep += (std::abs(turns) - 1) * kTurn;
        const double radius = (std::hypot(start[first] - cFirst, start[second] - cSecond) +
                               std::hypot(to[first] - cFirst, to[second] - cSecond)) /
                              2;
        run_.moves.back().arcLength = std::hypot(radius * sweep, to[normal] - start[normal]);
    }

    // As LinuxCNC's canon turns a program position into a machine one (emccanon.cc,
    // rotate_and_offset_pos): the G92 offset added, then turned about Z by the G5x system's
    // rotation (G10 L2 R), then the G5x and tool offsets added.
    Point toMachine(const Point& canonical) const {
        Point p{};
        for (std::size_t i = 0; i < 3; ++i) {
            p[i] = canonical[i] + g92_[i];
        }
        const double x = p[0];
        const double y = p[1];
        p[0] = x * std::cos(rotation_) - y * std::sin(rotation_);
        p[1] = x * std::sin(rotation_) + y * std::cos(rotation_);
        for (std::size_t i = 0; i < 3; ++i) {
            p[i] += g5x_[i] + tool_[i];
        }
        return p;
    }

    void move(const char* kind, const Point& canonical, const std::string& line) {
        CanonMove m{kind, toMachine(canonical), 0.0, line};
        last_ = m.machine;
        run_.moves.push_back(std::move(m));
    }

    void problem(const std::string& what, const std::string& line) {
        run_.problems.push_back(what + ": " + line);
    }

    CanonRun run_;
    double scale_ = 1.0; // millimetres per printed length unit
    Plane plane_ = Plane::XY;
    Point g5x_{};
    Point g92_{};
    Point tool_{};
    double rotation_ = 0.0; // radians, counter-clockwise about Z
    Point last_{}; // machine position after the last move: where rs274 starts, with no offsets, is 0
};

} // namespace

CanonRun readCanonOutput(const std::string& output) {
    CanonReader reader;
    std::istringstream in(output);
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') {
            line.pop_back();
        }
        reader.read(line);
    }
    return reader.take();
}

} // namespace m350::testing
