// SPDX-License-Identifier: MIT
#include "vroc/harness/documents/sweep_document.h"

namespace vroc::harness {
namespace {

Json optionalJson(const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); }

}  // namespace

Json sweepStepJson(const SweepStep& s) {
    Json j = {{"dt_s", s.dt}, {"robust", s.robust}, {"failure", s.failure}, {"state_hash", s.state_hash}};
    if (!s.not_valid.empty()) j["not_valid"] = s.not_valid;
    if (s.measured)
        j.update({{"cost_wall_per_sim_s", number(s.cost)}, {"window_error_m", number(s.window_error)},
                  {"closed_form_error", number(s.closed_form_error)}, {"step_p50_us", number(s.step_p50_us)}});
    return j;
}

Json sweepDetailJson(const SweepDetail& d) {
    return {{"level", d.level}, {"faces", d.faces}, {"cost_wall_per_sim_s", number(d.cost)}, {"window_error_m", number(d.window_error)},
            {"meets_target", d.meets_target}, {"state_hash", d.state_hash}};
}

namespace {

Json curveJson(const SweepCurveResult& c, const SweepResult& r) {
    Json steps = Json::array();
    for (const SweepStep& s : c.steps) steps.push_back(sweepStepJson(s));
    Json j = {{"backend", c.curve.run.info->name}, {"setting", c.curve.setting.empty() ? Json(nullptr) : Json(c.curve.setting)},
              {"steps", steps}, {"convergence_order", optionalJson(c.convergence_order)},
              {"robustness_limit_dt_s", optionalJson(c.robustness_limit_dt)}};
    if (!r.detail_sweep) return j;
    Json levels = Json::array();
    for (const SweepDetail& d : c.details) levels.push_back(sweepDetailJson(d));
    j["detail"] = {{"frame_dt_s", r.dts.front()}, {"levels", levels},
                   {"cheapest_meeting_target", c.cheapest_meeting_target ? Json(*c.cheapest_meeting_target) : Json(nullptr)}};
    return j;
}

Json paretoJson(const SweepResult& r) {
    Json front = Json::array();
    for (const SweepPoint& p : r.points) {
        if (!p.on_pareto_front) continue;
        const SweepCurve& c = r.curves[p.curve].curve;
        const SweepStep& s = r.stepOf(p);
        front.push_back({{"series", c.label}, {"backend", c.run.info->name}, {"dt_s", s.dt},
                         {"cost_wall_per_sim_s", s.cost}, {"window_error_m", s.window_error}});
    }
    return front;
}

void addTables(const SweepResult& r, Json& doc) {
    std::vector<std::vector<Json>> rows, robust_rows, detail_rows;
    for (const SweepPoint& p : r.points) {
        const SweepStep& s = r.stepOf(p);
        rows.push_back({r.curves[p.curve].curve.label, frameStepName(s.dt), s.dt, number(s.cost),
                        number(s.window_error), number(s.closed_form_error), s.robust ? "pass" : "FAIL",
                        p.on_pareto_front, s.not_valid.empty() ? Json("yes") : Json("not valid: " + s.not_valid)});
    }
    for (const SweepCurveResult& c : r.curves) {
        const auto& limit = c.robustness_limit_dt;
        robust_rows.push_back({c.curve.label, optionalJson(limit), limit ? Json(frameStepName(*limit)) : Json("none"),
                               optionalJson(c.convergence_order)});
        for (const SweepDetail& d : c.details)
            detail_rows.push_back({c.curve.label, d.level, d.faces, number(d.cost), number(d.window_error),
                                   r.target ? Json(d.meets_target ? "pass" : "FAIL") : Json(nullptr)});
    }
    doc["tables"].push_back(tableJson("sweep", "Speed and accuracy per backend and frame step",
                                      {"backend", "step", "dt [s]", "cost [s/s]", "window error [m]",
                                       "closed-form error", "robust", "on Pareto front", "valid"},
                                      rows));
    doc["tables"].push_back(tableJson("robustness", "Robustness limit (largest step that completes without NaN, tunnelling, blow-up or collapse)",
        {"backend", "limit dt [s]", "limit", "convergence order p [-]"}, robust_rows));
    if (!detail_rows.empty())
        doc["tables"].push_back(tableJson("detail", "Model detail (window error against the full-detail tiny-step reference)",
            {"backend", "level", "faces", "cost [s/s]", "window error [m]", "meets target"}, detail_rows));
}

void addCharts(const SweepResult& r, Json& doc) {
    ChartSpec speed{"speed-accuracy", "Speed vs accuracy (self-consistency, re-anchored windows); Pareto front dashed",
                    "cost [s wall per s simulated]", "mean window error [m]", true, true, {}};
    ChartSpec conv{"convergence", "Error vs frame step", "frame step [s]", "mean window error [m]", true, true, {}};
    ChartSpec closed{"closed-form", "Closed-form error vs cost", "cost [s wall per s simulated]", "|measured - closed form|", true, true, {}};
    ChartSpec detail{"detail", "Model detail: error vs cost at the scene's step", "cost [s wall per s simulated]", "mean window error [m]", true, true, {}};
    for (const SweepCurveResult& c : r.curves) {
        const std::string& name = c.curve.label;
        ChartSeries s_speed{name, "linespoints", {}, {}}, s_conv{name, "linespoints", {}, {}}, s_closed{name, "linespoints", {}, {}};
        for (const SweepStep& s : c.steps) {
            if (!s.measured) continue;
            s_speed.x.push_back(s.cost); s_speed.y.push_back(s.window_error);
            s_conv.x.push_back(s.dt); s_conv.y.push_back(s.window_error);
            s_closed.x.push_back(s.cost); s_closed.y.push_back(s.closed_form_error);
        }
        speed.series.push_back(s_speed);
        conv.series.push_back(s_conv);
        if (r.closed_form) closed.series.push_back(s_closed);
        if (!r.detail_sweep) continue;
        ChartSeries s_detail{name, "linespoints", {}, {}};
        for (const SweepDetail& d : c.details) { s_detail.x.push_back(d.cost); s_detail.y.push_back(d.window_error); }
        detail.series.push_back(s_detail);
    }
    ChartSeries s_front{"Pareto front", "linespoints", {}, {}};
    for (const SweepPoint& p : r.points)
        if (p.on_pareto_front) { s_front.x.push_back(r.stepOf(p).cost); s_front.y.push_back(r.stepOf(p).window_error); }
    speed.series.push_back(s_front);
    doc["charts"].push_back(chartJson(speed));
    doc["charts"].push_back(chartJson(conv));
    if (r.closed_form) doc["charts"].push_back(chartJson(closed));
    if (r.detail_sweep) doc["charts"].push_back(chartJson(detail));
}

}  // namespace

