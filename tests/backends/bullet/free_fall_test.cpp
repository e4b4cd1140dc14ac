// SPDX-License-Identifier: MIT
// Free flight against closed forms. Bullet integrates semi-implicit Euler with internal step h:
//   v_n = v0 + n h g,   x_n = x0 + n h v0 + g h^2 n (n + 1) / 2,
// which differs from the continuous x0 + v0 t + g t^2 / 2 (t = n h) by exactly g h t / 2.
#include <gtest/gtest.h>

#include "test_scenes.h"

namespace vroc::test {
namespace {

TEST(BulletFreeFall, MatchesSemiImplicitEulerAndBoundsTheContinuousError) {
    Scene scene = emptyScene();
    const Vec3 x0(0.5, -1.0, 10.0), v0(1.0, 0.25, 3.0);
    const int ball = addBall(scene, "ball", 0.1, 2.0, x0);
    scene.bodies[ball].linear_velocity = v0;
    const int substeps = 4, frames = 90;
    auto backend = makeBullet(scene, {{"bullet.substeps", std::to_string(substeps)}});
    for (int f = 0; f < frames; ++f) backend->stepFrame(scene.frame_dt);

    const double h = scene.frame_dt / substeps;
    const double n = substeps * frames, t = n * h;
    const Vec3 g = scene.gravity;
    const Vec3 discrete = x0 + n * h * v0 + g * (h * h * n * (n + 1) / 2);
    const Vec3 continuous = x0 + v0 * t + 0.5 * g * t * t;
    const BodyState s = backend->bodyState(ball);
    SCOPED_TRACE("x0=(0.5,-1,10) v0=(1,0.25,3) h=1/240 n=360");
    EXPECT_LT((s.pose.position - discrete).norm(), 1e-12 * discrete.norm());
    EXPECT_LT((s.linear_velocity - (v0 + g * t)).norm(), 1e-12);
    // The continuous closed form differs by the integrator's known error g h t / 2, no more.
    EXPECT_NEAR((s.pose.position - continuous).norm(), 0.5 * g.norm() * h * t, 1e-9);
    EXPECT_DOUBLE_EQ(backend->time(), frames * scene.frame_dt);
    // No interpolated states: the reported time is a whole number of internal steps.
    EXPECT_EQ(backend->statistics().at("internal_steps"), n);
}

TEST(BulletFreeFall, ErrorShrinksWithTheSubstepCount) {
    Scene scene = emptyScene();
    addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 0));
    double previous = 1e9;
    for (int substeps : {1, 2, 8}) {
        auto backend = makeBullet(scene, {{"bullet.substeps", std::to_string(substeps)}});
        for (int f = 0; f < 60; ++f) backend->stepFrame(scene.frame_dt);
        const double z = backend->bodyState(0).pose.position.z();
        const double error = std::abs(z - (-0.5 * 9.81));
        const double h = scene.frame_dt / substeps;
        EXPECT_NEAR(error, 0.5 * 9.81 * h * 1.0, 1e-9) << "substeps=" << substeps;
        EXPECT_LT(error, previous);
        previous = error;
    }
}

}  // namespace
}  // namespace vroc::test
