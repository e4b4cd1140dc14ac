// SPDX-License-Identifier: MIT
// Resting and sliding contact against closed forms: a hull at rest, Coulomb sliding distance
// v0^2 / (2 mu g) for any heading, rolling down an incline at (5/7) g sin(theta).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "native_test_scenes.h"
#include "vroc/core/scene_loader.h"

namespace vroc::native::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(NativeRest, DroppedHullComesToRestWithinCollisionDistance) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Vec3> pts;
    for (int i = 0; i < 30; ++i) pts.push_back(Vec3(0.3 * u(rng), 0.2 * u(rng), 0.15 * u(rng)));
    Scene s = bareScene(1e-3);
    const int mat = addMaterial(s, 0.3, 0.6);
    addFloor(s, mat, 20.0);
    const int hull = addBody(s, "hull", Shape::convexHull(ConvexPolyhedron::fromPoints(pts)),
                             at(Vec3(0, 0, 0.5), Quat(Eigen::AngleAxisd(0.4, Vec3(1, 1, 0).normalized()))),
                             mat, false, 2.0);
    auto be = makeBackend(s);
    for (int f = 0; f < 240; ++f) be->stepFrame(s.frame_dt);
    const BodyState rest = be->bodyState(hull);
    for (int f = 0; f < 120; ++f) be->stepFrame(s.frame_dt);
    const BodyState later = be->bodyState(hull);
    EXPECT_LT((later.pose.position - rest.pose.position).norm(), 1e-6) << "creep";
    EXPECT_LT(later.pose.orientation.angularDistance(rest.pose.orientation), 1e-6) << "creep";
    EXPECT_LT(later.linear_velocity.norm(), 1e-6);
    EXPECT_LT(later.angular_velocity.norm(), 1e-6);
    double gap = 1e9;
    const auto& poly = *s.bodies[hull].shape.hull;
    for (const Vec3& v : poly.vertices) gap = std::min(gap, later.pose.apply(v).z());
    EXPECT_GE(gap, 0.0);
    EXPECT_LE(gap, s.collision_distance);
    EXPECT_TRUE(be->warnings().count("penetration_recovered") == 0);
}

TEST(NativeRest, PaperNotepadDroppedOnTheTableComesToRest) {
    // The paper's notepad (a 0.148 x 0.21 x 0.012 m plate) dropped tilted onto the table: the
    // centroid impulse of issue 9 left it rocking at up to 0.4 m/s at its rim for ever (one corner
    // approaching while its neighbour rose); the patch impulse stops it. At rest: every point of it
    // still, so |v| + |w| r (r its half diagonal) below 1e-3 m/s (issue 22's target) from 2 s on.
    const Scene s = loadScene(std::string(VROC_SOURCE_DIR) + "/scenes/notepad.json");
    int pad = -1;
    for (std::size_t i = 0; i < s.bodies.size(); ++i)
        if (s.bodies[i].name == "notepad") pad = static_cast<int>(i);
    ASSERT_GE(pad, 0);
    const double r = std::hypot(0.074, 0.105, 0.006);
    auto be = makeBackend(s);
    double rim = 0.0;
    for (int f = 0; f < 240; ++f) {
        be->stepFrame(s.frame_dt);
        const BodyState st = be->bodyState(pad);
        if (be->time() >= 2.0) rim = std::max(rim, st.linear_velocity.norm() + st.angular_velocity.norm() * r);
    }
    EXPECT_LT(rim, 1e-3) << "rim speed after 2 s [m/s]";
    EXPECT_EQ(be->warnings().count("penetration_recovered"), 0u);
}

TEST(NativeRest, SlidingBoxStopsAtCoulombDistanceForEveryHeading) {
    const double mu = 0.5, v0 = 3.0, g = 9.81;
    const double expected = v0 * v0 / (2 * mu * g);
    double lo = 1e9, hi = -1e9;
    for (int k = 0; k < 8; ++k) {
        const double heading = k * kPi / 16;   // 0 .. 78.75 degrees
        Scene s = bareScene(1e-3);
        const int mat = addMaterial(s, 0.0, mu);
        addFloor(s, mat, 20.0);
        const Quat yaw(Eigen::AngleAxisd(heading, Vec3::UnitZ()));
        const int box = addBody(s, "box", Shape::box(Vec3(0.25, 0.25, 0.25)),
                                at(Vec3(0, 0, 0.25 + 0.5e-3), yaw), mat, false, 1.0);
        const Vec3 dir = yaw * Vec3::UnitX();
        s.bodies[box].linear_velocity = v0 * dir;
        auto be = makeBackend(s);
        for (int f = 0; f < 90; ++f) be->stepFrame(s.frame_dt);
        const BodyState st = be->bodyState(box);
        const Vec3 d = st.pose.position - Vec3(0, 0, 0.25 + 0.5e-3);
        const double along = d.dot(dir);
        EXPECT_NEAR(along, expected, 0.02 * expected) << "heading " << heading;
        EXPECT_LT((d - along * dir).head<2>().norm(), 1e-3 * expected) << "heading bent, heading " << heading;
        EXPECT_LT(st.linear_velocity.norm(), 1e-6) << "heading " << heading;
        EXPECT_LT(st.pose.orientation.angularDistance(yaw), 1e-3) << "not flat or turned, heading " << heading;
        lo = std::min(lo, along);
        hi = std::max(hi, along);
    }
    EXPECT_LE(hi - lo, 0.02 * expected) << "spread over headings";
}

TEST(NativeRest, SphereRollsDownInclineAtFiveSevenths) {
    const double theta = 20.0 * kPi / 180, g = 9.81, r = 0.1, cd = 1e-3;
    Scene s = bareScene(cd);
    const int mat = addMaterial(s, 0.0, 0.6);
    const Quat tilt(Eigen::AngleAxisd(-theta, Vec3::UnitY()));
    const Vec3 n = tilt * Vec3::UnitZ();
    addBody(s, "incline", Shape::box(Vec3(20, 2, 0.5)), at(tilt * Vec3(0, 0, -0.5), tilt), mat, true);
    const Vec3 start = n * (r + 0.5 * cd);
    const int ball = addBody(s, "ball", Shape::sphere(r), at(start), mat, false, 1.0);
    auto be = makeBackend(s);
    const int frames = 90;
    for (int f = 0; f < frames; ++f) be->stepFrame(s.frame_dt);
    const double t = frames * s.frame_dt;
    const double a = 5.0 / 7.0 * g * std::sin(theta);
    const Vec3 gt = s.gravity - s.gravity.dot(n) * n;   // gravity along the surface
    const Vec3 down = gt.normalized();
    const BodyState st = be->bodyState(ball);
    const double travelled = (st.pose.position - start).dot(down);
    EXPECT_NEAR(travelled, 0.5 * a * t * t, 0.01 * 0.5 * a * t * t);
    EXPECT_NEAR(st.linear_velocity.dot(down), a * t, 0.01 * a * t);
    // Rolling without slipping: the contact point's slip is below 1 % of the rolling speed.
    const Vec3 contact_velocity = st.linear_velocity + st.angular_velocity.cross(-r * n);
    EXPECT_LT(contact_velocity.norm(), 1e-2 * a * t);
}

}  // namespace
}  // namespace vroc::native::test
