// SPDX-License-Identifier: MIT
// The consensus of several backends on one observable, against hand-worked cases.
#include <gtest/gtest.h>

#include <cmath>

#include "vroc/harness/consensus.h"
#include "vroc/harness/scene_support.h"

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
    // c's twin runs differ by 0.6: its 0.5 offset is within its own noise, so it is no outlier.
    EXPECT_EQ(consensus(scalar({"a", "b", "c"}, {1.0, 1.0, 1.5}, {0, 0, 0.6}, 0.01)).verdict, "all agree");
    EXPECT_EQ(consensus(scalar({"a", "b", "c"}, {1.0, 1.0, 1.5}, {0, 0, 0.1}, 0.01)).verdict, "outlier: c");
}

TEST(Consensus, TwoThatDifferHaveNoMajority) {
    EXPECT_EQ(consensus(scalar({"a", "b"}, {1.0, 2.0}, {0, 0}, 0.1)).verdict, "no majority");
    EXPECT_EQ(consensus(scalar({"a", "b", "c"}, {1.0, 2.0, 3.0}, {0, 0, 0}, 0.1)).verdict, "no majority");
}

TEST(Consensus, MissingValuesAreLeftOut) {
    const auto r = consensus(scalar({"a", "b", "c"}, {1.0, NAN, 1.0}, {0, 0, 0}, 0.1));
    EXPECT_EQ(r.verdict, "all agree");
    EXPECT_EQ(r.agreeing, (std::vector<std::string>{"a", "c"}));
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

}  // namespace
}  // namespace vroc::harness
