// SPDX-License-Identifier: MIT
// ContactPairTracker against hand-made step sequences (docs/events.md): an impact starts one event,
// resting contact does not repeat it, a separation and a new contact start a new one; the event's
// point, normal and impulse from the step's impulse-carrying points; what touching without an
// impulse does under each TouchingRule.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "vroc/core/contact_pair_tracker.h"

namespace vroc {
namespace {

using Pairs = std::set<std::pair<int, int>>;

const TouchingRule kAllRules[] = {TouchingRule::StartsContact, TouchingRule::StartsContactEventAtFirstImpulse,
                                  TouchingRule::KeepsContact};

// One contact of the ball (0) on the floor (1) at the origin, normal +z, carrying `impulse` [N s].
std::vector<SolvedContact> ballOnFloor(double impulse) { return {{0, 1, Vec3::Zero(), Vec3::UnitZ(), impulse}}; }

// Steps `tracker` at `time` and returns the events it reports there.
std::vector<CollisionEvent> step(ContactPairTracker& tracker, const std::vector<SolvedContact>& solved,
                                 const Pairs& touching, double time) {
    tracker.afterStep(solved, touching, time);
    return tracker.take();
}

TEST(ContactPairTracker, AnImpactStartsOneEventAndRestingContactDoesNotRepeatIt) {
    for (TouchingRule rule : kAllRules) {
        SCOPED_TRACE(static_cast<int>(rule));
        ContactPairTracker tracker(rule);
        EXPECT_TRUE(step(tracker, {}, {}, 0.01).empty());  // in flight
        const auto impact = step(tracker, ballOnFloor(2.0), {{0, 1}}, 0.02);
        ASSERT_EQ(impact.size(), 1u);
        EXPECT_EQ(impact[0].time, 0.02);
        EXPECT_EQ(impact[0].body_a, 0);
        EXPECT_EQ(impact[0].body_b, 1);
        EXPECT_EQ(impact[0].impulse, 2.0);
        EXPECT_EQ(impact[0].normal, Vec3(0, 0, 1));
        for (double t : {0.03, 0.04, 0.05}) {  // resting: touching, small impulses every step
            EXPECT_TRUE(step(tracker, ballOnFloor(0.1), {{0, 1}}, t).empty()) << "t = " << t;
            EXPECT_EQ(tracker.pairsInContact(), 1u);
        }
        EXPECT_EQ(tracker.eventTotal(), 1u);
    }
}

TEST(ContactPairTracker, ASeparationThenANewContactStartsANewEvent) {
    for (TouchingRule rule : kAllRules) {
        SCOPED_TRACE(static_cast<int>(rule));
        ContactPairTracker tracker(rule);
        EXPECT_EQ(step(tracker, ballOnFloor(2.0), {{0, 1}}, 0.01).size(), 1u);
        EXPECT_TRUE(step(tracker, ballOnFloor(0.5), {{0, 1}}, 0.02).empty());
        EXPECT_TRUE(step(tracker, {}, {}, 0.03).empty());  // bounced off
        EXPECT_EQ(tracker.pairsInContact(), 0u);
        const auto second = step(tracker, ballOnFloor(1.5), {{0, 1}}, 0.04);
        ASSERT_EQ(second.size(), 1u);
        EXPECT_EQ(second[0].time, 0.04);
        EXPECT_EQ(second[0].impulse, 1.5);
        EXPECT_EQ(tracker.eventTotal(), 2u);
    }
}

TEST(ContactPairTracker, TheEventIsTheStepsImpulseCarryingPoints) {
    // 3 N s at (0,0,0) along +z and 1 N s at (2,0,0) along +x; a point without impulse is left out.
    const std::vector<SolvedContact> solved{{0, 1, Vec3(0, 0, 0), Vec3::UnitZ(), 3.0},
                                            {0, 1, Vec3(10, 10, 10), Vec3::UnitY(), 0.0},
                                            {0, 1, Vec3(2, 0, 0), Vec3::UnitX(), 1.0}};
    ContactPairTracker tracker(TouchingRule::StartsContact);
    const auto events = step(tracker, solved, {{0, 1}}, 0.5);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].impulse, 4.0);                    // summed
    EXPECT_EQ(events[0].point, Vec3(1, 0, 0));            // mean of the two points with impulse
    const Vec3 normal = Vec3(1, 0, 3) / std::sqrt(10.0);  // impulse-weighted, unit
    EXPECT_NEAR((events[0].normal - normal).norm(), 0.0, 1e-15);
}

TEST(ContactPairTracker, AnImpulseWithoutTouchingIsAContact) {
    // Bullet's speculative impulse: the surfaces are still apart after the step.
    for (TouchingRule rule : kAllRules) {
        SCOPED_TRACE(static_cast<int>(rule));
        ContactPairTracker tracker(rule);
        EXPECT_EQ(step(tracker, ballOnFloor(1.0), {}, 0.01).size(), 1u);
        EXPECT_EQ(tracker.pairsInContact(), 1u);
        EXPECT_TRUE(step(tracker, ballOnFloor(0.2), {{0, 1}}, 0.02).empty());
    }
}

