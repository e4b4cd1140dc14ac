// SPDX-License-Identifier: MIT
#include "vroc/harness/commands/sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "vroc/core/build_info.h"
#include "vroc/core/scene_loader.h"
#include "vroc/core/state_hash.h"
#include "vroc/harness/commands/sweep_curves.h"
#include "vroc/harness/documents/sweep_document.h"
#include "vroc/harness/metrics/divergence.h"
#include "vroc/harness/metrics/robustness.h"
#include "vroc/harness/pool/mpi_world.h"
#include "vroc/harness/runs/run_trace.h"
#include "vroc/harness/runs/run_trace_json.h"
#include "vroc/harness/runs/run_validity.h"
#include "vroc/harness/statistics/pareto.h"
#include "vroc/harness/statistics/timing_stats.h"

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
    const std::int64_t total = frameCount(duration, dt_max);
    const std::int64_t last = total - p.window_coarse;
    for (int i = 0; i < k && last >= 0; ++i) {
        const std::int64_t a = k == 1 ? 0 : last * i / (k - 1);
        if (p.anchors.empty() || p.anchors.back() != a) p.anchors.push_back(a);
    }
    return p;
}

// Mean over the windows of the largest body position error after one window, against the
// reference trace (recorded every largest step).
// A window run that is not valid names itself in `not_valid` (when given and still empty).
double windowError(const Scene& scene, const SelectedBackend& b, const RunTrace& ref, const WindowPlan& plan, double dt,
                   double dt_max, std::string* not_valid = nullptr) {
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
        if (const RunValidity v = runValidity(w); !v.valid && not_valid && not_valid->empty())
            *not_valid = v.reason + " (in a window run)";
        sum += maxPositionError(scene, w.states.back(), ref.states[static_cast<std::size_t>(a + plan.window_coarse)]);
    }
    return sum / static_cast<double>(plan.anchors.size());
}

// A number from a run's JSON (null = not finite).
double value(const Json& j) { return j.is_null() ? NAN : j.get<double>(); }

// A step or detail run as it travels through the pool (it may run in another process), in the
// document's form (sweep_document.h).
SweepStep stepFromJson(const Json& j) {
    SweepStep s;
    s.dt = j.at("dt_s").get<double>();
    s.robust = j.at("robust").get<bool>();
    s.failure = j.at("failure").get<std::string>();
    s.state_hash = j.at("state_hash").get<std::string>();
    if (j.contains("not_valid")) s.not_valid = j.at("not_valid").get<std::string>();
    s.measured = j.contains("cost_wall_per_sim_s");
    if (!s.measured) return s;
    s.cost = value(j.at("cost_wall_per_sim_s"));
    s.window_error = value(j.at("window_error_m"));
    s.closed_form_error = value(j.at("closed_form_error"));
    s.step_p50_us = value(j.at("step_p50_us"));
    return s;
}

SweepDetail detailFromJson(const Json& j) {
    return {j.at("level").get<std::string>(), j.at("faces").get<int>(), value(j.at("cost_wall_per_sim_s")),
            value(j.at("window_error_m")), j.at("meets_target").get<bool>(), j.at("state_hash").get<std::string>()};
}

// One (curve, step) run of phase 2: the run, its robustness against the reference and, for a
// measured step, its cost, window error and closed-form error.
SweepStep measureStep(const SweepScene& in, const SelectedBackend& b, const RunTrace& ref, const WindowPlan& plan, double dt,
                      double dt_max, double duration, bool measured) {
    const Scene& scene = in.scene;
    RunOptions mo;
    mo.frame_dt = dt;
    mo.frames = frameCount(duration, dt);
    const RunTrace run = runBackend(*b.info, scene, b.settings, mo);
    const RobustnessVerdict verdict = judgeRobustness(scene, run, ref);
    SweepStep s;
    s.dt = dt;
    s.measured = measured;
    s.robust = verdict.ok;
    s.failure = verdict.reason;
    s.state_hash = hashToHex(stateHash(run.states.back()));
    if (run.finite) s.not_valid = runValidity(run).reason;
    if (!measured) return s;
    const TimingSummary timing = summarizeTiming(run.step_wall_s, run.simulatedTime());
    s.cost = timing.wall_per_sim_s;
    s.step_p50_us = timing.p50_us;
    s.window_error = windowError(scene, b, ref, plan, dt, dt_max, &s.not_valid);
    if (in.closed_form && run.finite) s.closed_form_error = std::abs(in.closed_form->measure(scene, run) - in.closed_form->expected);
    return s;
}

// One (curve, detail level) run of phase 2, at the largest step, against the full-detail reference.
SweepDetail measureDetail(const Scene& scene, const SelectedBackend& b, const RunTrace& ref, const WindowPlan& plan, double dt_max,
                          const SweepOptions& o, const DetailLevel& level) {
    const Scene simple = simplifyScene(scene, level);
    RunOptions mo;
    mo.frame_dt = dt_max;
    mo.frames = frameCount(o.duration, dt_max);
    const RunTrace run = runBackend(*b.info, simple, b.settings, mo);
    const TimingSummary timing = summarizeTiming(run.step_wall_s, run.simulatedTime());
    const double err = windowError(simple, b, ref, plan, dt_max, dt_max);
    return {level.name, virtualFaceCount(simple), timing.wall_per_sim_s, err, o.target && err <= *o.target,
            hashToHex(stateHash(run.states.back()))};
}

// The robustness limit: the largest step from which every smaller step also passes.
std::optional<double> robustnessLimit(const std::vector<SweepStep>& steps) {
    std::optional<double> limit;
    for (auto it = steps.rbegin(); it != steps.rend() && it->robust; ++it) limit = it->dt;
    return limit;
}

