// SPDX-License-Identifier: MIT
// The backend contract (docs/backend-contract.md) on the ODE backend: errors vs warnings, round
// trips, exact impulses, determinism, vocabulary. Expected values are closed forms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "ode_test_scenes.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/backend_vocabulary.h"
#include "vroc/core/errors.h"
#include "vroc/core/scene_loader.h"
#include "vroc/core/state_hash.h"
#include "vroc/ode/ode_backend.h"

namespace vroc::test {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// A scene with a COM offset and a non-diagonal inertia, on a floor.
Scene offsetHullScene(int& body) {
    Scene scene = emptyScene();
    addFloor(scene);
    body = addHullCuboid(scene, "hull", Vec3(0.2, 0.1, 0.05), 3.0,
                         Pose{Vec3(0, 0, 1), Quat(Eigen::AngleAxisd(0.3, Vec3(1, 0, 1).normalized()))},
                         Quat(Eigen::AngleAxisd(0.5, Vec3(0, 1, 2).normalized())), Vec3(0.05, 0.02, -0.01));
    return scene;
}

TEST(OdeContract, RegistersWithCapabilitiesAndDeviations) {
    ode::registerBackend();
    ode::registerBackend();   // idempotent
    const BackendInfo& info = BackendRegistry::global().require("ode");
    EXPECT_NE(info.version.find("ODE 0.16"), std::string::npos) << info.version;
    EXPECT_EQ(info.capabilities.precision, "double");
    EXPECT_EQ(info.capabilities.friction, FrictionModel::Pyramid);
    EXPECT_FALSE(info.capabilities.continuous_collision);
    EXPECT_EQ(info.capabilities.sphere, Support::Exact);
    EXPECT_EQ(info.capabilities.hull, Support::Approximated);
    EXPECT_TRUE(info.capabilities.notes.count("hull"));
    EXPECT_FALSE(info.deviations.empty());
    for (const SettingSpec& s : info.settings) EXPECT_EQ(s.key.rfind("ode.", 0), 0u) << s.key;
}

TEST(OdeContract, CallersMistakesThrowInputError) {
    int body = 0;
    Scene scene = offsetHullScene(body);
    auto backend = makeOde(scene);
    EXPECT_THROW(backend->stepFrame(0.0), InputError);
    EXPECT_THROW(backend->stepFrame(-1.0 / 60), InputError);
    EXPECT_THROW(backend->stepFrame(kNaN), InputError);
    EXPECT_THROW(backend->stepFrame(kInf), InputError);
    EXPECT_THROW(backend->bodyState(2), InputError);
    EXPECT_THROW(backend->bodyState(-1), InputError);
    EXPECT_THROW(backend->setBodyState(7, BodyState{}), InputError);
    EXPECT_THROW(backend->applyImpulse(7, Vec3::UnitX(), Vec3::Zero()), InputError);
    EXPECT_THROW(makeOde(scene, {{"ode.stepper", "dantzig"}}), InputError);
    EXPECT_THROW(makeOde(scene, {{"ode.erp", "1.5"}}), InputError);
    EXPECT_EQ(backend->time(), 0.0);
}

TEST(OdeContract, UnrepresentableScenesAreRefusedWithAReason) {
    Scene scene = emptyScene();
    addFloor(scene);
    const int hull = addHullCuboid(scene, "faceless", Vec3(0.1, 0.1, 0.1), 1.0, Pose{Vec3(0, 0, 1), Quat::Identity()});
    ConvexPolyhedron points_only = *scene.bodies[hull].shape.hull;
    points_only.faces.clear();
    points_only.face_normals.clear();
    points_only.face_offsets.clear();
    scene.bodies[hull].shape = Shape::convexHull(points_only);
    try {
        makeOde(scene);
        FAIL() << "a hull without faces was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("faceless"), std::string::npos) << what;
        EXPECT_NE(what.find("faces"), std::string::npos) << what;
    }
    Scene massless = emptyScene();
    const int ball = addBall(massless, "ball", 0.1, 1.0, Vec3::Zero());
    massless.bodies[ball].mass_properties.mass = 0.0;
    EXPECT_THROW(makeOde(massless), InputError);
}

TEST(OdeContract, SetBodyStateRoundTrips) {
    int body = 0;
    Scene scene = offsetHullScene(body);
    auto backend = makeOde(scene);
    BodyState s;
    s.pose.position = Vec3(0.3, -0.7, 2.5);
    s.pose.orientation = Quat(Eigen::AngleAxisd(2.1, Vec3(-1, 3, 0.5).normalized()));
    s.linear_velocity = Vec3(1.5, -2, 0.25);
    s.angular_velocity = Vec3(-3, 0.5, 7);
    backend->setBodyState(body, s);
    const BodyState r = backend->bodyState(body);
    EXPECT_LT((r.pose.position - s.pose.position).norm(), 1e-12 * s.pose.position.norm());
    EXPECT_LT((r.pose.orientation.coeffs() - s.pose.orientation.coeffs()).norm(), 1e-12);
    EXPECT_LT((r.linear_velocity - s.linear_velocity).norm(), 1e-12 * s.linear_velocity.norm());
    EXPECT_LT((r.angular_velocity - s.angular_velocity).norm(), 1e-12 * s.angular_velocity.norm());
    // A real body ignores it.
    const BodyState floor_before = backend->bodyState(0);
    backend->setBodyState(0, s);
    backend->applyImpulse(0, Vec3(0, 0, 100), Vec3::Zero());
    backend->stepFrame(scene.frame_dt);
    EXPECT_EQ(backend->bodyState(0).pose.position, floor_before.pose.position);
    EXPECT_EQ(backend->bodyState(0).linear_velocity, Vec3::Zero());
}

TEST(OdeContract, ApplyImpulseChangesMomentaExactly) {
    int body = 0;
    Scene scene = offsetHullScene(body);
    const Body& b = scene.bodies[body];
    auto backend = makeOde(scene);
    const BodyState before = backend->bodyState(body);
    const Vec3 J(0.4, -1.3, 2.2), p(0.1, 0.3, 1.2);
    backend->applyImpulse(body, J, p);
    const BodyState after = backend->bodyState(body);
    // Linear momentum changes by J; angular momentum about the COM by (p - com) x J.
    const double m = b.mass_properties.mass;
    EXPECT_LT((m * (after.linear_velocity - before.linear_velocity) - J).norm(), 1e-12 * J.norm());
    const Mat3 R = b.pose.orientation.toRotationMatrix();
    const Mat3 I_world = R * b.mass_properties.inertia * R.transpose();
    const Vec3 L = (p - b.pose.apply(b.mass_properties.center_of_mass)).cross(J);
    const Vec3 dL = I_world * (after.angular_velocity - before.angular_velocity);
    EXPECT_LT((dL - L).norm(), 1e-9 * L.norm());
    EXPECT_EQ(after.pose.position, before.pose.position) << "an impulse moves nothing by itself";
}

TEST(OdeContract, NonfiniteInputIsCountedAndRefused) {
    int body = 0;
    Scene scene = offsetHullScene(body);
    auto backend = makeOde(scene);
    const BodyState before = backend->bodyState(body);
    BodyState bad = before;
    bad.linear_velocity.x() = kNaN;
    backend->setBodyState(body, bad);
    backend->applyImpulse(body, Vec3(kInf, 0, 0), Vec3::Zero());
    backend->applyImpulse(body, Vec3::UnitX(), Vec3(0, kNaN, 0));
    EXPECT_EQ(backend->warnings().at("nonfinite_state"), 3u);
    const BodyState after = backend->bodyState(body);
    EXPECT_EQ(after.pose.position, before.pose.position);
    EXPECT_EQ(after.linear_velocity, before.linear_velocity);
    EXPECT_EQ(after.angular_velocity, before.angular_velocity);
}

// A finite state that overflows in the step (x + h v > DBL_MAX): counted, back to the last finite
// state, never a non-finite number out.
TEST(OdeContract, OverflowInAStepIsRecovered) {
    Scene scene = emptyScene();
    const int ball = addBall(scene, "ball", 0.1, 1.0, Vec3::Zero());
    auto backend = makeOde(scene);
    BodyState huge;
    huge.pose.position = Vec3(1.797e308, 0, 0);
    huge.linear_velocity = Vec3(1e308, 0, 0);
    backend->setBodyState(ball, huge);
    backend->stepFrame(scene.frame_dt);
    EXPECT_GE(backend->warnings().at("nonfinite_state"), 1u);
    const BodyState s = backend->bodyState(ball);
    EXPECT_TRUE(s.pose.position.allFinite() && s.pose.orientation.coeffs().allFinite() &&
                s.linear_velocity.allFinite() && s.angular_velocity.allFinite());
    // The body is usable again afterwards.
    backend->setBodyState(ball, BodyState{});
    backend->stepFrame(scene.frame_dt);
    EXPECT_TRUE(backend->bodyState(ball).pose.position.allFinite());
}

TEST(OdeContract, StatisticsAndWarningsKeepToTheVocabulary) {
    int body = 0;
    Scene scene = offsetHullScene(body);
    auto backend = makeOde(scene);
    for (int f = 0; f < 90; ++f) backend->stepFrame(scene.frame_dt);
    std::vector<std::string> stats, warns;
    for (const auto& [k, v] : backend->statistics()) stats.push_back(k);
    for (const auto& [k, v] : backend->warnings()) warns.push_back(k);
    EXPECT_TRUE(vocabulary::foreignNames(stats, vocabulary::sharedStatistics(), "ode").empty());
    EXPECT_TRUE(vocabulary::foreignNames(warns, vocabulary::sharedWarnings(), "ode").empty());
    for (const char* name : {"frames", "internal_steps", "collision_events", "contact_points", "contact_points_mean",
                             "broadphase_pairs"})
        EXPECT_TRUE(backend->statistics().count(name)) << name;
    EXPECT_GT(backend->statistics().at("contact_points_mean"), 0.0) << "the hull landed";
}

// Several ODE worlds in one process, stepped interleaved, give the bits of a lone run: each keeps
// its own share of ODE's random generator (QuickStep's constraint order).
TEST(OdeContract, DeterministicAlsoBesideOtherWorlds) {
    Scene scene = emptyScene(0.3, 0.6);
    addFloor(scene);
    for (int i = 0; i < 6; ++i) {
        const Vec3 at(0.05 * i, 0.03 * (i % 2), 0.3 + 0.25 * i);
        if (i % 3 == 0) addBall(scene, "b" + std::to_string(i), 0.1, 1.0, at);
        else if (i % 3 == 1) addBox(scene, "x" + std::to_string(i), Vec3(0.1, 0.08, 0.06), 1.0, at);
        else addHullCuboid(scene, "h" + std::to_string(i), Vec3(0.07, 0.1, 0.05), 1.0,
                           Pose{at, Quat(Eigen::AngleAxisd(0.3 * i, Vec3(1, 1, 0).normalized()))});
    }
    for (const char* stepper : {"quickstep", "step"}) {
        auto run = [&](Backend& b) { b.stepFrame(scene.frame_dt); };
        auto lone = makeOde(scene, {{"ode.stepper", stepper}});
        for (int f = 0; f < 150; ++f) run(*lone);
        auto a = makeOde(scene, {{"ode.stepper", stepper}});
        auto b = makeOde(scene, {{"ode.stepper", stepper}});
        for (int f = 0; f < 150; ++f) {
            run(*a);
            run(*b);
            run(*b);   // b runs ahead: the generator must not be shared
        }
        const auto h = stateHash(*lone);
        EXPECT_EQ(stateHash(*a), h) << stepper;
        std::printf("| %s | state hash after 150 frames | %s |\n", stepper, hashToHex(h).c_str());
    }
}

// Every scene under scenes/ (checks and stress included) is created and steps to finite states.
TEST(OdeContract, EverySceneUnderScenesSteps) {
    namespace fs = std::filesystem;
    std::vector<fs::path> files;
    const fs::path dir = fs::path(VROC_SOURCE_DIR) / "scenes";
    if (fs::exists(dir))
        for (const auto& e : fs::recursive_directory_iterator(dir))
            if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    if (files.empty()) GTEST_SKIP() << "no scenes";
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        const Scene scene = loadScene(file.string());
        auto backend = makeOde(scene);
        for (int f = 0; f < 2; ++f) backend->stepFrame(scene.frame_dt);
        for (int i = 0; i < backend->bodyCount(); ++i) {
            const BodyState s = backend->bodyState(i);
            ASSERT_TRUE(s.pose.position.allFinite() && s.pose.orientation.coeffs().allFinite() &&
                        s.linear_velocity.allFinite() && s.angular_velocity.allFinite());
        }
        EXPECT_EQ(backend->warnings().at("nonfinite_state"), 0u);
    }
}

}  // namespace
}  // namespace vroc::test
