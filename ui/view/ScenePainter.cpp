#include "ui/view/ScenePainter.h"

#include <QPainter>
#include <QPainterPath>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace m350::ui {

namespace {

using preview::SceneBox;
using preview::ScenePoint;

QPointF on(ViewPlane plane, const ScenePoint& p) { return project(plane, p.x, p.y, p.z); }

QRectF pixelBox(ViewPlane plane, const SceneBox& box, const ViewTransform& view) {
    return QRectF(view.toPixel(on(plane, box.low)), view.toPixel(on(plane, box.high))).normalized();
}

QString say(const char* english, const char* chinese, MessageLanguage language) {
    return QString::fromUtf8(language == MessageLanguage::Chinese ? chinese : english);
}

void label(QPainter& painter, QPointF at, const QString& text, const QColor& colour) {
    painter.setPen(colour);
    painter.drawText(at + QPointF(4, -4), text);
}

const QColor kTravel(0x55, 0x62, 0x78);
const QColor kTable(0x18, 0x20, 0x2c);
const QColor kTableEdge(0x33, 0x3f, 0x52);
const QColor kPocket(0x9a, 0xa8, 0xbc);
const QColor kToolInPocket(0xe0, 0xc0, 0x60);
const QColor kToolInSpindle(0xff, 0x70, 0x50);
const QColor kSetter(0xff, 0x9a, 0x30);
const QColor kLevel(0x6a, 0x8a, 0xb0);
const QColor kZeroX(0xff, 0x60, 0x60);
const QColor kZeroY(0x60, 0xe0, 0x60);
const QColor kFallen(0xff, 0x40, 0x40);

void paintWorkZero(QPainter& painter, const preview::MachineScene& scene, ViewPlane plane, const ViewTransform& view) {
    const QPointF at = view.toPixel(on(plane, scene.workZero));
    painter.setPen(QPen(kZeroX, 2.0));
    painter.drawLine(at, at + QPointF(24, 0));
    painter.setPen(QPen(kZeroY, 2.0));
    painter.drawLine(at, at + QPointF(0, -24));
    painter.setPen(QPen(Qt::white, 1.0));
    painter.drawEllipse(at, 3.0, 3.0);
    label(painter, at + QPointF(2, 14), QString::fromStdString(scene.workSystem), Qt::white);
}

// The multi-process heads (多工序) ride with the spindle: each at its X Y offset from the nose,
// the one that is down at the nose's height, the others 40 mm up.
void paintHeads(QPainter& painter, const preview::MachineScene& scene, const ScenePoint& nose, ViewPlane plane,
                const ViewTransform& view) {
    for (const preview::ScenePocket& head : scene.magazine.pockets) {
        const ScenePoint at{nose.x + head.at.x, nose.y + head.at.y, nose.z + (head.atStation ? 0.0 : 40.0)};
        preview::SceneTool tool{head.tool, 0.0, 0.0};
        if (const preview::SceneTool* known = scene.tool(head.tool)) {
            tool = *known;
        }
        if (head.tool != 0) {
            ScenePainter::paintTool(painter, tool, at, plane, view, head.atStation ? kToolInSpindle : kToolInPocket);
        }
        painter.setPen(head.atStation ? Qt::white : kPocket);
        // stacked: heads often share a place (offsets of 0 until commissioned)
        painter.drawText(view.toPixel(on(plane, at)) + QPointF(8, -6 - 13.0 * (head.number - 1)),
                         head.tool != 0 ? QStringLiteral("H%1:T%2").arg(head.number).arg(head.tool) : QStringLiteral("H%1").arg(head.number));
    }
}

void paintPockets(QPainter& painter, const preview::MachineScene& scene, ViewPlane plane, const ViewTransform& view) {
    const preview::SceneMagazine& m = scene.magazine;
    if (m.kind == preview::SceneMagazine::Kind::None || m.followsSpindle) {
        return;
    }
    if (m.radius > 0.0 && plane == ViewPlane::Top) {
        painter.setPen(QPen(kPocket, 1.0, Qt::DashLine));
        painter.setBrush(Qt::NoBrush);
        const QPointF c = view.toPixel(on(plane, m.centre));
        const double r = m.radius / view.mmPerPixel();
        painter.drawEllipse(c, r, r);
    }
    // the closest two pockets on the screen: how much room a label has
    double pitch = 1e9;
    for (std::size_t i = 1; i < m.pockets.size(); ++i) {
        const QPointF d = view.toPixel(on(plane, m.pockets[i].at)) - view.toPixel(on(plane, m.pockets[i - 1].at));
        pitch = std::min(pitch, std::hypot(d.x(), d.y()));
    }
    for (const preview::ScenePocket& pocket : m.pockets) {
        const QPointF at = view.toPixel(on(plane, pocket.at));
        const double half = std::max(4.0, 14.0 / view.mmPerPixel()); // a fork about 28 mm wide
        painter.setBrush(Qt::NoBrush);
        painter.setPen(QPen(pocket.atStation ? Qt::white : kPocket, 1.5));
        if (plane == ViewPlane::Top) {
            if (m.kind == preview::SceneMagazine::Kind::LinearRack && !m.topLoading) {
                // a U opening toward the side the tool leaves by (+Y is up on screen)
                const double open = -m.openingY * half; // pixels: +Y opening points up
                QPainterPath fork;
                fork.moveTo(at + QPointF(-half, open));
                fork.lineTo(at + QPointF(-half, -open));
                fork.lineTo(at + QPointF(half, -open));
                fork.lineTo(at + QPointF(half, open));
                painter.drawPath(fork);
            } else {
                painter.drawRect(QRectF(at - QPointF(half, half), at + QPointF(half, half)));
            }
        } else {
            painter.drawLine(at + QPointF(-half, 0), at + QPointF(half, 0)); // the fork's plate at the nose's height
        }
        if (pocket.tool != 0) {
            preview::SceneTool tool{pocket.tool, 0.0, 0.0};
            if (const preview::SceneTool* known = scene.tool(pocket.tool)) {
                tool = *known;
            }
            ScenePainter::paintTool(painter, tool, pocket.at, plane, view, kToolInPocket);
        }
        // "4:T4" where there is room, "T4" where less, nothing where the pockets crowd together
        if (pitch >= 24.0) {
            painter.setPen(pocket.tool != 0 ? kToolInPocket : kPocket);
            const QString tool = pocket.tool != 0 ? QStringLiteral("T%1").arg(pocket.tool) : QString();
            const QString text = pitch >= 48.0 ? (tool.isEmpty() ? QString::number(pocket.number)
                                                                  : QStringLiteral("%1:%2").arg(pocket.number).arg(tool))
                                               : tool;
            painter.drawText(at + QPointF(-half, plane == ViewPlane::Top ? half + 14 : -6), text);
        }
    }
}

void paintSetters(QPainter& painter, const preview::MachineScene& scene, ViewPlane plane, const ViewTransform& view,
                  MessageLanguage language) {
    for (const preview::SceneSetter& setter : scene.setters) {
        const bool fixed = setter.kind == preview::SceneSetter::Kind::Fixed;
        const QString name = fixed ? say("tool setter", "对刀仪", language) : say("floating setter", "浮动对刀块", language);
        painter.setPen(QPen(kSetter, 1.5));
        painter.setBrush(QColor(kSetter.red(), kSetter.green(), kSetter.blue(), 60));
        if (!fixed) {
            if (plane == ViewPlane::Front) {
                const double y = view.toPixel({0.0, setter.top}).y();
                painter.setPen(QPen(kSetter, 1.0, Qt::DotLine));
                painter.drawLine(QPointF(0, y), QPointF(view.size().width(), y));
                label(painter, QPointF(0.0, y + 16.0), name, kSetter); // under its line, at the left
            }
            continue;
        }
        const double r = std::max(3.0, setter.radius / view.mmPerPixel());
        if (plane == ViewPlane::Top) {
            const QPointF c = view.toPixel({setter.x, setter.y});
            painter.drawEllipse(c, r, r);
            label(painter, c + QPointF(r, 0), name, kSetter);
        } else {
            const double floor = scene.table.high.z < setter.top ? scene.table.high.z : setter.top - 60.0;
            const QPointF top = view.toPixel({setter.x, setter.top});
            const QPointF bottom = view.toPixel({setter.x, floor});
            painter.drawRect(QRectF(QPointF(top.x() - r, top.y()), QPointF(bottom.x() + r, bottom.y())));
            label(painter, QPointF(top.x() + r, top.y()), name, kSetter);
        }
    }
    painter.setBrush(Qt::NoBrush);
}

// One line a height: levels within a pixel of each other share it, their names joined.
void paintLevels(QPainter& painter, const preview::MachineScene& scene, const ViewTransform& view, MessageLanguage language) {
    std::vector<std::pair<double, QStringList>> lines; // Z, names
    for (const preview::SceneLevel& level : scene.levels) {
        const QString name = QString::fromStdString(level.label.in(language));
        auto same = std::find_if(lines.begin(), lines.end(),
                                 [&](const auto& line) { return std::abs(line.first - level.z) < view.mmPerPixel(); });
        if (same == lines.end()) {
            lines.push_back({level.z, {name}});
        } else if (!same->second.contains(name)) {
            same->second << name;
        }
    }
    for (const auto& [z, names] : lines) {
        const double y = view.toPixel({0.0, z}).y();
        painter.setPen(QPen(kLevel, 1.0, Qt::DashDotLine));
        painter.drawLine(QPointF(0, y), QPointF(view.size().width(), y));
        // at the right edge: the pockets' labels sit at the left, where a rack usually starts
        const QString text = QStringLiteral("%1  Z%2").arg(names.join(QStringLiteral(" / "))).arg(z, 0, 'f', 1);
        const double width = painter.fontMetrics().horizontalAdvance(text);
        label(painter, QPointF(std::max(0.0, view.size().width() - width - 12.0), y), text, kLevel);
    }
}

} // namespace

