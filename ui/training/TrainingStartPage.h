#pragma once

#include "core/training/Exercise.h"
#include "ui/training/TrainingProgress.h"

#include <QWidget>

#include <vector>

class QLabel;
class QTableWidget;

namespace m350::ui {

// 训练 Training's start page: the exercises with their level, the trainee's status (not tried /
// passed / failed) and best time, and the selected one's task below (or a hint, or a note).
class TrainingStartPage : public QWidget {
    Q_OBJECT
public:
    explicit TrainingStartPage(QWidget* parent = nullptr);
    void show(const std::vector<training::Exercise>& exercises, const TrainingProgress& progress, const QString& trainee,
              MessageLanguage language);
    int selected() const;
    void select(int row);
    void move(int by); // UP / DOWN
    void showText(const QString& text); // the task, a hint, why something was refused
    QString text() const;
    QTableWidget* table() const { return table_; }

private:
    QLabel* heading_;
    QTableWidget* table_;
    QLabel* text_;
};

} // namespace m350::ui
