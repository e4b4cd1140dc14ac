// SPDX-License-Identifier: MIT
// Stereo eye poses and projection against hand-computed values.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "vroc/hmd/stereo_rig.h"

namespace vroc::hmd {
namespace {

HmdSettings testSettings() {
    HmdSettings s;
    s.ipd = 0.064;
    s.eye_relief = 0.02;
    s.fov_y_deg = 60.0;
    s.aspect = 4.0 / 3.0;
    s.near_plane = 0.1;
    s.far_plane = 100.0;
    return s;
}

TEST(StereoRig, EyePosesOfAYawedHead) {
    const StereoRig rig(testSettings());
    // Head at (1, 2, 3) turned 90 degrees about world z: head x (right) points along world +y.
    const Pose head{Vec3(1, 2, 3), Quat(Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitZ()))};
    const Pose left = rig.eyePose(head, Eye::Left);
    const Pose right = rig.eyePose(head, Eye::Right);
    // By hand: offset (-+0.032, 0, 0.02) rotated: (x, y, z) -> (-y, x, z).
    EXPECT_NEAR((left.position - Vec3(1.0, 2.0 - 0.032, 3.02)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((right.position - Vec3(1.0, 2.0 + 0.032, 3.02)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((left.position - right.position).norm(), 0.064, 1e-15);
    EXPECT_TRUE(left.orientation.isApprox(head.orientation, 1e-15));
}

TEST(StereoRig, ProjectionMatrixByHand) {
    const StereoRig rig(testSettings());
    const Eigen::Matrix4d p = rig.projectionMatrix();
    const double f = std::sqrt(3.0);   // 1 / tan(30 deg)
    EXPECT_NEAR(p(0, 0), f * 0.75, 1e-14);
    EXPECT_NEAR(p(1, 1), f, 1e-14);
    EXPECT_NEAR(p(2, 2), -100.1 / 99.9, 1e-14);
    EXPECT_NEAR(p(2, 3), -20.0 / 99.9, 1e-14);
    EXPECT_EQ(p(3, 2), -1.0);
    EXPECT_EQ(p(3, 3), 0.0);
    // The near and far planes map to depth -1 and +1.
    for (auto [z, ndc] : {std::pair{-0.1, -1.0}, std::pair{-100.0, 1.0}}) {
        const Eigen::Vector4d clip = p * Eigen::Vector4d(0, 0, z, 1);
        EXPECT_NEAR(clip.z() / clip.w(), ndc, 1e-12);
    }
}

TEST(StereoRig, ProjectToPixels) {
    const StereoRig rig(testSettings());
    const Pose eye = Pose::identity();   // looks down -z, y up
    const double t30 = std::tan(std::numbers::pi / 6);
    auto centre = rig.project(eye, Vec3(0, 0, -2), 640, 480);
    ASSERT_TRUE(centre);
    EXPECT_NEAR(centre->x, 320.0, 1e-12);
    EXPECT_NEAR(centre->y, 240.0, 1e-12);
    EXPECT_NEAR(centre->depth, 2.0, 1e-15);
    // Half way up the vertical half-angle (in tangent) is a quarter of the height from the top.
    auto up = rig.project(eye, Vec3(0, 2 * t30 * 0.5, -2), 640, 480);
    ASSERT_TRUE(up);
    EXPECT_NEAR(up->y, 120.0, 1e-9);
    // Three quarters of the horizontal half-extent (tan 30 * aspect) to the right.
    auto right = rig.project(eye, Vec3(2 * t30 * (4.0 / 3.0) * 0.75, 0, -2), 640, 480);
    ASSERT_TRUE(right);
    EXPECT_NEAR(right->x, 320.0 + 0.75 * 320.0, 1e-9);
    EXPECT_FALSE(rig.project(eye, Vec3(0, 0, 2), 640, 480));          // behind
    EXPECT_FALSE(rig.project(eye, Vec3(0, 2 * t30 * 1.01, -2), 640, 480));   // above the fov
}

TEST(StereoRig, LookAtFacesTheTarget) {
    const Pose head = lookAt(Vec3(0, -3, 1), Vec3(0, 0, 1));
    // -z of the head frame points at the target, x to the right (+x world), y up (+z world).
    EXPECT_NEAR((head.rotate(-Vec3::UnitZ()) - Vec3(0, 1, 0)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((head.rotate(Vec3::UnitX()) - Vec3(1, 0, 0)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((head.rotate(Vec3::UnitY()) - Vec3(0, 0, 1)).norm(), 0.0, 1e-15);
}

}  // namespace
}  // namespace vroc::hmd
