// SPDX-License-Identifier: MIT
// The robustness verdict (M17) on hand-made traces: NaN, tunnelling, energy blow-up, collapse.
#include <gtest/gtest.h>

#include <cmath>

#include "test_scene_builder.h"
#include "vroc/harness/metrics/robustness.h"

namespace vroc::harness {
namespace {

// Ground (top face z = 0) and a 0.2 m box (1 kg) resting on it; g = 10 m/s^2.
Scene restingBox() {
    Scene s = test::bareScene(1e-3, Vec3(0, 0, -10));
    test::addMaterial(s, "m", 0, 0.5);
    test::addBody(s, "ground", Shape::box(Vec3(5, 5, 0.5)), test::at(Vec3(0, 0, -0.5)), 0, true);
    test::addBody(s, "box", Shape::box(Vec3::Constant(0.1)), test::at(Vec3(0, 0, 0.1)), 0, false, 1.0);
    return s;
}

RunTrace traceEndingAt(const Scene& s, const Vec3& box_end, const Vec3& box_velocity = Vec3::Zero()) {
    RunTrace t;
    for (int f = 0; f < 2; ++f) {
        std::vector<BodyState> st = {{s.bodies[0].pose, Vec3::Zero(), Vec3::Zero()}, {s.bodies[1].pose, Vec3::Zero(), Vec3::Zero()}};
        if (f == 1) {
            st[1].pose.position = box_end;
            st[1].linear_velocity = box_velocity;
        }
        t.times.push_back(f);
        t.states.push_back(st);
        Invariants inv;
        inv.kinetic = 0.5 * box_velocity.squaredNorm() * f;
        t.invariants.push_back(inv);
    }
    return t;
}

TEST(HarnessRobustness, Verdicts) {
    const Scene s = restingBox();
    const RunTrace ref = traceEndingAt(s, Vec3(0, 0, 0.1));
    EXPECT_TRUE(judgeRobustness(s, traceEndingAt(s, Vec3(0.001, 0, 0.1)), ref).ok);
    RunTrace nan = traceEndingAt(s, Vec3(0, 0, 0.1));
    nan.finite = false;
    EXPECT_EQ(judgeRobustness(s, nan, ref).reason, "NaN");
    // Centre 0.2 m inside the ground: deeper than the box's bounding radius (0.173 m).
    EXPECT_EQ(judgeRobustness(s, traceEndingAt(s, Vec3(0, 0, -0.2)), ref).reason, "tunnelling");
    // KE floor: 1 kg x 10 m/s^2 x 1 cm = 0.1 J; 0.5 v^2 = 0.08 J passes, 2 J fails.
    EXPECT_TRUE(judgeRobustness(s, traceEndingAt(s, Vec3(0, 0, 0.1), Vec3(0.4, 0, 0)), ref).ok);
    EXPECT_EQ(judgeRobustness(s, traceEndingAt(s, Vec3(0, 0, 0.1), Vec3(2, 0, 0)), ref).reason, "energy blow-up");
    // Started at rest touching the ground: ending 0.3 m away (> 0.173 m) is a collapse.
    EXPECT_EQ(judgeRobustness(s, traceEndingAt(s, Vec3(0.3, 0, 0.1)), ref).reason, "collapse");
}

}  // namespace
}  // namespace vroc::harness
