#pragma once

#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"

#include <array>

class QGroupBox;
class QLabel;
class QPushButton;

namespace m350::ui {
class CompactDro;
}

namespace m350::ui {

// 对刀 Probe: the setter fields (coordinate system, current tool, floating setter thickness,
// fixed setter X/Y/Z) and the tools' Z offsets (params 930-945), with the panel's softkeys:
// 浮动对刀, 固定对刀 (asks the tool number), 多刀固定对刀 (a T1..T16 selection grid, then the
// key again), XY位置教导 and Z位置教导. Each runs the machine's own macros (slib-probe.nc: O502 to
// set a tool, O505 over #1970-#1989, O506/O507 to teach) so the trainee watches them do the work.
class ProbePage : public Page {
    Q_OBJECT
public:
    explicit ProbePage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::probe; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    void render(const PanelSnapshot& snapshot) override;
    void retranslate() override;
    QJsonObject state() const override;

    static constexpr int kMultiToolProgram = 505; // slib-g.nc: fixed setting of #1970-#1989 in turn
    QString fieldText(const QString& name) const; // "coord" "tool" "thickness" "x" "y" "z"
    QString offsetText(int tool) const;           // T1..T16 as shown
    bool selecting() const { return selecting_; }
    bool toolSelected(int tool) const { return selected_[static_cast<std::size_t>(tool - 1)]; }
    QString progressText() const;
    const CompactDro* dro() const { return dro_; }

private:
    void floating();
    void fixed();
    void fixedFor(int tool);
    void multi();
    void teach(bool xy);
    void showGrid(bool on);
    void refreshGrid();
    QMap<QString, QLabel*> captions_;
    QMap<QString, QLabel*> fields_;
    std::array<QLabel*, 16> offsets_{};
    std::array<QPushButton*, 16> grid_{};
    std::array<bool, 16> selected_{};
    QWidget* gridBox_;
    CompactDro* dro_;
    QLabel* gridTitle_;
    QLabel* progress_;
    QLabel* help_;
    QGroupBox* offsetsBox_;
    int cursor_ = 0;
    bool selecting_ = false;
};

} // namespace m350::ui
