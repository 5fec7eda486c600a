#include "ui/view/MachineView.h"

#include "ui/i18n/Language.h"
#include "ui/view/PathPainter.h"
#include "ui/view/ScenePainter.h"

#include "core/preview/PreviewBuilder.h"

#include <QJsonArray>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace m350::ui {

namespace {

const QColor kBackground(0x06, 0x0a, 0x10);
const QColor kFrame(0x2a, 0x34, 0x44);
const QColor kText(0xa8, 0xb4, 0xc8);
const QColor kCurrent(0xff, 0xff, 0xff);
const QColor kPicked(0x40, 0xe0, 0xff);
const QColor kFault(0xff, 0x30, 0x30);

constexpr int kClickSlop = 4;     // pixels a press may move and still be a click
constexpr double kPickRadius = 6; // pixels from a move that still pick it

QRectF planeRect(ViewPlane plane, const preview::Box& box) {
    return QRectF(project(plane, box.min.x, box.min.y, box.min.z), project(plane, box.max.x, box.max.y, box.max.z)).normalized();
}

QRectF planeRect(ViewPlane plane, const preview::SceneBox& box) {
    return QRectF(project(plane, box.low.x, box.low.y, box.low.z), project(plane, box.high.x, box.high.y, box.high.z)).normalized();
}

// 1, 2 or 5 times a power of ten: the longest such length under `most` mm.
double roundLength(double most) {
    const double power = std::pow(10.0, std::floor(std::log10(most)));
    for (double step : {5.0, 2.0, 1.0}) {
        if (step * power <= most) {
            return step * power;
        }
    }
    return power;
}

} // namespace

MachineView::MachineView(QWidget* parent) : QWidget(parent) {
    setObjectName("machineView");
    setMinimumSize(200, 150);
    setMouseTracking(false);
    flash_.setInterval(400);
    connect(&flash_, &QTimer::timeout, this, [this] {
        flashOn_ = !flashOn_;
        update();
    });
}

void MachineView::setContent(MachineViewContent content) {
    const bool newPath = content.preview.preview.get() != content_.preview.preview.get();
    content_ = std::move(content);
    if (newPath) {
        highlight_.reset();
        autoFitted_ = false; // a machine drawn before its path came is fitted again when the path comes
    }
    if (!autoFitted_ && (content_.preview.preview || content_.scene)) {
        fit();
        autoFitted_ = true;
    }
    if (content_.alarm.isEmpty()) {
        fault_.reset();
        flash_.stop();
    } else if (!fault_ || fault_->text != content_.alarm) {
        fault_ = Fault{content_.alarmAt.value_or(content_.nose.value_or(preview::ScenePoint{})), content_.alarm};
        flashOn_ = true;
        flash_.start();
    }
    update();
}

void MachineView::setPlane(ViewPlane plane) {
    plane_ = plane;
    update();
}

QRect MachineView::paneRect(ViewPlane plane) const {
    if (sideBySide()) {
        const int half = width() / 2;
        return plane == ViewPlane::Top ? QRect(0, 0, half, height()) : QRect(half, 0, width() - half, height());
    }
    return plane == plane_ ? rect() : QRect();
}

std::optional<ViewPlane> MachineView::paneAt(QPoint at) const {
    for (ViewPlane plane : {ViewPlane::Top, ViewPlane::Front}) {
        if (paneRect(plane).contains(at)) {
            return plane;
        }
    }
    return std::nullopt;
}

void MachineView::layoutPanes() {
    for (ViewPlane plane : {ViewPlane::Top, ViewPlane::Front}) {
        const QRect pane = paneRect(plane);
        // a hidden pane keeps the size of the whole widget, so that it shows the same when chosen
        views_[index(plane)].setSize(pane.isEmpty() ? QSizeF(size()) : QSizeF(pane.size()));
    }
}

QRectF MachineView::machineBox(ViewPlane plane) const {
    QRectF box = contentBox(plane);
    if (!content_.scene) {
        return box;
    }
    const preview::MachineScene& scene = *content_.scene;
    const auto add = [&](const preview::ScenePoint& p, double margin) {
        const QPointF at = project(plane, p.x, p.y, p.z);
        box = box.united(QRectF(at.x() - margin, at.y() - margin, 2 * margin, 2 * margin));
    };
    if (scene.travel.high != scene.travel.low) {
        box = box.united(planeRect(plane, scene.travel));
    }
    if (!scene.magazine.followsSpindle) {
        for (const preview::ScenePocket& pocket : scene.magazine.pockets) {
            add(pocket.at, 30.0);
        }
    }
    for (const preview::SceneSetter& setter : scene.setters) {
        if (setter.kind == preview::SceneSetter::Kind::Fixed) {
            add({setter.x, setter.y, setter.top}, std::max(setter.radius, 10.0));
        }
    }
    return box;
}

