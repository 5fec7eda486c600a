#include "core/training/Exam.h"

#include "core/training/ExerciseTomlReader.h"

namespace m350::training {

std::variant<Exam, ExerciseError> loadExam(const std::string& file) {
    ExerciseTomlReader in(file);
    try {
        const toml::table root = in.parse();
        in.onlyKeys(root, {"exercises", "time_limit", "key"}, "exam");
        const toml::array* list = root["exercises"].as_array();
        if (!list || list->empty()) {
            in.refuse(root.source(), message("exam_no_exercises"));
        }
        Exam exam;
        for (const toml::node& name : *list) {
            exam.exercises.push_back(in.text(name, "exercises"));
            if (exam.exercises.back().empty()) {
                in.refuse(name.source(), message("exercise_not_text", {"exercises"}));
            }
        }
        if (const toml::node* limit = root.get("time_limit")) {
            exam.timeLimit = in.number(*limit, "time_limit");
            if (*exam.timeLimit <= 0.0) {
                in.refuse(limit->source(), message("exercise_time_limit"));
            }
        }
        if (const toml::node* key = root.get("key")) {
            exam.key = in.text(*key, "key");
        }
        return exam;
    } catch (const ExerciseRefusal& refusal) {
        return refusal.error;
    }
}

} // namespace m350::training
