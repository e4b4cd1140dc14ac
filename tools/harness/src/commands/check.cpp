// SPDX-License-Identifier: MIT
#include "vroc/harness/commands/check.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "vroc/core/build_info.h"
#include "vroc/core/errors.h"
#include "vroc/core/state_hash.h"
#include "vroc/harness/runs/run_validity.h"

namespace vroc::harness {
namespace {

constexpr const char* kNative = "native";

bool passes(double measured, const CheckMetric& m) {
    return std::isfinite(measured) && std::abs(measured - m.expected) <= m.tolerance;
}

// One scenario on one backend, as it travels through the pool (the run may be in another process).
struct CellRun {
    std::vector<CheckCell> cells;   // one per metric of the scenario
    double seconds = 0;             // [s] wall time of the run
    std::string state_hash;         // of the last frame (kept in the run's file); empty: not run
};

Json cellRunJson(const CellRun& r) {
    Json cells = Json::array();
    for (const CheckCell& c : r.cells)
        cells.push_back({{"measured", number(c.measured)},
                         {"pass", c.pass ? Json(*c.pass) : Json(nullptr)},
                         {"support_level", static_cast<int>(c.support.level)},
                         {"support_reason", c.support.reason},
                         {"not_valid", c.validity.valid ? Json(nullptr) : Json(c.validity.reason)}});
    return {{"cells", cells}, {"seconds", r.seconds}, {"state_hash", r.state_hash}};
}

CellRun cellRunFromJson(const Json& j) {
    CellRun r;
    for (const Json& c : j.at("cells")) {
        CheckCell cell;
        cell.measured = c.at("measured").is_null() ? NAN : c.at("measured").get<double>();
        if (!c.at("pass").is_null()) cell.pass = c.at("pass").get<bool>();
        cell.support = {static_cast<Support>(c.at("support_level").get<int>()), c.at("support_reason").get<std::string>()};
        if (!c.at("not_valid").is_null()) cell.validity = {false, c.at("not_valid").get<std::string>()};
        r.cells.push_back(std::move(cell));
    }
    r.seconds = j.at("seconds").get<double>();
    r.state_hash = j.at("state_hash").get<std::string>();
    return r;
}

// One scenario on one backend: a cell per metric, and the wall time of the run.
// A scene the backend cannot represent is reported, not run; an approximated one is run and its
// cells say which of the features the run exercised are approximated, and why.
CellRun runCheckCell(const CheckScenario& sc, const SelectedBackend& b) {
    const Scene scene = sc.build();
    SceneSupport support = sceneSupport(scene, b.info->capabilities);
    RunTrace trace;
    const auto start = std::chrono::steady_clock::now();
    if (support.level != Support::Unsupported) {
        RunOptions ro;
        ro.frame_dt = sc.frame_dt;
        ro.frames = frameCount(sc.duration, sc.frame_dt);
        try {
            trace = runBackend(*b.info, scene, b.settings, ro);
        } catch (const InputError& e) {   // refused at creation: the backend's own word
            support = {Support::Unsupported, e.what()};
        }
    }
    // Honest labels: "~" only through the features this run exercised (what touched, with which
    // material and friction law), not every feature the scene file names.
    if (support.level != Support::Unsupported)
        support = exercisedSupport(scene, b.info->capabilitiesFor(b.settings), trace.events);
    CellRun run;
    const RunValidity validity = trace.finite ? runValidity(trace) : RunValidity{};
    for (const CheckMetric& cm : sc.metrics) {
        CheckCell cell;
        cell.support = support;
        cell.validity = validity;
        if (support.level != Support::Unsupported) {
            cell.measured = trace.finite ? cm.measure(scene, trace) : NAN;
            if (cm.judged() && validity.valid) cell.pass = passes(cell.measured, cm);
        }
        run.cells.push_back(std::move(cell));
    }
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!trace.states.empty()) run.state_hash = hashToHex(stateHash(trace.states.back()));
    return run;
}

// The scenarios `o` selects: the analytic set, then the stress section when asked for (or implied
// by a stress id in --only); only the selected stress scenes are loaded.
std::vector<CheckScenario> selectedScenarios(const CheckOptions& o, bool stress) {
    std::vector<CheckScenario> scenarios = checkScenarios(o.long_set);
    if (!o.only.empty())
        std::erase_if(scenarios, [&](const CheckScenario& s) { return std::find(o.only.begin(), o.only.end(), s.id) == o.only.end(); });
    if (!stress) return scenarios;
    std::vector<std::string> only_stress;
    const std::vector<std::string> known = stressScenarioIds();
    for (const std::string& id : o.only) {
        if (!isStressScenarioId(id)) continue;
        if (std::find(known.begin(), known.end(), id) == known.end()) {
            std::string list;
            for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
            throw InputError("--only " + id + ": no such stress scenario (known: " + list + ")");
        }
        only_stress.push_back(id);
    }
    if (o.only.empty() || !only_stress.empty())
        for (CheckScenario& s : stressScenarios(o.scenes_dir, only_stress)) scenarios.push_back(std::move(s));
    return scenarios;
}

}  // namespace

