// SPDX-License-Identifier: MIT
// Free flight against closed forms. MuJoCo's Euler integrator is semi-implicit with step h:
//   v_n = v0 + n h g,   x_n = x0 + n h v0 + g h^2 n (n + 1) / 2,
// which differs from the continuous x0 + v0 t + g t^2 / 2 (t = n h) by exactly g h t / 2.
#include <gtest/gtest.h>

#include "test_scenes.h"

namespace vroc::test {
namespace {

TEST(MujocoFreeFall, MatchesSemiImplicitEulerOnTheFrameGrid) {
    const FreeFlight f;
    const Scene& scene = f.scene;
    const int ball = f.ball;
    const Vec3 v0 = f.v0;
    const int frames = 90;
    auto backend = makeMujoco(scene);
    run(*backend, scene, frames);

    const double h = scene.frame_dt / 9;   // ceil((1/60) / 0.002) = 9 equal steps
    const double n = 9.0 * frames, t = n * h;
    const Vec3 g = scene.gravity;
    const Vec3 discrete = f.euler(h, n);
    const Vec3 continuous = f.parabola(t);
    const BodyState s = backend->bodyState(ball);
    EXPECT_LT((s.pose.position - discrete).norm(), 1e-12 * discrete.norm());
    EXPECT_LT((s.linear_velocity - (v0 + g * t)).norm(), 1e-12);
    EXPECT_NEAR((s.pose.position - continuous).norm(), 0.5 * g.norm() * h * t, 1e-9);
    EXPECT_DOUBLE_EQ(backend->time(), frames * scene.frame_dt);
    EXPECT_EQ(backend->statistics().at("internal_steps"), n);
}

TEST(MujocoFreeFall, TimestepSettingSetsTheStepCount) {
    Scene scene = emptyScene();
    addBall(scene, "ball", 0.1, 1.0, Vec3::Zero());
    for (const auto& [ts, steps] : {std::pair{"0.002", 9}, std::pair{"0.01", 2}, std::pair{"0.0001", 167}}) {
        auto backend = makeMujoco(scene, {{"mujoco.timestep", ts}, {"mujoco.contact_timeconst", "0.02"}});
        run(*backend, scene, 60);
        EXPECT_EQ(backend->statistics().at("internal_steps"), 60 * steps) << ts;
        const double h = scene.frame_dt / steps, n = 60.0 * steps;
        EXPECT_NEAR(backend->bodyState(0).pose.position.z(), -9.81 * h * h * n * (n + 1) / 2, 1e-12) << ts;
    }
    // A frame of exactly 5 timesteps is 5 steps, not 6 (rounding of 0.01 / 0.002).
    auto backend = makeMujoco(scene);
    backend->stepFrame(0.01);
    EXPECT_EQ(backend->statistics().at("internal_steps"), 5);
    // The step cap: a long frame takes max_substeps steps and is counted.
    auto capped = makeMujoco(scene, {{"mujoco.max_substeps", "10"}});
    capped->stepFrame(1.0);
    EXPECT_EQ(capped->statistics().at("internal_steps"), 10);
    EXPECT_EQ(capped->warnings().at("internal_step_cap"), 1u);
}

}  // namespace
}  // namespace vroc::test
