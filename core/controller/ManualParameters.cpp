#include "core/controller/ManualParameters.h"

#include "core/params/ParameterNumbers.h"

#include <array>
#include <cstddef>

namespace m350::controller::manual {


namespace {

// The M350's factory values (default_setting), X Y Z 4th 5th.
constexpr std::array<double, 5> kMaxSpeed{20000, 20000, 8000, 6000, 6000};
constexpr std::array<double, 5> kHighSpeed{3000, 3000, 3000, 3000, 4000};
constexpr std::array<double, 5> kLowSpeed{1000, 1000, 1000, 1000, 2000};
constexpr std::array<double, 5> kAcceleration{1000, 1000, 1000, 600, 600}; // start and stop alike
constexpr std::array<double, 3> kMpgSpeed{20, 50, 100};                   // x1 x10 x100
constexpr double kMpgAcceleration = 50.0;
constexpr double kMpgDistance = 0.004;
constexpr double kGuideChangeStep = 0.01;
constexpr double kGuideStopStep = 0.05;

double orDefault(const params::ParameterTable& p, int number, double factory) {
    double value = p.get(number);
    return value > 0.0 ? value : factory;
}

std::size_t at(int axis) { return static_cast<std::size_t>(axis); }

} // namespace

double jogSpeed(const params::ParameterTable& p, int axis, bool high) {
    return high ? orDefault(p, param::kManualHighSpeedX + axis, kHighSpeed[at(axis)])
                : orDefault(p, param::kManualLowSpeedX + axis, kLowSpeed[at(axis)]);
}

double maxManualSpeed(const params::ParameterTable& p, int axis) {
    return orDefault(p, param::kManualMaxSpeedX + axis, kMaxSpeed[at(axis)]);
}

double startAcceleration(const params::ParameterTable& p, int axis) {
    return orDefault(p, param::kManualStartAccelerationX + axis, kAcceleration[at(axis)]);
}

double stopAcceleration(const params::ParameterTable& p, int axis) {
    return orDefault(p, param::kManualStopAccelerationX + axis, kAcceleration[at(axis)]);
}

double mpgDistance(const params::ParameterTable& p) { return orDefault(p, param::kMpgDistance, kMpgDistance); }

bool mpgReversed(const params::ParameterTable& p) { return p.get(param::kMpgReversed) != 0.0; }

bool mpgPrecise(const params::ParameterTable& p) { return p.get(param::kMpgPrecise) == 0.0; }

double mpgSpeed(const params::ParameterTable& p, int multiplier) {
    switch (multiplier) {
    case 1: return orDefault(p, param::kMpgSpeedX1, kMpgSpeed[0]);
    case 10: return orDefault(p, param::kMpgSpeedX1 + 1, kMpgSpeed[1]);
    case 100: return orDefault(p, param::kMpgSpeedX1 + 2, kMpgSpeed[2]);
    default: return 0.0;
    }
}

double mpgAcceleration(const params::ParameterTable& p, int axis) {
    return orDefault(p, param::kMpgAccelerationX + axis, kMpgAcceleration);
}

double guideChangeStep(const params::ParameterTable& p) {
    return orDefault(p, param::kGuideChangeStep, kGuideChangeStep);
}

double guideStopStep(const params::ParameterTable& p) { return orDefault(p, param::kGuideStopStep, kGuideStopStep); }

bool softLimitsOn(const params::ParameterTable& p) { return p.get(param::kSoftLimitsEnabled) != 0.0; }

Travel softLimits(const params::ParameterTable& p, int axis) {
    return {p.get(param::kSoftLimitNegativeX + axis), p.get(param::kSoftLimitPositiveX + axis)};
}

} // namespace m350::controller::manual