TEST(ContactPairTracker, UnderStartsContactTouchingFirstMeansNoEvent) {
    ContactPairTracker tracker(TouchingRule::StartsContact);
    EXPECT_TRUE(step(tracker, ballOnFloor(0.0), {{0, 1}}, 0.01).empty());  // within the distance
    EXPECT_EQ(tracker.pairsInContact(), 1u);
    EXPECT_TRUE(step(tracker, ballOnFloor(1.0), {{0, 1}}, 0.02).empty());  // was in contact already
    EXPECT_TRUE(step(tracker, {}, {}, 0.03).empty());
    EXPECT_EQ(step(tracker, ballOnFloor(1.0), {{0, 1}}, 0.04).size(), 1u);
}

TEST(ContactPairTracker, UnderEventAtFirstImpulseTheRunsFirstImpulseIsTheEvent) {
    ContactPairTracker tracker(TouchingRule::StartsContactEventAtFirstImpulse);
    EXPECT_TRUE(step(tracker, {}, {{0, 1}}, 0.01).empty());  // inside the distance, no force yet
    EXPECT_TRUE(step(tracker, ballOnFloor(0.0), {{0, 1}}, 0.02).empty());
    EXPECT_EQ(tracker.pairsInContact(), 1u);
    const auto first = step(tracker, ballOnFloor(0.7), {{0, 1}}, 0.03);
    ASSERT_EQ(first.size(), 1u);
    EXPECT_EQ(first[0].time, 0.03);
    EXPECT_TRUE(step(tracker, ballOnFloor(0.7), {{0, 1}}, 0.04).empty());
    EXPECT_TRUE(step(tracker, {}, {{0, 1}}, 0.05).empty());  // force gone, still touching: same run
    EXPECT_TRUE(step(tracker, ballOnFloor(0.3), {{0, 1}}, 0.06).empty());
    EXPECT_TRUE(step(tracker, {}, {}, 0.07).empty());  // the run ends
    EXPECT_TRUE(step(tracker, {}, {{0, 1}}, 0.08).empty());
    EXPECT_EQ(step(tracker, ballOnFloor(0.4), {{0, 1}}, 0.09).size(), 1u);
    EXPECT_EQ(tracker.eventTotal(), 2u);
}

TEST(ContactPairTracker, UnderKeepsContactTouchingKeepsButNeverStartsAContact) {
    ContactPairTracker tracker(TouchingRule::KeepsContact);
    EXPECT_TRUE(step(tracker, ballOnFloor(0.0), {{0, 1}}, 0.01).empty());  // found touching, not yet acted on
    EXPECT_EQ(tracker.pairsInContact(), 0u);
    EXPECT_EQ(step(tracker, ballOnFloor(1.0), {{0, 1}}, 0.02).size(), 1u);
    EXPECT_TRUE(step(tracker, ballOnFloor(0.0), {{0, 1}}, 0.03).empty());  // resting, impulse zero this step
    EXPECT_EQ(tracker.pairsInContact(), 1u);
    EXPECT_TRUE(step(tracker, ballOnFloor(0.1), {{0, 1}}, 0.04).empty());
    EXPECT_TRUE(step(tracker, {}, {}, 0.05).empty());
    EXPECT_EQ(step(tracker, ballOnFloor(1.0), {{0, 1}}, 0.06).size(), 1u);
}

TEST(ContactPairTracker, AStepsEventsComeByPairAndAreTakenOnce) {
    ContactPairTracker tracker(TouchingRule::KeepsContact);
    tracker.afterStep({{2, 3, Vec3::Zero(), Vec3::UnitZ(), 1.0},
                       {0, 5, Vec3::Zero(), Vec3::UnitZ(), 1.0},
                       {0, 1, Vec3::Zero(), Vec3::UnitZ(), 1.0}},
                      {}, 0.01);
    const auto events = tracker.take();
    ASSERT_EQ(events.size(), 3u);
    EXPECT_EQ(std::pair(events[0].body_a, events[0].body_b), std::pair(0, 1));
    EXPECT_EQ(std::pair(events[1].body_a, events[1].body_b), std::pair(0, 5));
    EXPECT_EQ(std::pair(events[2].body_a, events[2].body_b), std::pair(2, 3));
    EXPECT_TRUE(tracker.take().empty());
}

TEST(ContactPairTracker, ResetForgetsEveryContact) {
    ContactPairTracker tracker(TouchingRule::StartsContactEventAtFirstImpulse);
    EXPECT_EQ(step(tracker, ballOnFloor(1.0), {{0, 1}}, 0.01).size(), 1u);
    tracker.reset();
    EXPECT_EQ(tracker.pairsInContact(), 0u);
    EXPECT_EQ(step(tracker, ballOnFloor(1.0), {{0, 1}}, 0.02).size(), 1u);
}

}  // namespace
}  // namespace vroc
