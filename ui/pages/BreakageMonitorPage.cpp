#include "ui/pages/BreakageMonitorPage.h"

#include "ui/pages/PanelContext.h"
#include "ui/widgets/MeasuredLabel.h"
#include "ui/widgets/WrappedLabel.h"

#include <QChart>
#include <QChartView>
#include <QGridLayout>
#include <QJsonArray>
#include <QLabel>
#include <QLineSeries>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace m350::ui {

namespace {

const char* const kFields[] = {"tool", "load", "register", "lambda", "limits", "rule", "alarm"};

QString percent(double v) { return QString::number(v, 'f', 2) + QStringLiteral(" %"); }

} // namespace

BreakageMonitorPage::BreakageMonitorPage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    setObjectName("breakagePage");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(4, 4, 4, 4);
    chart_ = new QChart();
    chart_->legend()->setVisible(true);
    chart_->legend()->setAlignment(Qt::AlignTop);
    chart_->setMargins(QMargins(2, 2, 2, 2));
    load_ = new QLineSeries(chart_);
    lower_ = new QLineSeries(chart_);
    upper_ = new QLineSeries(chart_);
    load_->setPen(QPen(QColor(0x1f, 0x6f, 0xd0), 2));
    lower_->setPen(QPen(QColor(0xd0, 0x80, 0x00), 1.5, Qt::DashLine));
    upper_->setPen(QPen(QColor(0xc0, 0x20, 0x20), 1.5, Qt::DashLine));
    time_ = new QValueAxis(chart_);
    percent_ = new QValueAxis(chart_);
    // Ticks on round values whatever the range: every 5 s (the 30 s shown scroll by), every 20 %
    // (more when a limit lifts the top); an empty chart shows 0-30 s and 0-100 %, not the
    // 0-1 a series without points would give it.
    time_->setLabelFormat(QStringLiteral("%.0f"));
    time_->setTickType(QValueAxis::TicksDynamic);
    time_->setTickAnchor(0.0);
    time_->setTickInterval(5.0);
    percent_->setLabelFormat(QStringLiteral("%.0f"));
    percent_->setTickType(QValueAxis::TicksDynamic);
    percent_->setTickAnchor(0.0);
    percent_->setTickInterval(20.0);
    chart_->addAxis(time_, Qt::AlignBottom);
    chart_->addAxis(percent_, Qt::AlignLeft);
    for (QLineSeries* series : {load_, lower_, upper_}) {
        chart_->addSeries(series);
        series->attachAxis(time_);
        series->attachAxis(percent_);
    }
    time_->setRange(0.0, controller::SpindleLoadView::kPlotSeconds);
    percent_->setRange(0.0, 100.0);
    view_ = new QChartView(chart_, this);
    view_->setObjectName("breakageChart");
    view_->setRenderHint(QPainter::Antialiasing);
    view_->setFocusPolicy(Qt::NoFocus);
    column->addWidget(view_, 1);
    auto* grid = new QGridLayout();
    int i = 0;
    for (const char* name : kFields) {
        auto* caption = new MeasuredLabel(this);
        auto* field = new MeasuredLabel(this);
        field->setObjectName(QStringLiteral("breakage_") + QLatin1String(name));
        captions_[QLatin1String(name)] = caption;
        fields_[QLatin1String(name)] = field;
        const bool wide = QLatin1String(name) == QLatin1String("alarm") || QLatin1String(name) == QLatin1String("rule");
        const int row = wide ? 4 + (QLatin1String(name) == QLatin1String("alarm")) : i / 2;
        const int col = wide ? 0 : (i % 2) * 2;
        grid->addWidget(caption, row, col);
        grid->addWidget(field, row, col + 1, 1, wide ? 3 : 1);
        field->setWordWrap(wide);
        ++i;
    }
    grid->setColumnStretch(1, 1);
    grid->setColumnStretch(3, 1);
    column->addLayout(grid);
    help_ = new WrappedLabel(this);
    help_->setObjectName("pageHelp");
    column->addWidget(help_);
    retranslate();
}

QString BreakageMonitorPage::title() const { return tr("Breakage Monitor"); }

QVector<Page::Softkey> BreakageMonitorPage::softkeys() const {
    return {{tr("Tool Table"), true, {}}, {}, {}, {}, {}, {}};
}

void BreakageMonitorPage::softkey(int number) {
    if (number == 1) {
        emit navigate(PageId::tools);
    }
}

bool BreakageMonitorPage::key(const QString& name) {
    if (name == QLatin1String("ESC")) {
        emit navigate(PageId::tools);
        return true;
    }
    return false;
}