QColor ScenePainter::toolInPocketColour() { return kToolInPocket; }
QColor ScenePainter::toolInSpindleColour() { return kToolInSpindle; }

void ScenePainter::paintTool(QPainter& painter, const preview::SceneTool& tool, const ScenePoint& nose, ViewPlane plane,
                             const ViewTransform& view, const QColor& colour) {
    const double diameter = tool.diameter > 0.0 ? tool.diameter : kUnknownDiameter;
    const double r = std::max(2.0, diameter / 2.0 / view.mmPerPixel());
    painter.setPen(QPen(colour, 1.2));
    painter.setBrush(QColor(colour.red(), colour.green(), colour.blue(), 90));
    if (plane == ViewPlane::Top) {
        painter.drawEllipse(view.toPixel(on(plane, nose)), r, r);
    } else {
        const QPointF top = view.toPixel(on(plane, nose));
        // a tool nobody measured is drawn 1 mm long: there, but plainly not to scale
        const double length = std::max(tool.length > 0.0 ? tool.length : 1.0, 0.0);
        const QPointF tip = view.toPixel(project(plane, nose.x, nose.y, nose.z - length));
        painter.drawRect(QRectF(QPointF(top.x() - r, top.y()), QPointF(tip.x() + r, std::max(tip.y(), top.y() + 2.0))));
    }
    painter.setBrush(Qt::NoBrush);
}

