// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "test_scenes.h"
#include "vroc/bullet/bullet_backend.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/errors.h"

namespace vroc::test {
namespace {

TEST(BulletRegistration, RegistersOnceWithVersionAndSettings) {
    bullet::registerBackend();
    bullet::registerBackend();   // harmless
    const BackendInfo* info = BackendRegistry::global().find("bullet");
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->version, "Bullet 3.24 (double)");
    for (const char* key : {"bullet.substeps", "bullet.solver_iterations", "bullet.ccd", "bullet.margin",
                            "bullet.shrink_hulls", "bullet.split_impulse", "bullet.restitution_threshold",
                            "bullet.warmstarting_factor", "bullet.friction_directions", "bullet.ccd_radius"}) {
        bool found = false;
        for (const auto& spec : info->settings) found |= spec.key == key && !spec.help.empty();
        EXPECT_TRUE(found) << key;
    }
    EXPECT_THROW(resolveSettings(info->settings, {{"bullet.substep", "4"}}), InputError);
    EXPECT_THROW(resolveSettings(info->settings, {{"bullet.substeps", "0"}}), InputError);
    EXPECT_THROW(resolveSettings(info->settings, {{"bullet.margin", "-1"}}), InputError);
}

TEST(BulletRegistration, BadCallsAreInputErrors) {
    Scene scene = emptyScene();
    addBall(scene, "ball", 0.1, 1.0, Vec3::Zero());
    auto backend = makeBullet(scene);
    EXPECT_THROW(backend->bodyState(5), InputError);
    EXPECT_THROW(backend->applyImpulse(-1, Vec3::UnitX(), Vec3::Zero()), InputError);
    BodyState bad;
    bad.linear_velocity.x() = std::numeric_limits<double>::quiet_NaN();
    const BodyState before = backend->bodyState(0);
    backend->setBodyState(0, bad);   // numerical trouble (docs/backend-contract.md): counted, refused
    EXPECT_EQ(backend->warnings().at("nonfinite_state"), 1u);
    EXPECT_EQ(backend->bodyState(0).pose.position, before.pose.position);
    BodyState no_rotation = before;
    no_rotation.pose.orientation.coeffs().setZero();
    EXPECT_THROW(backend->setBodyState(0, no_rotation), InputError);
    EXPECT_THROW(backend->stepFrame(0.0), InputError);
    Scene massless = emptyScene();
    addFloor(massless);
    addBall(massless, "good", 0.1, 1.0, Vec3(0, 0, 1));
    addBall(massless, "ball", 0.1, 0.0, Vec3::Zero());
    EXPECT_THROW(makeBullet(massless), InputError);   // after valid bodies: nothing leaks or dangles
    Scene no_material = emptyScene();
    addBall(no_material, "ball", 0.1, 1.0, Vec3::Zero(), /*material=*/3);
    EXPECT_THROW(makeBullet(no_material), InputError);
}

TEST(BulletRegistration, OverflowToInfinityIsCountedAndRecovered) {
    // A body set next to the largest double overflows to +inf in the next internal step; the
    // backend counts it and puts the body back to its last good state, which then falls on.
    Scene scene = emptyScene();
    addFloor(scene);
    const int ball = addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 1));
    auto backend = makeBullet(scene);
    backend->stepFrame(scene.frame_dt);
    const BodyState good = backend->bodyState(ball);
    BodyState wild = good;
    wild.pose.position.x() = 1.797e308;
    wild.linear_velocity.x() = 1e308;
    backend->setBodyState(ball, wild);
    backend->stepFrame(scene.frame_dt);
    EXPECT_EQ(backend->warnings().at("nonfinite_state"), 1u);
    const BodyState s = backend->bodyState(ball);
    ASSERT_TRUE(s.pose.position.allFinite() && s.linear_velocity.allFinite());
    EXPECT_LT((s.pose.position - good.pose.position).norm(), 0.05) << s.pose.position.transpose();
    for (int f = 0; f < 10; ++f) backend->stepFrame(scene.frame_dt);
    EXPECT_LT(backend->bodyState(ball).pose.position.z(), s.pose.position.z() - 0.05);
}

}  // namespace
}  // namespace vroc::test
