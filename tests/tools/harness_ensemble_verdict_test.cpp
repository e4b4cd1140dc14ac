// SPDX-License-Identifier: MIT
// The ensemble's verdicts say what they know (issue 23): a difference no larger than the coarser
// backend's resolution is never "distinguishable"; the paired test finds what the unpaired one
// cannot; dropped members are named; an event no member reaches is "not reached"; the report leads
// with a digest coloured by effect. Each against an answer fixed by construction.
#include <cmath>
#include <fstream>
#include <iterator>
#include <set>

#include <gtest/gtest.h>

#include "harness_test_backends.h"
#include "test_scenes.h"
#include "vroc/core/backend_vocabulary.h"
#include "vroc/core/scene_loader.h"
#include "vroc/harness/commands/ensemble.h"
#include "vroc/harness/documents/ensemble_document.h"
#include "vroc/harness/documents/html_report.h"

namespace vroc::harness {
namespace {

constexpr double kFrame = 1.0 / 60.0;  // [s]

EnsembleMember scalarMember(int member, const std::string& id, double value, double resolution) {
    EnsembleMember m;
    m.member = member;
    m.observables[id] = {value};
    m.event_time_resolution = resolution;
    return m;
}

// Both sides of one observable through the ensemble's own steps, with one family of one pair.
EnsembleTest testOnePair(const EnsembleObservable& ob, const std::vector<EnsembleMember>& a,
                         const std::vector<EnsembleMember>& b, double sampled_resolution = kFrame) {
    std::vector<EnsembleTest> tests = {ensembleTest(ob, ensembleSide("a", a, ob, sampled_resolution),
                                                    ensembleSide("b", b, ob, sampled_resolution), 999, 7)};
    concludeEnsembleTests(tests, 0.05);
    return tests.front();
}

TEST(EnsembleVerdicts, ExactTimesAndTheSameTimesRoundedUpToTheNextFrameAreNotDistinguishable) {
    // Backend a reports exact event times; b reports each at the end of its frame. Every value
    // moves by less than one frame, so the Wasserstein-1 distance is below the frame by construction,
    // while the test alone rejects (a's times all lie 0.01 s before b's single value).
    const EnsembleObservable ob{"first_impact_time", "first impact", "s", ObservableTiming::event};
    SplitMix64 rng(5);
    std::vector<EnsembleMember> exact, quantised, late;
    for (int m = 0; m < 16; ++m) {
        const double t = 0.29 + 1e-4 * rng.normal();  // 17.4 frames: rounds up to frame 18
        exact.push_back(scalarMember(m, ob.id, t, 0.0));
        quantised.push_back(scalarMember(m, ob.id, std::ceil(t / kFrame) * kFrame, kFrame));
        late.push_back(scalarMember(m, ob.id, (std::ceil(t / kFrame) + 2) * kFrame, kFrame));  // 2 frames later
    }
    const EnsembleTest t = testOnePair(ob, exact, quantised);
    EXPECT_LT(t.p_holm, 0.05) << "the test alone rejects";
    EXPECT_DOUBLE_EQ(t.floor, kFrame);
    EXPECT_LE(t.effect, kFrame);
    EXPECT_EQ(t.verdict, EnsembleVerdict::within_resolution);
    EXPECT_FALSE(t.distinguishable);
    // Control: two frames later is a difference the frames can tell.
    const EnsembleTest l = testOnePair(ob, exact, late);
    EXPECT_EQ(l.verdict, EnsembleVerdict::distinguishable);
    EXPECT_GT(l.effect, kFrame);
}

TEST(EnsembleVerdicts, MembersSharingAStartArePairedAndAShiftSmallerThanTheSpreadIsFound) {
    // Member m starts alike on both backends: b = a + 0.05 for every member, against a spread of 1
    // between members. The two ensembles overlap almost entirely (the energy test has no power),
    // but every paired difference is +0.05: the sign-flip test's exact p is 2 / 2^16.
    const EnsembleObservable ob{"final_energy", "final energy", "J", ObservableTiming::none};
    SplitMix64 rng(11);
    std::vector<EnsembleMember> a, b;
    for (int m = 0; m < 16; ++m) {
        const double v = rng.normal();
        a.push_back(scalarMember(m, ob.id, v, 0));
        b.push_back(scalarMember(m, ob.id, v + 0.05 + 1e-3 * rng.normal(), 0));
    }
    const EnsembleTest t = testOnePair(ob, a, b);
    EXPECT_EQ(t.paired.pairs, 16u);
    EXPECT_NEAR(t.paired.mean_difference, -0.05, 1e-3);
    EXPECT_GT(t.test.p_value, 0.5) << "the unpaired energy test sees two overlapping ensembles";
    EXPECT_LE(t.paired.p_value, 2.0 / 1000.0);
    EXPECT_LT(t.p_holm, 0.05);
    EXPECT_EQ(t.verdict, EnsembleVerdict::distinguishable);
    // A member missing on one side leaves 15 complete pairs.
    b[3].observables[ob.id] = {NAN};
    EXPECT_EQ(testOnePair(ob, a, b).paired.pairs, 15u);
}

TEST(EnsembleVerdicts, AnEventNoMemberReachesIsNotReachedNotIndistinguishable) {
    // rest_time: nobody came to rest, every value is the end of the run.
    const EnsembleObservable ob{"rest_time", "rest", "s", ObservableTiming::sampled};
    std::vector<EnsembleMember> a, b;
    for (int m = 0; m < 8; ++m) {
        a.push_back(scalarMember(m, ob.id, 2.0, kFrame));
        a.back().not_reached = {ob.id};
        b.push_back(scalarMember(m, ob.id, m < 4 ? 1.5 : 2.0, kFrame));  // half of b's members rest
        if (m >= 4) b.back().not_reached = {ob.id};
    }
    const EnsembleTest none = testOnePair(ob, a, a);
    EXPECT_EQ(none.verdict, EnsembleVerdict::not_reached);
    EXPECT_EQ(none.not_reached_by, (std::vector<std::string>{"a", "b"}));
    EXPECT_TRUE(std::isnan(none.p_holm)) << "not a hypothesis of the family";
    const EnsembleTest one = testOnePair(ob, a, b);
    EXPECT_EQ(one.verdict, EnsembleVerdict::not_reached);
    EXPECT_EQ(one.not_reached_by, (std::vector<std::string>{"a"}));
    EXPECT_EQ(one.reached_b, 4u);
}

// Exact flight that reports a full contact buffer whenever member m's ball starts right of the
// scene's ball: a run that is not valid (run_validity.h), for some members only.
class DroppingBackend final : public Backend {
public:
    explicit DroppingBackend(const Scene& scene) : flight_(scene, true), ball_x_(scene.bodies[1].pose.position.x()) {}
    void stepFrame(double dt) override { flight_.stepFrame(dt); }
    double time() const override { return flight_.time(); }
    int bodyCount() const override { return flight_.bodyCount(); }
    BodyState bodyState(int body) const override { return flight_.bodyState(body); }
    void setBodyState(int body, const BodyState& state) override {
        if (body == 1 && state.pose.position.x() > ball_x_) dropped_ = true;
        flight_.setBodyState(body, state);
    }
    void applyImpulse(int, const Vec3&, const Vec3&) override {}
    std::vector<CollisionEvent> takeEvents() override { return {}; }
    WarningCounts warnings() const override {
        return dropped_ ? WarningCounts{{vocabulary::kContactsDropped, 3}} : WarningCounts{};
    }
    Statistics statistics() const override { return flight_.statistics(); }

private:
    harness_test::FlightBackend flight_;
    double ball_x_;
    bool dropped_ = false;
};

void registerDroppingBackend() {
    harness_test::registerTestBackends();
    if (BackendRegistry::global().find("test-ens-dropping")) return;
    BackendInfo info = *BackendRegistry::global().find("test-exact");
    info.name = "test-ens-dropping";
    info.description = "exact flight that drops contacts in some members (tests only)";
    info.create = [](const Scene& s, const Settings&) -> std::unique_ptr<Backend> {
        return std::make_unique<DroppingBackend>(s);
    };
    BackendRegistry::global().add(info);
}

struct SmallEnsemble {
    EnsembleResult result;
    std::set<int> dropped;  // members whose ball starts right of the scene's: by construction
};

SmallEnsemble runSmallEnsemble() {
    registerDroppingBackend();
    const auto dir = test::freshTempDir("ensemble-verdicts");
    const Scene scene = loadScene(test::writeFile(dir / "two.json", test::kTwoBodyScene).string());
    EnsembleOptions o;
    o.members = 8;
    o.duration = 0.2;
    o.frame_dt = 0.01;
    o.perturb.position = 1e-3;
    RunPool pool = RunPool::inProcess();
    SmallEnsemble s{runEnsemble(scene, selectBackends("test-exact,test-ens-dropping", {}), o, pool), {}};
    for (int m = 0; m < o.members; ++m)
        if (ensembleMemberStates(scene, o.perturb, o.seed, m)[1].pose.position.x() > scene.bodies[1].pose.position.x())
            s.dropped.insert(m);
    return s;
}

TEST(EnsembleVerdicts, MembersOfRunsThatAreNotValidAreDroppedAndNamed) {
    const SmallEnsemble s = runSmallEnsemble();
    ASSERT_FALSE(s.dropped.empty());
    ASSERT_LT(s.dropped.size(), 7u) << "the seed should leave at least 2 valid members";
    const Json doc = ensembleDocument(s.result);
    const Json& dropped = doc["results"]["backends"]["test-ens-dropping"]["dropped"];
    for (const EnsembleObservable& ob : s.result.observables) {
        ASSERT_TRUE(dropped.contains(ob.id)) << ob.id;
        std::set<int> named;
        for (const Json& d : dropped[ob.id]) {
            named.insert(d["member"].get<int>());
            EXPECT_NE(d["reason"].get<std::string>().find(vocabulary::kContactsDropped), std::string::npos);
        }
        EXPECT_EQ(named, s.dropped) << ob.id;
    }
    EXPECT_TRUE(doc["results"]["backends"]["test-exact"]["dropped"].empty());
    for (const EnsembleTest& t : s.result.tests) {
        EXPECT_EQ(t.members_a, 8u);
        EXPECT_EQ(t.members_b + s.dropped.size(), 8u) << t.observable;
        EXPECT_EQ(t.dropped_b.size(), s.dropped.size());
    }
    bool table = false;
    for (const Json& tb : doc["tables"])
        if (tb["id"] == "ensemble-dropped") {
            table = true;
            ASSERT_EQ(tb["rows"].size(), 1u);
            EXPECT_EQ(tb["rows"][0][0], "test-ens-dropping");
            EXPECT_EQ(tb["rows"][0][1], "all");
        }
    EXPECT_TRUE(table);
    EXPECT_NE(ensembleVerdictText(s.result).find("test-ens-dropping member"), std::string::npos);
}

TEST(EnsembleVerdicts, FlightWithoutContactReachesNoImpactAndNoRestAndTheReportLeadsWithTheDigest) {
    // Neither backend has contact: no member has an impact or comes to rest.
    const SmallEnsemble s = runSmallEnsemble();
    std::set<std::string> not_reached;
    for (const EnsembleTest& t : s.result.tests)
        if (t.verdict == EnsembleVerdict::not_reached) not_reached.insert(t.observable);
    EXPECT_EQ(not_reached, (std::set<std::string>{"first_impact_time", "rest_time", "first_impact_time:ball",
                                                  "first_impact_time:box"}));
    const Json doc = ensembleDocument(s.result);
    const Json& v = doc["results"]["verdicts"]["test-exact vs test-ens-dropping"];
    for (const Json& o : v["not_distinguishable_by"]) EXPECT_EQ(not_reached.count(o.get<std::string>()), 0u) << o;
    EXPECT_EQ(v["not_reached"].size(), 4u);
    // The digest comes first: one row per observable, one class per cell.
    const Json& digest = doc["tables"][0];
    ASSERT_EQ(digest["id"], "ensemble-digest");
    ASSERT_EQ(digest["rows"].size(), s.result.observables.size());
    ASSERT_EQ(digest["cell_classes"].size(), digest["rows"].size());
    for (std::size_t r = 0; r < digest["rows"].size(); ++r) {
        ASSERT_EQ(digest["cell_classes"][r].size(), digest["rows"][r].size());
        if (not_reached.count(digest["rows"][r][0].get<std::string>())) {
            EXPECT_EQ(digest["cell_classes"][r][2], "eff-na");
        }
    }
    const auto dir = test::freshTempDir("ensemble-digest");
    std::ifstream in(writeReport({doc}, dir));
    const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto digest_at = html.find("id=\"table-ensemble-digest\""),
               tests_at = html.find("id=\"table-ensemble-tests\"");
    ASSERT_NE(digest_at, std::string::npos);
    EXPECT_LT(digest_at, tests_at);
    EXPECT_NE(html.find("<td class=\"text eff-na\">not reached by test-exact, test-ens-dropping</td>"),
              std::string::npos);
}

}  // namespace
}  // namespace vroc::harness
