#pragma once

#include "core/controller/SpindleLoadView.h"
#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"

#include <map>
#include <memory>

class QChart;
class QChartView;
class QLabel;
class QLineSeries;
class QValueAxis;

namespace m350::ui {

// 破损监测 Breakage Monitor (a simulator page, after the FANUC article's spindle load method; the
// 刀具表 page's Shift+F2 opens it): the spindle load of the last 30 s as a line with the tool's
// lower and upper limits, the tool in the spindle, the load % and the register macros read,
// lambda (parameter 4127), the sustained-anomaly rule and the alarm when the monitor raised one.
// Everything comes from the session's snapshot (controller::SpindleLoadView); ESC returns to 刀具表.
class BreakageMonitorPage : public Page {
    Q_OBJECT
public:
    explicit BreakageMonitorPage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::breakage; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    void render(const PanelSnapshot& snapshot) override;
    void retranslate() override;
    QJsonObject state() const override;

    // What the page shows, for tests: the fields by name (tool, load, register, lambda, limits,
    // rule, alarm) and the plotted series.
    QString fieldText(const QString& name) const;
    int plottedPoints() const;
    QPair<double, double> limitLines() const; // lower, upper as drawn (NaN: none)
    QChartView* chartView() const { return view_; }

private:
    void fill();
    void showAlarm(const PanelSnapshot& snapshot);

    QChart* chart_;
    QChartView* view_;
    QLineSeries* load_;
    QLineSeries* lower_;
    QLineSeries* upper_;
    QValueAxis* time_;
    QValueAxis* percent_;
    std::map<QString, QLabel*> captions_;
    std::map<QString, QLabel*> fields_;
    QLabel* help_;
    std::shared_ptr<const controller::SpindleLoadView> shown_;
    bool alarmed_ = false;
    QString alarmText_;
};

} // namespace m350::ui
