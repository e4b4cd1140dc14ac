// SPDX-License-Identifier: MIT
// A stack of ten 0.5 m boxes stands for 10 s at 60 Hz with the top box drifting <= 1 cm.
#include <gtest/gtest.h>

#include "native_test_scenes.h"

namespace vroc::native::test {
namespace {

TEST(NativeStack, TenBoxesHoldForTenSeconds) {
    const double cd = 1e-3, half = 0.25;
    Scene s = emptyScene(cd);
    const int mat = addMaterial(s, 0.0, 0.5);
    addFloor(s, mat);
    int top = -1;
    for (int i = 0; i < 10; ++i) {
        const double z = half + 0.5 * cd + i * (2 * half + 0.5 * cd);
        top = addBody(s, "box" + std::to_string(i), Shape::box(Vec3(half, half, half)), at(Vec3(0, 0, z)), mat,
                      false, 1.0);
    }
    auto be = makeBackend(s);
    const Vec3 start = be->bodyState(top).pose.position;
    double worst = 0.0;
    for (int f = 0; f < 600; ++f) {
        be->stepFrame(s.frame_dt);
        worst = std::max(worst, (be->bodyState(top).pose.position - start).norm());
    }
    EXPECT_LE(worst, 0.01) << "top box drift";
    for (int i = 1; i < static_cast<int>(s.bodies.size()); ++i) {
        EXPECT_LT(be->bodyState(i).linear_velocity.norm(), 1e-3) << s.bodies[i].name;
    }
    const auto stats = be->statistics();
    RecordProperty("internal_steps_per_frame_mean", std::to_string(stats.at("internal_steps_per_frame_mean")));
}

}  // namespace
}  // namespace vroc::native::test
