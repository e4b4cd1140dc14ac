// SPDX-License-Identifier: MIT
#include "vroc/harness/commands/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "compare_runs.h"
#include "vroc/core/build_info.h"
#include "vroc/core/errors.h"
#include "vroc/core/recording/atomic_output.h"
#include "vroc/core/state_hash.h"
#include "vroc/harness/documents/series_tools.h"
#include "vroc/harness/metrics/divergence.h"
#include "vroc/harness/metrics/event_timing.h"
#include "vroc/harness/metrics/penetration.h"
#include "vroc/harness/pool/mpi_world.h"
#include "vroc/harness/runs/run_trace_json.h"
#include "vroc/harness/statistics/consensus.h"
#include "vroc/harness/statistics/timing_stats.h"

namespace vroc::harness {
namespace {

constexpr int kBouncesReported = 3;
constexpr int kHistogramBins = 30;

BackendRuns runAll(const Scene& scene, const SelectedBackend& b, const CompareOptions& o, double dt,
                   std::int64_t frames) {
    BackendRuns r;
    RunOptions ro;
    ro.frame_dt = dt;
    ro.frames = frames;
    r.main = runBackend(*b.info, scene, b.settings, ro);
    {
        const RunTrace again = runBackend(*b.info, scene, b.settings, ro);
        r.state_hash = hashToHex(stateHash(r.main.states.back()));
        r.deterministic = r.state_hash == hashToHex(stateHash(again.states.back()));
    }
    ro.initial_states = perturbedStates(scene, o.twin_epsilon);
    r.twin = runBackend(*b.info, scene, b.settings, ro);
    r.penetration.reserve(r.main.states.size());
    for (const auto& s : r.main.states) r.penetration.push_back(maxPenetration(scene, s));
    return r;
}

void runWindows(const Scene& scene, const SelectedBackend& b, const RunTrace& reference,
                const std::vector<std::size_t>& anchors, std::int64_t window_frames, double dt, BackendRuns& r) {
    for (std::size_t f : anchors) {
        RunOptions ro;
        ro.frame_dt = dt;
        ro.frames = window_frames;
        ro.record_states = false;
        ro.initial_states = reference.states[f];
        r.window_ends.push_back(runBackend(*b.info, scene, b.settings, ro).states.back());
    }
}

InvariantDrift invariantDrift(const RunTrace& t, const Scene& scene) {
    const Invariants& i0 = t.invariants.front();
    InvariantDrift d;
    double mass = 0;
    for (const Body& b : scene.bodies)
        if (b.isDynamic()) mass += b.mass_properties.mass;
    for (std::size_t f = 0; f < t.invariants.size(); ++f) {
        const Invariants& i = t.invariants[f];
        d.energy_max_abs_change = std::max(d.energy_max_abs_change, std::abs(i.energy() - i0.energy()));
        d.angular_momentum_max_change = std::max(d.angular_momentum_max_change, (i.angular_momentum - i0.angular_momentum).norm());
        const Vec3 expected = i0.linear_momentum + mass * scene.gravity * (t.times[f] - t.times.front());
        d.linear_momentum_max_change_beyond_gravity = std::max(d.linear_momentum_max_change_beyond_gravity, (i.linear_momentum - expected).norm());
    }
    d.energy_initial = i0.energy();
    d.energy_max_rel_change = std::abs(i0.energy()) > 0 ? d.energy_max_abs_change / std::abs(i0.energy()) : NAN;
    return d;
}

EventSummary eventSummary(const RunTrace& t, const Scene& scene) {
    EventSummary e;
    if (!t.events.empty()) e.first_contact = t.events.front().time;
    e.event_count = t.events.size();
    e.rest_time = restTime(scene, t);
    for (int b : virtualBodyIndices(scene)) {
        const auto impacts = impactTimes(t.events, b, 2.5 * t.frame_dt);
        BodyImpacts bi{scene.bodies[static_cast<std::size_t>(b)].name, {}, impacts.size()};
        for (std::size_t k = 0; k < impacts.size() && k < static_cast<std::size_t>(kBouncesReported + 1); ++k) bi.times.push_back(impacts[k]);
        e.per_body.push_back(std::move(bi));
    }
    return e;
}

double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? NAN : s / static_cast<double>(v.size());
}

CompareBackendSummary summarize(const CompareResult& c, const BackendRuns& r, const CompareOptions& o) {
    const Scene& scene = c.scene;
    const RunTrace& ref = c.runs[0].main;
    CompareBackendSummary s;
    s.validity = runValidity(r.main);
    if (const RunValidity twin = runValidity(r.twin); s.validity.valid && !twin.valid)
        s.validity = {false, twin.reason + " (in the twin run)"};
    s.timing = summarizeTiming(r.main.step_wall_s, r.main.simulatedTime());
    std::vector<double> us;
    for (double w : r.main.step_wall_s) us.push_back(w * 1e6);
    s.step_times_us = histogram(us, kHistogramBins);
    double pen_sum = 0;
    for (double p : r.penetration) { s.penetration_max = std::max(s.penetration_max, p); pen_sum += p; }
    s.penetration_mean = r.penetration.empty() ? 0.0 : pen_sum / static_cast<double>(r.penetration.size());
    s.invariants = invariantDrift(r.main, scene);
    s.events = eventSummary(r.main, scene);
    s.twin_spread = divergence(scene, r.main, r.twin);
    s.horizon = horizon(s.twin_spread.t, s.twin_spread.distance, o.horizon_delta);
    s.ftle = ftle(s.twin_spread.t, s.twin_spread.distance, 10 * o.twin_epsilon, o.horizon_delta);
    for (std::size_t k = 0; k < c.anchors.size(); ++k) {
        const auto& truth = ref.states[c.anchors[k] + static_cast<std::size_t>(c.window_frames)];
        s.window_position_error.push_back(maxPositionError(scene, r.window_ends[k], truth));
        s.window_angle_error.push_back(maxAngleError(scene, r.window_ends[k], truth));
    }
    s.mean_window_position_error = mean(s.window_position_error);
    s.mean_window_angle_error = mean(s.window_angle_error);
    return s;
}

// The consensus rows: per observable, which backends agree within their own twin noise floors
// (plus the observable's stated resolution) and which one is the odd one out.
std::vector<ConsensusRow> consensusRows(const CompareResult& c) {
    const Scene& scene = c.scene;
    const std::size_t n = c.backends.size();
    double weight = 0;   // sum of m |g|: the energy of lifting every body by 1 m
    for (const Body& b : scene.bodies)
        if (b.isDynamic()) weight += b.mass_properties.mass * scene.gravity.norm();
    auto firstContact = [](const RunTrace& t) { return t.events.empty() ? NAN : t.events.front().time; };
    auto finalEnergy = [](const RunTrace& t) { return t.invariants.back().energy(); };
    std::vector<ConsensusInput> inputs(3);
    ConsensusInput& contact = inputs[0];
    contact.observable = "first contact [s]";
    contact.floor = c.frame_dt;
    contact.floor_reason = "one frame: events are reported per frame";
    ConsensusInput& rest = inputs[1];
    rest.observable = "final positions [m]";
    rest.floor = scene.collision_distance;
    rest.floor_reason = "the collision distance: where a body rests within the contact window";
    ConsensusInput& energy = inputs[2];
    energy.observable = "final energy [J]";
    energy.floor = weight * scene.collision_distance;
    energy.floor_reason = "sum m|g| x collision distance: the energy of resting one contact window higher";
    for (ConsensusInput& in : inputs) {
        for (const SelectedBackend& b : c.backends) in.backends.push_back(b.label());
        in.present.assign(n, true);
        in.absent_reason.assign(n, "");
        in.noise.assign(n, 0.0);
    }
    std::vector<double> t0(n), e(n);
    for (std::size_t i = 0; i < n; ++i) {
        const BackendRuns& r = c.runs[i];
        t0[i] = firstContact(r.main);
        contact.present[i] = std::isfinite(t0[i]);
        if (!contact.present[i]) contact.absent_reason[i] = "no contact event";
        const double twin_t0 = firstContact(r.twin);
        contact.noise[i] = std::isfinite(twin_t0) && contact.present[i] ? std::abs(t0[i] - twin_t0) : 0.0;
        rest.noise[i] = c.summaries[i].twin_spread.distance.back();
        e[i] = finalEnergy(r.main);
        energy.noise[i] = std::abs(e[i] - finalEnergy(r.twin));
    }
    contact.difference = [&](std::size_t a, std::size_t b) { return std::abs(t0[a] - t0[b]); };
    rest.difference = [&](std::size_t a, std::size_t b) {
        return maxPositionError(scene, c.runs[a].main.states.back(), c.runs[b].main.states.back());
    };
    energy.difference = [&](std::size_t a, std::size_t b) { return std::abs(e[a] - e[b]); };
    for (std::size_t i = 0; i < n; ++i) {  // a run that is not the engine's physics never votes
        if (c.summaries[i].validity.valid) continue;
        for (ConsensusInput& in : inputs) {
            in.present[i] = false;
            in.absent_reason[i] = invalidLabel(c.summaries[i].validity);
        }
    }
    std::vector<ConsensusRow> rows;
    for (const ConsensusInput& in : inputs) {
        const std::vector<double> values = &in == &contact ? t0 : &in == &energy ? e : std::vector<double>{};
        rows.push_back({in.observable, in.floor, in.floor_reason, values, in.noise, consensus(in)});
    }
    return rows;
}

// A finished main-run job as it travels through the pool (it may run in another process).
Json mainRunJson(const BackendRuns& r) {
    Json pen = Json::array();
    for (double p : r.penetration) pen.push_back(number(p));
    return {{"main", runTraceJson(r.main)}, {"twin", runTraceJson(r.twin)}, {"penetration", pen},
            {"state_hash", r.state_hash}, {"deterministic", r.deterministic}};
}

void mainRunFromJson(const Json& j, BackendRuns& r) {
    r.main = runTraceFromJson(j.at("main"));
    r.twin = runTraceFromJson(j.at("twin"));
    for (const Json& p : j.at("penetration")) r.penetration.push_back(p.is_null() ? NAN : p.get<double>());
    r.state_hash = j.at("state_hash").get<std::string>();
    r.deterministic = j.at("deterministic").get<bool>();
}

}  // namespace

