#include "tests/golden/JsonDiff.h"

#include <cmath>

namespace m350::testing {

namespace {

using nlohmann::json;

std::string shown(const json& j) {
    return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string escaped(const std::string& key) {
    std::string out; // JSON Pointer escaping: ~ as ~0, / as ~1
    for (char c : key) {
        out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    }
    return out;
}

void compare(const json& expected, const json& actual, const std::string& path, double tolerance,
             std::vector<std::string>& out) {
    const std::string where = path.empty() ? "/" : path;
    if (expected.is_number() && actual.is_number()) {
        double e = expected.get<double>();
        double a = actual.get<double>();
        if (!(std::abs(e - a) <= tolerance)) {
            out.push_back(where + ": expected " + shown(expected) + ", got " + shown(actual));
        }
        return;
    }
    if (expected.type() != actual.type()) {
        out.push_back(where + ": expected " + shown(expected) + ", got " + shown(actual));
        return;
    }
    if (expected.is_object()) {
        for (const auto& [key, value] : expected.items()) {
            if (!actual.contains(key)) {
                out.push_back(path + "/" + escaped(key) + ": missing (expected " + shown(value) + ")");
            } else {
                compare(value, actual.at(key), path + "/" + escaped(key), tolerance, out);
            }
        }
        for (const auto& [key, value] : actual.items()) {
            if (!expected.contains(key)) {
                out.push_back(path + "/" + escaped(key) + ": unexpected (got " + shown(value) + ")");
            }
        }
        return;
    }
    if (expected.is_array()) {
        if (expected.size() != actual.size()) {
            out.push_back(where + ": expected " + std::to_string(expected.size()) + " element(s), got " +
                          std::to_string(actual.size()) + ": expected " + shown(expected) + ", got " +
                          shown(actual));
            return;
        }
        for (std::size_t i = 0; i < expected.size(); ++i) {
            compare(expected[i], actual[i], path + "/" + std::to_string(i), tolerance, out);
        }
        return;
    }
    if (expected != actual) {
        out.push_back(where + ": expected " + shown(expected) + ", got " + shown(actual));
    }
}

} // namespace

std::vector<std::string> jsonDifferences(const json& expected, const json& actual, double tolerance) {
    std::vector<std::string> out;
    compare(expected, actual, "", tolerance, out);
    return out;
}

} // namespace m350::testing
