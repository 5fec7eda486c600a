#pragma once

#include "ui/session/PreviewShown.h"
#include "ui/view/ViewTransform.h"

#include "core/preview/MachineScene.h"

#include <QImage>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <QTimer>
#include <QWidget>

#include <array>
#include <memory>
#include <optional>

namespace m350::ui {

// What the machine view shows at one moment, taken from a snapshot by the page that holds it.
struct MachineViewContent {
    PreviewShown preview;                                 // the program's path
    std::shared_ptr<const preview::MachineScene> scene;  // the machine (null: none yet)
    std::optional<preview::ScenePoint> nose;              // the spindle nose, machine X Y Z
    std::size_t done = 0;                                 // moves of the path the run has made
    std::optional<std::size_t> current;                   // the move under way
    QString alarm;                                        // the alarm in force (empty: none), in the panel's language
    std::optional<preview::ScenePoint> alarmAt;           // where it happened, when not where the nose is
};

// 图形显示: the machine and the program's path to scale, from above (X-Y) and from the front
// (X-Z), side by side when the widget is wide enough, else the one chosen. Zoom by the wheel
// (around the cursor) or zoomBy(), pan by dragging or panBy(), fit() shows the whole path (or the
// machine when there is none) and happens by itself when a new path comes. A click on the path
// names the move's file and line (moveClicked). An alarm flashes where the spindle stood when it
// came, with its text, until it is cleared (RESET). One widget for the Monitor's page and the
// Program page's 仿真.
class MachineView : public QWidget {
    Q_OBJECT
public:
    explicit MachineView(QWidget* parent = nullptr);

    void setContent(MachineViewContent content);
    const MachineViewContent& content() const { return content_; }

    ViewPlane plane() const { return plane_; }
    void setPlane(ViewPlane plane);
    bool sideBySide() const { return width() >= kSideBySideWidth; }
    static constexpr int kSideBySideWidth = 880;

    void fit();        // the whole path (the machine's travel when there is none)
    void fitMachine(); // the path and the machine: travel, pockets, setters
    void fitNext();    // F3: the path, then the machine, then the path again
    void zoomBy(double factor);        // about the middle of the chosen plane's pane
    void panBy(double dx, double dy);  // pixels of the chosen pane: +dx shows what lies to the right
    const ViewTransform& transform(ViewPlane plane) const { return views_[index(plane)]; }
    // The pane of `plane` in widget pixels (empty when it is not shown).
    QRect paneRect(ViewPlane plane) const;

    struct Highlight {
        QString file;
        int line = 0;
        std::size_t move = 0;
    };
    const std::optional<Highlight>& highlight() const { return highlight_; }
    // The move at widget pixel `at` (as a click there finds it), highlighted and announced.
    bool pick(QPoint at);

    struct Fault {
        preview::ScenePoint at;
        QString text;
    };
    const std::optional<Fault>& fault() const { return fault_; }
    std::size_t lastDrawnLines() const { return drawnLines_; }
    // The lines the pane's corner shows: the path's moves, that it is being built, simplified to
    // a tolerance (a program past the memory budget), or that there is none.
    QStringList notes() const;
    QJsonObject state() const;

signals:
    void moveClicked(const QString& file, int line);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    static std::size_t index(ViewPlane plane) { return plane == ViewPlane::Top ? 0 : 1; }
    void layoutPanes();
    std::optional<ViewPlane> paneAt(QPoint at) const;
    QRectF contentBox(ViewPlane plane) const;
    QRectF machineBox(ViewPlane plane) const;
    void paintPane(QPainter& painter, ViewPlane plane, const QRect& pane);
    void paintOverlay(QPainter& painter, ViewPlane plane, const QRect& pane);
    void paintScaleBar(QPainter& painter, const ViewTransform& view, const QRect& pane);

    MachineViewContent content_;
    std::array<ViewTransform, 2> views_;
    ViewPlane plane_ = ViewPlane::Top;
    bool autoFitted_ = false; // fitted by itself since the path (or the machine) came
    enum class Fitted { Free, Path, Machine };
    Fitted fitted_ = Fitted::Free;
    std::optional<Highlight> highlight_;
    std::optional<Fault> fault_;
    bool flashOn_ = true;
    QTimer flash_;
    std::optional<QPoint> dragFrom_;
    bool dragged_ = false;
    std::size_t drawnLines_ = 0;

    // Each pane's machine and path as last painted: a frame in which only the run went on adds
    // the moves it made since; anything else (the view, the path, the machine) paints it anew.
    struct PaneCache {
        QImage image;
        QSize size;
        QPointF centre;
        double mmPerPixel = 0.0;
        const void* preview = nullptr;
        const void* scene = nullptr;
        MessageLanguage language = MessageLanguage::Chinese;
        std::size_t done = 0;
    };
    std::array<PaneCache, 2> caches_;
    void paintCached(QPainter& painter, ViewPlane plane, const QRect& pane);
};

} // namespace m350::ui
