#include "core/machine/MotionProfile.h"

#include <gtest/gtest.h>

namespace {

using m350::machine::MotionProfile;

TEST(MotionProfile, TrapezoidReachesCruiseSpeed) {
    // 100 mm at 50 mm/s with 500 mm/s^2: 0.1 s ramps (2.5 mm each), 95 mm cruise = 1.9 s
    MotionProfile p(100.0, 50.0, 500.0);
    EXPECT_DOUBLE_EQ(p.peakSpeed(), 50.0);
    EXPECT_NEAR(p.duration(), 2.1, 1e-12);
    EXPECT_NEAR(p.distanceAt(0.1), 2.5, 1e-12);
    EXPECT_NEAR(p.distanceAt(1.05), 50.0, 1e-9);
    EXPECT_NEAR(p.speedAt(1.0), 50.0, 1e-12);
    EXPECT_DOUBLE_EQ(p.distanceAt(5.0), 100.0);
}

TEST(MotionProfile, ShortMoveIsTriangular) {
    // 1 mm at 100 mm/s with 100 mm/s^2 never reaches 100 mm/s: peak sqrt(100) = 10 mm/s
    MotionProfile p(1.0, 100.0, 100.0);
    EXPECT_NEAR(p.peakSpeed(), 10.0, 1e-12);
    EXPECT_NEAR(p.duration(), 0.2, 1e-12);
    EXPECT_NEAR(p.distanceAt(0.1), 0.5, 1e-12);
}

TEST(MotionProfile, TimeAtInvertsDistanceAt) {
    MotionProfile p(37.0, 20.0, 300.0);
    for (double d : {0.0, 0.3, 0.6667, 5.0, 30.0, 36.5, 37.0}) {
        EXPECT_NEAR(p.distanceAt(p.timeAt(d)), d, 1e-9) << d;
    }
}

TEST(MotionProfile, ZeroLengthTakesNoTime) {
    MotionProfile p(0.0, 20.0, 300.0);
    EXPECT_EQ(p.duration(), 0.0);
    EXPECT_EQ(p.distanceAt(1.0), 0.0);
}

} // namespace
