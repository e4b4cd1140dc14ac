// SPDX-License-Identifier: MIT
// The grab's virtual coupling against closed forms, on Bullet and native: a held ball's free
// response follows the explicit spring-damper recurrence's two roots (so k = m w^2 and
// c = 2 zeta m w are what is applied, through Backend::applyImpulse only), for translation and
// rotation; with gravity compensation a held ball hangs exactly at the hand, without it it sags by
// g / w^2; the stability cap softens the coupling for long frames.
#include <cmath>
#include <complex>
#include <cstdio>

#include <gtest/gtest.h>

#include "test_backends.h"
#include "test_scene_builder.h"
#include "vroc/play/grab_controller.h"

namespace vroc::play {
namespace {

using test::registerBackendsOnce;

constexpr double kDt = 1.0 / 60.0;

/// One ball (r = 5 cm, 0.2 kg) at `at` with velocities, a real floor far below.
Scene ballScene(const Vec3& at, const Vec3& v, const Vec3& w, const Vec3& gravity) {
    Scene scene = test::emptyScene(0.5, 0.5);
    scene.name = "coupling";
    scene.gravity = gravity;
    test::addBody(scene, "floor", Shape::box(Vec3(2, 2, 0.1)), test::at(Vec3(0, 0, -5)), 0, true);
    const int ball = test::addBody(scene, "ball", Shape::sphere(0.05), test::at(at), 0, false, 0.2);
    scene.bodies[ball].linear_velocity = v;
    scene.bodies[ball].angular_velocity = w;
    return scene;
}

/// Holds the ball with a hand fixed at `hand` for `frames` frames; returns the ball's states
/// at the frame ends.
std::vector<BodyState> holdStill(const std::string& backend_name, const Scene& scene, const Pose& hand, int frames,
                                 const GrabSettings& settings = {}) {
    const BackendInfo& info = BackendRegistry::global().require(backend_name);
    auto backend = info.create(scene, resolveSettings(info.settings, {}));
    GrabController grab(scene, settings);
    std::vector<BodyState> out;
    for (int i = 0; i < frames; ++i) {
        HandInput in;
        in.t = i * kDt;
        in.dt = kDt;
        in.pose = hand;
        in.button = true;
        grab.update(in, *backend);
        EXPECT_EQ(grab.heldBody(), std::optional<int>(1));
        backend->stepFrame(kDt);
        out.push_back(backend->bodyState(1));
    }
    return out;
}

/// x_n of x_{n+1} = (2 - a - b) x_n - (1 - b) x_{n-1}, x_0 = 0, x_1 given: the explicit coupling's
/// free response (grab_controller.h) in closed form from its characteristic roots.
double closedForm(double a, double b, double x1, int n) {
    const std::complex<double> p = 2.0 - a - b, q = 1.0 - b;
    const std::complex<double> root = std::sqrt(p * p - 4.0 * q);
    const std::complex<double> z1 = 0.5 * (p + root), z2 = 0.5 * (p - root);
    return (x1 * (std::pow(z1, n) - std::pow(z2, n)) / (z1 - z2)).real();
}

TEST(GrabCoupling, FreeResponseFollowsTheClosedFormOnBothBackends) {
    // The ball starts at the hand moving at v0 and spinning at w0 about z; the hand holds still, so
    // the coupling brings it back: x_1 = v0 (1 - b) dt (the first frame's damping), then the
    // recurrence. Zero gravity, nothing to hit.
    registerBackendsOnce();
    const Vec3 at(0, 0, 1), v0(0.8, -0.3, 0.4), w0(0, 0, 5.0);
    const Scene scene = ballScene(at, v0, w0, Vec3::Zero());
    const double w = 2 * M_PI * 5.0, a = (w * kDt) * (w * kDt), b = 2 * 1.0 * w * kDt;
    for (const char* name : {"native", "bullet"}) {
        const std::vector<BodyState> states = holdStill(name, scene, Pose{at, Quat::Identity()}, 60);
        double worst_x = 0, worst_angle = 0;
        for (int n = 1; n <= 60; ++n) {
            const Vec3 expected = closedForm(a, b, 1.0, n) * (1.0 - b) * kDt * v0;
            worst_x = std::max(worst_x, (states[n - 1].pose.position - at - expected).norm());
            const double expected_angle = closedForm(a, b, 1.0, n) * (1.0 - b) * kDt * w0.z();
            const Vec3 rv = Eigen::AngleAxisd(states[n - 1].pose.orientation).angle() *
                            Eigen::AngleAxisd(states[n - 1].pose.orientation).axis();
            worst_angle = std::max(worst_angle, std::abs(rv.z() - expected_angle) + rv.head<2>().norm());
        }
        std::printf("%s: largest distance from the closed form over 60 frames: %.2e m, %.2e rad "
                    "(first step %.4f m)\n", name, worst_x, worst_angle, (1.0 - b) * kDt * v0.norm());
        EXPECT_LT(worst_x, 1e-12) << name;
        EXPECT_LT(worst_angle, 1e-11) << name;
    }
}

TEST(GrabCoupling, GravityCompensatedBallHangsAtTheHandAndSagsWithout) {
    // Held still under gravity: with the compensation the ball settles exactly at the hand (the
    // damper uses the ball's mean velocity over each frame, so no gravity bias whatever the
    // integrator); without it the spring carries the weight, m g = k e, so it sags by g / w^2.
    registerBackendsOnce();
    const Vec3 at(0, 0, 1);
    const Scene scene = ballScene(at, Vec3::Zero(), Vec3::Zero(), Vec3(0, 0, -9.81));
    const double w = 2 * M_PI * 5.0;
    GrabSettings no_compensation;
    no_compensation.gravity_compensation = false;
    for (const char* name : {"native", "bullet"}) {
        const Vec3 hang = holdStill(name, scene, Pose{at, Quat::Identity()}, 180).back().pose.position;
        const Vec3 sag = holdStill(name, scene, Pose{at, Quat::Identity()}, 180, no_compensation).back().pose.position;
        std::printf("%s: compensated ball %.2e m from the hand; uncompensated sag %.6f m (g/w^2 = %.6f m)\n", name,
                    (hang - at).norm(), at.z() - sag.z(), 9.81 / (w * w));
        EXPECT_LT((hang - at).norm(), 1e-9) << name;
        EXPECT_NEAR(at.z() - sag.z(), 9.81 / (w * w), 1e-9) << name;
        EXPECT_LT((sag - at).head<2>().norm(), 1e-12) << name;
    }
}

TEST(GrabCoupling, LongFramesAreCappedInsideTheStabilityRegion) {
    const Scene scene = ballScene(Vec3(0, 0, 1), Vec3::Zero(), Vec3::Zero(), Vec3::Zero());
    GrabController grab(scene, GrabSettings{});
    // 60 frames/s: 2 pi 5 Hz, uncapped (w dt = 0.52).
    EXPECT_DOUBLE_EQ(grab.couplingOmega(kDt), 2 * M_PI * 5.0);
    // 10 frames/s: capped at 0.7 of the limit x_max = 2 (sqrt(2) - 1) for zeta = 1.
    const double capped = grab.couplingOmega(0.1) * 0.1;
    EXPECT_NEAR(capped, 0.7 * 2 * (std::sqrt(2.0) - 1), 1e-12);
    // And that is stable: both roots of z^2 - (2 - a - b) z + (1 - b) inside the unit circle.
    const double a = capped * capped, b = 2 * capped;
    const std::complex<double> p = 2.0 - a - b, root = std::sqrt(p * p - 4.0 * (1.0 - b));
    EXPECT_LT(std::abs(0.5 * (p + root)), 1.0);
    EXPECT_LT(std::abs(0.5 * (p - root)), 1.0);
    // A ball held at 10 frames/s with a 1 m/s kick settles (native).
    registerBackendsOnce();
    const Scene kicked = ballScene(Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3::Zero(), Vec3::Zero());
    const BackendInfo& info = BackendRegistry::global().require("native");
    auto backend = info.create(kicked, resolveSettings(info.settings, {}));
    GrabController held(kicked, GrabSettings{});
    for (int i = 0; i < 100; ++i) {
        HandInput in;
        in.t = i * 0.1;
        in.dt = 0.1;
        in.pose = Pose{Vec3(0, 0, 1), Quat::Identity()};
        in.button = true;
        held.update(in, *backend);
        backend->stepFrame(0.1);
    }
    EXPECT_LT((backend->bodyState(1).pose.position - Vec3(0, 0, 1)).norm(), 1e-9);
}

}  // namespace
}  // namespace vroc::play
