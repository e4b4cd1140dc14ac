// SPDX-License-Identifier: MIT
#include "vroc/harness/check.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>

#include "vroc/core/build_info.h"
#include "vroc/core/errors.h"
#include "vroc/core/state_hash.h"
#include "vroc/harness/check_suite.h"
#include "vroc/harness/html_report.h"
#include "vroc/harness/scene_support.h"

namespace vroc::harness {
namespace {

constexpr const char* kNative = "native";

bool passes(double measured, const CheckMetric& m) {
    return std::isfinite(measured) && std::abs(measured - m.expected) <= m.tolerance;
}

// A result cell: pass null is a metric that is reported, not judged.
const char* resultText(const Json& pass) { return pass.is_null() ? "info" : pass.get<bool>() ? "pass" : "FAIL"; }

// A backend's result cell with its support: "n/s" (not supported), "pass~" (approximated).
std::string cellResult(const Json& result) {
    const std::string support = result.value("support", std::string("exact"));
    if (support.rfind("not supported", 0) == 0) return "n/s";
    return std::string(resultText(result["pass"])) + (support == "exact" ? "" : "~");
}

// One scenario on one backend: a cell per metric, and the wall time of the run.
// A scene the backend cannot represent is reported, not run; an approximated one is run and its
// cells say so.
Json runCheckCell(const CheckScenario& sc, const SelectedBackend& b) {
    const Scene scene = sc.build();
    SceneSupport support = sceneSupport(scene, b.info->capabilities);
    RunTrace trace;
    const auto start = std::chrono::steady_clock::now();
    if (support.level != Support::Unsupported) {
        RunOptions ro;
        ro.frame_dt = sc.frame_dt;
        ro.frames = framesFor(sc.duration, sc.frame_dt);
        try {
            trace = runBackend(*b.info, scene, b.settings, ro);
        } catch (const InputError& e) {   // refused at creation: the backend's own word
            support = {Support::Unsupported, e.what()};
        }
    }
    Json cells = Json::array();
    for (const CheckMetric& cm : sc.metrics) {
        if (support.level == Support::Unsupported) {
            cells.push_back({{"measured", nullptr}, {"pass", nullptr}, {"support", supportText(support)}});
            continue;
        }
        const double measured = trace.finite ? cm.measure(scene, trace) : NAN;
        cells.push_back({{"measured", number(measured)}, {"pass", cm.judged() ? Json(passes(measured, cm)) : Json(nullptr)},
                         {"support", supportText(support)}});
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string hash = trace.states.empty() ? "" : hashToHex(stateHash(trace.states.back()));
    return {{"cells", cells}, {"seconds", seconds}, {"state_hash", hash}};
}

}  // namespace

Json runCheckSuite(const std::vector<SelectedBackend>& backends, const CheckOptions& o, RunPool& pool) {
    std::vector<CheckScenario> scenarios = checkScenarios(o.long_set);
    if (!o.only.empty())
        std::erase_if(scenarios, [&](const CheckScenario& s) { return std::find(o.only.begin(), o.only.end(), s.id) == o.only.end(); });
    // The stress section comes after the analytic scenarios; only its selected scenes are loaded.
    const bool stress = o.stress || std::any_of(o.only.begin(), o.only.end(), isStressScenarioId);
    if (stress) {
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
    }
    Json doc = newDocument("check", o.command_line);
    doc["title"] = std::string("analytic suite (") + (o.long_set ? "long" : "default") + " set)" + (stress ? " + stress section" : "");
    doc["backends"] = backendsJson(backends);
    doc["parameters"] = {{"long", o.long_set}, {"scenarios", scenarios.size()}, {"stress", stress}};
    if (stress) doc["parameters"]["scenes_dir"] = o.scenes_dir.string();
    // One job per (scenario, backend): run it and measure every metric of the scenario.
    std::vector<PoolJob> jobs;
    for (const CheckScenario& sc : scenarios)
        for (const SelectedBackend& b : backends)
            jobs.push_back({poolJobId("check-" + sc.id + "-" + b.info->name), [&sc, &b] { return runCheckCell(sc, b); },
                            static_cast<double>(framesFor(sc.duration, sc.frame_dt))});
    const std::vector<Json> cells = pool.run(jobs);

    Json checks = Json::array();
    Json wall = Json::object();
    int native_failures = 0;
    std::size_t job = 0;
    for (const CheckScenario& sc : scenarios) {
        std::vector<Json> rows(sc.metrics.size(), Json::object());
        for (std::size_t m = 0; m < sc.metrics.size(); ++m) {
            const CheckMetric& cm = sc.metrics[m];
            rows[m] = {{"id", cm.id}, {"scenario", sc.id}, {"title", cm.title}, {"closed_form", cm.closed_form},
                       {"units", cm.units}, {"expected", cm.expected}, {"tolerance", number(cm.tolerance)},
                       {"criterion", cm.criterion},
                       {"required_for_native", cm.required_for_native}, {"results", Json::object()}};
        }
        for (const SelectedBackend& b : backends) {
            const Json& r = cells[job++];
            for (std::size_t m = 0; m < sc.metrics.size(); ++m) {
                const CheckMetric& cm = sc.metrics[m];
                const Json& cell = r["cells"][m];
                rows[m]["results"][b.info->name] = cell;
                if (cell["pass"].is_boolean() && !cell["pass"].get<bool>() && cm.required_for_native && b.info->name == kNative) ++native_failures;
            }
            wall[b.info->name] = wall.value(b.info->name, 0.0) + r["seconds"].get<double>();
        }
        for (Json& r : rows) checks.push_back(r);
    }
    doc["results"] = {{"checks", checks}, {"wall_time_s", wall}, {"required_failures_native", native_failures}};
    doc["execution"] = pool.executionJson();

    // Table: one row per check metric, measured and pass/fail per backend.
    std::vector<std::string> columns = {"check", "closed form", "units", "expected", "tolerance", "tolerance: why", "required for native"};
    for (const SelectedBackend& b : backends) {
        columns.push_back(b.info->name + " measured");
        columns.push_back(b.info->name + " result");
    }
    std::vector<std::vector<Json>> rows;
    for (const Json& c : checks) {
        std::vector<Json> row = {c["id"], c["closed_form"], c["units"], c["expected"], c["tolerance"], c["criterion"],
                                 c["required_for_native"]};
        for (const SelectedBackend& b : backends) {
            row.push_back(c["results"][b.info->name]["measured"]);
            row.push_back(cellResult(c["results"][b.info->name]));
        }
        rows.push_back(row);
    }
    doc["tables"].push_back(tableJson("checks", "Checks x backends", columns, rows));
    // Chart: error relative to tolerance, per check, one series per backend (1 = the tolerance).
    ChartSpec chart{"check-errors", "Check error / tolerance (below 1 passes; zero errors drawn at 1e-6)",
                    "check number (table order)", "|measured - expected| / tolerance [-]", false, true, {}};
    for (const SelectedBackend& b : backends) {
        ChartSeries s{b.info->name, "points", {}, {}};
        for (std::size_t i = 0; i < checks.size(); ++i) {
            const Json& c = checks[i];
            const Json& meas = c["results"][b.info->name]["measured"];
            if (c["tolerance"].is_null()) continue;   // reported, not judged
            if (cellResult(c["results"][b.info->name]) == "n/s") continue;   // not run
            const double tol = c["tolerance"];
            const double err = meas.is_null() ? 1e6 : std::abs(meas.get<double>() - c["expected"].get<double>());
            const double ratio = tol > 0 ? err / tol : (err > 0 ? 1e6 : 0);
            s.x.push_back(static_cast<double>(i + 1));
            s.y.push_back(std::max(ratio, 1e-6));
        }
        chart.series.push_back(s);
    }
    chart.series.push_back({"tolerance", "lines", {0.5, checks.size() + 0.5}, {1.0, 1.0}});
    doc["charts"].push_back(chartJson(chart));
    return doc;
}

Json runCheckSuite(const std::vector<SelectedBackend>& backends, const CheckOptions& o) {
    RunPool pool = RunPool::inProcess();
    return runCheckSuite(backends, o, pool);
}

Json checkPlan(const std::vector<SelectedBackend>& backends, const CheckOptions& o) {
    const BuildInfo& b = buildInfo();
    return {{"command", "check"}, {"backends", backendsJson(backends)}, {"long", o.long_set}, {"only", o.only}, {"stress", o.stress},
            {"scenes_dir", o.scenes_dir.string()}, {"build", {{"version", b.version}, {"commit", b.commit}}}};
}

std::string checkTableText(const Json& doc) {
    std::string out;
    char line[512];
    std::vector<std::string> names;
    for (const Json& b : doc["backends"]) names.push_back(b["name"]);
    int width = 36;   // the check column: the longest id (stress ids are longer)
    for (const Json& c : doc["results"]["checks"]) width = std::max(width, static_cast<int>(c["id"].get<std::string>().size()));
    std::snprintf(line, sizeof line, "%-*s %-5s %12s %10s", width, "check", "req", "expected", "tolerance");
    out += line;
    for (const auto& n : names) { std::snprintf(line, sizeof line, " | %-8s %12s %-5s", n.c_str(), "measured", ""); out += line; }
    out += "\n";
    for (const Json& c : doc["results"]["checks"]) {
        char tolerance[32] = "-";
        if (!c["tolerance"].is_null()) std::snprintf(tolerance, sizeof tolerance, "%.3g", c["tolerance"].get<double>());
        std::snprintf(line, sizeof line, "%-*s %-5s %12.4g %10s", width, c["id"].get<std::string>().c_str(),
                      c["required_for_native"].get<bool>() ? "yes" : "no", c["expected"].get<double>(), tolerance);
        out += line;
        for (const auto& n : names) {
            const Json& r = c["results"][n];
            std::snprintf(line, sizeof line, " | %-8s %12s %-5s", "", cellText(r["measured"]).c_str(), cellResult(r).c_str());
            out += line;
        }
        out += "\n";
    }
    // Why a cell is "n/s" or "~": one line per backend and reason.
    std::map<std::string, std::set<std::string>> why;
    for (const Json& c : doc["results"]["checks"])
        for (const auto& n : names) {
            const std::string support = c["results"][n].value("support", std::string("exact"));
            if (support != "exact") why[n].insert(support);
        }
    for (const auto& [n, reasons] : why)
        for (const std::string& r : reasons) out += n + ": " + r + "\n";
    return out;
}

int checkExitCode(const Json& doc) { return doc["results"]["required_failures_native"].get<int>() > 0 ? 1 : 0; }

}  // namespace vroc::harness
