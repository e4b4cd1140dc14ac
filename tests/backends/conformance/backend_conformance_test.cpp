// SPDX-License-Identifier: MIT
// The backend contract (docs/backend-contract.md), checked on every backend of
// conformance_backends.h. Expected values are closed forms (momentum, round trips) or the
// contract's own words (names, errors), never another backend's output. The clauses a broken
// backend can get wrong are checks in checks/ (functions of a BackendInfo that collect their
// failures): here each must pass on every real backend, in broken_backends_test.cpp each must
// reject its broken backend.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "checks/check_support.h"
#include "checks/conformance_checks.h"
#include "conformance_backends.h"
#include "conformance_scenes.h"
#include "known_failures.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/backend_vocabulary.h"
#include "vroc/core/errors.h"
#include "vroc/core/scene_loader.h"
#include "vroc/core/settings.h"

namespace vroc::conformance {
namespace {

const BackendInfo& infoOf(const std::string& name) { return registeredBackend(name); }

std::unique_ptr<Backend> create(const std::string& name, const Scene& scene) {
    return createBackend(infoOf(name), scene);
}

const KnownFailure* knownFailure(const std::string& backend, const std::string& check, const std::string& line) {
    for (const KnownFailure& k : knownFailures())
        if (k.backend == backend && k.check == check && line.find(k.line_has) != std::string::npos) return &k;
    return nullptr;
}

// Runs the check named `check` (checks/conformance_checks.h) on `backend`: it must pass, but for
// the entries of known_failures.h, which must each still fail (and are printed).
void expectPasses(const std::string& check, const std::string& backend) {
    const auto it = std::find_if(conformanceChecks().begin(), conformanceChecks().end(),
                                 [&](const ConformanceCheck& c) { return c.name == check; });
    ASSERT_NE(it, conformanceChecks().end()) << "no check named " << check;
    CheckResult r = it->run(infoOf(backend));
    std::vector<const KnownFailure*> seen;
    std::erase_if(r.failures, [&](const std::string& line) {
        const KnownFailure* k = knownFailure(backend, check, line);
        if (k)
            std::cout << "[  KNOWN   ] " << backend << ": " << line << "\n             (known_failures.h) " << k->why
                      << "\n";
        if (k) seen.push_back(k);
        return k != nullptr;
    });
    EXPECT_TRUE(r.passed()) << r;
    for (const KnownFailure& k : knownFailures())
        if (k.backend == backend && k.check == check && std::find(seen.begin(), seen.end(), &k) == seen.end())
            ADD_FAILURE() << backend << " no longer fails " << check << " on " << k.line_has
                          << ": remove its entry from known_failures.h";
}

class Conformance : public ::testing::TestWithParam<std::string> {};

// Every shipped scene is created (or refused with InputError when the backend declares a feature
// it needs unsupported), steps to finite states at the summed frame time, and a kicked body moves
// and falls back (checks/shipped_scenes_check.h).
TEST_P(Conformance, EveryShippedSceneLoadsStepsAndMoves) { expectPasses("shipped_scenes", GetParam()); }

// A body of each supported shape kind dropped onto a real floor reports the collision and comes to
// rest on the floor (checks/landing_check.h).
TEST_P(Conformance, DroppedBodiesLandOnTheFloor) { expectPasses("landing", GetParam()); }

TEST_P(Conformance, SetBodyStateRoundTrips) {
    for (Shape shape : {Shape::box(Vec3(0.3, 0.2, 0.1)), irregularHull()}) {
        SCOPED_TRACE(shape.kindName());
        const Scene scene = lonelyBody(shape);
        auto b = create(GetParam(), scene);
        BodyState s;
        s.pose = at(Vec3(1.25, -0.5, 2.0), Quat(Eigen::AngleAxisd(2.1, Vec3(-1, 0.5, 2).normalized())));
        s.linear_velocity = Vec3(0.3, -1.2, 2.5);
        s.angular_velocity = Vec3(-0.7, 1.9, 0.4);
        b->setBodyState(1, s);
        const BodyState r = b->bodyState(1);
        EXPECT_LE((r.pose.position - s.pose.position).norm(), 1e-12 * 4);
        EXPECT_TRUE(sameRotation(r.pose.orientation, s.pose.orientation, 1e-12));
        EXPECT_LE((r.linear_velocity - s.linear_velocity).norm(), 1e-12 * 4);
        EXPECT_LE((r.angular_velocity - s.angular_velocity).norm(), 1e-12 * 4);
    }
}

// Momentum changes by exactly J, angular momentum about the COM by (p - com) x J, in the world
// frame, on a body turned away from identity (checks/impulse_check.h).
TEST_P(Conformance, ApplyImpulseChangesMomentumByTheImpulse) { expectPasses("impulse", GetParam()); }

TEST_P(Conformance, RealBodiesIgnoreStateAndImpulses) {
    const Scene scene = lonelyBody(Shape::sphere(0.2));
    auto b = create(GetParam(), scene);
    const BodyState floor = b->bodyState(0);
    BodyState moved = floor;
    moved.pose.position += Vec3(1, 2, 3);
    moved.linear_velocity = Vec3(1, 0, 0);
    b->setBodyState(0, moved);
    b->applyImpulse(0, Vec3(0, 0, 100), floor.pose.position);
    b->stepFrame(scene.frame_dt);
    const BodyState after = b->bodyState(0);
    EXPECT_EQ(after.pose.position, floor.pose.position);
    EXPECT_EQ(after.linear_velocity, Vec3::Zero());
}

// A tracked body moves as prescribed (origin at p0 + v t, orientation turned by w t), an impulse
// never moves it, and setBodyState is a sample it moves on from (docs/backend-contract.md).
TEST_P(Conformance, TrackedBodiesMoveAsPrescribed) {
    if (infoOf(GetParam()).capabilities.tracked == Support::Unsupported) {
        EXPECT_THROW(create(GetParam(), lonelyTrackedBody(Shape::box(Vec3(0.3, 0.2, 0.1)))), InputError);
        GTEST_SKIP() << GetParam() << " declares tracked bodies unsupported (and refuses them)";
    }
    const Scene scene = lonelyTrackedBody(Shape::box(Vec3(0.3, 0.2, 0.1)));
    const Body& body = scene.bodies[1];
    auto b = create(GetParam(), scene);
    b->applyImpulse(1, Vec3(0, 0, 100), body.pose.position);
    for (int f = 0; f < 10; ++f) b->stepFrame(scene.frame_dt);
    const double t = b->time();
    BodyState s = b->bodyState(1);
    const Quat turned = Quat(Eigen::AngleAxisd(0.8 * t, Vec3::UnitZ())) * body.pose.orientation;
    EXPECT_LE((s.pose.position - (body.pose.position + body.linear_velocity * t)).norm(), 1e-9);
    EXPECT_TRUE(sameRotation(s.pose.orientation, turned, 1e-9));
    EXPECT_LE((s.linear_velocity - body.linear_velocity).norm(), 1e-9);
    EXPECT_LE((s.angular_velocity - body.angular_velocity).norm(), 1e-9);
    BodyState sample;
    sample.pose = at(Vec3(2, 1, 0), Quat::Identity());
    sample.linear_velocity = Vec3(-1, 0, 0);
    b->setBodyState(1, sample);
    for (int f = 0; f < 6; ++f) b->stepFrame(scene.frame_dt);
    s = b->bodyState(1);
    EXPECT_LE((s.pose.position - (sample.pose.position + sample.linear_velocity * (b->time() - t))).norm(), 1e-9);
    EXPECT_TRUE(sameRotation(s.pose.orientation, Quat::Identity(), 1e-9));
    // A non-finite sample is a tracker glitch: refused, counted, the body keeps its motion.
    BodyState bad = sample;
    bad.angular_velocity.y() = std::numeric_limits<double>::quiet_NaN();
    b->setBodyState(1, bad);
    EXPECT_EQ(b->warnings().at(vocabulary::kNonfiniteState), 1u);
    EXPECT_LE((b->bodyState(1).linear_velocity - sample.linear_velocity).norm(), 1e-12);
    // A tracked body without a finite motion in the scene is the caller's mistake.
    Scene broken = scene;
    broken.bodies[1].linear_velocity.x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(create(GetParam(), broken), InputError);
}

// Two infinite masses have no response: a tracked plate sinks through the real floor and crosses a
// second tracked plate; both keep their motion, with no event and no warning.
TEST_P(Conformance, TrackedBodiesPassThroughRealAndTrackedBodies) {
    if (infoOf(GetParam()).capabilities.tracked == Support::Unsupported) GTEST_SKIP() << "no tracked bodies";
    Scene scene = sceneWithMaterial(Vec3(0, 0, -9.81));
    addBody(scene, "floor", Shape::box(Vec3(5, 5, 0.5)), at(Vec3(0, 0, -0.5)), 0, true);
    Scene one = lonelyTrackedBody(Shape::box(Vec3(0.2, 0.2, 0.02)));
    Body a = one.bodies[1];
    a.name = "a";
    a.pose = at(Vec3(0, 0, 0.5), Quat::Identity());
    a.linear_velocity = Vec3(0, 0, -1.0);
    a.angular_velocity = Vec3::Zero();
    Body c = a;
    c.name = "c";
    c.shape = Shape::box(Vec3(0.02, 0.2, 0.2));
    c.pose = at(Vec3(-0.5, 0, 0), Quat::Identity());
    c.linear_velocity = Vec3(1.0, 0, 0);
    c.angular_velocity = Vec3(0, 0, 2.0);
    scene.bodies.push_back(a);
    scene.bodies.push_back(c);
    auto b = create(GetParam(), scene);
    for (int f = 0; f < 60; ++f) {
        b->stepFrame(1.0 / 60.0);
        EXPECT_TRUE(b->takeEvents().empty()) << "frame " << f;
    }
    EXPECT_LE((b->bodyState(1).pose.position - Vec3(0, 0, -0.5)).norm(), 1e-9);
    EXPECT_LE((b->bodyState(2).pose.position - Vec3(0.5, 0, 0)).norm(), 1e-9);
    EXPECT_LE((b->bodyState(2).angular_velocity - Vec3(0, 0, 2.0)).norm(), 1e-12);
    for (const auto& [name, count] : b->warnings()) EXPECT_EQ(count, 0u) << name;
}

// The same state hash on every run and at every worker count the backend's settings offer
// (checks/worker_count_check.h).
TEST_P(Conformance, SameInputGivesTheSameStateHashForAnyWorkerCount) { expectPasses("worker_count", GetParam()); }

// A non-finite state handed in mid-run is counted and refused: the body keeps a finite state and
// the run goes on.
TEST_P(Conformance, NonfiniteStateBecomesACountedWarningAndAFiniteState) {
    const Scene scene = loadScene(std::string(VROC_SOURCE_DIR) + "/scenes/ball_drop.json");
    auto b = create(GetParam(), scene);
    int ball = -1;
    for (int i = 0; i < static_cast<int>(scene.bodies.size()); ++i)
        if (!scene.bodies[static_cast<std::size_t>(i)].isStatic()) ball = i;
    ASSERT_GE(ball, 0);
    for (int f = 0; f < 10; ++f) b->stepFrame(scene.frame_dt);
    BodyState bad = b->bodyState(ball);
    bad.linear_velocity.z() = std::numeric_limits<double>::quiet_NaN();
    bad.pose.position.x() = std::numeric_limits<double>::infinity();
    b->setBodyState(ball, bad);
    b->applyImpulse(ball, Vec3(0, 0, std::numeric_limits<double>::quiet_NaN()), Vec3::Zero());
    const auto warnings = b->warnings();
    ASSERT_TRUE(warnings.count(vocabulary::kNonfiniteState));
    EXPECT_GE(warnings.at(vocabulary::kNonfiniteState), 2u);
    for (int f = 0; f < 10; ++f) b->stepFrame(scene.frame_dt);
    for (const BodyState& s : statesOf(*b)) EXPECT_TRUE(finite(s));
}

TEST_P(Conformance, StatisticsAndWarningsKeepToTheVocabulary) {
    const Scene scene = loadScene(std::string(VROC_SOURCE_DIR) + "/scenes/staircase.json");
    auto b = create(GetParam(), scene);
    for (int f = 0; f < 120; ++f) b->stepFrame(scene.frame_dt);
    std::vector<std::string> stats, warns;
    for (const auto& [k, v] : b->statistics()) stats.push_back(k);
    for (const auto& [k, v] : b->warnings()) warns.push_back(k);
    EXPECT_EQ(vocabulary::foreignNames(stats, vocabulary::sharedStatistics(), GetParam()), std::vector<std::string>{});
    EXPECT_EQ(vocabulary::foreignNames(warns, vocabulary::sharedWarnings(), GetParam()), std::vector<std::string>{});
    const auto s = b->statistics();
    for (const char* required : {vocabulary::kFrames, vocabulary::kInternalSteps, vocabulary::kCollisionEvents})
        ASSERT_TRUE(s.count(required)) << required;
    EXPECT_EQ(s.at(vocabulary::kFrames), 120.0);
    EXPECT_GE(s.at(vocabulary::kInternalSteps), 120.0);
    EXPECT_GE(s.at(vocabulary::kCollisionEvents), 1.0) << "the staircase ball hits the steps";
}

TEST_P(Conformance, CallersMistakesThrowInputError) {
    const Scene scene = lonelyBody(Shape::sphere(0.2));
    auto b = create(GetParam(), scene);
    EXPECT_THROW(b->bodyState(-1), InputError);
    EXPECT_THROW(b->bodyState(b->bodyCount()), InputError);
    EXPECT_THROW(b->setBodyState(7, BodyState{}), InputError);
    EXPECT_THROW(b->applyImpulse(-3, Vec3::UnitX(), Vec3::Zero()), InputError);
    EXPECT_THROW(b->stepFrame(0.0), InputError);
    EXPECT_THROW(b->stepFrame(-1.0 / 60.0), InputError);
    EXPECT_THROW(b->stepFrame(std::numeric_limits<double>::quiet_NaN()), InputError);
    BodyState zero = b->bodyState(1);
    zero.pose.orientation.coeffs().setZero();
    EXPECT_THROW(b->setBodyState(1, zero), InputError);
    EXPECT_EQ(b->time(), 0.0);
}

// Each shape kind (and tracked bodies) declared unsupported is refused at creation with an
// InputError naming the body; each declared exact or approximated is created and steps finitely
// (checks/shape_support_check.h). No real backend refuses a shape kind today: the refusal branch
// is exercised by the broken and control backends of broken_backends_test.cpp.
TEST_P(Conformance, ShapesAreRefusedOrAcceptedAsDeclared) { expectPasses("shape_support", GetParam()); }

// Every approximation has a note, no exact feature has one, every deviation says why
// (checks/capability_notes_check.h).
TEST_P(Conformance, CapabilitiesExplainEveryApproximation) { expectPasses("capability_notes", GetParam()); }

// Every known failure names a backend of the suite and a check that exists (else its entry would
// never match, and expectPasses would report it as fixed only once the names are right).
TEST(KnownFailures, NameSuiteBackendsAndChecks) {
    for (const KnownFailure& k : knownFailures()) {
        EXPECT_NE(BackendRegistry::global().find(k.backend), nullptr) << k.backend;
        EXPECT_TRUE(std::any_of(conformanceChecks().begin(), conformanceChecks().end(), [&](const ConformanceCheck& c) {
            return c.name == k.check;
        })) << k.check;
    }
}

std::vector<std::string> backendNames() {
    std::vector<std::string> names;
    for (const ConformanceBackend& b : conformanceBackends()) names.push_back(b.name);
    return names;
}

INSTANTIATE_TEST_SUITE_P(AllBackends, Conformance, ::testing::ValuesIn(backendNames()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

}  // namespace
}  // namespace vroc::conformance
