// SPDX-License-Identifier: MIT
#include "vroc/harness/sweep.h"

#include <algorithm>
#include <cmath>

#include "vroc/core/build_info.h"
#include "vroc/core/scene_loader.h"
#include "vroc/core/state_hash.h"
#include "vroc/harness/divergence.h"
#include "vroc/harness/pareto.h"
#include "vroc/harness/robustness.h"
#include "vroc/harness/mpi_world.h"
#include "vroc/harness/run_trace.h"
#include "vroc/harness/run_trace_json.h"
#include "vroc/harness/sweep_curves.h"
#include "vroc/harness/timing_stats.h"

namespace vroc::harness {
namespace {

struct WindowPlan {
    std::int64_t ref_per_coarse = 1;   ///< reference frames per largest step
    std::int64_t window_coarse = 1;    ///< window length in largest steps
    std::vector<std::int64_t> anchors; ///< anchor times in largest steps
};

WindowPlan planWindows(double dt_max, double ref_dt, double duration, double window, int k) {
    WindowPlan p;
    p.ref_per_coarse = std::max<std::int64_t>(1, std::llround(dt_max / ref_dt));
    p.window_coarse = std::max<std::int64_t>(1, std::llround(window / dt_max));
    const std::int64_t total = framesFor(duration, dt_max);
    const std::int64_t last = total - p.window_coarse;
    for (int i = 0; i < k && last >= 0; ++i) {
        const std::int64_t a = k == 1 ? 0 : last * i / (k - 1);
        if (p.anchors.empty() || p.anchors.back() != a) p.anchors.push_back(a);
    }
    return p;
}

// Mean over the windows of the largest body position error after one window, against the
// reference trace (recorded every largest step).
double windowError(const Scene& scene, const SelectedBackend& b, const RunTrace& ref, const WindowPlan& plan, double dt, double dt_max) {
    if (plan.anchors.empty()) return NAN;
    double sum = 0;
    for (std::int64_t a : plan.anchors) {
        RunOptions ro;
        ro.frame_dt = dt;
        ro.frames = std::max<std::int64_t>(1, std::llround(plan.window_coarse * dt_max / dt));
        ro.record_states = false;
        ro.initial_states = ref.states[static_cast<std::size_t>(a)];
        const RunTrace w = runBackend(*b.info, scene, b.settings, ro);
        if (!w.finite) return INFINITY;
        sum += maxPositionError(scene, w.states.back(), ref.states[static_cast<std::size_t>(a + plan.window_coarse)]);
    }
    return sum / static_cast<double>(plan.anchors.size());
}

std::string stepName(double dt) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "1/%.4g", 1.0 / dt);
    return buf;
}

// A number from a result (null = not finite).
double value(const Json& j) { return j.is_null() ? NAN : j.get<double>(); }

// One (curve, step) run of phase 2: the run, its robustness against the reference and, for a
// measured step, its cost, window error and closed-form error.
Json measureStep(const SweepScene& in, const SelectedBackend& b, const RunTrace& ref, const WindowPlan& plan, double dt,
                 double dt_max, double duration, bool measured) {
    const Scene& scene = in.scene;
    RunOptions mo;
    mo.frame_dt = dt;
    mo.frames = framesFor(duration, dt);
    const RunTrace run = runBackend(*b.info, scene, b.settings, mo);
    const RobustnessVerdict verdict = judgeRobustness(scene, run, ref);
    const std::string hash = hashToHex(stateHash(run.states.back()));
    if (!measured) return {{"dt_s", dt}, {"robust", verdict.ok}, {"failure", verdict.reason}, {"state_hash", hash}};
    const TimingSummary timing = summarizeTiming(run.step_wall_s, run.simulatedTime());
    const double err = windowError(scene, b, ref, plan, dt, dt_max);
    const double cf = in.closed_form && run.finite ? std::abs(in.closed_form->measure(scene, run) - in.closed_form->expected) : NAN;
    return {{"dt_s", dt}, {"cost_wall_per_sim_s", timing.wall_per_sim_s}, {"window_error_m", number(err)},
            {"closed_form_error", number(cf)}, {"robust", verdict.ok}, {"failure", verdict.reason},
            {"step_p50_us", timing.p50_us}, {"state_hash", hash}};
}

