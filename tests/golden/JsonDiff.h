#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace m350::testing {

// The differences between two JSON documents, one readable line each, addressed by JSON Pointer:
//   /vars/1300: expected 2, got 1
//   /messages: expected 1 element(s), got 0
// Numbers compare with an absolute tolerance (integers and floats alike, so 2 equals 2.0); object
// keys must match exactly; arrays compare element by element. Empty when the documents agree.
std::vector<std::string> jsonDifferences(const nlohmann::json& expected, const nlohmann::json& actual,
                                         double tolerance = 1e-9);

} // namespace m350::testing
