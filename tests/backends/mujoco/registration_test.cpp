// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "test_scenes.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/backend_vocabulary.h"
#include "vroc/core/errors.h"
#include "vroc/mujoco/mujoco_backend.h"

namespace vroc::test {
namespace {

TEST(MujocoRegistration, RegistersOnceWithVersionCapabilitiesAndSettings) {
    mujoco::registerBackend();
    mujoco::registerBackend();   // harmless
    const BackendInfo* info = BackendRegistry::global().find("mujoco");
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->version, "MuJoCo 2.2.2 (double)");
    for (const char* key : {"mujoco.timestep", "mujoco.contact_timeconst", "mujoco.restitution", "mujoco.max_substeps",
                            "mujoco.cone", "mujoco.impratio", "mujoco.noslip_iterations", "mujoco.integrator",
                            "mujoco.bound_box_depth"}) {
        bool found = false;
        for (const auto& spec : info->settings) found |= spec.key == key && !spec.help.empty();
        EXPECT_TRUE(found) << key;
    }
    EXPECT_THROW(resolveSettings(info->settings, {{"mujoco.timestp", "0.001"}}), InputError);
    EXPECT_THROW(resolveSettings(info->settings, {{"mujoco.timestep", "0"}}), InputError);
    EXPECT_THROW(resolveSettings(info->settings, {{"mujoco.restitution", "exact"}}), InputError);
    const BackendCapabilities& c = info->capabilities;
    EXPECT_EQ(c.sphere, Support::Exact);
    EXPECT_EQ(c.box, Support::Exact);
    EXPECT_EQ(c.hull, Support::Approximated);   // one contact point per mesh pair
    EXPECT_FALSE(c.notes.at("hull").empty());
    EXPECT_EQ(c.compound, Support::Exact);
    EXPECT_EQ(c.restitution, Support::Approximated);
    EXPECT_FALSE(c.notes.at("restitution").empty());
    EXPECT_EQ(c.friction, FrictionModel::Pyramid);   // the default cone; the note names the elliptic one
    EXPECT_NE(c.notes.at("friction").find("mujoco.cone=elliptic"), std::string::npos);
    EXPECT_FALSE(c.continuous_collision);
    EXPECT_TRUE(c.deterministic);
    EXPECT_EQ(c.precision, "double");
    EXPECT_GE(info->deviations.size(), 4u);
}

TEST(MujocoRegistration, BadCallsAndScenesAreInputErrors) {
    Scene scene = emptyScene();
    addBall(scene, "ball", 0.1, 1.0, Vec3::Zero());
    auto backend = makeMujoco(scene);
    EXPECT_THROW(backend->bodyState(5), InputError);
    EXPECT_THROW(backend->bodyState(-1), InputError);
    EXPECT_THROW(backend->applyImpulse(-1, Vec3::UnitX(), Vec3::Zero()), InputError);
    EXPECT_THROW(backend->setBodyState(1, BodyState{}), InputError);
    EXPECT_THROW(backend->stepFrame(0.0), InputError);
    EXPECT_THROW(backend->stepFrame(-0.01), InputError);
    EXPECT_THROW(backend->stepFrame(std::numeric_limits<double>::quiet_NaN()), InputError);
    EXPECT_THROW(backend->stepFrame(std::numeric_limits<double>::infinity()), InputError);

    Scene massless = emptyScene();
    addFloor(massless);
    addBall(massless, "good", 0.1, 1.0, Vec3(0, 0, 1));
    addBall(massless, "ball", 0.1, 0.0, Vec3::Zero());
    EXPECT_THROW(makeMujoco(massless), InputError);
    Scene no_material = emptyScene();
    addBall(no_material, "ball", 0.1, 1.0, Vec3::Zero(), /*material=*/3);
    EXPECT_THROW(makeMujoco(no_material), InputError);
    // MuJoCo's own refusal comes back as InputError with its text: a diagonal inertia that breaks
    // the triangle inequality (the scene loader would refuse it too).
    Scene bad_inertia = emptyScene();
    const int b = addBall(bad_inertia, "ball", 0.1, 1.0, Vec3::Zero());
    bad_inertia.bodies[b].mass_properties.inertia = Vec3(0.001, 0.001, 0.01).asDiagonal();
    try {
        makeMujoco(bad_inertia);
        ADD_FAILURE() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("MuJoCo refused the model"), std::string::npos) << e.what();
        std::printf("MuJoCo's refusal: %s\n", e.what());
    }
    EXPECT_THROW(makeMujoco(scene, {{"mujoco.contact_timeconst", "0.003"}}), InputError);   // < 2 x 0.002
}

TEST(MujocoRegistration, StatisticsAndWarningsKeepToTheVocabulary) {
    Scene scene = emptyScene(0.0, 0.5);   // e = 0: the ball ends resting on the floor
    addFloor(scene);
    addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 0.3));
    auto backend = makeMujoco(scene);
    run(*backend, scene, 30);
    std::vector<std::string> stats, warnings;
    for (const auto& [name, value] : backend->statistics()) stats.push_back(name);
    for (const auto& [name, value] : backend->warnings()) warnings.push_back(name);
    EXPECT_TRUE(vocabulary::foreignNames(stats, vocabulary::sharedStatistics(), "mujoco").empty());
    EXPECT_TRUE(vocabulary::foreignNames(warnings, vocabulary::sharedWarnings(), "mujoco").empty());
    const Statistics s = backend->statistics();
    EXPECT_EQ(s.at("frames"), 30);
    EXPECT_EQ(s.at("internal_steps"), 30 * 9);   // 1/60 s in steps of at most 2 ms
    EXPECT_GE(s.at("collision_events"), 1);
    EXPECT_GE(s.at("contact_points"), 1);
    EXPECT_GT(s.at("contact_points_mean"), 0);
    for (const auto& [name, count] : backend->warnings()) EXPECT_EQ(count, 0u) << name;
}

}  // namespace
}  // namespace vroc::test
