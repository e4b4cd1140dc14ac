// SPDX-License-Identifier: MIT
// AxisKalman against closed forms: a constant-acceleration signal is tracked to its value, rate and
// acceleration; the first value update has the scalar gain P00 / (P00 + r^2).
#include <gtest/gtest.h>

#include "vroc/core/axis_kalman.h"

namespace vroc {
namespace {

// x(t) = 1 + 2 t + 1.5 t^2: rate 2 + 3 t, acceleration 3.
double signal(double t) { return 1 + 2 * t + 1.5 * t * t; }

TEST(AxisKalman, TracksAConstantAccelerationSignalFromValuesAlone) {
    AxisKalman k(1e-6, 1e-6);
    const double dt = 0.01;
    k.reset(signal(0), 0, false);
    for (int i = 1; i <= 200; ++i) {
        k.predict(dt);
        k.update(signal(i * dt), 0, false);
    }
    const double t = 2.0;
    EXPECT_NEAR(k.value(), signal(t), 1e-6);
    EXPECT_NEAR(k.rate(), 2 + 3 * t, 1e-3);
    EXPECT_NEAR(k.acceleration(), 3.0, 1e-2);
    EXPECT_NEAR(k.extrapolate(0.1), signal(t + 0.1), 1e-3);
}

TEST(AxisKalman, MeasuredRatesAreUsedFromTheFirstSample) {
    AxisKalman k(1e-6, 1e-6, 1e-6);
    k.reset(signal(0), 2.0, true);
    EXPECT_DOUBLE_EQ(k.rate(), 2.0);
    const double dt = 0.01;
    for (int i = 1; i <= 50; ++i) {
        k.predict(dt);
        k.update(signal(i * dt), 2 + 3 * i * dt, true);
    }
    EXPECT_NEAR(k.rate(), 2 + 3 * 0.5, 1e-4);
    EXPECT_NEAR(k.acceleration(), 3.0, 1e-2);
}

TEST(AxisKalman, FirstUpdateHasTheScalarGain) {
    // Prior P = diag(r^2, 100, 1e4); no time passes, so the update alone moves the value:
    // k0 = r^2 / (r^2 + r^2) = 1/2, halfway to the measurement; rate and acceleration stay 0.
    AxisKalman k(50.0, 0.1);
    k.reset(1.0, 0, false);
    k.predict(0.0);   // dt <= 0: nothing
    k.update(2.0, 0, false);
    EXPECT_DOUBLE_EQ(k.value(), 1.5);
    EXPECT_DOUBLE_EQ(k.rate(), 0.0);
    EXPECT_DOUBLE_EQ(k.acceleration(), 0.0);
    k.shift(-0.5);
    EXPECT_DOUBLE_EQ(k.value(), 1.0);
}

}  // namespace
}  // namespace vroc
