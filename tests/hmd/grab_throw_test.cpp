// SPDX-License-Identifier: MIT
// Grab and throw on the Bullet and native backends: the analytic plugin's throw arc picks a ball
// up and releases it; the thrown velocity must match the device's own (analytic) velocity at the
// release frame, the backend must carry exactly that velocity, and both backends must agree.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "test_backends.h"
#include "vroc/core/mass_properties.h"
#include "vroc/play/device_source.h"
#include "vroc/play/grab_controller.h"
#include "vroc/plugin/plugin_host.h"

namespace vroc::play {
namespace {

using test::registerBackendsOnce;

/// Zero gravity, a real floor far below and one ball where the throw arc starts.
Scene throwScene(const Vec3& ball_at) {
    Scene scene;
    scene.name = "throw";
    scene.gravity = Vec3::Zero();
    scene.materials.push_back({"m", 0.5, 0.5});
    Body floor;
    floor.name = "floor";
    floor.role = BodyRole::Real;
    floor.shape = Shape::box(Vec3(2, 2, 0.1));
    floor.pose.position = Vec3(0, 0, -5);
    scene.bodies.push_back(floor);
    Body ball;
    ball.name = "ball";
    ball.role = BodyRole::Virtual;
    ball.shape = Shape::sphere(0.05);
    ball.pose.position = ball_at;
    ball.mass_properties = massProperties(ball.shape, 0.2);
    scene.bodies.push_back(ball);
    return scene;
}

struct ThrowOutcome {
    ThrowRecord record;
    BodyState after;   // the ball one frame after the release
};

ThrowOutcome throwOn(const std::string& backend_name, DeviceSource& device, const Scene& scene) {
    const BackendInfo& info = BackendRegistry::global().require(backend_name);
    auto backend = info.create(scene, resolveSettings(info.settings, {}));
    GrabController grab(scene, GrabSettings{});
    const double dt = 1.0 / 60.0;
    for (int i = 0; i < 240; ++i) {
        const double t = i * dt;
        const DeviceReading r = device.read(t);
        EXPECT_TRUE(r.valid);
        grab.update(t, r.pose, (r.buttons & 1u) != 0, *backend, &r.linear_velocity, &r.angular_velocity);
        backend->stepFrame(dt);
        if (!grab.throws().empty()) return {grab.throws().front(), backend->bodyState(grab.throws().front().body)};
    }
    ADD_FAILURE() << backend_name << ": no throw within 4 s (grabs: " << grab.grabs() << ")";
    return {};
}

TEST(GrabThrow, AnalyticThrowMatchesOnBulletAndNative) {
    registerBackendsOnce();
    plugins::PluginHost host;
    // Shoulder at (0, 0, 1.2), arm 0.6 m: the hand starts at (-0.6, 0, 1.2), button held.
    const std::string spec = "analytic:motion=throw,x=0,y=0,z=1.2,radius=0.6,throw_speed=3,period=2";
    const Scene scene = throwScene(Vec3(-0.6, 0.0, 1.2));
    PluginDevice bullet_hand(host, spec);
    PluginDevice native_hand(host, spec);
    const ThrowOutcome b = throwOn("bullet", bullet_hand, scene);
    const ThrowOutcome n = throwOn("native", native_hand, scene);
    ASSERT_EQ(b.record.body, 1);
    ASSERT_TRUE(b.record.device_velocity_known);
    std::printf("release at t=%.4f s: thrown v=(%.4f, %.4f, %.4f) m/s, device v=(%.4f, %.4f, %.4f) m/s, "
                "thrown w=(%.4f, %.4f, %.4f), device w=(%.4f, %.4f, %.4f) rad/s\n",
                b.record.time, b.record.linear_velocity.x(), b.record.linear_velocity.y(), b.record.linear_velocity.z(),
                b.record.device_linear_velocity.x(), b.record.device_linear_velocity.y(), b.record.device_linear_velocity.z(),
                b.record.angular_velocity.x(), b.record.angular_velocity.y(), b.record.angular_velocity.z(),
                b.record.device_angular_velocity.x(), b.record.device_angular_velocity.y(), b.record.device_angular_velocity.z());
    // Estimated against analytic: within 3 % of the speed (the fit window straddles the release,
    // where the arc's acceleration jumps from wind-up to follow-through).
    const double speed = b.record.device_linear_velocity.norm();
    EXPECT_GT(speed, 1.0);
    EXPECT_LT((b.record.linear_velocity - b.record.device_linear_velocity).norm(), 0.03 * speed);
    EXPECT_LT((b.record.angular_velocity - b.record.device_angular_velocity).norm(),
              0.03 * b.record.device_angular_velocity.norm());
    // Both backends got the same calls: identical releases.
    EXPECT_EQ(b.record.time, n.record.time);
    EXPECT_LT((b.record.linear_velocity - n.record.linear_velocity).norm(), 1e-12);
    EXPECT_LT((b.record.angular_velocity - n.record.angular_velocity).norm(), 1e-12);
    // And each backend flies the ball with that velocity (no gravity, nothing to hit).
    for (const ThrowOutcome* o : {&b, &n}) {
        EXPECT_LT((o->after.linear_velocity - o->record.linear_velocity).norm(), 1e-9);
        EXPECT_LT((o->after.angular_velocity - o->record.angular_velocity).norm(), 1e-9);
    }
    EXPECT_LT((b.after.pose.position - n.after.pose.position).norm(), 1e-9);
}

TEST(GrabThrow, ScriptedStraightThrowIsExactOnBothBackends) {
    // Without plugins: a hand moving at constant velocity and spin; release after 0.5 s.
    registerBackendsOnce();
    const Vec3 start(0.0, 0.0, 1.0), v(2.0, -0.5, 1.5), w(0.0, 3.0, 1.0);
    FunctionDevice hand("script", [&](double t) {
        DeviceReading r;
        r.valid = true;
        r.pose = {start + v * t, Quat(Eigen::AngleAxisd(w.norm() * t, w.normalized()))};
        r.buttons = t < 0.5 ? 1u : 0u;
        r.linear_velocity = v;
        r.angular_velocity = w;
        return r;
    });
    const Scene scene = throwScene(start + Vec3(0.02, 0, 0));   // ball 2 cm from the hand
    for (const char* name : {"bullet", "native"}) {
        const ThrowOutcome o = throwOn(name, hand, scene);
        // The ball's centre is 2 cm off the hand: it moves with v + w x r.
        const Vec3 r = o.record.linear_velocity - o.record.hand_linear_velocity;
        EXPECT_LT((o.record.hand_linear_velocity - v).norm(), 1e-9) << name;
        EXPECT_LT((o.record.angular_velocity - w).norm(), 1e-9) << name;
        EXPECT_NEAR(r.norm(), (w.cross(Vec3(0.02, 0, 0))).norm(), 1e-9) << name;
        EXPECT_LT((o.after.linear_velocity - o.record.linear_velocity).norm(), 1e-9) << name;
    }
}

}  // namespace
}  // namespace vroc::play
