// SPDX-License-Identifier: MIT
#include "vroc/harness/documents/ensemble_document.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "vroc/harness/statistics/timing_stats.h"

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

bool tested(const EnsembleTest& t) {
    return t.verdict != EnsembleVerdict::not_reached && t.verdict != EnsembleVerdict::too_few_members;
}

std::string formatted(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

// Pair "a vs b" -> its observables by verdict.
struct PairVerdicts {
    std::vector<std::string> distinguishable, not_distinguishable, within_resolution, not_reached, too_few;
};

std::map<std::string, PairVerdicts> verdicts(const EnsembleResult& r) {
    std::map<std::string, PairVerdicts> out;
    for (const EnsembleTest& t : r.tests) {
        PairVerdicts& v = out[t.a + " vs " + t.b];
        switch (t.verdict) {
            case EnsembleVerdict::distinguishable:
                v.distinguishable.push_back(t.observable);
                break;
            case EnsembleVerdict::not_distinguishable:
                v.not_distinguishable.push_back(t.observable);
                break;
            case EnsembleVerdict::within_resolution:
                v.within_resolution.push_back(t.observable);
                break;
            case EnsembleVerdict::not_reached:
                v.not_reached.push_back(t.observable + " (by " + joinText(t.not_reached_by) + ")");
                break;
            case EnsembleVerdict::too_few_members:
                v.too_few.push_back(t.observable);
                break;
        }
    }
    return out;
}

Json droppedJson(const std::vector<DroppedMember>& dropped) {
    Json out = Json::array();
    for (const DroppedMember& d : dropped) out.push_back({{"member", d.member}, {"reason", d.reason}});
    return out;
}

Json testJson(const EnsembleTest& t, const std::string& units) {
    const bool done = tested(t);
    const Json paired = t.paired.pairs >= 2 ? Json{{"test", "sign-flip on the per-member differences"},
                                                   {"pairs", t.paired.pairs},
                                                   {"mean_difference", t.paired.mean_difference},
                                                   {"p_value", t.paired.p_value},
                                                   {"p_holm", number(t.p_holm_paired)}}
                                            : Json(nullptr);
    return {{"observable", t.observable},
            {"units", units},
            {"a", t.a},
            {"b", t.b},
            {"members_a", t.members_a},
            {"members_b", t.members_b},
            {"reached_a", t.reached_a},
            {"reached_b", t.reached_b},
            {"dropped_a", droppedJson(t.dropped_a)},
            {"dropped_b", droppedJson(t.dropped_b)},
            {"energy_distance", done ? number(t.test.statistic) : Json(nullptr)},
            {"wasserstein1", number(t.wasserstein1)},
            {"effect", number(t.effect)},
            {"resolution_a", t.resolution_a},
            {"resolution_b", t.resolution_b},
            {"resolution_floor", t.floor},
            {"spread", number(t.spread)},
            {"standardized_effect", number(t.standardized_effect)},
            {"effect_class", effectClassName(t.effect_class)},
            {"p_value", done ? number(t.test.p_value) : Json(nullptr)},
            {"paired", paired},
            {"p_holm_unpaired", number(t.p_holm_unpaired)},
            {"p_holm", number(t.p_holm)},
            {"verdict", verdictName(t.verdict)},
            {"not_reached_by", t.not_reached_by},
            {"distinguishable", t.distinguishable}};
}

// The digest's cell for one test: the verdict and the effect, and its colour class.
std::pair<std::string, std::string> digestCell(const EnsembleTest& t) {
    switch (t.verdict) {
        case EnsembleVerdict::distinguishable:
            return {"yes: " + formatted(t.effect) +
                        (std::isfinite(t.standardized_effect) ? " (" + formatted(t.standardized_effect) + "\u00d7)"
                                                              : " (no spread)"),
                    std::string("eff-") + effectClassName(t.effect_class)};
        case EnsembleVerdict::within_resolution:
            return {"no: " + formatted(t.effect) + " \u2264 floor " + formatted(t.floor), "eff-none"};
        case EnsembleVerdict::not_distinguishable:
            return {"no: " + formatted(t.effect), "eff-none"};
        case EnsembleVerdict::not_reached:
            return {"not reached by " + joinText(t.not_reached_by), "eff-na"};
        case EnsembleVerdict::too_few_members:
            return {"too few members (" + std::to_string(t.members_a) + "/" + std::to_string(t.members_b) + ")",
                    "eff-na"};
    }
    return {"?", ""};
}

// Observables x backend pairs, each cell coloured by the effect (html_report.cpp: cell_classes).
Json digestTable(const EnsembleResult& r) {
    std::vector<std::string> columns = {"observable", "units"}, pairs;
    for (std::size_t i = 0; i < r.backends.size(); ++i)
        for (std::size_t j = i + 1; j < r.backends.size(); ++j)
            pairs.push_back(r.backends[i].info->name + " vs " + r.backends[j].info->name);
    columns.insert(columns.end(), pairs.begin(), pairs.end());
    std::map<std::pair<std::string, std::string>, const EnsembleTest*> by_cell;
    for (const EnsembleTest& t : r.tests) by_cell[{t.observable, t.a + " vs " + t.b}] = &t;
    std::vector<std::vector<Json>> rows;
    Json classes = Json::array();
    for (const EnsembleObservable& ob : r.observables) {
        std::vector<Json> row = {ob.id, ob.units};
        Json row_classes = {"", ""};
        for (const std::string& pair : pairs) {
            const auto it = by_cell.find({ob.id, pair});
            const auto [text, cls] =
                it == by_cell.end() ? std::pair<std::string, std::string>{"\u2014", ""} : digestCell(*it->second);
            row.push_back(text);
            row_classes.push_back(cls);
        }
        rows.push_back(row);
        classes.push_back(row_classes);
    }
    Json table = tableJson(
        "ensemble-digest",
        "Digest: which observables tell each pair of engines apart. \"yes: effect (n\u00d7)\": effect in "
        "the observable's units, n = effect / max(resolution floor, spread); red n \u2265 3, orange 1\u20133, "
        "yellow < 1; pale: no difference above the floor; grey: not reached",
        columns, rows);
    table["cell_classes"] = classes;
    return table;
}

Json testsTable(const EnsembleResult& r) {
    std::vector<std::vector<Json>> rows;
    for (const EnsembleTest& t : r.tests) {
        const bool done = tested(t);
        rows.push_back({t.observable, unitsOf(r, t.observable), t.a + " vs " + t.b,
                        std::to_string(t.members_a) + "/" + std::to_string(t.members_b),
                        std::to_string(t.dropped_a.size()) + "/" + std::to_string(t.dropped_b.size()),
                        done ? number(t.test.statistic) : Json(nullptr), number(t.effect), t.floor,
                        done ? number(t.test.p_value) : Json(nullptr),
                        t.paired.pairs >= 2 ? Json(t.paired.p_value) : Json(nullptr), number(t.p_holm),
                        verdictName(t.verdict), t.distinguishable ? "yes" : "no"});
    }
    char alpha[16];
    std::snprintf(alpha, sizeof alpha, "%g", r.options.alpha);
    return tableJson("ensemble-tests",
                     "All tests. Energy distance (unbiased U-statistic; negative means closer than two draws of one "
                     "ensemble) with its permutation p; for scalars also the paired sign-flip test over members run "
                     "from the same start; both Holm-adjusted over all tests (alpha " +
                         std::string(alpha) +
                         "), the smaller decides. Effect: Wasserstein-1 (vectors: the norm of the per-coordinate "
                         "ones); distinguishable only when it also exceeds the resolution floor (the coarser engine's "
                         "step for event times, the recorded frame for rest time)",
                     {"observable", "units", "backends", "members a/b", "dropped a/b", "energy distance [units]",
                      "effect [units]", "floor [units]", "p", "p (paired)", "p (Holm)", "verdict", "distinguishable"},
                     rows);
}

// Per backend, members dropped from the tests grouped by (members, reasons): which observables.
Json droppedTable(const EnsembleResult& r) {
    std::vector<std::vector<Json>> rows;
    for (std::size_t bi = 0; bi < r.backends.size(); ++bi) {
        // (members, reasons) -> observables
        std::map<std::pair<std::string, std::string>, std::vector<std::string>> groups;
        for (const EnsembleObservable& ob : r.observables) {
            const std::vector<DroppedMember> dropped = droppedMembers(r.members[bi], ob.id);
            if (dropped.empty()) continue;
            std::vector<std::string> members;
            std::set<std::string> reasons;
            for (const DroppedMember& d : dropped) {
                members.push_back(std::to_string(d.member));
                reasons.insert(d.reason);
            }
            groups[{joinText(members), joinText(std::vector<std::string>(reasons.begin(), reasons.end()), "; ")}].push_back(
                ob.id);
        }
        for (const auto& [key, obs] : groups)
            rows.push_back({r.backends[bi].info->name, obs.size() == r.observables.size() ? "all" : joinText(obs),
                            key.first, key.second});
    }
    return tableJson("ensemble-dropped", "Members left out of the tests, per backend: which observables, and why",
                     {"backend", "observables", "members", "why"}, rows);
}

// One sentence on what was left out, for the report's summary and stdout.
std::string droppedSummary(const EnsembleResult& r) {
    std::string out;
    for (std::size_t bi = 0; bi < r.backends.size(); ++bi) {
        std::set<int> members;
        for (const EnsembleObservable& ob : r.observables)
            for (const DroppedMember& d : droppedMembers(r.members[bi], ob.id)) members.insert(d.member);
        if (members.empty()) continue;
        std::vector<std::string> names;
        for (int m : members) names.push_back(std::to_string(m));
        out += (out.empty() ? "" : "; ") + r.backends[bi].info->name + " member" + (members.size() > 1 ? "s " : " ") +
               joinText(names) + " (table ensemble-dropped)";
    }
    return out.empty() ? "No member was dropped." : "Dropped from some tests: " + out + ".";
}

}  // namespace