// One (curve, detail level) run of phase 2, at the largest step, against the full-detail reference.
Json measureDetail(const Scene& scene, const SelectedBackend& b, const RunTrace& ref, const WindowPlan& plan, double dt_max,
                   const SweepOptions& o, const DetailLevel& level) {
    const Scene simple = simplifyScene(scene, level);
    RunOptions mo;
    mo.frame_dt = dt_max;
    mo.frames = framesFor(o.duration, dt_max);
    const RunTrace run = runBackend(*b.info, simple, b.settings, mo);
    const TimingSummary timing = summarizeTiming(run.step_wall_s, run.simulatedTime());
    const double err = windowError(simple, b, ref, plan, dt_max, dt_max);
    return {{"level", level.name}, {"faces", virtualFaceCount(simple)}, {"cost_wall_per_sim_s", timing.wall_per_sim_s},
            {"window_error_m", number(err)}, {"meets_target", o.target && err <= *o.target},
            {"state_hash", hashToHex(stateHash(run.states.back()))}};
}

}  // namespace

std::vector<double> defaultSweepSteps() { return {1.0 / 60, 1.0 / 120, 1.0 / 240, 1.0 / 480, 1.0 / 960}; }

SweepScene loadSweepScene(const std::string& source) {
    if (source.rfind("check:", 0) == 0) {
        CheckScenario c = findCheckScenario(source.substr(6));
        return {c.build(), c.metrics.front(), source};
    }
    return {loadScene(source), std::nullopt, source};
}

Json sweepPlan(const SweepScene& in, const std::vector<SelectedBackend>& backends, const SweepOptions& o) {
    Json details = Json::array();
    for (const DetailLevel& d : o.details) details.push_back(d.name);
    const BuildInfo& b = buildInfo();
    return {{"command", "sweep"}, {"scene", in.source}, {"scene_sha256", in.scene.source_sha256}, {"backends", backendsJson(backends)},
            {"dts_s", o.dts}, {"reference_dt_s", o.reference_dt ? Json(*o.reference_dt) : Json(nullptr)}, {"duration_s", o.duration},
            {"windows", o.windows}, {"window_s", o.window}, {"vary", o.vary}, {"details", details},
            {"target_m", o.target ? Json(*o.target) : Json(nullptr)}, {"robustness_extra", o.robustness_extra},
            {"build", {{"version", b.version}, {"commit", b.commit}}}};
}