// Convergence order, Pareto front and cheapest detail level, from the runs alone.
void summarize(SweepResult& r) {
    std::vector<CostError> costs;
    for (std::size_t ci = 0; ci < r.curves.size(); ++ci) {
        SweepCurveResult& c = r.curves[ci];
        std::vector<double> dts, errors;
        for (std::size_t k = 0; k < c.steps.size(); ++k) {
            if (!c.steps[k].measured) continue;
            r.points.push_back({ci, k, false});
            const bool valid = c.steps[k].not_valid.empty();  // a point that is not valid is never on the front
            costs.push_back({valid ? c.steps[k].cost : NAN, c.steps[k].window_error});
            dts.push_back(c.steps[k].dt);
            errors.push_back(c.steps[k].window_error);
        }
        c.convergence_order = convergenceOrder(dts, errors);
        c.robustness_limit_dt = robustnessLimit(c.steps);
        std::optional<double> cheapest;
        for (const SweepDetail& d : c.details)
            if (d.meets_target && (!cheapest || d.cost < *cheapest)) {
                cheapest = d.cost;
                c.cheapest_meeting_target = d.level;
            }
    }
    for (std::size_t i : paretoFront(costs)) r.points[i].on_pareto_front = true;
}

}  // namespace

std::string frameStepName(double dt) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "1/%.4g", 1.0 / dt);
    return buf;
}

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

SweepResult runSweep(const SweepScene& in, const std::vector<SelectedBackend>& requested, const SweepOptions& o, RunPool& pool) {
    SweepResult r;
    r.source = in.source;
    r.scene = in.scene;
    r.closed_form = in.closed_form;
    r.target = o.target;
    r.vary = o.vary;
    r.duration = o.duration;
    r.detail_sweep = !o.details.empty();
    const Scene& scene = in.scene;
    // A backend that cannot represent the scene is left out (and named); an approximated one runs.
    r.backends = representableBackends(scene, requested, "sweep", o.progress && mpi::isRoot(), r.support);
    const std::vector<SelectedBackend>& backends = r.backends;
    r.dts = o.dts.empty() ? defaultSweepSteps() : o.dts;
    std::sort(r.dts.begin(), r.dts.end(), std::greater<>());
    const double dt_max = r.dts.front();
    r.reference_dt = o.reference_dt.value_or(r.dts.back() / 8);
    const WindowPlan plan = planWindows(dt_max, r.reference_dt, o.duration, o.window, o.windows);
    r.windows = plan.anchors.size();
    r.window = plan.window_coarse * dt_max;
    r.robustness_dts = r.dts;
    for (int i = 1; i <= o.robustness_extra; ++i) r.robustness_dts.insert(r.robustness_dts.begin(), dt_max * std::pow(2.0, i));
    const std::vector<SweepCurve> curves = sweepCurves(backends, o.vary);

    // One tiny-step reference run per backend (its base settings), recorded every largest step;
    // then every (curve, step) and (curve, detail level) run, each after its backend's reference.
    std::vector<PoolJob> jobs;
    for (std::size_t bi = 0; bi < backends.size(); ++bi)
        jobs.push_back({poolJobId("ref-" + backends[bi].info->name), [&, bi] {
            RunOptions ro;
            ro.frame_dt = r.reference_dt;
            ro.frames = frameCount(o.duration, dt_max) * plan.ref_per_coarse;
            ro.record_every = plan.ref_per_coarse;
            return runTraceJson(runBackend(*backends[bi].info, scene, backends[bi].settings, ro));
        }, static_cast<double>(frameCount(o.duration, dt_max) * plan.ref_per_coarse)});
    std::vector<RunTrace> refs(backends.size());   // filled as each reference finishes (DependencyHook)
    std::vector<std::vector<std::size_t>> step_job(curves.size()), detail_job(curves.size());
    for (std::size_t ci = 0; ci < curves.size(); ++ci) {
        const std::vector<std::size_t> after = {curves[ci].backend};
        for (double dt : r.robustness_dts) {
            const bool measured = std::find(r.dts.begin(), r.dts.end(), dt) != r.dts.end();
            step_job[ci].push_back(jobs.size());
            jobs.push_back({poolJobId("step-" + curves[ci].label + "-dt" + frameStepName(dt)), [&, ci, dt, measured] {
                return sweepStepJson(measureStep(in, curves[ci].run, refs[curves[ci].backend], plan, dt, dt_max, o.duration, measured));
            }, static_cast<double>(frameCount(o.duration, dt)) * (measured ? 2 : 1), after});   // the windows cover about one more run
        }
        for (const DetailLevel& level : o.details) {
            detail_job[ci].push_back(jobs.size());
            jobs.push_back({poolJobId("detail-" + curves[ci].label + "-" + level.name), [&, ci, &level = level] {
                return sweepDetailJson(measureDetail(scene, curves[ci].run, refs[curves[ci].backend], plan, dt_max, o, level));
            }, 2.0 * static_cast<double>(frameCount(o.duration, dt_max)), after});
        }
    }
    const std::vector<Json> done = pool.run(jobs, [&refs](std::size_t i, const Json& j) { refs[i] = runTraceFromJson(j); });
    for (std::size_t ci = 0; ci < curves.size(); ++ci) {
        SweepCurveResult c{curves[ci], {}, {}, {}, {}, {}};
        for (std::size_t j : step_job[ci]) c.steps.push_back(stepFromJson(done[j]));
        for (std::size_t j : detail_job[ci]) c.details.push_back(detailFromJson(done[j]));
        r.curves.push_back(std::move(c));
    }
    summarize(r);
    r.execution = pool.execution();
    return r;
}

}  // namespace vroc::harness
