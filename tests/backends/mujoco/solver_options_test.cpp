// SPDX-License-Identifier: MIT
// MuJoCo's solver options as settings (mujoco.cone, mujoco.impratio, mujoco.noslip_iterations,
// mujoco.integrator): each reaches mjModel::opt, bad values are refused, and each does what MuJoCo
// says it does, against an independent answer: RK4 integrates constant gravity exactly (the
// continuous parabola), the implicit integrator without velocity-dependent forces is the
// semi-implicit Euler closed form, and a box resting on an incline below its friction angle does
// not move at all in Coulomb's model (MuJoCo's soft friction creeps; impratio and noslip are
// MuJoCo's remedies). The cone's own tests are in cone_test.cpp.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "mujoco_backend.h"
#include "test_scenes.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/errors.h"
#include "vroc/core/state_hash.h"

namespace vroc::test {
namespace {

const mjModel& modelOf(const Backend& backend) { return dynamic_cast<const mujoco::MujocoBackend&>(backend).model(); }

TEST(MujocoSolverOptions, SettingsReachTheModelAndBadValuesAreRefused) {
    Scene scene = emptyScene();
    addFloor(scene);
    addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 0.5));
    auto defaults = makeMujoco(scene);  // MuJoCo's own options
    const mjModel& m0 = modelOf(*defaults);
    EXPECT_EQ(m0.opt.cone, mjCONE_PYRAMIDAL);
    EXPECT_EQ(m0.opt.impratio, 1.0);
    EXPECT_EQ(m0.opt.noslip_iterations, 0);
    EXPECT_EQ(m0.opt.integrator, mjINT_EULER);
    auto set = makeMujoco(scene, {{"mujoco.cone", "elliptic"},
                                  {"mujoco.impratio", "7.5"},
                                  {"mujoco.noslip_iterations", "12"},
                                  {"mujoco.integrator", "rk4"}});
    const mjModel& m = modelOf(*set);
    EXPECT_EQ(m.opt.cone, mjCONE_ELLIPTIC);
    EXPECT_EQ(m.opt.impratio, 7.5);
    EXPECT_EQ(m.opt.noslip_iterations, 12);
    EXPECT_EQ(m.opt.integrator, mjINT_RK4);
    EXPECT_EQ(modelOf(*makeMujoco(scene, {{"mujoco.integrator", "implicit"}})).opt.integrator, mjINT_IMPLICIT);
    EXPECT_EQ(modelOf(*makeMujoco(scene, {{"mujoco.integrator", "euler"}})).opt.integrator, mjINT_EULER);

    const BackendInfo& info = BackendRegistry::global().require("mujoco");
    for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
             {"mujoco.cone", "circular"},
             {"mujoco.impratio", "0"},
             {"mujoco.impratio", "-1"},
             {"mujoco.noslip_iterations", "-1"},
             {"mujoco.noslip_iterations", "2.5"},
             {"mujoco.integrator", "implicitfast"},  // MuJoCo 3's, not in 2.2
             {"mujoco.integrator", "RK4"}}) {
        EXPECT_THROW(resolveSettings(info.settings, {{key, value}}), InputError) << key << "=" << value;
    }
}

// Free flight: RK4 is exact for a constant acceleration, so the ball is on the continuous
// parabola; the implicit integrator has no velocity-dependent force to treat implicitly here and
// is the semi-implicit Euler closed form of free_fall_test.cpp (g h t / 2 off the parabola).
TEST(MujocoSolverOptions, IntegratorsAgainstTheClosedFormsOfFreeFlight) {
    const FreeFlight f;
    const Scene& scene = f.scene;
    const int ball = f.ball;
    const Vec3 v0 = f.v0;
    const int frames = 90;
    const double h = scene.frame_dt / 9, n = 9.0 * frames, t = n * h;
    const Vec3 g = scene.gravity;
    const Vec3 continuous = f.parabola(t);
    const Vec3 euler = f.euler(h, n);

    auto rk4 = makeMujoco(scene, {{"mujoco.integrator", "rk4"}});
    run(*rk4, scene, frames);
    const BodyState r = rk4->bodyState(ball);
    EXPECT_LT((r.pose.position - continuous).norm(), 1e-12 * continuous.norm());
    EXPECT_LT((r.linear_velocity - (v0 + g * t)).norm(), 1e-12);

    auto implicit = makeMujoco(scene, {{"mujoco.integrator", "implicit"}});
    run(*implicit, scene, frames);
    const BodyState i = implicit->bodyState(ball);
    EXPECT_LT((i.pose.position - euler).norm(), 1e-12 * euler.norm());
    EXPECT_NEAR((i.pose.position - continuous).norm(), 0.5 * g.norm() * h * t, 1e-9);
    std::printf(
        "free flight after %.2f s: rk4 %.2e m off the parabola, implicit %.2e m off the Euler closed form "
        "(Euler is %.4f m off the parabola)\n",
        t, (r.pose.position - continuous).norm(), (i.pose.position - euler).norm(), (euler - continuous).norm());
}

