#include "ui/pages/MiddlePage.h"

#include "ui/pages/CompactDro.h"
#include "ui/pages/PanelContext.h"
#include "ui/widgets/MeasuredLabel.h"
#include "ui/widgets/WrappedLabel.h"

#include <QJsonObject>
#include <QLabel>
#include <QVBoxLayout>

#include <cmath>

namespace m350::ui {

namespace {

QString value(const std::optional<double>& v) { return v ? droText(*v).trimmed() : QStringLiteral("-"); }
QString point(const std::optional<QPointF>& p) {
    return p ? QStringLiteral("X %1  Y %2").arg(droText(p->x()).trimmed(), droText(p->y()).trimmed()) : QStringLiteral("-");
}

} // namespace

MiddlePage::MiddlePage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    setObjectName("middlePage");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(8, 8, 8, 8);
    values_ = new MeasuredLabel(this);
    values_->setObjectName("middleValues");
    values_->setStyleSheet(QStringLiteral("font-family: 'DejaVu Sans Mono', 'WenQuanYi Micro Hei Mono', monospace; font-size: 13pt;"));
    help_ = new WrappedLabel(this);
    help_->setObjectName("pageHelp");
    column->addWidget(values_);
    column->addStretch(1);
    column->addWidget(help_);
    retranslate();
}

QString MiddlePage::title() const { return tr("Middle", "msg 321"); }

void MiddlePage::retranslate() { show(); }

QVector<Page::Softkey> MiddlePage::softkeys() const {
    if (arc_) {
        return {{tr("Set 1", "msg 524"), true, {}}, {tr("Set 2", "msg 525"), true, {}},
                {tr("Middle", "msg 526"), true, {}}, {}, {}, {tr("4pts", "msg 529"), true, {}}};
    }
    return {{tr("Set X", "msg 512"), true, {}}, {tr("Middle X", "msg 513"), true, {}},
            {tr("Set Y", "msg 514"), true, {}}, {tr("Middle Y", "msg 515"), true, {}},
            {}, {tr("3Pts", "msg 517"), true, {}}};
}

void MiddlePage::softkey(int number) {
    if (arc_) {
        switch (number) {
        case 1: points_[0] = here(); break;
        case 2: points_[1] = here(); break;
        case 3: centreArc(); break;
        case 6: arc_ = false; emit softkeysChanged(); break;
        default: break;
        }
    } else {
        switch (number) {
        case 1: record(0); break;
        case 2: centreAxis(0); break;
        case 3: record(1); break;
        case 4: centreAxis(1); break;
        case 6: arc_ = true; emit softkeysChanged(); break;
        default: break;
        }
    }
    show();
}

QPointF MiddlePage::here() const {
    auto s = context().snapshot();
    return s ? QPointF(s->status.machine(0), s->status.machine(1)) : QPointF();
}

void MiddlePage::record(int axis) {
    const auto a = static_cast<std::size_t>(axis);
    first_[a] = axis == 0 ? here().x() : here().y();
    second_[a].reset();
    middle_[a].reset();
}

// The current point is the second side: the midpoint of the two sides becomes work zero.
void MiddlePage::centreAxis(int axis) {
    const auto a = static_cast<std::size_t>(axis);
    if (!first_[a]) {
        context().notify(axis == 0 ? tr("Press [Set X] at the first side first") : tr("Press [Set Y] at the first side first"));
        return;
    }
    double now = axis == 0 ? here().x() : here().y();
    second_[a] = now;
    middle_[a] = (*first_[a] + now) / 2.0;
    context().session().setWorkPosition(axis, now - *middle_[a]);
}

