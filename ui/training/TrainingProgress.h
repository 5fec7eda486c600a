#pragma once

#include <QString>

#include <map>
#include <optional>

namespace m350::ui {

// What a trainee has done so far, exercise by exercise (the start page's status and best time):
// progress.json in the attempts folder, written whole and atomically after each hand-in.
class TrainingProgress {
public:
    struct Entry {
        int tries = 0;
        bool passed = false;
        std::optional<double> bestTime; // of the passed attempts, s
    };
    explicit TrainingProgress(QString file);
    const Entry* find(const QString& trainee, const QString& exercise) const;
    // Counts an attempt and saves; why the file could not be written, else empty.
    QString add(const QString& trainee, const QString& exercise, bool passed, double seconds);

private:
    QString file_;
    std::map<QString, std::map<QString, Entry>> entries_;
};

} // namespace m350::ui
