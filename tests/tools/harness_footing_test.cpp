// SPDX-License-Identifier: MIT
// The footing of a comparison (issue 23; docs/harness.md, "Footing"): which settings the equal
// footing gives each backend and in what order they apply (test backends), and that it really
// changes the engines' internal step: free fall on each reference at the equal footing follows
// semi-implicit Euler at frame_dt / K in closed form (through the built program).
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "csv_reader.h"
#include "harness_test_backends.h"
#include "subprocess.h"
#include "test_scenes.h"
#include "vroc/core/errors.h"
#include "vroc/harness/backend_selection.h"
#include "vroc/harness/metrics_document.h"

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

}  // namespace
}  // namespace vroc::harness
