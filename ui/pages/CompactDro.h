#pragma once

#include "ui/session/PanelSnapshot.h"

#include <QWidget>

#include <array>
#include <optional>

class QLabel;

namespace m350::ui {

// A small 机械坐标 / 工件坐标 table for the pages that move the machine without showing the big
// DRO (MDI, Probe), so the operator always sees where the axes are.
class CompactDro : public QWidget {
    Q_OBJECT
public:
    explicit CompactDro(QWidget* parent = nullptr);
    void render(const PanelSnapshot& snapshot);
    QString workText(int axis) const;
    QString axisText(int axis) const; // the row's name and unit ("A", "deg"), for tests
    QString unitText(int axis) const;
    bool axisVisible(int axis) const;

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    QLabel* machineHeader_;
    QLabel* workHeader_;
    std::array<QLabel*, 5> names_{};
    std::array<QLabel*, 5> machine_{};
    std::array<QLabel*, 5> work_{};
    std::array<QLabel*, 5> units_{};
    // What each row shows now: a row the same again is not written (its words and numbers cost
    // more than the comparison, at every snapshot).
    struct Row {
        bool shown = false;
        char name = 0;
        bool rotary = false;
        double machine = 0.0;
        double work = 0.0;
        friend bool operator==(const Row&, const Row&) = default;
    };
    std::array<std::optional<Row>, 5> rows_{};
};

// A coordinate as the panel shows it: three decimals, fixed width, no "-0.000", so digits never jump.
QString droText(double value);

} // namespace m350::ui