QRectF MachineView::contentBox(ViewPlane plane) const {
    if (content_.preview.preview && !content_.preview.preview->path.bounds().empty()) {
        QRectF box = planeRect(plane, content_.preview.preview->path.bounds());
        return box.adjusted(-1.0, -1.0, 1.0, 1.0); // a path along one axis still has a size
    }
    if (content_.scene && content_.scene->travel.high != content_.scene->travel.low) {
        return planeRect(plane, content_.scene->travel);
    }
    return QRectF(-250.0, -250.0, 500.0, 500.0);
}

void MachineView::fit() {
    layoutPanes();
    for (ViewPlane plane : {ViewPlane::Top, ViewPlane::Front}) {
        views_[index(plane)].fit(contentBox(plane), 24.0);
    }
    fitted_ = Fitted::Path;
    update();
}

void MachineView::fitMachine() {
    layoutPanes();
    for (ViewPlane plane : {ViewPlane::Top, ViewPlane::Front}) {
        views_[index(plane)].fit(machineBox(plane), 24.0);
    }
    fitted_ = Fitted::Machine;
    update();
}

void MachineView::fitNext() {
    if (fitted_ == Fitted::Path) {
        fitMachine();
    } else {
        fit();
    }
}

void MachineView::zoomBy(double factor) {
    fitted_ = Fitted::Free;
    ViewTransform& view = views_[index(plane_)];
    view.zoomAt(QPointF(view.size().width() / 2.0, view.size().height() / 2.0), factor);
    update();
}

void MachineView::panBy(double dx, double dy) {
    fitted_ = Fitted::Free;
    views_[index(plane_)].pan(QPointF(-dx, -dy));
    update();
}

void MachineView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    // keep what is in the middle in the middle, at the same scale
    layoutPanes();
    // a fitted view stays fitted to the new size
    if (fitted_ == Fitted::Path) {
        fit();
    } else if (fitted_ == Fitted::Machine) {
        fitMachine();
    }
}

void MachineView::wheelEvent(QWheelEvent* event) {
    const QPoint at = event->position().toPoint();
    if (auto plane = paneAt(at)) {
        plane_ = sideBySide() ? *plane : plane_;
        const QPoint local = at - paneRect(*plane).topLeft();
        views_[index(*plane)].zoomAt(local, std::pow(1.0015, event->angleDelta().y()));
        fitted_ = Fitted::Free;
        update();
    }
    event->accept();
}

void MachineView::mousePressEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton) {
        dragFrom_ = event->position().toPoint();
        dragged_ = false;
        if (auto plane = paneAt(*dragFrom_); plane && sideBySide()) {
            plane_ = *plane;
        }
    }
}

void MachineView::mouseMoveEvent(QMouseEvent* event) {
    if (!dragFrom_) {
        return;
    }
    const QPoint now = event->position().toPoint();
    const QPoint delta = now - *dragFrom_;
    if (!dragged_ && delta.manhattanLength() < kClickSlop) {
        return;
    }
    dragged_ = true;
    fitted_ = Fitted::Free;
    views_[index(plane_)].pan(delta);
    dragFrom_ = now;
    update();
}

void MachineView::mouseReleaseEvent(QMouseEvent* event) {
    if (dragFrom_ && !dragged_ && event->button() == Qt::LeftButton) {
        pick(event->position().toPoint());
    }
    dragFrom_.reset();
}

bool MachineView::pick(QPoint at) {
    const auto plane = paneAt(at);
    const auto& built = content_.preview.preview;
    if (!plane || !built) {
        return false;
    }
    const QPoint local = at - paneRect(*plane).topLeft();
    const auto move = PathPainter::hit(built->path, *plane, views_[index(*plane)], local, kPickRadius);
    if (!move) {
        highlight_.reset();
        update();
        return false;
    }
    const preview::PathSegment& s = PathPainter::segment(built->path, *move);
    const auto& files = built->path.files();
    const QString file = s.file < files.size() ? QString::fromStdString(files[s.file]) : QString();
    highlight_ = Highlight{file, int(s.line), *move};
    update();
    emit moveClicked(file, int(s.line));
    return true;
}

