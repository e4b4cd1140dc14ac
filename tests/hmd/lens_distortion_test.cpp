// SPDX-License-Identifier: MIT
// The pre-warp is the inverse of the lens distortion (both ways, 1e-9).
#include <random>

#include <gtest/gtest.h>

#include "vroc/hmd/lens_distortion.h"

namespace vroc::hmd {
namespace {

void expectInverse(double k1, double k2, double max_radius) {
    const LensDistortion lens(k1, k2);
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-max_radius, max_radius);
    for (int i = 0; i < 2000; ++i) {
        const Vec2 q(u(rng), u(rng));
        if (q.norm() > max_radius) continue;
        const Vec2 back = lens.distort(lens.prewarp(q));
        ASSERT_LT((back - q).norm(), 1e-9) << "k1=" << k1 << " k2=" << k2 << " q=(" << q.x() << ", " << q.y() << ")";
        const Vec2 again = lens.prewarp(lens.distort(q));
        ASSERT_LT((again - q).norm(), 1e-9) << "k1=" << k1 << " k2=" << k2 << " p=(" << q.x() << ", " << q.y() << ")";
    }
}

TEST(LensDistortion, PincushionPrewarpIsTheInverse) { expectInverse(0.22, 0.24, 1.7); }
TEST(LensDistortion, BarrelPrewarpIsTheInverse) { expectInverse(-0.1, 0.01, 1.2); }

TEST(LensDistortion, ClosedFormPointAndIdentity) {
    const LensDistortion lens(0.5, 0.25);
    // r = 1: r_d = 1 + 0.5 + 0.25 = 1.75, along the direction of the point.
    const Vec2 d = lens.distort(Vec2(0.6, 0.8));
    EXPECT_NEAR((d - Vec2(0.6, 0.8) * 1.75).norm(), 0.0, 1e-15);
    EXPECT_NEAR((lens.prewarp(Vec2(0.6, 0.8) * 1.75) - Vec2(0.6, 0.8)).norm(), 0.0, 1e-12);
    const LensDistortion none(0.0, 0.0);
    EXPECT_EQ(none.prewarp(Vec2(0.3, -0.2)), Vec2(0.3, -0.2));
    EXPECT_EQ(lens.prewarp(Vec2(0, 0)), Vec2(0, 0));
}

}  // namespace
}  // namespace vroc::hmd
