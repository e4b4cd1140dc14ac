// SPDX-License-Identifier: MIT
#include "vroc/harness/documents/compare_document.h"

#include <algorithm>
#include <cstdio>

#include "vroc/harness/documents/series_tools.h"

namespace vroc::harness {
namespace {

constexpr std::size_t kMaxChartPoints = 800;
constexpr std::size_t kTrajectoryCharts = 3;   // the first virtual bodies get one each

Json optionalNumber(const std::optional<double>& v) { return v ? number(*v) : Json(nullptr); }

// How tables, charts and verdicts name a backend's run ("bullet", or "bullet (equal footing)" with
// both footings side by side), and its key in metrics.json ("bullet", or "bullet-equal").
std::string nameOf(const CompareResult& c, std::size_t backend) { return c.backends[backend].label(); }
std::string keyOf(const CompareResult& c, std::size_t backend) { return c.backends[backend].key(); }

// A chart's legend entry: the backend, marked when its run is not the engine's physics.
std::string seriesName(const CompareResult& c, std::size_t backend) {
    return nameOf(c, backend) + (c.summaries[backend].validity.valid ? "" : " (not valid)");
}

Json invariantsJson(const InvariantDrift& d) {
    return {{"energy_initial_J", number(d.energy_initial)},
            {"energy_max_abs_change_J", number(d.energy_max_abs_change)},
            {"energy_max_rel_change", number(d.energy_max_rel_change)},
            {"angular_momentum_max_change", number(d.angular_momentum_max_change)},
            {"linear_momentum_max_change_beyond_gravity", number(d.linear_momentum_max_change_beyond_gravity)}};
}

Json eventsJson(const EventSummary& e) {
    Json per_body = Json::object();
    for (const BodyImpacts& b : e.per_body) per_body[b.body] = {{"impact_times_s", b.times}, {"impact_count", b.count}};
    return {{"first_contact_s", optionalNumber(e.first_contact)}, {"event_count", e.event_count},
            {"rest_time_s", optionalNumber(e.rest_time)}, {"per_body", per_body}};
}

Json backendJson(const CompareBackendSummary& s, const BackendRuns& r) {
    const TimingSummary& t = s.timing;
    Json stats = Json::object();
    for (const auto& [k, v] : r.main.statistics) stats[k] = number(v);
    return {{"valid", s.validity.valid},
            {"invalid_reason", s.validity.valid ? Json(nullptr) : Json(s.validity.reason)},
            {"timing",
             {{"p50_us", t.p50_us},
              {"p90_us", t.p90_us},
              {"p99_us", t.p99_us},
              {"mean_us", t.mean_us},
              {"max_us", t.max_us},
              {"real_time_factor", number(t.real_time_factor)},
              {"wall_per_sim_s", t.wall_per_sim_s},
              {"histogram", {{"centers_us", s.step_times_us.centers}, {"counts", s.step_times_us.counts}}}}},
            {"penetration", {{"max_m", s.penetration_max}, {"mean_m", s.penetration_mean}}},
            {"invariants", invariantsJson(s.invariants)},
            {"events", eventsJson(s.events)},
            {"twin",
             {{"horizon_s", optionalNumber(s.horizon)},
              {"ftle_per_s", optionalNumber(s.ftle)},
              {"final_spread_m", s.twin_spread.distance.back()}}},
            {"windows",
             {{"position_error_m", s.window_position_error},
              {"angle_error_rad", s.window_angle_error},
              {"mean_position_error_m", number(s.mean_window_position_error)},
              {"mean_angle_error_rad", number(s.mean_window_angle_error)}}},
            {"finite", r.main.finite},
            {"state_hash", r.state_hash},
            {"deterministic", r.deterministic},
            {"warnings", r.main.warnings},
            {"statistics", stats}};
}

double maxDivergence(const ComparePair& p) {
    const auto& d = p.divergence.distance;
    return *std::max_element(d.begin(), d.end());
}

Json pairJson(const CompareResult& c, const ComparePair& p) {
    Json per_body = Json::object();
    const auto vb = virtualBodyIndices(c.scene);
    for (std::size_t v = 0; v < vb.size(); ++v) per_body[c.scene.bodies[static_cast<std::size_t>(vb[v])].name] = p.divergence.per_body_max[v];
    return {{"a", keyOf(c, 0)},
            {"b", keyOf(c, p.backend)},
            {"max_divergence_m", maxDivergence(p)},
            {"final_divergence_m", p.divergence.distance.back()},
            {"per_body_max_m", per_body},
            {"first_significant_s", optionalNumber(p.significance.first_time)},
            {"significant_fraction", p.significance.fraction}};
}

Json consensusJson(const CompareResult& c, const ConsensusRow& row) {
    Json values = Json::object(), noise = Json::object();
    for (std::size_t i = 0; i < c.backends.size(); ++i) {
        noise[keyOf(c, i)] = number(row.noise[i]);
        if (!row.values.empty()) values[keyOf(c, i)] = number(row.values[i]);
    }
    return {{"observable", row.observable},
            {"verdict", row.result.verdict},
            {"agreeing", row.result.agreeing},
            {"outliers", row.result.outliers},
            {"left_out", row.result.left_out},
            {"uninformative", row.result.uninformative},
            {"floor", row.floor},
            {"floor_reason", row.floor_reason},
            {"values", values},
            {"noise", noise}};
}

Json consensusTable(const CompareResult& c) {
    std::vector<std::vector<Json>> rows;
    for (const ConsensusRow& row : c.consensus) {
        const std::string agreeing = joinText(row.result.agreeing);
        std::string value_text;
        for (std::size_t i = 0; i < row.values.size(); ++i) {
            char v[64];
            std::snprintf(v, sizeof v, "%s%s %.6g", value_text.empty() ? "" : "; ", nameOf(c, i).c_str(), row.values[i]);
            value_text += v;
        }
        if (row.values.empty()) value_text = "(pairwise: largest body distance between final states)";
        const std::string left_out = joinText(row.result.left_out, "; ");
        rows.push_back(
            {row.observable, value_text, row.result.verdict, agreeing, left_out, row.floor, row.floor_reason});
    }
    return tableJson("consensus", "Consensus: which backends agree (within their own twin noise floors plus the floor)",
                     {"observable", "values", "verdict", "agreeing", "left out", "floor", "floor: why"}, rows);
}

Json summaryTable(const CompareResult& c) {
    std::vector<std::vector<Json>> rows;
    for (std::size_t i = 0; i < c.backends.size(); ++i) {
        const CompareBackendSummary& s = c.summaries[i];
        const BackendRuns& r = c.runs[i];
        const std::string name = s.validity.valid ? nameOf(c, i) : nameOf(c, i) + " (" + invalidLabel(s.validity) + ")";
        rows.push_back({name, number(s.timing.real_time_factor), s.timing.p50_us, s.timing.p99_us,
                        s.penetration_max * 1e3, number(s.invariants.energy_max_abs_change),
                        optionalNumber(s.events.first_contact), optionalNumber(s.events.rest_time),
                        optionalNumber(s.horizon), number(s.mean_window_position_error * 1e3),
                        r.main.finite ? "pass" : "FAIL", r.deterministic ? "pass" : "FAIL"});
    }
    const int at_once = c.execution.atOnce();
    const std::string title = at_once > 1 ? "Summary per backend (step times measured with up to " + std::to_string(at_once) +
                                                " runs at once; --jobs 1 for timings alone on the machine)"
                                          : std::string("Summary per backend");
    return tableJson("summary", title,
        {"backend", "real-time factor [-]", "step p50 [µs]", "step p99 [µs]", "max penetration [mm]",
         "max |ΔE| [J]", "first contact [s]", "rest [s]", "horizon t_δ [s]", "window error [mm]", "finite", "deterministic"}, rows);
}

Json pairsTable(const CompareResult& c) {
    std::vector<std::vector<Json>> rows;
    for (const ComparePair& p : c.pairs) {
        const RunValidity& va = c.summaries[0].validity;
        const RunValidity& vb = c.summaries[p.backend].validity;
        const std::string mark =
            va.valid && vb.valid ? "" : " (not valid: " + (va.valid ? nameOf(c, p.backend) : nameOf(c, 0)) + ")";
        rows.push_back({nameOf(c, 0) + " vs " + nameOf(c, p.backend) + mark, maxDivergence(p),
                        p.divergence.distance.back(), optionalNumber(p.significance.first_time),
                        p.significance.fraction});
    }
    return tableJson("pairs", "Cross-backend divergence (counts only above both twin spreads)",
                     {"pair", "max [m]", "final [m]", "first significant [s]", "significant fraction [-]"}, rows);
}

ChartSeries traceSeries(const RunTrace& t, const std::string& name, const std::vector<double>& y) {
    const auto idx = strideIndices(std::min(t.times.size(), y.size()), kMaxChartPoints);
    return {name, "lines", pick(t.times, idx), pick(y, idx)};
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

void addCharts(const CompareResult& c, Json& doc) {
    const std::size_t n = c.backends.size();
    const RunTrace& ref = c.runs[0].main;
    const auto vb = virtualBodyIndices(c.scene);
    for (std::size_t k = 0; k < vb.size() && k < kTrajectoryCharts; ++k) {
        const int body = vb[k];
        const int axis = liveliestAxis(ref, body);
        const char* axis_name = axis == 0 ? "x" : axis == 1 ? "y" : "z";
        const std::string bname = c.scene.bodies[static_cast<std::size_t>(body)].name;
        ChartSpec chart{"trajectory-" + std::to_string(k), "Trajectory of '" + bname + "' (" + axis_name + ")", "t [s]",
                        std::string(axis_name) + " [m]", false, false, {}};
        for (std::size_t i = 0; i < n; ++i) {
            std::vector<double> y;
            for (const auto& s : c.runs[i].main.states) y.push_back(s[static_cast<std::size_t>(body)].pose.position[axis]);
            chart.series.push_back(traceSeries(c.runs[i].main, seriesName(c, i), y));
        }
        doc["charts"].push_back(chartJson(chart));
    }
    ChartSpec div{"divergence", "Divergence from " + nameOf(c, 0) + " with twin noise floors",
                  "t [s]", "max body distance [m]", false, true, {}};
    for (const ComparePair& p : c.pairs)
        div.series.push_back(
            traceSeries(ref, seriesName(c, 0) + " vs " + seriesName(c, p.backend), p.divergence.distance));
    for (std::size_t i = 0; i < n; ++i)
        div.series.push_back(traceSeries(c.runs[i].main, "noise floor " + nameOf(c, i) + " (twin spread)", c.summaries[i].twin_spread.distance));
    doc["charts"].push_back(chartJson(div));
    ChartSpec energy{"energy", "Mechanical energy of the virtual bodies", "t [s]", "E [J]", false, false, {}};
    ChartSpec pen{"penetration", "Deepest penetration (neutral distance query)", "t [s]", "depth [m]", false, false, {}};
    ChartSpec win{"windows", "Re-anchored windows: error after one window vs " + nameOf(c, 0) + " (continuous)",
                  "anchor time [s]", "max body position error [m]", false, true, {}};
    ChartSpec hist{"step-times", "Per-step wall time histogram", "step wall time [µs]", "steps [-]", false, false, {}};
    std::vector<double> anchor_times;
    for (std::size_t f : c.anchors) anchor_times.push_back(ref.times[f]);
    for (std::size_t i = 0; i < n; ++i) {
        std::vector<double> e;
        for (const auto& inv : c.runs[i].main.invariants) e.push_back(inv.energy());
        energy.series.push_back(traceSeries(c.runs[i].main, seriesName(c, i), e));
        pen.series.push_back(traceSeries(c.runs[i].main, seriesName(c, i), c.runs[i].penetration));
        win.series.push_back({nameOf(c, i), "linespoints", anchor_times, c.summaries[i].window_position_error});
        hist.series.push_back({nameOf(c, i), "steps", c.summaries[i].step_times_us.centers, c.summaries[i].step_times_us.counts});
    }
    for (const ChartSpec* chart : {&energy, &pen, &win, &hist}) doc["charts"].push_back(chartJson(*chart));
}

}  // namespace

Json compareDocument(const CompareResult& c, const std::string& command_line) {
    const std::size_t n = c.backends.size();
    Json doc = newDocument("compare", command_line);
    doc["title"] = "scene '" + c.scene.name + "' on " + std::to_string(n) + " backend(s)";
    if (n > 0 && c.backends[0].both_footings)
        doc["title"] = "scene '" + c.scene.name + "' on " + std::to_string(n / 2) +
                       " backend(s), each on both footings (own defaults and equal footing side by side)";
    doc["scene"] = {{"name", c.scene.name}, {"file", c.scene.source_path}, {"sha256", c.scene.source_sha256},
                    {"bodies", c.scene.bodies.size()}, {"virtual_bodies", c.scene.virtualBodyCount()}};
    doc["backends"] = backendsJson(c.backends);
    doc["support"] = c.support;
    doc["parameters"] = {{"frame_dt_s", c.frame_dt},
                         {"duration_s", c.duration},
                         {"frames", c.frames},
                         {"windows", c.anchors.size()},
                         {"window_s", c.window_frames * c.frame_dt},
                         {"twin_epsilon_m", c.twin_epsilon},
                         {"horizon_delta_m", c.horizon_delta},
                         {"reference_backend", keyOf(c, 0)}};
    Json results = Json::object();
    for (std::size_t i = 0; i < n; ++i) {
        Json& r = results[keyOf(c, i)] = backendJson(c.summaries[i], c.runs[i]);
        if (c.backends[i].both_footings) {  // two runs of one engine: which engine, on which footing
            r["backend"] = c.backends[i].info->name;
            r["footing"] = c.backends[i].footing.kind == Footing::Kind::Equal ? "equal" : "defaults";
            r["label"] = nameOf(c, i);
        }
    }
    Json pairs = Json::array(), consensus = Json::array();
    for (const ComparePair& p : c.pairs) pairs.push_back(pairJson(c, p));
    for (const ConsensusRow& row : c.consensus) consensus.push_back(consensusJson(c, row));
    results["pairs"] = pairs;
    results["consensus"] = consensus;
    doc["results"] = results;
    std::string not_valid;
    for (std::size_t i = 0; i < n; ++i)
        if (!c.summaries[i].validity.valid)
            not_valid += (not_valid.empty() ? "" : "; ") + nameOf(c, i) + ": " + c.summaries[i].validity.reason;
    if (!not_valid.empty())
        doc["summary"] =
            "Not valid (shown, but not the engine's physics, and left out of the consensus): " + not_valid + ".";
    // The report leads with the consensus: which backend is the odd one out, per observable.
    doc["tables"].push_back(consensusTable(c));
    doc["tables"].push_back(summaryTable(c));
    if (!c.pairs.empty()) doc["tables"].push_back(pairsTable(c));
    addCharts(c, doc);
    doc["execution"] = executionJson(c.execution);
    return doc;
}

}  // namespace vroc::harness
