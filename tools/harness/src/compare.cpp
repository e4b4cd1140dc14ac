// SPDX-License-Identifier: MIT
#include "vroc/harness/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "compare_runs.h"
#include "vroc/core/build_info.h"
#include "vroc/core/errors.h"
#include "vroc/core/state_hash.h"
#include "vroc/core/recording/atomic_output.h"
#include "vroc/harness/consensus.h"
#include "vroc/harness/divergence.h"
#include "vroc/harness/event_timing.h"
#include "vroc/harness/html_report.h"
#include "vroc/harness/mpi_world.h"
#include "vroc/harness/run_trace_json.h"
#include "vroc/harness/penetration.h"
#include "vroc/harness/series_tools.h"
#include "vroc/harness/timing_stats.h"

namespace vroc::harness {
namespace {

constexpr std::size_t kMaxChartPoints = 800;
constexpr int kBouncesReported = 3;

Json optionalNumber(const std::optional<double>& v) { return v ? number(*v) : Json(nullptr); }

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

Json invariantsJson(const RunTrace& t, const Scene& scene) {
    const Invariants& i0 = t.invariants.front();
    double de = 0, dl = 0, dp = 0, mass = 0;
    for (const Body& b : scene.bodies)
        if (b.isDynamic()) mass += b.mass_properties.mass;
    for (std::size_t f = 0; f < t.invariants.size(); ++f) {
        const Invariants& i = t.invariants[f];
        de = std::max(de, std::abs(i.energy() - i0.energy()));
        dl = std::max(dl, (i.angular_momentum - i0.angular_momentum).norm());
        const Vec3 expected = i0.linear_momentum + mass * scene.gravity * (t.times[f] - t.times.front());
        dp = std::max(dp, (i.linear_momentum - expected).norm());
    }
    return {{"energy_initial_J", number(i0.energy())},
            {"energy_max_abs_change_J", number(de)},
            {"energy_max_rel_change", number(std::abs(i0.energy()) > 0 ? de / std::abs(i0.energy()) : NAN)},
            {"angular_momentum_max_change", number(dl)},
            {"linear_momentum_max_change_beyond_gravity", number(dp)}};
}

Json eventsJson(const RunTrace& t, const Scene& scene) {
    Json per_body = Json::object();
    for (int b : virtualBodyIndices(scene)) {
        const auto impacts = impactTimes(t.events, b, 2.5 * t.frame_dt);
        Json list = Json::array();
        for (std::size_t k = 0; k < impacts.size() && k < static_cast<std::size_t>(kBouncesReported + 1); ++k)
            list.push_back(impacts[k]);
        per_body[scene.bodies[static_cast<std::size_t>(b)].name] = {{"impact_times_s", list}, {"impact_count", impacts.size()}};
    }
    return {{"first_contact_s", t.events.empty() ? Json(nullptr) : Json(t.events.front().time)},
            {"event_count", t.events.size()},
            {"rest_time_s", optionalNumber(restTime(scene, t))},
            {"per_body", per_body}};
}

// The position component (x, y or z) of a body that moves most in the reference run.
int liveliestAxis(const RunTrace& t, int body) {
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const auto& s : t.states) {
        lo = lo.cwiseMin(s[static_cast<std::size_t>(body)].pose.position);
        hi = hi.cwiseMax(s[static_cast<std::size_t>(body)].pose.position);
    }
    int axis = 2;
    (hi - lo).maxCoeff(&axis);
    return axis;
}

ChartSeries traceSeries(const RunTrace& t, const std::string& name, const std::vector<double>& y) {
    const auto idx = strideIndices(std::min(t.times.size(), y.size()), kMaxChartPoints);
    return {name, "lines", pick(t.times, idx), pick(y, idx)};
}

// The consensus table: per observable, which backends agree within their own twin noise floors
// (plus the observable's stated resolution) and which one is the odd one out.
Json consensusJson(const Scene& scene, const std::vector<SelectedBackend>& backends, const std::vector<BackendRuns>& runs,
                   const std::vector<Divergence>& twin_spread, double dt, std::vector<std::vector<Json>>& rows) {
    const std::size_t n = backends.size();
    std::vector<std::string> names;
    for (const SelectedBackend& b : backends) names.push_back(b.info->name);
    double weight = 0;   // sum of m |g|: the energy of lifting every body by 1 m
    for (const Body& b : scene.bodies)
        if (b.isDynamic()) weight += b.mass_properties.mass * scene.gravity.norm();
    auto firstContact = [](const RunTrace& t) { return t.events.empty() ? NAN : t.events.front().time; };
    auto finalEnergy = [](const RunTrace& t) { return t.invariants.back().energy(); };
    std::vector<ConsensusInput> inputs(3);
    ConsensusInput& contact = inputs[0];
    contact.observable = "first contact [s]";
    contact.floor = dt;
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
        in.backends = names;
        in.present.assign(n, true);
        in.noise.assign(n, 0.0);
    }
    std::vector<double> t0(n), e(n);
    for (std::size_t i = 0; i < n; ++i) {
        t0[i] = firstContact(runs[i].main);
        contact.present[i] = std::isfinite(t0[i]);
        const double twin_t0 = firstContact(runs[i].twin);
        contact.noise[i] = std::isfinite(twin_t0) && contact.present[i] ? std::abs(t0[i] - twin_t0) : 0.0;
        rest.noise[i] = twin_spread[i].distance.back();
        e[i] = finalEnergy(runs[i].main);
        energy.noise[i] = std::abs(e[i] - finalEnergy(runs[i].twin));
    }
    contact.difference = [&](std::size_t a, std::size_t b) { return std::abs(t0[a] - t0[b]); };
    rest.difference = [&](std::size_t a, std::size_t b) {
        return maxPositionError(scene, runs[a].main.states.back(), runs[b].main.states.back());
    };
    energy.difference = [&](std::size_t a, std::size_t b) { return std::abs(e[a] - e[b]); };
    Json out = Json::array();
    for (const ConsensusInput& in : inputs) {
        const ConsensusResult r = consensus(in);
        Json values = Json::object(), noise = Json::object();
        for (std::size_t i = 0; i < n; ++i) {
            noise[names[i]] = number(in.noise[i]);
            if (&in == &contact) values[names[i]] = number(t0[i]);
            if (&in == &energy) values[names[i]] = number(e[i]);
        }
        out.push_back({{"observable", in.observable}, {"verdict", r.verdict}, {"agreeing", r.agreeing},
                       {"outliers", r.outliers}, {"floor", in.floor}, {"floor_reason", in.floor_reason},
                       {"values", values}, {"noise", noise}});
        std::string agreeing;
        for (const std::string& a : r.agreeing) agreeing += (agreeing.empty() ? "" : ", ") + a;
        std::string value_text;
        for (std::size_t i = 0; i < n && &in != &rest; ++i) {
            char v[64];
            std::snprintf(v, sizeof v, "%s%s %.6g", value_text.empty() ? "" : "; ", names[i].c_str(),
                          &in == &contact ? t0[i] : e[i]);
            value_text += v;
        }
        if (&in == &rest) value_text = "(pairwise: largest body distance between final states)";
        rows.push_back({in.observable, value_text, r.verdict, agreeing, in.floor, in.floor_reason});
    }
    return out;
}

}  // namespace

