// SPDX-License-Identifier: MIT
// The footing of a comparison (issue 23; docs/harness.md, "Footing"): which settings the equal
// footing gives each backend and in what order they apply (test backends), and that it really
// changes the engines' internal step: free fall on each reference at the equal footing follows
// semi-implicit Euler at frame_dt / K in closed form (through the built program). With both
// footings side by side (`--footing both`), every backend runs twice in one report, each run on
// its own footing and labelled with it.
#include <algorithm>
#include <cmath>
#include <memory>
#include <set>

#include <gtest/gtest.h>

#include "csv_reader.h"
#include "harness_test_backends.h"
#include "subprocess.h"
#include "test_scenes.h"
#include "vroc/core/errors.h"
#include "vroc/harness/commands/check.h"
#include "vroc/harness/commands/compare.h"
#include "vroc/harness/documents/check_document.h"
#include "vroc/harness/documents/compare_document.h"
#include "vroc/harness/documents/metrics_document.h"
#include "vroc/harness/runs/backend_selection.h"

namespace vroc::harness {
namespace {
namespace fs = std::filesystem;

/// A stand-in engine with a step count and a friction law, and an equal footing that sets both.
void registerFootedBackend() {
    harness_test::registerTestBackends();
    if (BackendRegistry::global().find("test-footed")) return;
    BackendInfo info = *BackendRegistry::global().find("test-exact");
    info.name = "test-footed";
    info.settings = {{"test-footed.substeps", SettingSpec::Type::Integer, "1", 1, 100, {}, "steps per frame"},
                     {"test-footed.friction", SettingSpec::Type::Choice, "pyramid", 0, 0, {"pyramid", "cone"}, "law"}};
    info.equal_footing = [](int substeps) -> std::vector<std::pair<std::string, std::string>> {
        return {{"test-footed.substeps", std::to_string(substeps)}, {"test-footed.friction", "cone"}};
    };
    BackendRegistry::global().add(info);
}

TEST(HarnessFooting, EqualFootingSetsEachEnginesKeysUnderTheUsersSet) {
    registerFootedBackend();
    Footing equal;
    equal.kind = Footing::Kind::Equal;
    equal.substeps = 3;
    // Defaults: the engine's own values, nothing applied.
    auto b = selectBackends("test-footed,test-exact", {});
    EXPECT_EQ(b[0].settings.text("test-footed.substeps"), "1");
    EXPECT_TRUE(b[0].footing_settings.empty());
    // Equal: the footing's values; an engine without an equal footing runs at its defaults.
    b = selectBackends("test-footed,test-exact", {}, equal);
    EXPECT_EQ(b[0].settings.text("test-footed.substeps"), "3");
    EXPECT_EQ(b[0].settings.text("test-footed.friction"), "cone");
    EXPECT_EQ(b[0].footing_settings.size(), 2u);
    EXPECT_TRUE(b[1].footing_settings.empty());
    EXPECT_EQ(b[1].footing.kind, Footing::Kind::Equal);
    // The user's --set wins over the footing.
    b = selectBackends("test-footed", {"test-footed.substeps=7"}, equal);
    EXPECT_EQ(b[0].settings.text("test-footed.substeps"), "7");
    EXPECT_EQ(b[0].settings.text("test-footed.friction"), "cone");
    // metrics.json says which footing and what it set.
    const Json doc = backendsJson(b);
    EXPECT_EQ(doc[0]["footing"]["kind"], "equal");
    EXPECT_EQ(doc[0]["footing"]["substeps_per_frame"], 3);
    EXPECT_EQ(doc[0]["footing"]["settings"]["test-footed.substeps"], "3");
    EXPECT_EQ(backendsJson(selectBackends("test-footed", {}))[0]["footing"]["kind"], "defaults");
    // Bad input names the option.
    EXPECT_THROW(footingKind("fair"), InputError);
    try {
        footingKind("fair");
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--footing"), std::string::npos) << e.what();
    }
    equal.substeps = 0;
    EXPECT_THROW(selectBackends("test-footed", {}, equal), InputError);
    EXPECT_NE(footingText(Footing{}).find("defaults"), std::string::npos);
}

/// The ball's height at frame `frame` of a compare run's trajectory.csv.
double heightAt(const fs::path& trajectory, int frame, double frame_dt) {
    const auto lines = test::splitLines(test::readText(trajectory.string()));
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const auto f = test::splitCsv(lines[i]);
        if (f.size() > 4 && f[1] == "ball" && std::abs(std::stod(f[0]) - frame * frame_dt) < 1e-9) return std::stod(f[4]);
    }
    return NAN;
}

TEST(HarnessFooting, EqualFootingGivesEveryReferenceTheSameInternalStep) {
    // ball_drop: the ball falls from z = 1.1 m and first touches at 0.45 s. At 0.3 s (frame 18),
    // semi-implicit Euler with n steps of dt from rest is at 1.1 - g dt^2 n (n + 1) / 2.
    const std::string names = test::runVroc({"backends"}, test::freshTempDir("footing-probe")).out;
    std::vector<std::string> refs;
    for (const char* name : {"bullet", "ode", "mujoco"})
        if (names.find(std::string(name) + " ") != std::string::npos) refs.push_back(name);
    if (refs.empty()) GTEST_SKIP() << "no reference backend in this build";
    std::string list;
    for (const std::string& r : refs) list += (list.empty() ? "" : ",") + r;
    const fs::path dir = test::freshTempDir("footing-compare");
    const fs::path scene = fs::path(VROC_SOURCE_DIR) / "scenes" / "ball_drop.json";
    const double frame_dt = 1.0 / 60.0, g = 9.81;
    const int frame = 18, k = 3;
    auto euler = [&](int steps_per_frame) {
        const double dt = frame_dt / steps_per_frame;
        const double n = frame * steps_per_frame;
        return 1.1 - g * dt * dt * n * (n + 1) / 2;
    };
    const auto r = test::runVroc({"compare", scene.string(), "--backends", list, "--footing", "equal", "--footing-substeps",
                                  std::to_string(k), "--duration", "0.3", "--windows", "1", "--window", "0.1", "-q", "--out", "equal"},
                                 dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const std::string& ref : refs) {
        const double z = heightAt(dir / "equal" / ref / "trajectory.csv", frame, frame_dt);
        EXPECT_NEAR(z, euler(k), 1e-9) << ref << " at the equal footing takes " << k << " steps a frame";
    }
    const Json doc = readDocument(dir / "equal" / "metrics.json");
    for (const Json& b : doc["backends"]) EXPECT_EQ(b["footing"]["kind"], "equal") << b.dump();
    // The default footing leaves them at their own rates: Bullet and ODE one step a frame (MuJoCo
    // its 2 ms step), so the K = 3 closed form no longer holds (by 8-16 mm at 0.3 s).
    const auto d = test::runVroc({"compare", scene.string(), "--backends", list, "--duration", "0.3", "--windows", "1",
                                  "--window", "0.1", "-q", "--out", "defaults"},
                                 dir);
    ASSERT_EQ(d.exit_code, 0) << d.err;
    for (const std::string& ref : refs) {
        const double z = heightAt(dir / "defaults" / ref / "trajectory.csv", frame, frame_dt);
        EXPECT_GT(std::abs(z - euler(k)), 1e-3) << ref;
    }
}

/// Semi-implicit Euler flight in `test-substepped.substeps` steps a frame (1 by default); its
/// equal footing sets the count. Its error against exact flight is g (dt / k) t / 2 in closed form,
/// so each run's position says which footing it ran on.
class SubsteppedFlight final : public Backend {
public:
    SubsteppedFlight(const Scene& scene, int substeps) : inner_(scene, false), substeps_(substeps) {}
    void stepFrame(double dt) override {
        for (int k = 0; k < substeps_; ++k) inner_.stepFrame(dt / substeps_);
    }
    double time() const override { return inner_.time(); }
    int bodyCount() const override { return inner_.bodyCount(); }
    BodyState bodyState(int body) const override { return inner_.bodyState(body); }
    void setBodyState(int body, const BodyState& state) override { inner_.setBodyState(body, state); }
    void applyImpulse(int body, const Vec3& impulse, const Vec3& point) override {
        inner_.applyImpulse(body, impulse, point);
    }
    std::vector<CollisionEvent> takeEvents() override { return inner_.takeEvents(); }
    WarningCounts warnings() const override { return inner_.warnings(); }
    Statistics statistics() const override { return inner_.statistics(); }

private:
    harness_test::FlightBackend inner_;
    int substeps_;
};

void registerSubsteppedBackend() {
    harness_test::registerTestBackends();
    if (BackendRegistry::global().find("test-substepped")) return;
    BackendInfo info = *BackendRegistry::global().find("test-euler");
    info.name = "test-substepped";
    info.settings = {{"test-substepped.substeps", SettingSpec::Type::Integer, "1", 1, 100, {}, "steps per frame"}};
    info.equal_footing = [](int substeps) -> std::vector<std::pair<std::string, std::string>> {
        return {{"test-substepped.substeps", std::to_string(substeps)}};
    };
    info.create = [](const Scene& scene, const Settings& settings) -> std::unique_ptr<Backend> {
        return std::make_unique<SubsteppedFlight>(scene,
                                                  static_cast<int>(settings.integer("test-substepped.substeps")));
    };
    BackendRegistry::global().add(info);
}

std::size_t checkRow(const CheckSuiteResult& r, const std::string& id) {
    for (std::size_t i = 0; i < r.rows.size(); ++i)
        if (r.rows[i].metric.id == id) return i;
    ADD_FAILURE() << "no check row " << id;
    return 0;
}

TEST(HarnessFooting, BothFootingsRunEveryBackendTwiceEachLabelledWithItsFooting) {
    registerSubsteppedBackend();
    constexpr int k = 4;
    const auto backends = selectBackendsOnBothFootings("test-substepped,test-exact", {}, k);
    ASSERT_EQ(backends.size(), 4u);
    const std::vector<std::string> labels = {"test-substepped (own defaults)", "test-substepped (equal footing)",
                                             "test-exact (own defaults)", "test-exact (equal footing)"};
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(backends[i].label(), labels[i]);
        EXPECT_EQ(backends[i].footing.kind, i % 2 == 0 ? Footing::Kind::Defaults : Footing::Kind::Equal) << labels[i];
    }
    EXPECT_EQ(backends[0].settings.text("test-substepped.substeps"), "1");
    EXPECT_EQ(backends[1].settings.text("test-substepped.substeps"), std::to_string(k));

