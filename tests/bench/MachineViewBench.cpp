// The machine view (图形显示) painting a 1,000,000-move preview (issue 27): a frame at 1024x600 of
// the whole path (the coarse levels), zoomed in ten times (the chunks in view, finer levels), and
// while a run goes on (the run's colour moving, the spindle moving: what 60 repaints a second
// cost; the machine and the path are kept from the frame before, the run's new moves added).
// Painted into an image with the raster engine, as the window's backing store is.
// Benchmarks, not tests: they report, never judge. Counters: lines (drawn a frame), moves.
#include "tests/bench/MouldProgram.h"

#include "core/config/MachineConfig.h"
#include "core/preview/PreviewBuilder.h"
#include "ui/view/MachineView.h"

#include <QApplication>
#include <QImage>

#include <benchmark/benchmark.h>

#include <variant>

namespace {

using namespace m350;

const std::shared_ptr<const preview::Preview>& millionMoves() {
    static const std::shared_ptr<const preview::Preview> built = [] {
        auto loaded = config::loadMachineFolder(config::bundledMachinesDirectory() + "/" + config::kDefaultMachine);
        return std::make_shared<const preview::Preview>(
            preview::buildPreview(std::get<config::MachineConfig>(std::move(loaded)), bench::program(1'000'000).path()));
    }();
    return built;
}

ui::MachineViewContent contentAt(std::size_t done) {
    ui::MachineViewContent content;
    content.preview.preview = millionMoves();
    content.preview.file = "mould.nc";
    content.done = done;
    content.current = done;
    const auto& path = content.preview.preview->path;
    const auto& s = path.chunks()[done / preview::PathStore::kChunkSegments].segments[done % preview::PathStore::kChunkSegments];
    content.nose = preview::ScenePoint{s.end.x, s.end.y, s.end.z};
    return content;
}

void frames(benchmark::State& state, double zoom, bool running) {
    ui::MachineView view;
    view.resize(1024, 600);
    view.setPlane(ui::ViewPlane::Top);
    view.setContent(contentAt(0));
    view.fit();
    if (zoom > 1.0) {
        // about the middle of the raster (the path's box reaches back to machine zero, where the
        // program starts from)
        const auto& path = millionMoves()->path;
        const auto& middle = path.chunks()[path.chunks().size() / 2].start;
        const ui::ViewTransform& top = view.transform(ui::ViewPlane::Top);
        const QPointF at = top.toPixel({middle.x, middle.y});
        view.panBy(at.x() - top.size().width() / 2.0, at.y() - top.size().height() / 2.0);
        view.zoomBy(zoom);
    }
    QImage image(view.size(), QImage::Format_ARGB32_Premultiplied);
    const std::size_t moves = millionMoves()->path.size();
    std::size_t done = 0;
    double step = 1.0;
    for (auto _ : state) {
        if (running) {
            done = (done + 997) % moves; // a run a few hundred moves a frame further on
            view.setContent(contentAt(done));
        } else {
            view.panBy(step, 0.0); // a drag: every frame is drawn anew
            step = -step;
        }
        view.render(&image);
        benchmark::DoNotOptimize(image.constBits());
    }
    state.counters["lines"] = double(view.lastDrawnLines());
    state.counters["moves"] = double(moves);
}

void BM_ViewFrame_1M_Whole(benchmark::State& state) { frames(state, 1.0, false); }
BENCHMARK(BM_ViewFrame_1M_Whole)->Unit(benchmark::kMillisecond);

void BM_ViewFrame_1M_Zoom10(benchmark::State& state) { frames(state, 10.0, false); }
BENCHMARK(BM_ViewFrame_1M_Zoom10)->Unit(benchmark::kMillisecond);

void BM_ViewFrame_1M_Running(benchmark::State& state) { frames(state, 1.0, true); }
BENCHMARK(BM_ViewFrame_1M_Running)->Unit(benchmark::kMillisecond);

} // namespace