void BreakageMonitorPage::retranslate() {
    captions_["tool"]->setText(tr("Current tool:"));
    captions_["load"]->setText(tr("Spindle load:"));
    captions_["register"]->setText(tr("Register:"));
    captions_["lambda"]->setText(tr("Lambda (param 4127):"));
    captions_["limits"]->setText(tr("Limits:"));
    captions_["rule"]->setText(tr("Rule:"));
    captions_["alarm"]->setText(tr("Alarm:"));
    load_->setName(tr("Load %"));
    lower_->setName(tr("Lower limit"));
    upper_->setName(tr("Upper limit"));
    time_->setTitleText(tr("Time (s)"));
    percent_->setTitleText(tr("Load (%)"));
    help_->setText(tr("Load% = L / 32767 x lambda, kept x100 in a 16-bit register. Limits per tool in "
                      "spindle-load.toml; the lower one counts only while the tool cuts."));
    shown_.reset();
    if (auto s = context().snapshot()) {
        render(*s);
    }
}

void BreakageMonitorPage::render(const PanelSnapshot& snapshot) {
    showAlarm(snapshot);
    if (snapshot.spindleLoad == shown_ && shown_) {
        return;
    }
    shown_ = snapshot.spindleLoad;
    fill();
}

void BreakageMonitorPage::showAlarm(const PanelSnapshot& snapshot) {
    const bool alarmed = snapshot.status.alarm && snapshot.status.alarm->code == AlarmCode::SpindleLoad;
    QString text = alarmed ? QString::fromStdString(snapshot.status.alarm->message) : QString();
    if (alarmed == alarmed_ && text == alarmText_ && !fields_["alarm"]->text().isEmpty()) {
        return;
    }
    alarmed_ = alarmed;
    alarmText_ = text;
    fields_["alarm"]->setText(alarmed ? text : tr("None"));
    fields_["alarm"]->setStyleSheet(alarmed ? QStringLiteral("color: #c02020; font-weight: bold;") : QString());
}

void BreakageMonitorPage::fill() {
    if (!shown_) {
        for (const char* name : kFields) {
            if (QLatin1String(name) != QLatin1String("alarm")) {
                fields_[QLatin1String(name)]->setText(QStringLiteral("-"));
            }
        }
        fields_["rule"]->setText(tr("This machine has no spindle load model ([spindle_load] in machine.toml)."));
        for (QLineSeries* series : {load_, lower_, upper_}) {
            series->clear();
        }
        return;
    }
    const controller::SpindleLoadView& v = *shown_;
    fields_["tool"]->setText(QStringLiteral("T%1").arg(v.tool));
    fields_["load"]->setText(percent(v.percent));
    fields_["register"]->setText(QStringLiteral("#%1 = %2").arg(v.registerVariable).arg(v.reg));
    fields_["lambda"]->setText(QString::number(v.lambda));
    fields_["limits"]->setText(v.limits ? percent(v.limits->lower) + QStringLiteral(" - ") +
                                              (v.limits->upper > 0.0 ? percent(v.limits->upper) : tr("none"))
                                        : tr("none for this tool"));
    fields_["rule"]->setText(tr("%1 samples in a row out of the limits, one every %2 ms")
                                 .arg(v.samplesToAlarm)
                                 .arg(std::lround(v.sampleSeconds * 1000.0)));
    QList<QPointF> points;
    points.reserve(static_cast<qsizetype>(v.points.size()));
    for (const auto& [t, p] : v.points) {
        points.append(QPointF(t, p));
    }
    load_->replace(points);
    auto line = [&](QLineSeries* series, bool shown, double level) {
        shown ? series->replace(QList<QPointF>{{v.from, level}, {v.to, level}}) : series->clear();
    };
    line(lower_, v.limits.has_value(), v.limits ? v.limits->lower : 0.0);
    line(upper_, v.limits && v.limits->upper > 0.0, v.limits ? v.limits->upper : 0.0);
    time_->setRange(v.from, v.to);
    percent_->setRange(0.0, v.top);
    percent_->setTickInterval(std::max(20.0, std::ceil(v.top / 5.0 / 10.0) * 10.0)); // at most ~6 labels
}

QString BreakageMonitorPage::fieldText(const QString& name) const {
    auto it = fields_.find(name);
    return it == fields_.end() ? QString() : it->second->text();
}

int BreakageMonitorPage::plottedPoints() const { return static_cast<int>(load_->count()); }

QPair<double, double> BreakageMonitorPage::limitLines() const {
    const double none = std::numeric_limits<double>::quiet_NaN();
    return {lower_->count() ? lower_->at(0).y() : none, upper_->count() ? upper_->at(0).y() : none};
}

QJsonObject BreakageMonitorPage::state() const {
    QJsonObject o;
    for (const auto& [name, label] : fields_) {
        o[QStringLiteral("breakage_") + name] = label->text(); // beside the panel's own keys (alarm ...)
    }
    o["breakage_points"] = plottedPoints();
    return o;
}

} // namespace m350::ui
