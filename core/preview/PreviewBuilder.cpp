#include "core/preview/PreviewBuilder.h"

#include "core/controller/Controller.h"
#include "core/machine/ArcGeometry.h"
#include "core/preview/ArcPoints.h"

#include <algorithm>

namespace m350::preview {

namespace {

// Thrown from the machine's observer to leave a run nobody waits for: the controller is the
// preview's own and is thrown away with it.
struct PreviewCancelled {};

template <class Vector> Point3 point(const Vector& a) { return {float(a(0)), float(a(1)), float(a(2))}; }

// Takes the controller's moves into the store, each with the line running when it was made.
class PathRecorder : public machine::MachineObserver {
public:
    PathRecorder(Preview& preview, const PreviewSettings& settings) : preview_(preview), settings_(settings) {}
    void attach(const controller::Controller* controller) { controller_ = controller; }

    void onMachineEvent(const machine::MachineEvent& event) override {
        using Type = machine::MachineEvent::Type;
        if (event.type != Type::Rapid && event.type != Type::Feed && event.type != Type::Arc) {
            return;
        }
        PathStore& path = preview_.path;
        if (!started_) {
            path = PathStore(point(event.from));
            started_ = true;
        }
        if ((++preview_.moves & 4095U) == 0 && settings_.cancel && settings_.cancel->load(std::memory_order_relaxed)) {
            throw PreviewCancelled{};
        }
        PathSegment segment;
        segment.end = point(event.to);
        locate(segment);
        if (event.type == Type::Arc && event.arc) {
            const machine::Arc& arc = *event.arc;
            segment.kind = arc.sweep < 0.0 ? SegmentKind::ArcCw : SegmentKind::ArcCcw;
            segment.plane = static_cast<ArcPlane>(arc.plane);
            const Point3 c = point(arc.center);
            path.addArc(segment, {float(PlanarArc::u(c, segment.plane)), float(PlanarArc::v(c, segment.plane))});
        } else {
            segment.kind = event.type == Type::Rapid ? SegmentKind::Rapid : SegmentKind::Feed;
            path.addLine(segment);
        }
        if (path.size() >= settings_.segmentBudget) {
            // the moves since the last time at the tolerance reached so far first (the older ones
            // are within it already); twice as coarse only while that leaves more than half the
            // budget, so the store halves at least and this stays rare
            preview_.coarsenedTo = preview_.coarsenedTo > 0.0 ? preview_.coarsenedTo : firstTolerance();
            path.coarsen(preview_.coarsenedTo);
            while (path.size() * 2 > settings_.segmentBudget) {
                preview_.coarsenedTo *= 2.0;
                path.coarsen(preview_.coarsenedTo);
            }
        }
    }

private:
    void locate(PathSegment& segment) {
        if (!controller_) {
            return;
        }
        if (auto where = controller_->status().location()) {
            if (where->file != lastFile_ || !fileKnown_) {
                lastFile_ = where->file;
                lastIndex_ = preview_.path.fileIndex(controller_->program().fileName(*where));
                fileKnown_ = true;
            }
            segment.file = lastIndex_;
            segment.line = where->line;
        }
    }

    // a thousandth of the path's size: a 1000-pixel view of the whole still loses nothing
    double firstTolerance() const {
        const Box b = preview_.path.bounds();
        const double size = std::max({b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z});
        return std::max(size / 1000.0, 1e-3);
    }

    Preview& preview_;
    const PreviewSettings& settings_;
    const controller::Controller* controller_ = nullptr;
    bool started_ = false;
    std::uint32_t lastFile_ = 0;
    std::uint16_t lastIndex_ = 0;
    bool fileKnown_ = false;
};

} // namespace

Preview buildPreview(config::MachineConfig config, const std::string& program, const PreviewSettings& settings) {
    Preview preview;
    PathRecorder recorder(preview, settings);
    controller::RunSettings run;
    run.maxSimTime = settings.maxSimTime;
    run.observer = &recorder;
    run.tool = settings.tool;
    controller::Controller controller(std::move(config), run);
    recorder.attach(&controller);
    preview.loaded = controller.loadFile(program);
    preview.diagnostics = controller.diagnostics();
    if (preview.loaded) {
        try {
            controller::RunReport report = controller.run();
            preview.alarm = report.alarm;
        } catch (const PreviewCancelled&) {
            preview.cancelled = true;
            return preview;
        }
    }
    preview.levels = PathLevels::build(preview.path);
    return preview;
}

} // namespace m350::preview