void MachineView::paintEvent(QPaintEvent* event) {
    (void)event;
    QPainter painter(this);
    painter.fillRect(rect(), kBackground);
    layoutPanes();
    drawnLines_ = 0;
    for (ViewPlane plane : {ViewPlane::Top, ViewPlane::Front}) {
        const QRect pane = paneRect(plane);
        if (!pane.isEmpty()) {
            paintPane(painter, plane, pane);
        }
    }
}

void MachineView::paintPane(QPainter& painter, ViewPlane plane, const QRect& pane) {
    const ViewTransform& view = views_[index(plane)];
    painter.save();
    painter.setClipRect(pane);
    painter.translate(pane.topLeft());
    paintCached(painter, plane, pane);
    if (const auto& built = content_.preview.preview) {
        painter.setRenderHint(QPainter::Antialiasing, true);
        if (content_.current) {
            QPen pen(kCurrent, 3.0);
            pen.setCosmetic(true);
            painter.setPen(pen);
            PathPainter::paintMove(painter, built->path, *content_.current, plane, view);
        }
        if (highlight_) {
            QPen pen(kPicked, 3.0);
            pen.setCosmetic(true);
            painter.setPen(pen);
            PathPainter::paintMove(painter, built->path, highlight_->move, plane, view);
        }
    }
    if (content_.nose) {
        static const preview::MachineScene kNoMachine;
        ScenePainter::paintSpindle(painter, content_.scene ? *content_.scene : kNoMachine, *content_.nose, plane, view);
    }
    if (fault_) {
        painter.setRenderHint(QPainter::Antialiasing, true);
        const QPointF at = view.toPixel(project(plane, fault_->at.x, fault_->at.y, fault_->at.z));
        const QColor colour = flashOn_ ? kFault : kFault.darker(220);
        painter.setPen(QPen(colour, 3.0));
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(at, 16.0, 16.0);
        painter.drawLine(at + QPointF(-22, 0), at + QPointF(22, 0));
        painter.drawLine(at + QPointF(0, -22), at + QPointF(0, 22));
        // the text beside the mark, on a dark plate so that the machine under it does not garble it
        const double width = std::max(160.0, std::min(pane.width() - at.x() - 30.0, pane.width() / 2.0));
        QRectF box = painter.boundingRect(QRectF(0, 0, width, 400), Qt::AlignLeft | Qt::TextWordWrap, fault_->text);
        box.moveTopLeft(at + QPointF(at.x() + 22 + box.width() > pane.width() ? -22 - box.width() : 22, 6));
        painter.fillRect(box.adjusted(-4, -2, 4, 2), QColor(0x10, 0x04, 0x04, 220));
        painter.setPen(kFault);
        painter.drawText(box, Qt::AlignLeft | Qt::TextWordWrap, fault_->text);
    }
    paintOverlay(painter, plane, pane);
    painter.restore();
    if (sideBySide()) {
        painter.setPen(QPen(plane == plane_ ? kText : kFrame, 1.0));
        painter.drawRect(pane.adjusted(0, 0, -1, -1));
    }
}

void MachineView::paintCached(QPainter& painter, ViewPlane plane, const QRect& pane) {
    // a run's part drawn over the cache a frame at a time; a jump of more moves paints all anew
    constexpr std::size_t kMostAdded = 20000;
    const ViewTransform& view = views_[index(plane)];
    const MessageLanguage language = Language::messageLanguage();
    PaneCache& cache = caches_[index(plane)];
    const auto* built = content_.preview.preview.get();
    const bool same = cache.size == pane.size() && cache.centre == view.centre() && cache.mmPerPixel == view.mmPerPixel() &&
                      cache.preview == built && cache.scene == content_.scene.get() && cache.language == language &&
                      !cache.image.isNull();
    if (same && content_.done >= cache.done && content_.done - cache.done <= kMostAdded) {
        if (built && content_.done > cache.done) {
            QPainter onCache(&cache.image);
            drawnLines_ += PathPainter::paintDone(onCache, built->path, plane, view, cache.done, content_.done);
        }
    } else {
        cache = PaneCache{QImage(pane.size(), QImage::Format_ARGB32_Premultiplied), pane.size(), view.centre(),
                          view.mmPerPixel(), built, content_.scene.get(), language, 0};
        cache.image.fill(kBackground);
        QPainter onCache(&cache.image);
        if (content_.scene) {
            ScenePainter::paintMachine(onCache, *content_.scene, plane, view, language);
        }
        if (built) {
            drawnLines_ += PathPainter::paint(onCache, *built, plane, view, content_.done);
        }
    }
    cache.done = content_.done;
    painter.drawImage(QPoint(0, 0), cache.image);
}

