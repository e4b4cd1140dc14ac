// SPDX-License-Identifier: MIT
// The least-squares velocity estimator against closed-form motions.
#include <cmath>

#include <gtest/gtest.h>

#include "vroc/core/rotation_vector.h"
#include "vroc/play/velocity_estimator.h"

namespace vroc::play {
namespace {

TEST(VelocityEstimator, QuadraticFitIsExactForConstantAccelerationAndSteadySpin) {
    VelocityEstimator est(6, 2);
    const Vec3 p0(0.1, -0.2, 1.0), v0(1.0, 0.5, -0.3), acc(2.0, -1.0, 4.0);
    const Vec3 w(0.3, -1.2, 2.0);   // constant axis: rotation vectors are exactly w t
    const Quat q0(Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()));
    double t = 0.0;
    for (int i = 0; i < 10; ++i) {
        t = 0.3 + i / 60.0;
        est.add(t, {p0 + v0 * t + 0.5 * acc * t * t, quatFromRotationVector(w * t) * q0});
    }
    EXPECT_LT((est.linearVelocity() - (v0 + acc * t)).norm(), 1e-9);
    EXPECT_LT((est.angularVelocity() - w).norm(), 1e-9);
}

TEST(VelocityEstimator, StraightLineFitLagsByHalfTheWindowUnderAcceleration) {
    // Degree 1 returns the mean velocity over the window: v(t_newest - (n-1) dt / 2) exactly.
    VelocityEstimator est(5, 1);
    const Vec3 acc(0, 0, -9.81);
    double t = 0.0;
    for (int i = 0; i < 5; ++i) {
        t = i / 60.0;
        est.add(t, {0.5 * acc * t * t, Quat::Identity()});
    }
    EXPECT_LT((est.linearVelocity() - acc * (t - 2.0 / 60.0)).norm(), 1e-12);
}

}  // namespace
}  // namespace vroc::play