    // compare: each run's final height is semi-implicit Euler's at its own step, frame_dt / steps,
    // from the flight scene (z0 = 100 m, vz0 = 3 m/s, g = 10 m/s^2, frame 0.01 s) after 1 s.
    CompareOptions o;
    o.duration = 1.0;
    o.windows = 2;
    o.window = 0.1;
    o.write_csv = false;
    o.progress = false;
    const Scene scene = harness_test::flightScene();
    const CompareResult c = compareScene(scene, backends, o, {});
    ASSERT_EQ(c.runs.size(), 4u);
    auto euler = [](int steps_per_frame) {
        const double dt = 0.01 / steps_per_frame, n = 100.0 * steps_per_frame;
        return 100 + 3 * n * dt - 10 * dt * dt * n * (n + 1) / 2;
    };
    const double exact = 100 + 3 * 1.0 - 10 * 1.0 / 2;
    const std::vector<double> expected = {euler(1), euler(k), exact, exact};
    for (std::size_t i = 0; i < 4; ++i)
        EXPECT_NEAR(c.runs[i].main.states.back()[0].pose.position.z(), expected[i], 1e-9) << labels[i];

    // The document: every run under its own key with its footing; tables and verdicts use labels.
    const Json doc = compareDocument(c, "test");
    const std::vector<std::string> keys = {"test-substepped-defaults", "test-substepped-equal", "test-exact-defaults",
                                           "test-exact-equal"};
    for (std::size_t i = 0; i < 4; ++i) {
        const std::string footing = i % 2 == 0 ? "defaults" : "equal";
        EXPECT_EQ(doc["backends"][i]["label"], labels[i]);
        EXPECT_EQ(doc["backends"][i]["footing"]["kind"], footing) << labels[i];
        ASSERT_TRUE(doc["results"].contains(keys[i])) << doc["results"].dump();
        EXPECT_EQ(doc["results"][keys[i]]["footing"], footing) << keys[i];
        EXPECT_EQ(doc["results"][keys[i]]["label"], labels[i]);
    }
    EXPECT_EQ(doc["backends"][1]["footing"]["settings"]["test-substepped.substeps"], std::to_string(k));
    std::vector<std::string> summary_rows;
    for (const Json& t : doc["tables"])
        if (t["id"] == "summary")
            for (const Json& row : t["rows"]) summary_rows.push_back(row[0].get<std::string>());
    EXPECT_EQ(summary_rows, labels);
    // Final positions: exact flight is the same on both footings; substepped Euler is 5 cm off on its
    // own defaults (g dt T / 2) and 1.25 cm on the equal footing, far above the 1 mm floor. The
    // verdict names the agreeing runs with their footings.
    bool found = false;
    for (const Json& row : doc["results"]["consensus"])
        if (row["observable"] == "final positions [m]") {
            found = true;
            EXPECT_EQ(row["agreeing"], Json({"test-exact (own defaults)", "test-exact (equal footing)"})) << row.dump();
        }
    EXPECT_TRUE(found);

