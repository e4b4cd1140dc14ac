// SPDX-License-Identifier: MIT
// A rendered frame checked for content where the projection says: shaded virtual pixels at a
// projected sphere centre, real wireframe pixels along a projected box edge, nothing drawn for
// the filled real model, and a virtual sphere behind a real box hidden.
#include <filesystem>

#include <gtest/gtest.h>

#include "test_scene_builder.h"
#include "vroc/hmd/lens_distortion.h"
#include "vroc/render/stereo_renderer.h"

namespace vroc::render {
namespace {

/// A real cube (half 0.3) at the origin and one virtual sphere (r 0.1) at `sphere_at`.
Scene boxAndSphere(const Vec3& sphere_at, bool with_box = true) {
    Scene scene = test::emptyScene(0.5, 0.5);
    if (with_box) test::addBody(scene, "box", Shape::box(Vec3(0.3, 0.3, 0.3)), test::at(Vec3::Zero()), 0, true);
    test::addBody(scene, "ball", Shape::sphere(0.1), test::at(sphere_at), 0, false);
    return scene;
}

std::vector<Pose> posesOf(const Scene& scene) {
    std::vector<Pose> poses;
    for (const Body& b : scene.bodies) poses.push_back(b.pose);
    return poses;
}

struct Viewer {
    hmd::StereoRig rig{hmd::HmdSettings{}};
    Pose head = hmd::lookAt(Vec3(0.1, -3.0, 0.4), Vec3(0.1, 0.0, 0.0));
    std::array<Pose, 2> eyes{rig.eyePose(head, hmd::Eye::Left), rig.eyePose(head, hmd::Eye::Right)};
};

Image renderOnce(const Scene& scene, const Viewer& v) {
    StereoRenderer renderer(scene, v.rig, RenderSettings{});
    renderer.render(v.eyes, posesOf(scene));
    return renderer.image();
}

bool isShadedRed(std::array<std::uint8_t, 3> c) { return c[0] > 80 && c[1] < c[0] / 2 && c[2] < c[0] / 2; }
bool isWire(std::array<std::uint8_t, 3> c) { return c[1] > 200 && c[0] < 60 && c[2] < 60; }
bool isBlack(std::array<std::uint8_t, 3> c) { return c[0] == 0 && c[1] == 0 && c[2] == 0; }

/// Pixel of a world point in eye `e` of the side-by-side image.
std::pair<int, int> pixelOf(const Viewer& v, int e, const Vec3& p) {
    auto px = v.rig.project(v.eyes[e], p, 640, 480);
    EXPECT_TRUE(px) << "point (" << p.transpose() << ") not in view of eye " << e;
    if (!px) return {0, 0};
    return {static_cast<int>(px->x) + e * 640, static_cast<int>(px->y)};
}

TEST(StereoRenderer, ShadedSphereAndWireframeWhereProjected) {
    const Scene scene = boxAndSphere(Vec3(0.9, -0.5, 0.0));
    const Viewer v;
    const Image image = renderOnce(scene, v);
    ASSERT_EQ(image.width, 1280);
    ASSERT_EQ(image.height, 480);
    for (int e = 0; e < 2; ++e) {
        auto [sx, sy] = pixelOf(v, e, Vec3(0.9, -0.5, 0.0));
        EXPECT_TRUE(isShadedRed(image.at(sx, sy))) << "eye " << e << " sphere centre pixel " << sx << "," << sy;
        // The top front edge of the cube, at its midpoint: a green line within a pixel.
        auto [ex, ey] = pixelOf(v, e, Vec3(0.0, -0.3, 0.3));
        bool found = false;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) found = found || isWire(image.at(ex + dx, ey + dy));
        EXPECT_TRUE(found) << "eye " << e << " no wireframe near pixel " << ex << "," << ey;
        // The middle of the cube's front face: real surfaces are not drawn (see-through).
        auto [fx, fy] = pixelOf(v, e, Vec3(0.0, -0.3, 0.0));
        EXPECT_TRUE(isBlack(image.at(fx, fy))) << "eye " << e;
    }
    // The eyes differ: the sphere sits at different columns within each half (disparity).
    auto [lx, ly] = pixelOf(v, 0, Vec3(0.9, -0.5, 0.0));
    auto [rx, ry] = pixelOf(v, 1, Vec3(0.9, -0.5, 0.0));
    EXPECT_GT(lx - (rx - 640), 5);
    EXPECT_EQ(ly, ry);
}

TEST(StereoRenderer, VirtualSphereBehindRealBoxIsHidden) {
    const Vec3 behind(0.1, 1.0, 0.0);   // the cube lies between the viewer and this point
    const Viewer v;
    const Image hidden = renderOnce(boxAndSphere(behind, true), v);
    const Image shown = renderOnce(boxAndSphere(behind, false), v);
    for (int e = 0; e < 2; ++e) {
        auto [x, y] = pixelOf(v, e, behind);
        EXPECT_TRUE(isBlack(hidden.at(x, y))) << "eye " << e << " pixel " << x << "," << y;
        EXPECT_TRUE(isShadedRed(shown.at(x, y))) << "eye " << e << " pixel " << x << "," << y;
    }
}

TEST(StereoRenderer, PngRoundTripKeepsRowOrder) {
    const Viewer v;
    const Image image = renderOnce(boxAndSphere(Vec3(0.9, -0.5, 0.0)), v);
    const std::string path = std::string(VROC_BINARY_DIR) + "/render_test_frame.png";
    writePng(path, image);
    const Image back = readPng(path);
    EXPECT_EQ(back.rgb, image.rgb);
    // The sphere is in the lower half of the image (it is below the line of sight): top-down rows.
    auto [sx, sy] = pixelOf(v, 0, Vec3(0.9, -0.5, 0.0));
    EXPECT_GT(sy, 240);
    EXPECT_TRUE(isShadedRed(back.at(sx, sy)));
    std::filesystem::remove(path);
}

TEST(StereoRenderer, LensPrewarpMovesTheSphereToThePrewarpedPoint) {
    hmd::HmdSettings s;
    s.k1 = 0.2;
    s.k2 = 0.05;
    Viewer v;
    v.rig = hmd::StereoRig(s);
    const Vec3 centre(0.9, -0.5, 0.0);
    StereoRenderer renderer(boxAndSphere(centre), v.rig, RenderSettings{});
    renderer.render(v.eyes, posesOf(boxAndSphere(centre)));
    const Image image = renderer.image();
    auto px = v.rig.project(v.eyes[0], centre, 640, 480);
    ASSERT_TRUE(px);
    // Apparent (undistorted) point a, in half-height units; it must be drawn at prewarp(a).
    const hmd::Vec2 a((px->x - 320) / 240, (240 - px->y) / 240);
    const hmd::Vec2 s_pt = hmd::LensDistortion(0.2, 0.05).prewarp(a);
    const int x = static_cast<int>(s_pt.x() * 240 + 320), y = static_cast<int>(240 - s_pt.y() * 240);
    EXPECT_TRUE(isShadedRed(image.at(x, y))) << "prewarped pixel " << x << "," << y;
    EXPECT_GT((s_pt - a).norm() * 240, 5.0);   // the pre-warp moved it noticeably
}

}  // namespace
}  // namespace vroc::render