void MachineView::paintOverlay(QPainter& painter, ViewPlane plane, const QRect& pane) {
    const ViewTransform& view = views_[index(plane)];
    painter.setPen(kText);
    const QRect inner(6, 4, pane.width() - 12, pane.height() - 8);
    painter.drawText(inner, Qt::AlignLeft | Qt::AlignTop, plane == ViewPlane::Top ? tr("X-Y  Top view") : tr("X-Z  Front view"));
    painter.drawText(inner, Qt::AlignRight | Qt::AlignTop, notes().join(QLatin1Char('\n')));
    if (highlight_) {
        painter.setPen(kPicked);
        painter.drawText(inner, Qt::AlignRight | Qt::AlignBottom,
                         QStringLiteral("%1:%2").arg(highlight_->file.section(QLatin1Char('/'), -1)).arg(highlight_->line));
    }
    paintScaleBar(painter, view, pane);
}

QStringList MachineView::notes() const {
    QStringList notes;
    const auto& built = content_.preview.preview;
    if (content_.preview.building) {
        notes << tr("Building the preview...");
    }
    if (built) {
        notes << tr("%1 moves").arg(built->moves);
        if (built->coarsenedTo > 0.0) {
            notes << tr("Simplified to %1 mm (memory budget)").arg(built->coarsenedTo, 0, 'g', 3);
        }
        if (!built->loaded) {
            notes << tr("The program has errors: no path");
        }
    } else if (!content_.preview.building) {
        notes << tr("No program path");
    }
    return notes;
}

void MachineView::paintScaleBar(QPainter& painter, const ViewTransform& view, const QRect& pane) {
    const double length = roundLength(120.0 * view.mmPerPixel());
    const double pixels = length / view.mmPerPixel();
    const QPointF left(12.0, pane.height() - 14.0);
    painter.setPen(QPen(kText, 1.5));
    painter.drawLine(left, left + QPointF(pixels, 0));
    painter.drawLine(left + QPointF(0, -4), left + QPointF(0, 4));
    painter.drawLine(left + QPointF(pixels, -4), left + QPointF(pixels, 4));
    const QString text = length >= 1.0 ? QStringLiteral("%1 mm").arg(length) : QStringLiteral("%1 mm").arg(length, 0, 'g', 3);
    painter.drawText(left + QPointF(pixels + 6, 4), text);
}

QJsonObject MachineView::state() const {
    QJsonObject out;
    out["plane"] = plane_ == ViewPlane::Top ? "top" : "front";
    out["sideBySide"] = sideBySide();
    out["fit"] = fitted_ == Fitted::Path ? "path" : fitted_ == Fitted::Machine ? "machine" : "free";
    for (ViewPlane plane : {ViewPlane::Top, ViewPlane::Front}) {
        const ViewTransform& view = views_[index(plane)];
        out[plane == ViewPlane::Top ? "top" : "front"] =
            QJsonObject{{"mmPerPixel", view.mmPerPixel()}, {"centre", QJsonArray{view.centre().x(), view.centre().y()}}};
    }
    QJsonObject path{{"file", content_.preview.file}, {"building", content_.preview.building}};
    if (const auto& built = content_.preview.preview) {
        path["moves"] = double(built->moves);
        path["segments"] = double(built->path.size());
        path["coarsenedTo"] = built->coarsenedTo;
        path["done"] = double(content_.done);
    }
    out["path"] = path;
    if (highlight_) {
        out["highlight"] = QJsonObject{{"file", highlight_->file}, {"line", highlight_->line}};
    }
    if (fault_) {
        out["fault"] = QJsonObject{{"x", fault_->at.x}, {"y", fault_->at.y}, {"z", fault_->at.z}, {"text", fault_->text}};
    }
    return out;
}

} // namespace m350::ui
