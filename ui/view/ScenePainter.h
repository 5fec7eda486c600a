#pragma once

#include "ui/view/ViewTransform.h"

#include "core/common/Message.h"
#include "core/preview/MachineScene.h"

#include <QColor>

class QPainter;

namespace m350::ui {

// Draws the machine of a scene (core/preview/MachineScene.h) in one plane, to scale: the travel
// box, the table, the work zero, the magazine's pockets with the tools they hold, the setters,
// the Z levels of a change (front view), tools lying where they fell; and the spindle nose with
// its tool where the axes stand now. Labels are in `language`.
class ScenePainter {
public:
    static void paintMachine(QPainter& painter, const preview::MachineScene& scene, ViewPlane plane, const ViewTransform& view,
                             MessageLanguage language);
    // The spindle and its tool, drawn over the path: nose at machine X Y Z `nose`.
    static void paintSpindle(QPainter& painter, const preview::MachineScene& scene, const preview::ScenePoint& nose,
                             ViewPlane plane, const ViewTransform& view);
    // A tool as it stands with the nose at `nose` (its tip `length` below): a circle from above, a
    // bar from the front; drawn at least a few pixels wide so that it shows far out.
    static void paintTool(QPainter& painter, const preview::SceneTool& tool, const preview::ScenePoint& nose, ViewPlane plane,
                          const ViewTransform& view, const QColor& colour);
    // The colours of a tool in a pocket and of the spindle's.
    static QColor toolInPocketColour();
    static QColor toolInSpindleColour();
    // The diameter a tool is drawn with when nobody knows it, mm.
    static constexpr double kUnknownDiameter = 8.0;
    static constexpr double kSpindleRadius = 40.0; // the nose's housing, drawn only as an outline
};

} // namespace m350::ui