Json compareScene(const Scene& scene, const std::vector<SelectedBackend>& requested, const CompareOptions& o,
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

Json compareScene(const Scene& scene, const std::vector<SelectedBackend>& requested, const CompareOptions& o,
                  const std::filesystem::path& csv_dir, RunPool& pool) {
    // A backend that cannot represent the scene is left out (and named); an approximated one runs.
    Json support;
    const std::vector<SelectedBackend> backends = representableBackends(scene, requested, "compare", o.progress, support);
    const double dt = o.frame_dt.value_or(scene.frame_dt);
    const std::int64_t frames = framesFor(o.duration, dt);
    const std::int64_t window_frames = std::max<std::int64_t>(1, framesFor(o.window, dt));
    const std::size_t n = backends.size();
    // Phase 1, one job per backend: main run, determinism rerun, twin run. Phase 2 (they need the
    // reference backend's main run): every backend's re-anchored windows.
    // Per backend: main run, determinism rerun and twin run; then its re-anchored windows, which
    // restart from the reference backend's (the first's) main run, so they wait for that run.
    std::vector<PoolJob> jobs;
    for (std::size_t i = 0; i < n; ++i)
        jobs.push_back({poolJobId("main-" + backends[i].info->name), [&, i] {
            const BackendRuns r = runAll(scene, backends[i], o, dt, frames);
            Json pen = Json::array();
            for (double p : r.penetration) pen.push_back(number(p));
            return Json{{"main", runTraceJson(r.main)}, {"twin", runTraceJson(r.twin)}, {"penetration", pen},
                        {"state_hash", r.state_hash}, {"deterministic", r.deterministic}};
        }, 3.0 * static_cast<double>(frames)});
    RunTrace ref;             // the reference backend's main run, once it is done (DependencyHook)
    std::vector<std::size_t> anchors;
    for (std::size_t i = 0; i < n; ++i)
        jobs.push_back({poolJobId("windows-" + backends[i].info->name), [&, i] {
            BackendRuns r;
            runWindows(scene, backends[i], ref, anchors, window_frames, dt, r);
            Json ends = Json::array();
            for (const auto& e : r.window_ends) ends.push_back(statesJson(e));
            return Json{{"window_ends", ends}};
        }, static_cast<double>(o.windows * window_frames), {0}});
    const std::vector<Json> done = pool.run(jobs, [&](std::size_t, const Json& r) {
        ref = runTraceFromJson(r["main"]);
        anchors = anchorFrames(ref.states.size(), o.windows, window_frames);
    });
    std::vector<BackendRuns> runs(n);
    for (std::size_t i = 0; i < n; ++i) {
        runs[i].main = runTraceFromJson(done[i]["main"]);
        runs[i].twin = runTraceFromJson(done[i]["twin"]);
        for (const Json& p : done[i]["penetration"]) runs[i].penetration.push_back(p.is_null() ? NAN : p.get<double>());
        runs[i].state_hash = done[i]["state_hash"];
        runs[i].deterministic = done[i]["deterministic"];
        for (const Json& e : done[n + i]["window_ends"]) runs[i].window_ends.push_back(statesFromJson(e));
        if (o.write_csv && !csv_dir.empty() && mpi::isRoot()) writeTraceCsv(scene, runs[i].main, csv_dir / backends[i].info->name);
    }
    ref = runs[0].main;   // on every rank, whichever ran what
    anchors = anchorFrames(ref.states.size(), o.windows, window_frames);

    Json doc = newDocument("compare", o.command_line);
    doc["title"] = "scene '" + scene.name + "' on " + std::to_string(n) + " backend(s)";
    doc["scene"] = {{"name", scene.name}, {"file", scene.source_path}, {"sha256", scene.source_sha256},
                    {"bodies", scene.bodies.size()}, {"virtual_bodies", scene.virtualBodyCount()}};
    doc["backends"] = backendsJson(backends);
    doc["support"] = support;
    doc["parameters"] = {{"frame_dt_s", dt}, {"duration_s", o.duration}, {"frames", frames},
                         {"windows", anchors.size()}, {"window_s", window_frames * dt},
                         {"twin_epsilon_m", o.twin_epsilon}, {"horizon_delta_m", o.horizon_delta},
                         {"reference_backend", backends[0].info->name}};

    Json results = Json::object();
    std::vector<std::vector<Json>> summary;
    std::vector<Divergence> twin_spread(n);
    for (std::size_t i = 0; i < n; ++i) {
        const BackendRuns& r = runs[i];
        twin_spread[i] = divergence(scene, r.main, r.twin);
        const TimingSummary timing = summarizeTiming(r.main.step_wall_s, r.main.simulatedTime());
        double pen_max = 0, pen_sum = 0;
        for (double p : r.penetration) { pen_max = std::max(pen_max, p); pen_sum += p; }
        std::vector<double> win_pos, win_ang;
        for (std::size_t k = 0; k < anchors.size(); ++k) {
            const auto& truth = ref.states[anchors[k] + static_cast<std::size_t>(window_frames)];
            win_pos.push_back(maxPositionError(scene, r.window_ends[k], truth));
            win_ang.push_back(maxAngleError(scene, r.window_ends[k], truth));
        }
        auto mean = [](const std::vector<double>& v) { double s = 0; for (double x : v) s += x; return v.empty() ? NAN : s / v.size(); };
        const auto t_delta = horizon(twin_spread[i].t, twin_spread[i].distance, o.horizon_delta);
        const auto lambda = ftle(twin_spread[i].t, twin_spread[i].distance, 10 * o.twin_epsilon, o.horizon_delta);
        Json warnings = r.main.warnings;
        Json stats = Json::object();
        for (const auto& [k, v] : r.main.statistics) stats[k] = number(v);
        results[backends[i].info->name] = {
            {"timing", {{"p50_us", timing.p50_us}, {"p90_us", timing.p90_us}, {"p99_us", timing.p99_us},
                        {"mean_us", timing.mean_us}, {"max_us", timing.max_us},
                        {"real_time_factor", number(timing.real_time_factor)}, {"wall_per_sim_s", timing.wall_per_sim_s}}},
            {"penetration", {{"max_m", pen_max}, {"mean_m", r.penetration.empty() ? 0.0 : pen_sum / r.penetration.size()}}},
            {"invariants", invariantsJson(r.main, scene)},
            {"events", eventsJson(r.main, scene)},
            {"twin", {{"horizon_s", optionalNumber(t_delta)}, {"ftle_per_s", optionalNumber(lambda)},
                      {"final_spread_m", twin_spread[i].distance.back()}}},
            {"windows", {{"position_error_m", win_pos}, {"angle_error_rad", win_ang},
                         {"mean_position_error_m", number(mean(win_pos))}, {"mean_angle_error_rad", number(mean(win_ang))}}},
            {"finite", r.main.finite},
            {"state_hash", r.state_hash},
            {"deterministic", r.deterministic},
            {"warnings", warnings},
            {"statistics", stats}};
        const Json& e = results[backends[i].info->name]["events"];
        summary.push_back({backends[i].info->name, number(timing.real_time_factor), timing.p50_us, timing.p99_us,
                           pen_max * 1e3, results[backends[i].info->name]["invariants"]["energy_max_abs_change_J"],
                           e["first_contact_s"], e["rest_time_s"], optionalNumber(t_delta),
                           number(mean(win_pos) * 1e3), r.main.finite ? "pass" : "FAIL", r.deterministic ? "pass" : "FAIL"});
    }
    // Cross-backend divergence, counted only above both noise floors.
    Json pairs = Json::array();
    std::vector<std::vector<Json>> pair_rows;
    ChartSpec div{"divergence", "Divergence from " + backends[0].info->name + " with twin noise floors",
                  "t [s]", "max body distance [m]", false, true, {}};
    for (std::size_t i = 1; i < n; ++i) {
        const Divergence d = divergence(scene, ref, runs[i].main);
        const Significance s = significantDivergence(d.distance, twin_spread[0].distance, twin_spread[i].distance, d.t);
        Json per_body = Json::object();
        const auto vb = virtualBodyIndices(scene);
        for (std::size_t v = 0; v < vb.size(); ++v) per_body[scene.bodies[static_cast<std::size_t>(vb[v])].name] = d.per_body_max[v];
        pairs.push_back({{"a", backends[0].info->name}, {"b", backends[i].info->name},
                         {"max_divergence_m", *std::max_element(d.distance.begin(), d.distance.end())},
                         {"final_divergence_m", d.distance.back()}, {"per_body_max_m", per_body},
                         {"first_significant_s", optionalNumber(s.first_time)}, {"significant_fraction", s.fraction}});
        pair_rows.push_back({backends[0].info->name + " vs " + backends[i].info->name, pairs.back()["max_divergence_m"],
                             pairs.back()["final_divergence_m"], pairs.back()["first_significant_s"], s.fraction});
        div.series.push_back(traceSeries(ref, backends[0].info->name + " vs " + backends[i].info->name, d.distance));
    }
    for (std::size_t i = 0; i < n; ++i)
        div.series.push_back(traceSeries(runs[i].main, "noise floor " + backends[i].info->name + " (twin spread)", twin_spread[i].distance));
    results["pairs"] = pairs;
    std::vector<std::vector<Json>> consensus_rows;
    results["consensus"] = consensusJson(scene, backends, runs, twin_spread, dt, consensus_rows);
    doc["results"] = results;

    const int at_once = pool.executionJson()["jobs"].get<int>() * pool.executionJson()["ranks"].get<int>();
    doc["tables"].push_back(tableJson("summary", at_once > 1 ? "Summary per backend (step times measured with up to " +
                                                     std::to_string(at_once) + " runs at once; --jobs 1 for timings alone on the machine)"
                                                             : std::string("Summary per backend"),
        {"backend", "real-time factor [-]", "step p50 [µs]", "step p99 [µs]", "max penetration [mm]",
         "max |ΔE| [J]", "first contact [s]", "rest [s]", "horizon t_δ [s]", "window error [mm]", "finite", "deterministic"},
        summary));
    // The report leads with the consensus: which backend is the odd one out, per observable.
    doc["tables"].insert(doc["tables"].begin(),
        tableJson("consensus", "Consensus: which backends agree (within their own twin noise floors plus the floor)",
                  {"observable", "values", "verdict", "agreeing", "floor", "floor: why"}, consensus_rows));
    if (!pair_rows.empty())
        doc["tables"].push_back(tableJson("pairs", "Cross-backend divergence (counts only above both twin spreads)",
            {"pair", "max [m]", "final [m]", "first significant [s]", "significant fraction [-]"}, pair_rows));

    // Charts: trajectories, divergence, energy, penetration, windows, timing histograms.
    const auto vb = virtualBodyIndices(scene);
    for (std::size_t k = 0; k < vb.size() && k < 3; ++k) {
        const int body = vb[k];
        const int axis = liveliestAxis(ref, body);
        const char* axis_name = axis == 0 ? "x" : axis == 1 ? "y" : "z";
        const std::string bname = scene.bodies[static_cast<std::size_t>(body)].name;
        ChartSpec c{"trajectory-" + std::to_string(k), "Trajectory of '" + bname + "' (" + axis_name + ")", "t [s]",
                    std::string(axis_name) + " [m]", false, false, {}};
        for (std::size_t i = 0; i < n; ++i) {
            std::vector<double> y;
            for (const auto& s : runs[i].main.states) y.push_back(s[static_cast<std::size_t>(body)].pose.position[axis]);
            c.series.push_back(traceSeries(runs[i].main, backends[i].info->name, y));
        }
        doc["charts"].push_back(chartJson(c));
    }
    doc["charts"].push_back(chartJson(div));
    ChartSpec energy{"energy", "Mechanical energy of the virtual bodies", "t [s]", "E [J]", false, false, {}};
    ChartSpec pen{"penetration", "Deepest penetration (neutral distance query)", "t [s]", "depth [m]", false, false, {}};
    ChartSpec win{"windows", "Re-anchored windows: error after one window vs " + backends[0].info->name + " (continuous)",
                  "anchor time [s]", "max body position error [m]", false, true, {}};
    ChartSpec hist{"step-times", "Per-step wall time histogram", "step wall time [µs]", "steps [-]", false, false, {}};
    for (std::size_t i = 0; i < n; ++i) {
        std::vector<double> e;
        for (const auto& inv : runs[i].main.invariants) e.push_back(inv.energy());
        energy.series.push_back(traceSeries(runs[i].main, backends[i].info->name, e));
        pen.series.push_back(traceSeries(runs[i].main, backends[i].info->name, runs[i].penetration));
        std::vector<double> at;
        for (std::size_t f : anchors) at.push_back(ref.times[f]);
        win.series.push_back({backends[i].info->name, "linespoints", at,
                              results[backends[i].info->name]["windows"]["position_error_m"].get<std::vector<double>>()});
        std::vector<double> us;
        for (double s : runs[i].main.step_wall_s) us.push_back(s * 1e6);
        const Histogram h = histogram(us, 30);
        hist.series.push_back({backends[i].info->name, "steps", h.centers, h.counts});
        results[backends[i].info->name]["timing"]["histogram"] = {{"centers_us", h.centers}, {"counts", h.counts}};
    }
    doc["results"] = results;
    for (const ChartSpec* c : {&energy, &pen, &win, &hist}) doc["charts"].push_back(chartJson(*c));
    doc["execution"] = pool.executionJson();
    return doc;
}

}  // namespace vroc::harness
