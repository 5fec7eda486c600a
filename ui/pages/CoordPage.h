#pragma once

#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"

#include <array>

class QLabel;
class QTableWidget;

namespace m350::ui {

// 坐标管理 Coord Set (a Monitor sub-page): the work systems' offsets (G92, G54-G59 and the common
// offset 公共偏置) with the active one marked. 选择坐标系 picks the active system (param 78),
// 设置X..5th give the current point a work coordinate, 加深 / 抬高 move the common offset's Z by
// the Z step (Z轴调整值), as the M350's help says they do. Esc goes back to the Monitor.
class CoordPage : public Page {
    Q_OBJECT
public:
    explicit CoordPage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::coord; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    void render(const PanelSnapshot& snapshot) override;
    void retranslate() override;
    QJsonObject state() const override;

    double zStep() const { return zStep_; }
    QString offsetText(int slot, int axis) const; // slot 0 G92, 1-6 G54-G59, 8 common
    QString columnText(int axis) const;           // the column's heading ("A (deg)")
    bool columnShown(int axis) const;

private:
    void setAxis(int axis);
    void moveCommonZ(double by);
    QTableWidget* table_;
    QLabel* step_;
    QLabel* help_;
    double zStep_ = 0.1;
    std::array<bool, 5> shown_{true, true, true, false, false};
    QString names_; // the headings the softkeys were made with
};

} // namespace m350::ui
