#pragma once

#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"

#include <QPointF>

#include <array>
#include <optional>

class QLabel;

namespace m350::ui {

// 分中 Middle (a Monitor sub-page): centring on a workpiece. Two points: 记录X records one side,
// 分中X at the other side makes the midpoint the work X zero (Y likewise). 圆弧分中: three points on
// a circle (记录1, 记录2, then 分中 at the third) make its centre the work XY zero. Esc goes back.
class MiddlePage : public Page {
    Q_OBJECT
public:
    explicit MiddlePage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::middle; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    void render(const PanelSnapshot& snapshot) override;
    void retranslate() override;
    QJsonObject state() const override;

    bool arcMode() const { return arc_; }
    std::optional<double> middle(int axis) const { return middle_[static_cast<std::size_t>(axis)]; }
    std::optional<QPointF> centre() const { return centre_; }

    // The centre of the circle through three points; nullopt when they lie on a line.
    static std::optional<QPointF> circleCentre(QPointF a, QPointF b, QPointF c);

private:
    void record(int axis);
    void centreAxis(int axis);
    void centreArc();
    QPointF here() const;
    void show();
    bool arc_ = false;
    std::array<std::optional<double>, 2> first_{};
    std::array<std::optional<double>, 2> second_{};
    std::array<std::optional<double>, 2> middle_{};
    std::array<std::optional<QPointF>, 2> points_{};
    std::optional<QPointF> third_;
    std::optional<QPointF> centre_;
    QLabel* values_;
    QLabel* help_;
};

} // namespace m350::ui
