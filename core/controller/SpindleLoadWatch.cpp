#include "core/controller/SpindleLoadWatch.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace m350::controller {

namespace {

// Samples beyond this many in one event are skipped: a 100-hour dwell must not cost millions of
// samples (the history keeps 600 anyway).
constexpr int kMaxSamplesPerEvent = 100000;

} // namespace

tools::LoadSample SpindleLoadWatch::measure(const machine::SimulatedMachine& machine,
                                            const machine::MachineEvent& event, const machine::ToolWorld& world,
                                            int tool, double t) const {
    const machine::SpindleLoadModel& model = *model_;
    const bool moving = (event.type == machine::MachineEvent::Type::Feed ||
                         event.type == machine::MachineEvent::Type::Arc) &&
                        t >= event.start && t <= event.end;
    const double feed = moving ? event.feed : 0.0;
    const double rpm = machine.spindleTurning() ? machine.spindleRpm() : 0.0;
    const machine::Axes at = machine.positionAt(t);
    // depth below the stock's top of the tip as made and as it really is now
    auto depth = [&](double length) {
        if (!model.stock || !model.stock->covers(at(0), at(1))) {
            return 0.0;
        }
        return std::max(0.0, model.stock->top - (at(2) - length));
    };
    const double width = world.diameter(tool).value_or(model.defaultWidth);
    const double expected = depth(world.nominalLength(tool));
    double percent = 0.0;
    if (std::optional<double> brokeAt = world.breakTime(tool); brokeAt && *brokeAt <= t) {
        // the break: a short spike as the tool goes, then the stub cuts nothing
        percent = model.percent(rpm, 0.0, 0.0, 0.0);
        if (t - *brokeAt < model.spikeSeconds) {
            percent += model.spikeFactor * (model.percent(rpm, feed, expected, width) - percent);
        }
    } else {
        percent = model.percent(rpm, feed, depth(world.length(tool, t)), width);
    }
    tools::LoadSample sample;
    sample.time = t;
    sample.tool = tool;
    sample.reg = machine::loadRegister(model.signal(percent), model.lambda);
    sample.percent = sample.reg / 100.0;
    sample.cutting = feed > 0.0 && rpm > 0.0 && expected > 0.0;
    return sample;
}

std::optional<SpindleLoadWatch::Anomaly> SpindleLoadWatch::sampleUpTo(const machine::SimulatedMachine& machine,
                                                                      const machine::MachineEvent& event,
                                                                      const machine::ToolWorld& world, int tool) {
    if (!model_ || !std::isfinite(machine.time())) {
        return std::nullopt;
    }
    const double period = monitor_.settings().sampleSeconds;
    const double until = machine.time();
    if ((until - next_) / period > kMaxSamplesPerEvent) {
        next_ = until - period * kMaxSamplesPerEvent;
    }
    std::optional<Anomaly> anomaly;
    while (next_ <= until + 1e-12 && !anomaly) {
        tools::LoadSample sample = measure(machine, event, world, tool, next_);
        reg_ = sample.reg;
        if (auto message = monitor_.add(sample)) {
            anomaly = Anomaly{next_, *message};
        }
        const double following = next_ + period;
        if (!(following > next_)) {
            // a move of 1e120 mm ends where a period is below the clock's resolution: adding it
            // changes nothing, and the loop would sample that instant forever
            next_ = std::nextafter(until, std::numeric_limits<double>::infinity());
            break;
        }
        next_ = following;
    }
    return anomaly;
}

SpindleLoadView SpindleLoadWatch::view(int tool, bool fanuc) const {
    SpindleLoadView v;
    v.lambda = model_ ? model_->lambda : v.lambda;
    v.registerVariable = fanuc ? 1032 : 2990;
    v.tool = tool;
    v.reg = reg_;
    v.percent = reg_ / 100.0;
    if (const tools::LoadLimits* limits = monitor_.settings().limitsFor(tool)) {
        v.limits = *limits;
    }
    v.samplesToAlarm = monitor_.settings().samples;
    v.sampleSeconds = monitor_.settings().sampleSeconds;
    v.taken = monitor_.taken();
    const std::deque<tools::LoadSample>& history = monitor_.history();
    v.to = std::max(SpindleLoadView::kPlotSeconds, history.empty() ? 0.0 : history.back().time);
    v.from = v.to - SpindleLoadView::kPlotSeconds;
    double highest = v.limits ? std::max(v.limits->upper, v.limits->lower) : 0.0;
    for (const tools::LoadSample& s : history) {
        if (s.time >= v.from) {
            v.points.emplace_back(s.time, s.percent);
            highest = std::max(highest, s.percent);
        }
    }
    v.top = std::max(100.0, std::ceil(highest * 1.1 / 10.0) * 10.0); // room above the upper limit
    return v;
}

} // namespace m350::controller
