// SPDX-License-Identifier: MIT
#include "vroc/harness/ensemble_document.h"

#include <cmath>
#include <cstdio>
#include <map>

#include "vroc/harness/timing_stats.h"

namespace vroc::harness {
namespace {

// Mean and standard deviation of a scalar sample; for a vector, the mean norm and the RMS distance
// to the ensemble's mean vector (its spread).
std::pair<double, double> meanSpread(const std::vector<Sample>& s) {
    if (s.empty()) return {NAN, NAN};
    Sample mean(s.front().size(), 0.0);
    for (const Sample& x : s)
        for (std::size_t k = 0; k < x.size(); ++k) mean[k] += x[k] / double(s.size());
    double spread = 0;
    for (const Sample& x : s)
        for (std::size_t k = 0; k < x.size(); ++k) spread += (x[k] - mean[k]) * (x[k] - mean[k]) / double(s.size());
    double norm = 0;
    for (double m : mean) norm += m * m;
    return {mean.size() == 1 ? mean[0] : std::sqrt(norm), std::sqrt(spread)};
}

// Percentile bands of a series over the members (all sampled at the same frames).
void spreadSeries(const std::vector<EnsembleMember>& members, std::vector<double> EnsembleMember::*series, const std::string& name,
                  ChartSpec& chart) {
    if (members.empty()) return;
    const std::vector<double>& t = members.front().t;
    ChartSeries p10{name + " p10", "lines", {}, {}}, p50{name + " median", "lines", {}, {}}, p90{name + " p90", "lines", {}, {}};
    for (std::size_t f = 0; f < t.size(); ++f) {
        std::vector<double> v;
        for (const EnsembleMember& m : members) {
            const std::vector<double>& x = m.*series;
            if (f < x.size() && std::isfinite(x[f])) v.push_back(x[f]);
        }
        if (v.empty()) continue;
        p10.x.push_back(t[f]); p10.y.push_back(percentile(v, 10));
        p50.x.push_back(t[f]); p50.y.push_back(percentile(v, 50));
        p90.x.push_back(t[f]); p90.y.push_back(percentile(v, 90));
    }
    chart.series.push_back(p10);
    chart.series.push_back(p50);
    chart.series.push_back(p90);
}

std::string unitsOf(const EnsembleResult& r, const std::string& id) {
    for (const EnsembleObservable& ob : r.observables)
        if (ob.id == id) return ob.units;
    return {};
}

// Pair "a vs b" -> (observables that distinguish them, observables that do not).
std::map<std::string, std::pair<std::vector<std::string>, std::vector<std::string>>> verdicts(const EnsembleResult& r) {
    std::map<std::string, std::pair<std::vector<std::string>, std::vector<std::string>>> out;
    for (const EnsembleTest& t : r.tests) {
        auto& v = out[t.a + " vs " + t.b];
        (t.distinguishable ? v.first : v.second).push_back(t.observable);
    }
    return out;
}

}  // namespace

Json ensembleMemberJson(const EnsembleMember& m, bool with_series) {
    Json obs = Json::object();
    for (const auto& [id, values] : m.observables) {
        Json v = Json::array();
        for (double x : values) v.push_back(number(x));
        obs[id] = v;
    }
    Json j = {{"member", m.member}, {"finite", m.finite}, {"observables", obs}, {"state_hash", m.state_hash}, {"wall_s", m.wall_s}};
    if (!with_series) return j;
    Json ke = Json::array(), height = Json::array();
    for (double x : m.kinetic_energy) ke.push_back(number(x));
    for (double x : m.mean_height) height.push_back(number(x));
    j["series"] = {{"t_s", m.t}, {"kinetic_energy_J", ke}, {"mean_height_m", height}};
    return j;
}

Json ensembleDocument(const EnsembleResult& r) {
    const EnsembleOptions& o = r.options;
    Json doc = newDocument("ensemble", o.command_line);
    doc["title"] = "ensemble of " + std::to_string(o.members) + " perturbed runs per backend on '" + r.scene.name + "'";
    doc["scene"] = {{"name", r.scene.name}, {"source", o.source}, {"sha256", r.scene.source_sha256}, {"bodies", r.scene.bodies.size()}};
    doc["backends"] = backendsJson(r.backends);
    doc["support"] = r.support;
    doc["parameters"] = {{"members", o.members}, {"duration_s", o.duration}, {"frame_dt_s", o.frame_dt}, {"seed", o.seed},
                         {"perturb", {{"positions_m", o.perturb.position}, {"velocities_m_per_s", o.perturb.velocity},
                                      {"orientations_rad", o.perturb.orientation}, {"angular_rad_per_s", o.perturb.angular_velocity}}},
                         {"alpha", o.alpha}, {"statistic", "energy distance, permutation test, Holm-adjusted"},
                         {"permutations", r.permutations}, {"tests", r.tests.size()}};
    Json tests_json = Json::array();
    std::vector<std::vector<Json>> test_rows;
    for (const EnsembleTest& t : r.tests) {
        const std::string units = unitsOf(r, t.observable);
        tests_json.push_back({{"observable", t.observable}, {"units", units}, {"a", t.a}, {"b", t.b},
                              {"members_a", t.members_a}, {"members_b", t.members_b}, {"energy_distance", t.test.statistic},
                              {"wasserstein1", number(t.wasserstein1)}, {"p_value", t.test.p_value}, {"p_holm", t.p_holm},
                              {"distinguishable", t.distinguishable}});
        test_rows.push_back({t.observable, units, t.a + " vs " + t.b, t.test.statistic, number(t.wasserstein1), t.test.p_value,
                             t.p_holm, t.distinguishable ? "yes" : "no"});
    }
    Json verdict_json = Json::object();
    for (const auto& [pair, v] : verdicts(r)) verdict_json[pair] = {{"distinguishable_by", v.first}, {"not_distinguishable_by", v.second}};
    // Per backend: mean and spread of each observable, and determinism facts.
    std::vector<std::vector<Json>> summary_rows;
    Json per_backend = Json::object();
    for (std::size_t bi = 0; bi < r.backends.size(); ++bi) {
        const std::string& name = r.backends[bi].info->name;
        double wall = 0;
        int finite = 0;
        Json stored = Json::array();
        for (const EnsembleMember& m : r.members[bi]) {
            stored.push_back(ensembleMemberJson(m, false));
            wall += m.wall_s;
            finite += m.finite ? 1 : 0;
        }
        per_backend[name] = {{"members", stored}, {"finite_members", finite}, {"wall_total_s", wall}};
        for (const EnsembleObservable& ob : r.observables) {
            const auto [mean, spread] = meanSpread(ensembleSamples(r.members[bi], ob.id));
            summary_rows.push_back({ob.id, ob.units, name, number(mean), number(spread)});
        }
    }
    doc["results"] = {{"tests", tests_json}, {"verdicts", verdict_json}, {"backends", per_backend}};
    char alpha[16];
    std::snprintf(alpha, sizeof alpha, "%g", o.alpha);
    doc["tables"].push_back(tableJson("ensemble-tests",
        "Are the backends' ensembles distinguishable? Energy distance, permutation p-value, Holm-adjusted over all tests (alpha " +
            std::string(alpha) + ")",
        {"observable", "units", "backends", "energy distance [units]", "Wasserstein-1 [units]", "p", "p (Holm)", "distinguishable"}, test_rows));
    doc["tables"].push_back(tableJson("ensemble-summary", "Per backend: ensemble mean (vectors: norm of the mean) and spread (std; vectors: RMS distance to the mean)",
        {"observable", "units", "backend", "mean", "spread"}, summary_rows));
    ChartSpec ke{"ensemble-kinetic-energy", "Kinetic energy over time: ensemble median and 10-90 % band per backend", "t [s]", "kinetic energy [J]", false, false, {}};
    ChartSpec height{"ensemble-height", "Mean height of the virtual bodies over time: median and 10-90 % band per backend", "t [s]", "mean height [m]", false, false, {}};
    for (std::size_t bi = 0; bi < r.backends.size(); ++bi) {
        spreadSeries(r.members[bi], &EnsembleMember::kinetic_energy, r.backends[bi].info->name, ke);
        spreadSeries(r.members[bi], &EnsembleMember::mean_height, r.backends[bi].info->name, height);
    }
    doc["charts"].push_back(chartJson(ke));
    doc["charts"].push_back(chartJson(height));
    doc["execution"] = executionJson(r.execution);
    return doc;
}

std::string ensembleVerdictText(const EnsembleResult& r) {
    auto join = [](const std::vector<std::string>& list) {
        std::string s;
        for (const std::string& x : list) s += (s.empty() ? "" : ", ") + x;
        return s.empty() ? std::string("none") : s;
    };
    std::string out;
    for (const auto& [pair, v] : verdicts(r))
        out += pair + ": distinguishable by " + join(v.first) + "; not by " + join(v.second) + "\n";
    return out;
}

}  // namespace vroc::harness