Json ensembleMemberJson(const EnsembleMember& m, bool with_series) {
    Json obs = Json::object();
    for (const auto& [id, values] : m.observables) {
        Json v = Json::array();
        for (double x : values) v.push_back(number(x));
        obs[id] = v;
    }
    Json j = {{"member", m.member},
              {"finite", m.finite},
              {"valid", m.valid},
              {"invalid_reason", m.invalid_reason},
              {"observables", obs},
              {"not_reached", m.not_reached},
              {"event_time_resolution_s", m.event_time_resolution},
              {"state_hash", m.state_hash},
              {"wall_s", m.wall_s}};
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
    doc["summary"] =
        "Member m starts from the same perturbed state on every backend, so scalars are also tested in pairs. " +
        droppedSummary(r);
    doc["scene"] = {{"name", r.scene.name}, {"source", o.source}, {"sha256", r.scene.source_sha256}, {"bodies", r.scene.bodies.size()}};
    doc["backends"] = backendsJson(r.backends);
    doc["support"] = r.support;
    doc["parameters"] = {{"members", o.members},
                         {"duration_s", o.duration},
                         {"frame_dt_s", o.frame_dt},
                         {"seed", o.seed},
                         {"perturb",
                          {{"positions_m", o.perturb.position},
                           {"velocities_m_per_s", o.perturb.velocity},
                           {"orientations_rad", o.perturb.orientation},
                           {"angular_rad_per_s", o.perturb.angular_velocity}}},
                         {"alpha", o.alpha},
                         {"statistic",
                          "energy distance (unbiased U-statistic), permutation test; scalars also a paired "
                          "sign-flip test; Holm-adjusted; effect above the resolution floor"},
                         {"permutations", r.permutations},
                         {"tests", r.tests.size()}};
    Json tests_json = Json::array();
    for (const EnsembleTest& t : r.tests) tests_json.push_back(testJson(t, unitsOf(r, t.observable)));
    Json verdict_json = Json::object();
    for (const auto& [pair, v] : verdicts(r)) {
        std::vector<std::string> not_by = v.not_distinguishable;
        not_by.insert(not_by.end(), v.within_resolution.begin(), v.within_resolution.end());
        verdict_json[pair] = {{"distinguishable_by", v.distinguishable},
                              {"not_distinguishable_by", not_by},
                              {"within_resolution", v.within_resolution},
                              {"not_reached", v.not_reached},
                              {"too_few_members", v.too_few}};
    }
    // Per backend: mean and spread of each observable, and determinism facts.
    std::vector<std::vector<Json>> summary_rows;
    Json per_backend = Json::object();
    for (std::size_t bi = 0; bi < r.backends.size(); ++bi) {
        const std::string& name = r.backends[bi].info->name;
        double wall = 0;
        int finite = 0, valid = 0;
        Json stored = Json::array(), dropped = Json::object();
        for (const EnsembleMember& m : r.members[bi]) {
            stored.push_back(ensembleMemberJson(m, false));
            wall += m.wall_s;
            finite += m.finite ? 1 : 0;
            valid += m.valid ? 1 : 0;
        }
        for (const EnsembleObservable& ob : r.observables) {
            const std::vector<DroppedMember> d = droppedMembers(r.members[bi], ob.id);
            if (!d.empty()) dropped[ob.id] = droppedJson(d);
            const auto [mean, spread] = meanSpread(ensembleSamples(r.members[bi], ob.id));
            summary_rows.push_back({ob.id, ob.units, name, number(mean), number(spread)});
        }
        per_backend[name] = {{"members", stored},
                             {"finite_members", finite},
                             {"valid_members", valid},
                             {"dropped", dropped},
                             {"wall_total_s", wall}};
    }
    doc["results"] = {{"tests", tests_json}, {"verdicts", verdict_json}, {"backends", per_backend}};
    doc["tables"].push_back(digestTable(r));
    doc["tables"].push_back(testsTable(r));
    const Json dropped_table = droppedTable(r);
    if (!dropped_table["rows"].empty()) doc["tables"].push_back(dropped_table);
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
    auto list = [](const std::vector<std::string>& l) { return l.empty() ? std::string("none") : joinText(l); };
    std::string out;
    for (const auto& [pair, v] : verdicts(r)) {
        out += pair + ": distinguishable by " + list(v.distinguishable) + "; not by " + list(v.not_distinguishable);
        if (!v.within_resolution.empty()) out += "; within resolution: " + joinText(v.within_resolution);
        if (!v.not_reached.empty()) out += "; not reached: " + joinText(v.not_reached);
        if (!v.too_few.empty()) out += "; too few members: " + joinText(v.too_few);
        out += "\n";
    }
    return out + droppedSummary(r) + "\n";
}

}  // namespace vroc::harness
