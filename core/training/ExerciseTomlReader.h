#pragma once

#include "core/files/Toml.h"
#include "core/training/Exercise.h"

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace m350::training {

// Thrown by ExerciseTomlReader::refuse; loadExercise and loadExam return its error.
struct ExerciseRefusal {
    ExerciseError error;
};

// Reads a training file's TOML (exercise.toml, exam.toml): every value checked where it is, every
// refusal thrown as ExerciseRefusal at the node concerned (file:line:col, by message id).
class ExerciseTomlReader {
public:
    explicit ExerciseTomlReader(std::string file) : file_(std::move(file)) {}

    [[noreturn]] void refuse(const toml::source_region& where, Message words) const;
    [[noreturn]] void refuseFile(Message words) const { refuse(toml::source_region{}, std::move(words)); }
    // The file read and parsed (a regular file of a machine file's size at most).
    toml::table parse() const;

    // Every key of `table` is one of `known` (a typo in an exercise is a check that never runs).
    void onlyKeys(const toml::table& table, std::initializer_list<std::string_view> known, const std::string& in) const;
    const toml::node& required(const toml::table& table, std::string_view key, const toml::source_region& where) const;
    double number(const toml::node& node, std::string_view key) const; // finite
    int whole(const toml::node& node, std::string_view key, int low, int high) const;
    std::string text(const toml::node& node, std::string_view key) const;
    const toml::table& table(const toml::node& node, std::string_view key) const;
    // [title] zh_CN = "..." en = "...": both, never one alone (every word a trainee sees is in both).
    LocalText localText(const toml::node& node, std::string_view key) const;
    // [hints] zh_CN = [...] en = [...], as many in each.
    std::vector<LocalText> hints(const toml::node& node) const;

    const std::string& file() const { return file_; }

private:
    std::string file_;
};

} // namespace m350::training