// A 0.2 m cube (1 kg) resting on a real 20-degree incline with mu = 0.5 (tan 20 deg = 0.36 < 0.5):
// Coulomb's answer is that it never moves. Returns how far it slid down the slope in 2 s [m].
double creepDownIncline(const Overrides& overrides) {
    const double slope = 20.0 * M_PI / 180;
    Scene scene = emptyScene(0.0, 0.5);
    const Quat tilt(Eigen::AngleAxisd(slope, Vec3::UnitY()));
    const Vec3 normal = tilt * Vec3::UnitZ(), down_slope = tilt * Vec3::UnitX();
    addBody(scene, "incline", Shape::box(Vec3(3, 3, 0.5)), at(-0.5 * normal, tilt), 0, true);
    const int box = addBox(scene, "box", Vec3(0.1, 0.1, 0.1), 1.0, 0.1 * normal);
    scene.bodies[static_cast<std::size_t>(box)].pose.orientation = tilt;
    auto backend = makeMujoco(scene, overrides);
    run(*backend, scene, 120);
    for (const auto& [name, count] : backend->warnings()) EXPECT_EQ(count, 0u) << name;
    return (backend->bodyState(box).pose.position - 0.1 * normal).dot(down_slope);
}

// MuJoCo's soft friction lets a sticking contact creep at a speed proportional to the friction
// rows' regulariser R, which impratio divides (mj_makeImpedance: R_friction = R_normal / impratio);
// the noslip post-solver removes the slip the regulariser allows.
TEST(MujocoSolverOptions, ImpratioAndNoslipCutTheCreepOfAStickingContact) {
    std::printf(
        "| cone | impratio | noslip_iterations | creep down a 20 deg incline in 2 s (m) |\n|---|---|---|---|\n");
    for (const char* cone : {"pyramidal", "elliptic"}) {
        const auto creep = [&](const char* impratio, const char* noslip) {
            const double c = creepDownIncline(
                {{"mujoco.cone", cone}, {"mujoco.impratio", impratio}, {"mujoco.noslip_iterations", noslip}});
            std::printf("| %s | %s | %s | %.3e |\n", cone, impratio, noslip, c);
            return c;
        };
        const double base = creep("1", "0"), stiff = creep("10", "0"), stiffer = creep("100", "0");
        EXPECT_GT(base, 0.0) << cone;  // MuJoCo's soft friction does creep (else the test shows nothing)
        EXPECT_LT(stiff, 0.2 * base) << cone;
        EXPECT_LT(stiffer, 0.2 * stiff) << cone;
        if (std::string(cone) == "elliptic")
            EXPECT_LT(creep("1", "10"), 0.05 * base);
        else
            creep("1", "10");  // printed: noslip does not reach this creep under the pyramidal cone
    }
}

// Every option on a mixed scene (a falling 3-box stack, balls, a hull): finite, no warnings, the
// same bits twice, and not the default's bits (the setting changed what MuJoCo did).
TEST(MujocoSolverOptions, EachOptionRunsFiniteDeterministicAndChangesTheRun) {
    const auto scene = [] {
        Scene s = emptyScene(0.3, 0.6);
        addFloor(s);
        for (int i = 0; i < 3; ++i)
            addBox(s, "box" + std::to_string(i), Vec3(0.1, 0.1, 0.1), 1.0, Vec3(0.01 * i, 0, 0.1 + 0.2 * i));
        for (int i = 0; i < 3; ++i) {
            const int b = addBall(s, "ball" + std::to_string(i), 0.05, 0.3, Vec3(0.5, 0.1 * i, 0.3 + 0.2 * i));
            s.bodies[static_cast<std::size_t>(b)].linear_velocity = Vec3(-1.0, 0.3 * i, 0);
        }
        addHullCuboid(s, "hull", Vec3(0.07, 0.07, 0.05), 0.5,
                      at(Vec3(-0.5, 0, 0.3), Quat(Eigen::AngleAxisd(0.4, Vec3(1, 1, 0).normalized()))));
        return s;
    }();
    const auto once = [&](const Overrides& o) {
        auto backend = makeMujoco(scene, o);
        run(*backend, scene, 60);
        for (int b = 0; b < backend->bodyCount(); ++b) {
            const BodyState s = backend->bodyState(b);
            EXPECT_TRUE(s.pose.position.allFinite() && s.linear_velocity.allFinite() && s.angular_velocity.allFinite());
        }
        for (const auto& [name, count] : backend->warnings()) EXPECT_EQ(count, 0u) << name;
        return stateHash(*backend);
    };
    const std::uint64_t defaults = once({});
    for (const Overrides& o :
         std::vector<Overrides>{{{"mujoco.cone", "elliptic"}},
                                {{"mujoco.impratio", "10"}},
                                {{"mujoco.noslip_iterations", "20"}},
                                {{"mujoco.integrator", "rk4"}},
                                {{"mujoco.integrator", "implicit"}},
                                {{"mujoco.cone", "elliptic"}, {"mujoco.noslip_iterations", "20"}}}) {
        const std::uint64_t a = once(o), b = once(o);
        std::string label;
        for (const auto& [k, v] : o) label += k + "=" + v + " ";
        EXPECT_EQ(a, b) << label;
        EXPECT_NE(a, defaults) << label;
        std::printf("%-60s state hash after 1 s %s (defaults %s)\n", label.c_str(), hashToHex(a).c_str(),
                    hashToHex(defaults).c_str());
    }
}

}  // namespace
}  // namespace vroc::test