    // check: the ballistic scenario's euler-ratio is 1 at one step a frame and 1/k at k steps.
    CheckOptions co;
    co.only = {"ballistic"};
    co.progress = false;
    const auto pair = selectBackendsOnBothFootings("test-substepped", {}, k);
    const CheckSuiteResult r = runCheckSuite(pair, co);
    const CheckRow& ratio = r.rows[checkRow(r, "ballistic.euler-ratio")];
    ASSERT_EQ(ratio.cells.size(), 2u);
    EXPECT_NEAR(ratio.cells[0].measured, 1.0, 1e-6);
    EXPECT_NEAR(ratio.cells[1].measured, 1.0 / k, 1e-6);
    const Json check = checkDocument(r, "test");
    const Json& cells = check["results"]["checks"][checkRow(r, "ballistic.euler-ratio")]["results"];
    EXPECT_NEAR(cells["test-substepped-defaults"]["measured"].get<double>(), 1.0, 1e-6);
    EXPECT_EQ(cells["test-substepped-defaults"]["footing"], "defaults");
    EXPECT_NEAR(cells["test-substepped-equal"]["measured"].get<double>(), 1.0 / k, 1e-6);
    EXPECT_EQ(cells["test-substepped-equal"]["footing"], "equal");
    const std::string text = checkTableText(r);
    EXPECT_EQ(text.rfind("footing: both", 0), 0u) << text;
    EXPECT_LT(text.find("test-substepped (own defaults)"), text.find("test-substepped (equal footing)")) << text;
}

