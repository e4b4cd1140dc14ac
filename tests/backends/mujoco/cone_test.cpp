// SPDX-License-Identifier: MIT
// mujoco.cone: MuJoCo's pyramidal (default) and elliptic friction cones against Coulomb's closed
// forms, the elliptic cone's friction damping (friction_damping.h) against MuJoCo's formula, and a
// resting stack under the elliptic cone. Numbers printed here are quoted in docs/mujoco-backend.md.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "contact_materials.h"
#include "mjcf_writer.h"
#include "model_loader.h"
#include "mujoco_backend.h"
#include "restitution_mapping.h"
#include "test_scenes.h"

namespace vroc::test {
namespace {

constexpr double kG = 9.81, kMu = 0.5, kV0 = 3.0;
const double kCoulomb = kV0 * kV0 / (2 * kMu * kG);  // [m] stop distance, 0.9174

struct Slide {
    double heading_error = 0.0;       ///< [deg] largest |heading - initial heading| while faster than 0.1 v0
    double path_heading_error = 0.0;  ///< [deg] |heading of the displacement after 2 s - initial heading|
    double stop = 0.0;                ///< [m] horizontal distance from the start after 2 s
    double speed = 0.0;               ///< [m/s] horizontal speed after 2 s
    double lift = 0.0;                ///< [m/s] largest upward velocity
    std::uint64_t warnings = 0;
};

// A box of half extents (0.1, 0.1, half_height) m, 1 kg, resting on the floor and sliding at
// v0 = 3 m/s along `heading_deg` (world frame), friction 0.5, restitution e, for 2 s.
Slide slide(double heading_deg, double e, double half_height, const Overrides& overrides) {
    Scene scene = emptyScene(e, kMu);
    addFloor(scene);
    const double heading = heading_deg * M_PI / 180;
    const int box = addBox(scene, "box", Vec3(0.1, 0.1, half_height), 1.0, Vec3(0, 0, half_height));
    scene.bodies[static_cast<std::size_t>(box)].linear_velocity = kV0 * Vec3(std::cos(heading), std::sin(heading), 0);
    auto backend = makeMujoco(scene, overrides);
    Slide r;
    for (int f = 0; f < 120; ++f) {
        backend->stepFrame(scene.frame_dt);
        const Vec3 v = backend->bodyState(box).linear_velocity;
        r.lift = std::max(r.lift, v.z());
        if (v.head<2>().norm() > 0.1 * kV0)
            r.heading_error = std::max(r.heading_error, std::abs(std::atan2(v.y(), v.x()) * 180 / M_PI - heading_deg));
    }
    const BodyState s = backend->bodyState(box);
    r.stop = s.pose.position.head<2>().norm();
    r.path_heading_error = std::abs(std::atan2(s.pose.position.y(), s.pose.position.x()) * 180 / M_PI - heading_deg);
    r.speed = s.linear_velocity.head<2>().norm();
    for (const auto& [name, count] : backend->warnings()) r.warnings += count;
    return r;
}

void printRow(const char* cone, double heading, double e, double half_height, const Slide& s, double expected) {
    std::printf("| %s | %.0f | %.1f | %.2f | %.3f | %.3f | %.4f | %.4f (%+.2f %%) | %.3f |\n", cone, heading, e,
                2 * half_height, s.heading_error, s.path_heading_error, s.stop, expected, 100 * (s.stop / expected - 1),
                s.lift);
}

const char* kTableHead =
    "| cone | heading (deg) | e | box height (m) | heading error (deg) | path heading error (deg) | stop (m) | "
    "expected "
    "(m) | lift (m/s) |\n|---|---|---|---|---|---|---|---|---|\n";

// Along the pyramid's diagonal: Coulomb's circular cone keeps the heading and stops the box after
// v0^2 / (2 mu g); MuJoCo's 4-edge pyramid (edges along the contact frame's tangents, world x and y
// for a floor contact) is the square |f_x| + |f_y| <= mu N, which keeps the heading by symmetry but
// gives only mu / sqrt2 along the diagonal: sqrt2 times as far.
TEST(MujocoCone, DiagonalSlideEllipticKeepsItsHeadingAndStopsAtTheCoulombDistance) {
    const Slide elliptic = slide(45, 0.0, 0.1, {{"mujoco.cone", "elliptic"}});
    const Slide pyramidal = slide(45, 0.0, 0.1, {});
    std::printf("%s", kTableHead);
    printRow("elliptic", 45, 0.0, 0.1, elliptic, kCoulomb);
    printRow("pyramidal", 45, 0.0, 0.1, pyramidal, std::sqrt(2.0) * kCoulomb);
    EXPECT_LT(elliptic.heading_error, 1.0);
    EXPECT_NEAR(elliptic.stop, kCoulomb, 0.02 * kCoulomb);
    EXPECT_LT(elliptic.speed, 1e-3);
    EXPECT_NEAR(pyramidal.stop, std::sqrt(2.0) * kCoulomb, 0.02 * std::sqrt(2.0) * kCoulomb);
    EXPECT_EQ(elliptic.warnings + pyramidal.warnings, 0u);
}

// Off the diagonal (30 degrees), the pyramid's square of forces answers a slide with its corner
// (maximum dissipation): the force is -mu N along x alone until v_x = v_y, then the slide goes
// on along the diagonal at mu g / sqrt2. Heading 30 -> 45 degrees and a stop at
//   x = (vx^2 - vy^2) / (2 mu g) + vy^2 / (mu g),  y = vy (vx - vy) / (mu g) + vy^2 / (mu g),
// 10.9 degrees off the launch direction. Coulomb's circle keeps the direction. The headings are
// those of the displacement (as vroc check's slide.heading): MuJoCo's soft cone throws the box up
// at its first contact (lift, printed) and the velocity's heading wobbles while it lands.
TEST(MujocoCone, OffDiagonalSlidePyramidTurnsToItsEdgeEllipticDoesNot) {
    const double vx = kV0 * std::cos(M_PI / 6), vy = kV0 * std::sin(M_PI / 6), a = kMu * kG;
    const double x = (vx * vx - vy * vy) / (2 * a) + vy * vy / a;
    const double y = vy * (vx - vy) / a + vy * vy / a;
    const double pyramid_stop = std::hypot(x, y);  // 1.2136 m
    const Slide elliptic = slide(30, 0.0, 0.05, {{"mujoco.cone", "elliptic"}});
    const Slide pyramidal = slide(30, 0.0, 0.05, {});
    std::printf("%s", kTableHead);
    printRow("elliptic", 30, 0.0, 0.05, elliptic, kCoulomb);
    printRow("pyramidal", 30, 0.0, 0.05, pyramidal, pyramid_stop);
    EXPECT_GT(pyramidal.path_heading_error, 5.0);
    EXPECT_GT(pyramidal.heading_error, 5.0);
    EXPECT_NEAR(pyramidal.stop, pyramid_stop, 0.02 * pyramid_stop);
    EXPECT_LT(elliptic.path_heading_error, 2.0);
    EXPECT_NEAR(elliptic.stop, kCoulomb, 0.02 * kCoulomb);
}

// vroc check's slide: 8 boxes (0.2 m, 1 kg, e = 0) launched at 2 m/s at headings 0 .. 78.75 degrees,
// mu = 0.4: each should stop after v0^2 / (2 mu g) = 0.5097 m. Isotropy = largest / smallest
// distance: 1 for Coulomb's circle, up to sqrt2 for the pyramid (its diagonal).
TEST(MujocoCone, EllipticSlideIsIsotropicOverHeadings) {
    const double v0 = 2.0, mu = 0.4, d = v0 * v0 / (2 * mu * kG);
    const auto distances = [&](const char* cone, double frame_dt) {
        Scene scene = emptyScene(0.0, mu);
        scene.frame_dt = frame_dt;
        addFloor(scene);
        for (int k = 0; k < 8; ++k) {
            const double h = k * 11.25 * M_PI / 180;
            const int b =
                addBox(scene, "box" + std::to_string(k), Vec3(0.1, 0.1, 0.1), 1.0, Vec3(-6 + 1.6 * k, -1, 0.1));
            scene.bodies[static_cast<std::size_t>(b)].linear_velocity = v0 * Vec3(std::cos(h), std::sin(h), 0);
        }
        auto backend = makeMujoco(scene, {{"mujoco.cone", cone}});
        run(*backend, scene, static_cast<int>(std::lround(1.2 / frame_dt)));
        std::vector<double> out;
        std::printf("| %s | 1/%.0f s |", cone, 1 / frame_dt);
        for (int k = 0; k < 8; ++k) {
            out.push_back((backend->bodyState(k + 1).pose.position - Vec3(-6 + 1.6 * k, -1, 0.1)).head<2>().norm());
            std::printf(" %+.2f |", 100 * (out.back() / d - 1));
        }
        const auto [lo, hi] = std::minmax_element(out.begin(), out.end());
        std::printf(" %.4f |\n", *hi / *lo);
        return *hi / *lo;
    };
    std::printf(
        "| cone | frame | 0 | 11.25 | 22.5 | 33.75 | 45 | 56.25 | 67.5 | 78.75 (stop - d) / d, %% | isotropy |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n");
    const double elliptic = distances("elliptic", 1.0 / 60), pyramidal = distances("pyramidal", 1.0 / 60);
    distances("elliptic", 1.0 / 240);
    distances("pyramidal", 1.0 / 240);
    EXPECT_LT(elliptic, 1.03);
    EXPECT_NEAR(pyramidal, std::sqrt(2.0), 0.03);
}

// The elliptic cone's friction rows get the damping of an inelastic pair (friction_damping.h), so
// the slide hardly depends on the restitution the normal row carries. Under the pyramidal cone the
// mapped damping reaches the friction: at e = 1 it is zero and the box never stops (printed).
TEST(MujocoCone, EllipticFrictionDoesNotDependOnRestitution) {
    std::printf("%s", kTableHead);
    for (double e : {0.0, 0.5, 1.0}) {
        const Slide elliptic = slide(45, e, 0.1, {{"mujoco.cone", "elliptic"}});
        const Slide pyramidal = slide(45, e, 0.1, {});
        printRow("elliptic", 45, e, 0.1, elliptic, kCoulomb);
        printRow("pyramidal", 45, e, 0.1, pyramidal, std::sqrt(2.0) * kCoulomb);
        std::printf("|  (after 2 s: elliptic %.3f m/s, pyramidal %.3f m/s) |\n", elliptic.speed, pyramidal.speed);
        if (e < 1.0) {
            EXPECT_NEAR(elliptic.stop, kCoulomb, 0.02 * kCoulomb) << e;
        } else {  // the undamped normal spring keeps the box hopping, but friction still acts
            EXPECT_NEAR(elliptic.stop, kCoulomb, 0.1 * kCoulomb) << e;
            EXPECT_LT(elliptic.speed, 0.1 * kV0) << e;
        }
    }
}

// The rows MuJoCo makes for a box resting on the floor, e = 0.5, under the elliptic cone: the normal
// row keeps the pair's mapped damping, B = -solref[1] / dmax (mj_makeImpedance's direct form,
// dmax = solimp[1] = 0.95, MuJoCo's default solimp); the friction rows get the damping the mapping
// gives e = 0, contactSpring(0, tc, timestep).damping / dmax. Without the <numeric> (MuJoCo's own
// rule) the friction rows carry the pair's damping too.
TEST(MujocoCone, EllipticFrictionRowsGetTheInelasticDamping) {
    Scene scene = emptyScene(0.5, kMu);
    addFloor(scene);
    addBox(scene, "box", Vec3(0.1, 0.1, 0.1), 1.0, Vec3(0, 0, 0.1 - 1e-4));  // 0.1 mm deep: in the solver
    const mujoco::ContactMaterials materials(scene, 0.006, 0.002, true);
    mujoco::SolverOptions options;
    options.timestep = scene.frame_dt / 9;
    options.cone = "elliptic";
    const auto rowsDamping = [&](double friction_damping) {
        options.friction_damping = friction_damping;
        const mujoco::ModelPtr model = mujoco::loadModel(mujoco::writeMjcf(scene, materials, options), scene.name);
        mujoco::DataPtr data(mj_makeData(model.get()));
        mj_forward(model.get(), data.get());
        std::vector<std::pair<double, double>> out;  // (normal B, friction B) per contact
        for (int c = 0; c < data->ncon; ++c) {
            const int i = data->contact[c].efc_address;
            if (i < 0) continue;
            EXPECT_EQ(data->efc_type[i], mjCNSTR_CONTACT_ELLIPTIC);
            EXPECT_EQ(data->contact[c].dim, 3);
            EXPECT_EQ(data->efc_KBIP[4 * (i + 1) + 1], data->efc_KBIP[4 * (i + 2) + 1]);
            out.emplace_back(data->efc_KBIP[4 * i + 1], data->efc_KBIP[4 * (i + 1) + 1]);
        }
        return out;
    };
    const double dmax = 0.95;
    const double mapped = materials.ofBody(1).spring.damping / dmax;            // e = 0.5
    const double inelastic = mujoco::contactSpring(0.0, 0.006, 0.002).damping;  // B h = 1 at h = 2 ms
    EXPECT_DOUBLE_EQ(inelastic, 1 / 0.002);
    const auto fixed = rowsDamping(inelastic);
    ASSERT_GE(fixed.size(), 4u);
    for (const auto& [normal, friction] : fixed) {
        EXPECT_NEAR(normal, mapped, 1e-9 * mapped);
        EXPECT_NEAR(friction, inelastic / dmax, 1e-9 * inelastic);
    }
    for (const auto& [normal, friction] : rowsDamping(0.0)) {  // MuJoCo's own rule: the pair's damping
        EXPECT_NEAR(normal, mapped, 1e-9 * mapped);
        EXPECT_NEAR(friction, mapped, 1e-9 * mapped);
    }
    std::printf(
        "elliptic rows at e = 0.5: normal B = %.2f 1/s (mapped), friction B = %.2f 1/s (e = 0's; the pair's "
        "would be %.2f)\n",
        fixed.front().first, fixed.front().second, mapped);
}

// A resting stack of five 0.2 m boxes (1 kg, e = 0, mu = 0.5) under the elliptic cone: 5 s, the top
// box stays within 1 cm, no warnings (the 10-box stack is in box_depth_bound_test.cpp).
TEST(MujocoCone, EllipticFiveBoxStackStands) {
    Scene scene = emptyScene(0.0, kMu);
    addFloor(scene);
    int top = -1;
    for (int i = 0; i < 5; ++i)
        top = addBox(scene, "box" + std::to_string(i), Vec3(0.1, 0.1, 0.1), 1.0, Vec3(0, 0, 0.1 + 0.2 * i));
    auto backend = makeMujoco(scene, {{"mujoco.cone", "elliptic"}});
    const Vec3 start = backend->bodyState(top).pose.position;
    double worst = 0.0;
    for (int f = 0; f < 300; ++f) {
        backend->stepFrame(scene.frame_dt);
        worst = std::max(worst, (backend->bodyState(top).pose.position - start).norm());
    }
    std::printf("elliptic 5-box stack, 5 s: top box moved at most %.6f m\n", worst);
    EXPECT_LT(worst, 0.01) << "5 boxes 0.2 m, 1 kg, e 0, mu 0.5, --set mujoco.cone=elliptic";
    for (const auto& [name, count] : backend->warnings()) EXPECT_EQ(count, 0u) << name;
}

}  // namespace
}  // namespace vroc::test