CompareResult compareScene(const Scene& scene, const std::vector<SelectedBackend>& requested, const CompareOptions& o,
                           const std::filesystem::path& csv_dir) {
    RunPool pool = RunPool::inProcess();
    return compareScene(scene, requested, o, csv_dir, pool);
}

Json comparePlan(const Scene& scene, const std::vector<SelectedBackend>& backends, const CompareOptions& o) {
    const BuildInfo& b = buildInfo();
    return {{"command", "compare"}, {"scene", scene.source_path}, {"scene_sha256", scene.source_sha256}, {"backends", backendsJson(backends)},
            {"frame_dt_s", o.frame_dt ? Json(*o.frame_dt) : Json(nullptr)}, {"duration_s", o.duration}, {"windows", o.windows},
            {"window_s", o.window}, {"twin_epsilon_m", o.twin_epsilon}, {"build", {{"version", b.version}, {"commit", b.commit}}}};
}

CompareResult compareScene(const Scene& scene, const std::vector<SelectedBackend>& requested, const CompareOptions& o,
                           const std::filesystem::path& csv_dir, RunPool& pool) {
    CompareResult c;
    c.scene = scene;
    // A backend that cannot represent the scene is left out (and named); an approximated one runs.
    c.backends = representableBackends(scene, requested, "compare", o.progress, c.support);
    const std::vector<SelectedBackend>& backends = c.backends;
    c.frame_dt = o.frame_dt.value_or(scene.frame_dt);
    c.duration = o.duration;
    c.frames = frameCount(o.duration, c.frame_dt);
    c.window_frames = std::max<std::int64_t>(1, frameCount(o.window, c.frame_dt));
    c.twin_epsilon = o.twin_epsilon;
    c.horizon_delta = o.horizon_delta;
    const std::size_t n = backends.size();
    // Per backend: main run, determinism rerun and twin run; then its re-anchored windows, which
    // restart from the reference backend's (the first's) main run, so they wait for that run.
    std::vector<PoolJob> jobs;
    for (std::size_t i = 0; i < n; ++i)
        jobs.push_back({poolJobId("main-" + backends[i].key()),
                        [&, i] { return mainRunJson(runAll(scene, backends[i], o, c.frame_dt, c.frames)); },
                        3.0 * static_cast<double>(c.frames)});
    RunTrace ref;             // the reference backend's main run, once it is done (DependencyHook)
    std::vector<std::size_t> anchors;
    for (std::size_t i = 0; i < n; ++i)
        jobs.push_back({poolJobId("windows-" + backends[i].key()),
                        [&, i] {
                            BackendRuns r;
                            runWindows(scene, backends[i], ref, anchors, c.window_frames, c.frame_dt, r);
                            Json ends = Json::array();
                            for (const auto& e : r.window_ends) ends.push_back(statesJson(e));
                            return Json{{"window_ends", ends}};
                        },
                        static_cast<double>(o.windows * c.window_frames),
                        {0}});
    const std::vector<Json> done = pool.run(jobs, [&](std::size_t, const Json& r) {
        ref = runTraceFromJson(r["main"]);
        anchors = anchorFrames(ref.states.size(), o.windows, c.window_frames);
    });
    c.runs.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        mainRunFromJson(done[i], c.runs[i]);
        for (const Json& e : done[n + i].at("window_ends")) c.runs[i].window_ends.push_back(statesFromJson(e));
        if (o.write_csv && !csv_dir.empty() && mpi::isRoot())
            writeTraceCsv(scene, c.runs[i].main, csv_dir / backends[i].key());
    }
    c.anchors = anchorFrames(c.runs[0].main.states.size(), o.windows, c.window_frames);   // on every rank, whichever ran what
    for (std::size_t i = 0; i < n; ++i) c.summaries.push_back(summarize(c, c.runs[i], o));
    // Cross-backend divergence, counted only above both noise floors.
    for (std::size_t i = 1; i < n; ++i) {
        ComparePair p{i, divergence(scene, c.runs[0].main, c.runs[i].main), {}};
        p.significance = significantDivergence(p.divergence.distance, c.summaries[0].twin_spread.distance,
                                               c.summaries[i].twin_spread.distance, p.divergence.t);
        c.pairs.push_back(std::move(p));
    }
    c.consensus = consensusRows(c);
    c.execution = pool.execution();
    return c;
}

}  // namespace vroc::harness