Json sweepDocument(const SweepResult& r, const std::string& command_line) {
    const Scene& scene = r.scene;
    Json doc = newDocument("sweep", command_line);
    doc["title"] = "speed vs accuracy on '" + scene.name + "'";
    doc["scene"] = {{"name", scene.name}, {"source", r.source}, {"sha256", scene.source_sha256}, {"bodies", scene.bodies.size()}};
    doc["backends"] = backendsJson(r.backends);
    doc["support"] = r.support;
    doc["parameters"] = {{"dts_s", r.dts}, {"reference_dt_s", r.reference_dt}, {"duration_s", r.duration}, {"windows", r.windows},
                         {"window_s", r.window}, {"robustness_dts_s", r.robustness_dts},
                         {"closed_form", r.closed_form ? Json(r.closed_form->id + ": " + r.closed_form->closed_form) : Json(nullptr)},
                         {"target_m", optionalJson(r.target)}, {"vary", r.vary}};
    Json results = Json::object();
    for (const SweepCurveResult& c : r.curves) results[c.curve.label] = curveJson(c, r);
    results["pareto_front"] = paretoJson(r);
    doc["results"] = results;
    addTables(r, doc);
    addCharts(r, doc);
    doc["execution"] = executionJson(r.execution);
    return doc;
}

}  // namespace vroc::harness