int requiredFailuresNative(const std::vector<SelectedBackend>& backends, const std::vector<CheckRow>& rows) {
    int failures = 0;
    for (std::size_t b = 0; b < backends.size(); ++b) {
        if (backends[b].info->name != kNative) continue;
        for (const CheckRow& row : rows)
            if (row.metric.required_for_native && row.cells.at(b).pass == false) ++failures;
    }
    return failures;
}

CheckSuiteResult runCheckSuite(const std::vector<SelectedBackend>& backends, const CheckOptions& o, RunPool& pool) {
    CheckSuiteResult result;
    result.backends = backends;
    result.long_set = o.long_set;
    result.stress = o.stress || std::any_of(o.only.begin(), o.only.end(), isStressScenarioId);
    if (result.stress) result.scenes_dir = o.scenes_dir;
    const std::vector<CheckScenario> scenarios = selectedScenarios(o, result.stress);
    result.scenario_count = scenarios.size();
    // One job per (scenario, backend): run it and measure every metric of the scenario.
    std::vector<PoolJob> jobs;
    for (const CheckScenario& sc : scenarios)
        for (const SelectedBackend& b : backends)
            jobs.push_back({poolJobId("check-" + sc.id + "-" + b.key()),
                            [&sc, &b] { return cellRunJson(runCheckCell(sc, b)); },
                            static_cast<double>(frameCount(sc.duration, sc.frame_dt))});
    const std::vector<Json> done = pool.run(jobs);

    result.wall_time_s.assign(backends.size(), 0.0);
    std::size_t job = 0;
    for (const CheckScenario& sc : scenarios) {
        const std::size_t first = result.rows.size();
        for (const CheckMetric& cm : sc.metrics) result.rows.push_back({sc.id, cm, {}});
        for (std::size_t b = 0; b < backends.size(); ++b) {
            const CellRun run = cellRunFromJson(done[job++]);
            for (std::size_t m = 0; m < sc.metrics.size(); ++m) result.rows[first + m].cells.push_back(run.cells[m]);
            result.wall_time_s[b] += run.seconds;
        }
    }
    result.required_failures_native = requiredFailuresNative(backends, result.rows);
    result.execution = pool.execution();
    return result;
}

CheckSuiteResult runCheckSuite(const std::vector<SelectedBackend>& backends, const CheckOptions& o) {
    RunPool pool = RunPool::inProcess();
    return runCheckSuite(backends, o, pool);
}

Json checkPlan(const std::vector<SelectedBackend>& backends, const CheckOptions& o) {
    const BuildInfo& b = buildInfo();
    return {{"command", "check"}, {"backends", backendsJson(backends)}, {"long", o.long_set}, {"only", o.only}, {"stress", o.stress},
            {"scenes_dir", o.scenes_dir.string()}, {"build", {{"version", b.version}, {"commit", b.commit}}}};
}

}  // namespace vroc::harness
