// SPDX-License-Identifier: MIT
// The consensus of several backends on one observable, against hand-worked cases.
#include <gtest/gtest.h>

#include <cmath>

#include "vroc/harness/runs/scene_support.h"
#include "vroc/harness/statistics/consensus.h"

namespace vroc::harness {
namespace {

ConsensusInput scalar(std::vector<std::string> names, std::vector<double> values, std::vector<double> noise, double floor) {
    ConsensusInput in;
    in.observable = "x";
    in.backends = std::move(names);
    in.noise = std::move(noise);
    in.floor = floor;
    for (double v : values) in.present.push_back(std::isfinite(v));
    in.difference = [values](std::size_t a, std::size_t b) { return std::abs(values[a] - values[b]); };
    return in;
}

TEST(Consensus, ThreeAgreeingValuesAllAgree) {
    const auto r = consensus(scalar({"a", "b", "c"}, {1.00, 1.01, 0.995}, {0.0, 0.0, 0.0}, 0.02));
    EXPECT_EQ(r.verdict, "all agree");
    EXPECT_EQ(r.agreeing, (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_TRUE(r.outliers.empty());
}

TEST(Consensus, TheOddOneOutIsNamed) {
    // b is 0.5 away from a and c, which are 0.01 apart: b is the outlier (floor 0.02).
    const auto r = consensus(scalar({"a", "b", "c", "d"}, {1.0, 1.5, 1.01, 0.995}, {0, 0, 0, 0}, 0.02));
    EXPECT_EQ(r.verdict, "outlier: b");
    EXPECT_EQ(r.agreeing, (std::vector<std::string>{"a", "c", "d"}));
}

TEST(Consensus, OwnNoiseFloorWidensAgreement) {
    // b's and c's twin runs differ by 0.3: their 0.2 offsets from a are within their own noise,
    // and b and c agree with each other within the floor, so neither is an outlier and both vote.
    EXPECT_EQ(consensus(scalar({"a", "b", "c"}, {1.0, 1.2, 1.205}, {0, 0.3, 0.3}, 0.01)).verdict, "all agree");
    EXPECT_EQ(consensus(scalar({"a", "b", "c"}, {1.0, 1.0, 1.5}, {0, 0, 0.1}, 0.01)).verdict, "outlier: c");
}

TEST(Consensus, ANoisyBackendThatAgreesWithEveryoneOnlyThroughItsNoiseIsUninformative) {
    // c's twin runs differ by 0.6: it is 0.5 from a and b, within its own noise only. It would agree
    // with any value within 0.6, so it does not vote and is named.
    const auto r = consensus(scalar({"a", "b", "c"}, {1.0, 1.0, 1.5}, {0, 0, 0.6}, 0.01));
    EXPECT_EQ(r.verdict, "all agree (uninformative: c)");
    EXPECT_EQ(r.agreeing, (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(r.uninformative, (std::vector<std::string>{"c"}));
    // The same noisy c next to two backends that disagree: before, c "agreed" with both; now the
    // vote is a and b alone, and they have no majority.
    const auto split = consensus(scalar({"a", "b", "c"}, {1.0, 2.0, 1.5}, {0, 0, 0.6}, 0.01));
    EXPECT_EQ(split.verdict, "no majority (uninformative: c)");
}

TEST(Consensus, TwoThatDifferHaveNoMajority) {
    EXPECT_EQ(consensus(scalar({"a", "b"}, {1.0, 2.0}, {0, 0}, 0.1)).verdict, "no majority");
    EXPECT_EQ(consensus(scalar({"a", "b", "c"}, {1.0, 2.0, 3.0}, {0, 0, 0}, 0.1)).verdict, "no majority");
}

TEST(Consensus, MissingValuesAreLeftOutAndNamed) {
    auto in = scalar({"a", "b", "c"}, {1.0, NAN, 1.0}, {0, 0, 0}, 0.1);
    auto r = consensus(in);
    EXPECT_EQ(r.verdict, "all agree");
    EXPECT_EQ(r.agreeing, (std::vector<std::string>{"a", "c"}));
    EXPECT_EQ(r.left_out, (std::vector<std::string>{"b: no value"}));
    in.absent_reason = {"", "no contact event", ""};
    EXPECT_EQ(consensus(in).left_out, (std::vector<std::string>{"b: no contact event"}));
    EXPECT_EQ(consensus(scalar({"a", "b"}, {1.0, NAN}, {0, 0}, 0.1)).verdict, "too few values");
}

TEST(SceneSupport, TheWorstFeatureDecidesAndSaysWhy) {
    Scene s;
    s.materials.push_back({"m", 0.5, 0.5});
    Body ball;
    ball.shape = Shape::sphere(0.1);
    Body box;
    box.shape = Shape::box(Vec3(0.1, 0.1, 0.1));
    s.bodies = {ball, box};
    BackendCapabilities c;
    c.sphere = Support::Exact;
    c.box = Support::Exact;
    c.restitution = Support::Exact;
    EXPECT_EQ(supportText(sceneSupport(s, c)), "exact");
    c.restitution = Support::Approximated;
    c.notes["restitution"] = "through solref";
    EXPECT_EQ(supportText(sceneSupport(s, c)), "approximated: restitution: through solref");
    s.materials[0].restitution = 0.0;   // no bounce asked for: restitution is not used
    EXPECT_EQ(supportText(sceneSupport(s, c)), "exact");
    c.box = Support::Unsupported;
    EXPECT_EQ(supportText(sceneSupport(s, c)), "not supported: box is not supported");
}

// Honest labels: only what the run exercised. A ball (sphere, e = 0.5, mu = 0.5) over a ground
// box, a hull far away; the backend approximates restitution, hulls and friction (pyramid).
TEST(SceneSupport, ARunIsApproximatedOnlyThroughWhatItExercised) {
    Scene s;
    s.materials.push_back({"m", 0.5, 0.5});
    s.materials.push_back({"slippery", 0.0, 0.0});
    Body ball, ground, hull;
    ball.shape = Shape::sphere(0.1);
    ground.shape = Shape::box(Vec3(1, 1, 0.1));
    ground.role = BodyRole::Real;
    hull.shape = Shape::box(Vec3(0.1, 0.1, 0.1));
    hull.shape.kind = Shape::Kind::Hull;  // only its kind is read here
    s.bodies = {ball, ground, hull};
    BackendCapabilities c;
    c.sphere = c.box = Support::Exact;
    c.hull = c.restitution = Support::Approximated;
    c.friction = FrictionModel::Pyramid;
    c.notes = {{"restitution", "soft spring"}, {"hull", "one point"}, {"friction", "four edges"}};
    // The scene names restitution and a hull; a ball in flight touched nothing: exact.
    EXPECT_EQ(sceneSupport(s, c).level, Support::Approximated);
    EXPECT_EQ(supportText(exercisedSupport(s, c, {})), "exact");
    // The ball bounced on the ground: restitution and friction were exercised, the far hull was not.
    CollisionEvent bounce;
    bounce.body_a = 0;
    bounce.body_b = 1;
    EXPECT_EQ(supportText(exercisedSupport(s, c, {bounce})),
              "approximated: friction: four edges; restitution: soft spring");
    // With mu = e = 0 on the ball, the same contact exercises neither.
    s.bodies[0].material = 1;
    EXPECT_EQ(supportText(exercisedSupport(s, c, {bounce})), "exact");
    // The hull touched the ball: its approximation now counts.
    CollisionEvent touch;
    touch.body_a = 0;
    touch.body_b = 2;
    EXPECT_EQ(supportText(exercisedSupport(s, c, {touch})), "approximated: hull: one point");
    // Coulomb's cone is not an approximation of friction.
    s.bodies[0].material = 0;
    c.friction = FrictionModel::Cone;
    c.restitution = Support::Exact;
    EXPECT_EQ(supportText(exercisedSupport(s, c, {bounce})), "exact");
}

BackendCapabilities ellipticWhenAsked(const Settings& s) {
    BackendCapabilities c;
    c.friction = s.values().count("cone") ? FrictionModel::Cone : FrictionModel::Pyramid;
    return c;
}

TEST(SceneSupport, CapabilitiesFollowTheSettingsWhenTheBackendSaysHow) {
    BackendInfo info;
    info.capabilities.friction = FrictionModel::Pyramid;
    EXPECT_EQ(info.capabilitiesFor(Settings(std::map<std::string, std::string>{{"cone", "elliptic"}})).friction,
              FrictionModel::Pyramid);
    info.capabilities_with = &ellipticWhenAsked;
    EXPECT_EQ(info.capabilitiesFor(Settings(std::map<std::string, std::string>{{"cone", "elliptic"}})).friction,
              FrictionModel::Cone);
    EXPECT_EQ(info.capabilitiesFor(Settings()).friction, FrictionModel::Pyramid);
}

}  // namespace
}  // namespace vroc::harness