void ScenePainter::paintMachine(QPainter& painter, const preview::MachineScene& scene, ViewPlane plane, const ViewTransform& view,
                                MessageLanguage language) {
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    // the table, under everything
    const QRectF table = pixelBox(plane, scene.table, view);
    if (table.isValid()) {
        painter.fillRect(table, kTable);
        painter.setPen(QPen(kTableEdge, 1.0));
        painter.drawRect(table);
    }
    // the travel box
    const QRectF travel = pixelBox(plane, scene.travel, view);
    if (travel.isValid()) {
        painter.setPen(QPen(kTravel, 1.0, Qt::DashLine));
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(travel);
        // at the box's corner, or the pane's when the corner is out of view
        const QPointF corner(std::max(travel.left(), 0.0), std::max(travel.top(), 16.0));
        label(painter, corner + QPointF(0, 14),
              scene.travelFromSoftLimits ? say("soft limits", "软限位", language) : say("travel", "行程", language), kTravel);
    }
    if (plane == ViewPlane::Front) {
        paintLevels(painter, scene, view, language);
    }
    paintSetters(painter, scene, plane, view, language);
    paintPockets(painter, scene, plane, view);
    paintWorkZero(painter, scene, plane, view);
    for (const preview::SceneFallenTool& fallen : scene.fallen) {
        const QPointF at = view.toPixel(on(plane, fallen.at));
        painter.setPen(QPen(kFallen, 2.0));
        painter.drawLine(at + QPointF(-6, -6), at + QPointF(6, 6));
        painter.drawLine(at + QPointF(-6, 6), at + QPointF(6, -6));
        label(painter, at, QStringLiteral("T%1 %2").arg(fallen.tool).arg(say("dropped", "掉刀", language)), kFallen);
    }
    painter.restore();
}

void ScenePainter::paintSpindle(QPainter& painter, const preview::MachineScene& scene, const ScenePoint& nose, ViewPlane plane,
                                const ViewTransform& view) {
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    const QPointF at = view.toPixel(on(plane, nose));
    const double r = std::max(6.0, kSpindleRadius / view.mmPerPixel());
    painter.setPen(QPen(QColor(0xd0, 0xd8, 0xe8, 110), 1.5)); // the housing: faint, the nose and tool count
    painter.setBrush(Qt::NoBrush);
    if (plane == ViewPlane::Top) {
        painter.drawEllipse(at, r, r);
    } else {
        painter.drawRect(QRectF(QPointF(at.x() - r, at.y() - std::max(12.0, 120.0 / view.mmPerPixel())), QPointF(at.x() + r, at.y())));
    }
    if (scene.magazine.followsSpindle) {
        paintHeads(painter, scene, nose, plane, view);
    } else if (scene.spindleTool != 0) {
        preview::SceneTool tool{scene.spindleTool, 0.0, 0.0};
        if (const preview::SceneTool* known = scene.tool(scene.spindleTool)) {
            tool = *known;
        }
        paintTool(painter, tool, nose, plane, view, kToolInSpindle);
    }
    // the nose itself: a cross, so that its place reads exactly
    painter.setPen(QPen(QColor(0xff, 0x50, 0x50), 2.0));
    painter.drawLine(at + QPointF(-7, 0), at + QPointF(7, 0));
    painter.drawLine(at + QPointF(0, -7), at + QPointF(0, 7));
    painter.restore();
}

} // namespace m350::ui
