#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace m350::params {

// The text of a TOML file with the numeric keys of one table set to new values, every other byte
// kept: comments, blank lines, order, the spacing around `=` and a comment after the value. A key
// the table lacks is added after its last entry (in ascending order); a missing table is added at
// the end. Only `N = number` lines are edited (the shape params.toml and variables.toml have).
// With `addMissing` false, only keys the table lists change and nothing is added.
std::string setTomlNumbers(std::string_view text, std::string_view table, const std::map<int, double>& values,
                           bool addMissing = true);

// A number as the writer puts it in a TOML file: the shortest text that reads back as the same
// double ("3000", "0.5", "-30", "1e-07").
std::string tomlNumber(double value);

} // namespace m350::params