void MiddlePage::centreArc() {
    if (!points_[0] || !points_[1]) {
        context().notify(tr("Record two points of the circle first ([Set 1], [Set 2])"));
        return;
    }
    third_ = here();
    centre_ = circleCentre(*points_[0], *points_[1], *third_);
    if (!centre_) {
        context().notify(tr("The three points lie on a line: no circle through them"));
        return;
    }
    context().session().setWorkPosition(0, third_->x() - centre_->x());
    context().session().setWorkPosition(1, third_->y() - centre_->y());
}

std::optional<QPointF> MiddlePage::circleCentre(QPointF a, QPointF b, QPointF c) {
    const double d = 2.0 * (a.x() * (b.y() - c.y()) + b.x() * (c.y() - a.y()) + c.x() * (a.y() - b.y()));
    const double scale = std::max({std::abs(a.x()), std::abs(a.y()), std::abs(b.x()), std::abs(b.y()), std::abs(c.x()),
                                   std::abs(c.y()), 1.0});
    if (std::abs(d) < 1e-9 * scale * scale) {
        return std::nullopt;
    }
    auto sq = [](QPointF p) { return p.x() * p.x() + p.y() * p.y(); };
    const double x = (sq(a) * (b.y() - c.y()) + sq(b) * (c.y() - a.y()) + sq(c) * (a.y() - b.y())) / d;
    const double y = (sq(a) * (c.x() - b.x()) + sq(b) * (a.x() - c.x()) + sq(c) * (b.x() - a.x())) / d;
    return QPointF(x, y);
}

bool MiddlePage::key(const QString& name) {
    if (name == QLatin1String("ESC")) {
        emit navigate(PageId::monitor);
        return true;
    }
    return false;
}

void MiddlePage::render(const PanelSnapshot&) {}

void MiddlePage::show() {
    QStringList lines;
    if (arc_) {
        lines << tr("Arc 3 pts:", "msg 964") << tr("First pts:", "msg 968") + QLatin1Char(' ') + point(points_[0])
              << tr("Second pts:", "msg 969") + QLatin1Char(' ') + point(points_[1])
              << tr("Third pts:", "msg 970") + QLatin1Char(' ') + point(third_)
              << tr("Center:", "msg 971") + QLatin1Char(' ') + point(centre_);
        help_->setText(tr("1:Move to the first point and press [Set 1];", "msg 965") + QLatin1Char('\n') +
                       tr("2:Move to the second point and press [Set 2];", "msg 966") + QLatin1Char('\n') +
                       tr("3:Move to the third point and press[Middle],get center of arc and set it to zero;", "msg 967"));
    } else {
        lines << tr("4 Pts:", "msg 972") << tr("Px1:", "msg 976") + QLatin1Char(' ') + value(first_[0])
              << tr("Px2:", "msg 977") + QLatin1Char(' ') + value(second_[0])
              << tr("Pxm:", "msg 978") + QLatin1Char(' ') + value(middle_[0])
              << tr("Py1:", "msg 979") + QLatin1Char(' ') + value(first_[1])
              << tr("Py2", "msg 980") + QStringLiteral(": ") + value(second_[1])
              << tr("Pym:", "msg 981") + QLatin1Char(' ') + value(middle_[1]);
        help_->setText(tr("Mannal Center Operation(X):", "msg 973") + QLatin1Char('\n') +
                       tr("1:Take the tool to the point Px1 and press [Set X] to set;", "msg 974") + QLatin1Char('\n') +
                       tr("2:Take the tool to the point Px2 and press [Middle X],get  midpoint and set the X zero;",
                          "msg 975"));
    }
    values_->setText(lines.join(QLatin1Char('\n')));
}

QJsonObject MiddlePage::state() const {
    QJsonObject out{{"middle_arc", arc_}};
    if (middle_[0]) {
        out["middle_x"] = *middle_[0];
    }
    if (middle_[1]) {
        out["middle_y"] = *middle_[1];
    }
    if (centre_) {
        out["middle_centre"] = QJsonObject{{"X", centre_->x()}, {"Y", centre_->y()}};
    }
    return out;
}

} // namespace m350::ui