Json runSweep(const SweepScene& in, const std::vector<SelectedBackend>& requested, const SweepOptions& o, RunPool& pool) {
    const Scene& scene = in.scene;
    // A backend that cannot represent the scene is left out (and named); an approximated one runs.
    Json support;
    const std::vector<SelectedBackend> backends = representableBackends(scene, requested, "sweep", o.progress && mpi::isRoot(), support);
    std::vector<double> dts = o.dts.empty() ? defaultSweepSteps() : o.dts;
    std::sort(dts.begin(), dts.end(), std::greater<>());
    const double dt_max = dts.front();
    const double ref_dt = o.reference_dt.value_or(dts.back() / 8);
    const WindowPlan plan = planWindows(dt_max, ref_dt, o.duration, o.window, o.windows);
    std::vector<double> robust_dts = dts;
    for (int i = 1; i <= o.robustness_extra; ++i) robust_dts.insert(robust_dts.begin(), dt_max * std::pow(2.0, i));

    Json doc = newDocument("sweep", o.command_line);
    doc["title"] = "speed vs accuracy on '" + scene.name + "'";
    doc["scene"] = {{"name", scene.name}, {"source", in.source}, {"sha256", scene.source_sha256}, {"bodies", scene.bodies.size()}};
    doc["backends"] = backendsJson(backends);
    doc["support"] = support;
    doc["parameters"] = {{"dts_s", dts}, {"reference_dt_s", ref_dt}, {"duration_s", o.duration}, {"windows", plan.anchors.size()},
                         {"window_s", plan.window_coarse * dt_max}, {"robustness_dts_s", robust_dts},
                         {"closed_form", in.closed_form ? Json(in.closed_form->id + ": " + in.closed_form->closed_form) : Json(nullptr)},
                         {"target_m", o.target ? Json(*o.target) : Json(nullptr)}, {"vary", o.vary}};
    const std::vector<SweepCurve> curves = sweepCurves(backends, o.vary);

    // One tiny-step reference run per backend (its base settings), recorded every largest step;
    // then every (curve, step) and (curve, detail level) run, each after its backend's reference.
    std::vector<PoolJob> jobs;
    for (std::size_t bi = 0; bi < backends.size(); ++bi)
        jobs.push_back({poolJobId("ref-" + backends[bi].info->name), [&, bi] {
            RunOptions ro;
            ro.frame_dt = ref_dt;
            ro.frames = framesFor(o.duration, dt_max) * plan.ref_per_coarse;
            ro.record_every = plan.ref_per_coarse;
            return runTraceJson(runBackend(*backends[bi].info, scene, backends[bi].settings, ro));
        }, static_cast<double>(framesFor(o.duration, dt_max) * plan.ref_per_coarse)});
    std::vector<RunTrace> refs(backends.size());   // filled as each reference finishes (DependencyHook)
    std::vector<std::vector<std::size_t>> step_job(curves.size()), detail_job(curves.size());
    for (std::size_t ci = 0; ci < curves.size(); ++ci) {
        const std::vector<std::size_t> after = {curves[ci].backend};
        for (double dt : robust_dts) {
            const bool measured = std::find(dts.begin(), dts.end(), dt) != dts.end();
            step_job[ci].push_back(jobs.size());
            jobs.push_back({poolJobId("step-" + curves[ci].label + "-dt" + stepName(dt)), [&, ci, dt, measured] {
                return measureStep(in, curves[ci].run, refs[curves[ci].backend], plan, dt, dt_max, o.duration, measured);
            }, static_cast<double>(framesFor(o.duration, dt)) * (measured ? 2 : 1), after});   // the windows cover about one more run
        }
        for (const DetailLevel& level : o.details) {
            detail_job[ci].push_back(jobs.size());
            jobs.push_back({poolJobId("detail-" + curves[ci].label + "-" + level.name), [&, ci, &level = level] {
                return measureDetail(scene, curves[ci].run, refs[curves[ci].backend], plan, dt_max, o, level);
            }, 2.0 * static_cast<double>(framesFor(o.duration, dt_max)), after});
        }
    }
    const std::vector<Json> measured = pool.run(jobs, [&refs](std::size_t i, const Json& r) { refs[i] = runTraceFromJson(r); });

    std::vector<CostError> points;
    std::vector<std::pair<std::size_t, double>> point_owner;   // (curve, dt)
    Json results = Json::object();
    std::vector<std::vector<Json>> rows, robust_rows, detail_rows;
    ChartSpec speed{"speed-accuracy", "Speed vs accuracy (self-consistency, re-anchored windows); Pareto front dashed",
                    "cost [s wall per s simulated]", "mean window error [m]", true, true, {}};
    ChartSpec conv{"convergence", "Error vs frame step", "frame step [s]", "mean window error [m]", true, true, {}};
    ChartSpec closed{"closed-form", "Closed-form error vs cost", "cost [s wall per s simulated]", "|measured - closed form|", true, true, {}};
    ChartSpec detail{"detail", "Model detail: error vs cost at the scene's step", "cost [s wall per s simulated]", "mean window error [m]", true, true, {}};
    for (std::size_t ci = 0; ci < curves.size(); ++ci) {
        const SelectedBackend& b = curves[ci].run;
        const std::string& name = curves[ci].label;
        Json steps = Json::array();
        ChartSeries s_speed{name, "linespoints", {}, {}}, s_conv{name, "linespoints", {}, {}}, s_closed{name, "linespoints", {}, {}};
        for (std::size_t k = 0; k < robust_dts.size(); ++k) {
            const Json& step = measured[step_job[ci][k]];
            steps.push_back(step);
            if (!step.contains("cost_wall_per_sim_s")) continue;   // robustness only
            const double cost = step["cost_wall_per_sim_s"], err = value(step["window_error_m"]), cf = value(step["closed_form_error"]);
            points.push_back({cost, err});
            point_owner.emplace_back(ci, robust_dts[k]);
            s_speed.x.push_back(cost); s_speed.y.push_back(err);
            s_conv.x.push_back(robust_dts[k]); s_conv.y.push_back(err);
            s_closed.x.push_back(cost); s_closed.y.push_back(cf);
        }
        // The limit is the largest step from which every smaller step also passes.
        std::optional<double> robust_limit;
        for (auto it = robust_dts.rbegin(); it != robust_dts.rend(); ++it) {
            const Json* entry = nullptr;
            for (const Json& s : steps) if (s["dt_s"].get<double>() == *it) entry = &s;
            if (!entry || !(*entry)["robust"].get<bool>()) break;
            robust_limit = *it;
        }
        const auto order = convergenceOrder(s_conv.x, s_conv.y);
        results[name] = {{"backend", b.info->name}, {"setting", curves[ci].setting.empty() ? Json(nullptr) : Json(curves[ci].setting)},
                         {"steps", steps}, {"convergence_order", order ? Json(*order) : Json(nullptr)},
                         {"robustness_limit_dt_s", robust_limit ? Json(*robust_limit) : Json(nullptr)}};
        robust_rows.push_back({name, robust_limit ? Json(*robust_limit) : Json(nullptr),
                               robust_limit ? Json(stepName(*robust_limit)) : Json("none"), order ? Json(*order) : Json(nullptr)});
        speed.series.push_back(s_speed);
        conv.series.push_back(s_conv);
        if (in.closed_form) closed.series.push_back(s_closed);

        // Model detail at the scene's own frame step, against the full-detail reference.
        if (!o.details.empty()) {
            Json levels = Json::array();
            ChartSeries s_detail{name, "linespoints", {}, {}};
            std::optional<std::pair<double, std::string>> cheapest;
            for (std::size_t k = 0; k < o.details.size(); ++k) {
                const Json& level = measured[detail_job[ci][k]];
                const double cost = level["cost_wall_per_sim_s"], err = value(level["window_error_m"]);
                const bool meets = level["meets_target"];
                if (meets && (!cheapest || cost < cheapest->first)) cheapest = {{cost, o.details[k].name}};
                levels.push_back(level);
                detail_rows.push_back({name, o.details[k].name, level["faces"], cost, level["window_error_m"],
                                       o.target ? Json(meets ? "pass" : "FAIL") : Json(nullptr)});
                s_detail.x.push_back(cost);
                s_detail.y.push_back(err);
            }
            results[name]["detail"] = {{"frame_dt_s", dt_max}, {"levels", levels},
                                       {"cheapest_meeting_target", cheapest ? Json(cheapest->second) : Json(nullptr)}};
            detail.series.push_back(s_detail);
        }
    }
    // Pareto front over every (curve, step) point.
    const auto front = paretoFront(points);
    ChartSeries s_front{"Pareto front", "linespoints", {}, {}};
    Json front_json = Json::array();
    for (std::size_t i : front) {
        s_front.x.push_back(points[i].cost);
        s_front.y.push_back(points[i].error);
        const SweepCurve& c = curves[point_owner[i].first];
        front_json.push_back({{"series", c.label}, {"backend", c.run.info->name}, {"dt_s", point_owner[i].second},
                              {"cost_wall_per_sim_s", points[i].cost}, {"window_error_m", points[i].error}});
    }
    speed.series.push_back(s_front);
    results["pareto_front"] = front_json;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const bool on = std::find(front.begin(), front.end(), i) != front.end();
        const Json& step = [&]() -> const Json& {
            for (const Json& s : results[curves[point_owner[i].first].label]["steps"])
                if (s["dt_s"].get<double>() == point_owner[i].second) return s;
            return results;   // unreachable: every point has its step entry
        }();
        rows.push_back({curves[point_owner[i].first].label, stepName(point_owner[i].second), point_owner[i].second,
                        step["cost_wall_per_sim_s"], step["window_error_m"], step["closed_form_error"],
                        step["robust"].get<bool>() ? "pass" : "FAIL", on});
    }
    doc["results"] = results;
    doc["tables"].push_back(tableJson("sweep", "Speed and accuracy per backend and frame step",
        {"backend", "step", "dt [s]", "cost [s/s]", "window error [m]", "closed-form error", "robust", "on Pareto front"}, rows));
    doc["tables"].push_back(tableJson("robustness", "Robustness limit (largest step that completes without NaN, tunnelling, blow-up or collapse)",
        {"backend", "limit dt [s]", "limit", "convergence order p [-]"}, robust_rows));
    if (!detail_rows.empty())
        doc["tables"].push_back(tableJson("detail", "Model detail (window error against the full-detail tiny-step reference)",
            {"backend", "level", "faces", "cost [s/s]", "window error [m]", "meets target"}, detail_rows));
    doc["charts"].push_back(chartJson(speed));
    doc["charts"].push_back(chartJson(conv));
    if (in.closed_form) doc["charts"].push_back(chartJson(closed));
    if (!o.details.empty()) doc["charts"].push_back(chartJson(detail));
    doc["execution"] = pool.executionJson();
    return doc;
}

}  // namespace vroc::harness
