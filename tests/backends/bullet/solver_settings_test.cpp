// SPDX-License-Identifier: MIT
// bullet.friction_directions and bullet.ccd_radius against independent answers: Coulomb's slide
// (heading kept, stop after v0^2 / (2 mu g)) and the geometry of Bullet's swept-sphere CCD (a body
// too fast for one step is stopped where the swept sphere touches the wall). Numbers printed here
// are quoted in docs/bullet-backend.md.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "test_scenes.h"
#include "vroc/bullet/bullet_backend.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/errors.h"
#include "vroc/core/state_hash.h"

namespace vroc::test {
namespace {

constexpr double kMu = 0.5, kV0 = 3.0, kG = 9.81;

struct Slide {
    double heading_error = 0.0;       ///< [deg] largest |velocity heading - 45| while faster than v0 / 3
    double path_heading_error = 0.0;  ///< [deg] |heading of the displacement - 45| at the end
    double stop = 0.0;                ///< [m] horizontal distance after 2 s
    double speed = 0.0;               ///< [m/s] horizontal speed after 2 s
    double spin = 0.0;                ///< [rad/s] largest |yaw rate|
};

// A 0.2 m cube (1 kg) resting on the floor, sliding at 3 m/s along the world diagonal, mu = 0.5, e = 0.
Slide diagonalSlide(const Overrides& overrides) {
    Scene scene = emptyScene(0.0, kMu);
    addFloor(scene);
    const int box = addBox(scene, "box", Vec3(0.1, 0.1, 0.1), 1.0, Vec3(0, 0, 0.1));
    scene.bodies[static_cast<std::size_t>(box)].linear_velocity = kV0 * Vec3(1, 1, 0).normalized();
    auto backend = makeBullet(scene, overrides);
    Slide r;
    for (int f = 0; f < 120; ++f) {
        backend->stepFrame(scene.frame_dt);
        const BodyState s = backend->bodyState(box);
        r.spin = std::max(r.spin, std::abs(s.angular_velocity.z()));
        const Vec3& v = s.linear_velocity;
        if (v.head<2>().norm() > kV0 / 3)
            r.heading_error = std::max(r.heading_error, std::abs(std::atan2(v.y(), v.x()) * 180 / M_PI - 45));
    }
    const BodyState s = backend->bodyState(box);
    r.stop = s.pose.position.head<2>().norm();
    r.speed = s.linear_velocity.head<2>().norm();
    r.path_heading_error = std::abs(std::atan2(s.pose.position.y(), s.pose.position.x()) * 180 / M_PI - 45);
    return r;
}

// One row along the slip (the default) is Coulomb's cone for a sliding point: the heading is kept.
// A second row across the slip (SOLVER_USE_2_FRICTION_DIRECTIONS) is clamped to mu N on its own;
// Bullet promises no more than that each row is, so of Coulomb's answer only the stop distance
// (the row along the slip still carries mu N) is asserted; the heading is printed. Bullet at its
// own 60 Hz stops a few per cent short (its 60 Hz discretisation, as in contact_test.cpp).
TEST(BulletFrictionDirections, OneRowKeepsTheHeadingBothStopAtTheCoulombDistance) {
    const double coulomb = kV0 * kV0 / (2 * kMu * kG);
    std::printf(
        "| friction_directions | substeps | heading error, v > 1 m/s (deg) | path heading error (deg) | stop (m) "
        "| v0^2/(2 mu g) | largest yaw rate (rad/s) |\n|---|---|---|---|---|---|---|\n");
    for (const char* substeps : {"1", "4"}) {
        for (const char* directions : {"1", "2"}) {
            const Slide s = diagonalSlide({{"bullet.friction_directions", directions}, {"bullet.substeps", substeps}});
            std::printf("| %s | %s | %.3f | %.3f | %.4f (%+.2f %%) | %.4f | %.3f |\n", directions, substeps,
                        s.heading_error, s.path_heading_error, s.stop, 100 * (s.stop / coulomb - 1), coulomb, s.spin);
            const std::string label = std::string("friction_directions ") + directions + ", substeps " + substeps;
            EXPECT_NEAR(s.stop, coulomb, 0.05 * coulomb) << label;
            EXPECT_LT(s.speed, 1e-2) << label;
            if (std::string(directions) == "1") {
                EXPECT_LT(s.heading_error, 1.0) << label;
                EXPECT_LT(s.path_heading_error, 1.0) << label;
            }
        }
    }
}

TEST(BulletFrictionDirections, TwoRowsChangeTheRunAndAreDeterministic) {
    const auto hash = [](const Overrides& o) {
        Scene scene = emptyScene(0.2, 0.6);
        addFloor(scene);
        for (int i = 0; i < 3; ++i) {
            const int b = addBox(scene, "box" + std::to_string(i), Vec3(0.1, 0.08, 0.06), 1.0, Vec3(0.3 * i, 0, 0.06));
            scene.bodies[static_cast<std::size_t>(b)].linear_velocity = Vec3(1.0, 0.5 * i, 0);
            scene.bodies[static_cast<std::size_t>(b)].angular_velocity = Vec3(0, 0, 2.0);
        }
        auto backend = makeBullet(scene, o);
        for (int f = 0; f < 60; ++f) backend->stepFrame(scene.frame_dt);
        return stateHash(*backend);
    };
    const std::uint64_t one = hash({}), two = hash({{"bullet.friction_directions", "2"}});
    EXPECT_EQ(one, hash({{"bullet.friction_directions", "1"}}));  // 1 is the default
    EXPECT_EQ(two, hash({{"bullet.friction_directions", "2"}}));
    EXPECT_NE(one, two);
}

// A box (inner radius 0.1 m) flying at 100 m/s, no gravity, at a real wall 2 cm thick whose face is
// 0.99 m ahead of its centre: one 1/60 s step would carry it 1.67 m, through the wall. Bullet's CCD
// sweeps a sphere of radius ccd_radius x 0.1 m along the step (btDiscreteDynamicsWorld::
// createPredictiveContacts, integrateTransforms) and stops the body where that sphere touches the
// face: its centre ends ccd_radius x 0.1 m before the face.
TEST(BulletCcd, AFastBoxStopsWhereItsSweptSphereTouchesTheWall) {
    const auto firstFrameGap = [](const Overrides& o, double* furthest) {
        Scene scene = bareScene(1e-3, Vec3::Zero());
        scene.materials.push_back({"default", 0.0, 0.5});
        addBody(scene, "wall", Shape::box(Vec3(0.01, 1, 1)), at(Vec3(1.0, 0, 0)), 0, true);
        const int box = addBox(scene, "box", Vec3(0.1, 0.1, 0.1), 1.0, Vec3::Zero());
        scene.bodies[static_cast<std::size_t>(box)].linear_velocity = Vec3(100, 0, 0);
        auto backend = makeBullet(scene, o);
        backend->stepFrame(scene.frame_dt);
        const double gap = 0.99 - backend->bodyState(box).pose.position.x();
        *furthest = backend->bodyState(box).pose.position.x();
        for (int f = 0; f < 60; ++f) {
            backend->stepFrame(scene.frame_dt);
            *furthest = std::max(*furthest, backend->bodyState(box).pose.position.x());
        }
        return gap;
    };
    std::printf(
        "| ccd_radius | centre to wall face after the first frame (m) | expected (m) | furthest x in 1 s (m) |\n"
        "|---|---|---|---|\n");
    for (double radius : {0.1, 0.25, 0.5, 1.0}) {
        double furthest = 0.0;
        const double gap = firstFrameGap({{"bullet.ccd_radius", std::to_string(radius)}}, &furthest);
        std::printf("| %.2f | %.6f | %.6f | %.4f |\n", radius, gap, radius * 0.1, furthest);
        EXPECT_NEAR(gap, radius * 0.1, 1e-6) << "ccd_radius " << radius;
        EXPECT_LT(furthest, 0.99) << "ccd_radius " << radius;  // the centre never reached the face
    }
    double furthest = 0.0;
    const double gap = firstFrameGap({{"bullet.ccd", "false"}}, &furthest);
    std::printf("| ccd off | %.4f | - | %.4f |\n", gap, furthest);
    EXPECT_GT(furthest, 1.01);  // without CCD it tunnels: the test can tell
}

TEST(BulletSolverSettings, DeclaredWithBulletsDefaultsAndBadValuesRefused) {
    bullet::registerBackend();
    const BackendInfo& info = BackendRegistry::global().require("bullet");
    for (const auto& [key, value] :
         std::vector<std::pair<std::string, std::string>>{{"bullet.friction_directions", "0"},
                                                          {"bullet.friction_directions", "3"},
                                                          {"bullet.friction_directions", "1.5"},
                                                          {"bullet.ccd_radius", "0"},
                                                          {"bullet.ccd_radius", "1.5"},
                                                          {"bullet.ccd_radius", "half"}}) {
        EXPECT_THROW(resolveSettings(info.settings, {{key, value}}), InputError) << key << "=" << value;
    }
    const Settings s = resolveSettings(info.settings, {});
    EXPECT_EQ(s.integer("bullet.friction_directions"), 1);
    EXPECT_EQ(s.real("bullet.ccd_radius"), 0.5);
}

}  // namespace
}  // namespace vroc::test
