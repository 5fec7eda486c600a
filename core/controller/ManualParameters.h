#pragma once

#include "core/params/ParameterTable.h"

namespace m350::controller::manual {

// The manual-motion parameters (35-59, 172-185) as the jog keys and the handwheel use them. A
// machine folder that leaves one unset (0) gets the M350's factory value, as the controller's
// other speeds fall back when a folder does not set them. Speeds in mm/min (deg/min), accelerations
// in mm/s^2; axis 0..4 = X Y Z 4th 5th.

double jogSpeed(const params::ParameterTable& p, int axis, bool high); // 手动高速 / 手动低速
double maxManualSpeed(const params::ParameterTable& p, int axis);      // 手动最大速度
double startAcceleration(const params::ParameterTable& p, int axis);   // 手动启动加速度
double stopAcceleration(const params::ParameterTable& p, int axis);    // 手动停止加速度

double mpgDistance(const params::ParameterTable& p);                   // mm per detent at x1 (172)
bool mpgReversed(const params::ParameterTable& p);                     // 175
// 171 手轮精准控制模式: 0 开启 (Yes): after the wheel stops the axis runs out every pulse it was
// given; 1 关闭 (No, the factory value): it stops as the wheel stops.
bool mpgPrecise(const params::ParameterTable& p);
// The wheel's speed at x1, x10 or x100 (176-178); 0 for any other multiplier.
double mpgSpeed(const params::ParameterTable& p, int multiplier);
double mpgAcceleration(const params::ParameterTable& p, int axis);     // 181-185

double guideChangeStep(const params::ParameterTable& p);               // 180, a fraction
double guideStopStep(const params::ParameterTable& p);                 // 179, a fraction

// Soft limits (155, 161-170): the travel of `axis` when they are on.
struct Travel {
    double low;
    double high;
};
bool softLimitsOn(const params::ParameterTable& p);
Travel softLimits(const params::ParameterTable& p, int axis);

} // namespace m350::controller::manual