TEST(HarnessFooting, BothFootingsOnTheCommandLine) {
    // `vroc check --footing both`: native's two runs, the second with the equal footing's settings.
    const fs::path dir = test::freshTempDir("footing-both");
    const auto r = test::runVroc({"check", "--backends", "native", "--only", "ballistic", "--footing", "both",
                                  "--footing-substeps", "3", "--jobs", "1", "-q", "--out", "both"},
                                 dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("native (own defaults)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("native (equal footing)"), std::string::npos) << r.out;
    const Json doc = readDocument(dir / "both" / "metrics.json");
    ASSERT_EQ(doc["backends"].size(), 2u) << doc["backends"].dump();
    EXPECT_EQ(doc["backends"][0]["footing"]["kind"], "defaults");
    EXPECT_EQ(doc["backends"][1]["footing"]["kind"], "equal");
    EXPECT_EQ(doc["backends"][1]["label"], "native (equal footing)");
    EXPECT_EQ(doc["backends"][1]["settings"]["native.contact_substeps"], "3");
    EXPECT_NE(doc["backends"][0]["settings"]["native.contact_substeps"], "3");
    EXPECT_TRUE(doc["results"]["wall_time_s"].contains("native-equal")) << doc["results"].dump();
    // sweep and ensemble run one footing at a time: a one-line error, exit 2.
    const auto sweep =
        test::runVroc({"sweep", "check:ballistic", "--backends", "native", "--footing", "both", "-q"}, dir);
    EXPECT_EQ(sweep.exit_code, 2) << sweep.err;
    EXPECT_NE(sweep.err.find("--footing both"), std::string::npos) << sweep.err;
}

}  // namespace
}  // namespace vroc::harness
