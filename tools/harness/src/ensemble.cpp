// SPDX-License-Identifier: MIT
#include "vroc/harness/ensemble.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "vroc/core/build_info.h"
#include "vroc/core/errors.h"
#include "vroc/core/state_hash.h"
#include "vroc/harness/event_timing.h"
#include "vroc/harness/invariants.h"
#include "vroc/harness/mpi_world.h"
#include "vroc/harness/run_trace.h"
#include "vroc/harness/timing_stats.h"
#include "vroc/harness/two_sample_tests.h"

namespace vroc::harness {
namespace {

// Bodies named one by one in the tests; beyond this only their joint rest positions are tested.
constexpr std::size_t kMaxBodiesNamed = 8;

struct Observable {
    std::string id;       ///< key in each member's result
    std::string title;
    std::string units;
};

// The observables of a scene, in report order.
std::vector<Observable> observables(const Scene& scene) {
    const std::vector<int> bodies = virtualBodyIndices(scene);
    std::vector<Observable> out = {
        {"rest_positions", "rest positions of all virtual bodies (joint)", "m"},
        {"first_impact_time", "time of the first impact", "s"},
        {"impacts", "impacts, all virtual bodies", "-"},
        {"rest_time", "time from which every body rests (end of run if never)", "s"},
        {"final_energy", "mechanical energy at the end", "J"},
        {"final_kinetic_energy", "kinetic energy at the end", "J"},
    };
    if (bodies.size() <= kMaxBodiesNamed)
        for (int b : bodies) {
            const std::string& name = scene.bodies[static_cast<std::size_t>(b)].name;
            out.push_back({"rest_position:" + name, "rest position of " + name, "m"});
            out.push_back({"first_impact_time:" + name, "first impact of " + name, "s"});
        }
    return out;
}

Json vec3(const Vec3& v) { return Json::array({v.x(), v.y(), v.z()}); }

// One member on one backend: the observables, a decimated time series, and the final state hash.
Json runMember(const Scene& scene, const SelectedBackend& b, const EnsembleOptions& o, int member) {
    RunOptions ro;
    ro.frame_dt = o.frame_dt;
    ro.frames = framesFor(o.duration, o.frame_dt);
    ro.record_every = std::max<std::int64_t>(1, ro.frames / std::max(1, o.series_points));
    ro.initial_states = ensembleMemberStates(scene, o.perturb, o.seed, member);
    const RunTrace t = runBackend(*b.info, scene, b.settings, ro);
    const std::vector<int> bodies = virtualBodyIndices(scene);
    const double merge = 2.5 * o.frame_dt;   // contact points of one impact arrive over a few frames
    const double end = t.times.back();
    Json obs = Json::object();
    Json all_rest = Json::array();
    double first_any = end;
    int impacts = 0;
    for (int bi : bodies) {
        const Body& body = scene.bodies[static_cast<std::size_t>(bi)];
        const Vec3 rest = centerOfMass(body, t.states.back()[static_cast<std::size_t>(bi)]);
        for (int k = 0; k < 3; ++k) all_rest.push_back(number(rest[k]));
        const std::vector<double> hits = impactTimes(t.events, bi, merge);
        impacts += static_cast<int>(hits.size());
        const double first = hits.empty() ? end : hits.front();
        first_any = std::min(first_any, first);
        if (bodies.size() <= kMaxBodiesNamed) {
            obs["rest_position:" + body.name] = vec3(rest);
            obs["first_impact_time:" + body.name] = Json::array({first});
        }
    }
    obs["rest_positions"] = all_rest;
    obs["first_impact_time"] = Json::array({first_any});
    obs["impacts"] = Json::array({impacts});
    const std::optional<double> rest = restTime(scene, t);
    obs["rest_time"] = Json::array({rest ? *rest : end});
    obs["final_energy"] = Json::array({number(t.invariants.back().energy())});
    obs["final_kinetic_energy"] = Json::array({number(t.invariants.back().kinetic)});
    Json times = Json::array(), ke = Json::array(), height = Json::array();
    for (std::size_t f = 0; f < t.times.size(); ++f) {
        times.push_back(t.times[f]);
        ke.push_back(number(t.invariants[f].kinetic));
        double z = 0;
        for (int bi : bodies) z += centerOfMass(scene.bodies[static_cast<std::size_t>(bi)], t.states[f][static_cast<std::size_t>(bi)]).z();
        height.push_back(number(bodies.empty() ? 0 : z / double(bodies.size())));
    }
    return {{"member", member}, {"finite", t.finite}, {"observables", obs},
            {"series", {{"t_s", times}, {"kinetic_energy_J", ke}, {"mean_height_m", height}}},
            {"state_hash", hashToHex(stateHash(t.states.back()))}, {"wall_s", t.wallTotal()}};
}

// Members' values of one observable (a missing or non-finite value drops that member).
std::vector<Sample> samples(const std::vector<Json>& members, const std::string& id) {
    std::vector<Sample> out;
    for (const Json& m : members) {
        if (!m["observables"].contains(id)) continue;
        Sample s;
        bool finite = true;
        for (const Json& v : m["observables"][id]) {
            if (v.is_null()) finite = false;
            else s.push_back(v.get<double>());
        }
        if (finite && !s.empty()) out.push_back(s);
    }
    return out;
}

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
void spreadSeries(const std::vector<Json>& members, const std::string& key, const std::string& name, ChartSpec& chart) {
    if (members.empty()) return;
    const Json& t = members.front()["series"]["t_s"];
    ChartSeries p10{name + " p10", "lines", {}, {}}, p50{name + " median", "lines", {}, {}}, p90{name + " p90", "lines", {}, {}};
    for (std::size_t f = 0; f < t.size(); ++f) {
        std::vector<double> v;
        for (const Json& m : members) {
            const Json& x = m["series"][key];
            if (f < x.size() && !x[f].is_null()) v.push_back(x[f].get<double>());
        }
        if (v.empty()) continue;
        const double tf = t[f].get<double>();
        p10.x.push_back(tf); p10.y.push_back(percentile(v, 10));
        p50.x.push_back(tf); p50.y.push_back(percentile(v, 50));
        p90.x.push_back(tf); p90.y.push_back(percentile(v, 90));
    }
    chart.series.push_back(p10);
    chart.series.push_back(p50);
    chart.series.push_back(p90);
}

}  // namespace

Perturbation parsePerturbation(const std::string& text) {
    Perturbation p;
    std::string item;
    for (char c : text + ",") {
        if (c != ',') { item += c; continue; }
        if (item.empty()) continue;
        const auto eq = item.find('=');
        const std::string key = item.substr(0, eq);
        char* end = nullptr;
        const double v = eq == std::string::npos ? NAN : std::strtod(item.c_str() + eq + 1, &end);
        if (eq == std::string::npos || *end != '\0' || !(v >= 0) || !std::isfinite(v))
            throw InputError("--perturb: '" + item + "': expected KEY=SIGMA with SIGMA >= 0 (e.g. positions=1e-6)");
        if (key == "positions") p.position = v;
        else if (key == "velocities") p.velocity = v;
        else if (key == "orientations") p.orientation = v;
        else if (key == "angular") p.angular_velocity = v;
        else throw InputError("--perturb: unknown key '" + key + "' (known: positions [m], velocities [m/s], orientations [rad], angular [rad/s])");
        item.clear();
    }
    return p;
}

std::vector<BodyState> ensembleMemberStates(const Scene& scene, const Perturbation& p, std::uint64_t seed, int member) {
    std::vector<BodyState> states = initialStates(scene);
    // One generator per member, seeded from (seed, member): a member's noise does not depend on how
    // many members there are or which process runs it.
    SplitMix64 rng(seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(member) + 1);
    auto noise = [&](double sigma) { return Vec3(sigma * rng.normal(), sigma * rng.normal(), sigma * rng.normal()); };
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        if (!scene.bodies[i].isDynamic()) continue;
        BodyState& s = states[i];
        s.pose.position += noise(p.position);
        s.linear_velocity += noise(p.velocity);
        const Vec3 r = noise(p.orientation);
        if (r.norm() > 0) s.pose.orientation = (Quat(Eigen::AngleAxisd(r.norm(), r.normalized())) * s.pose.orientation).normalized();
        s.angular_velocity += noise(p.angular_velocity);
    }
    return states;
}

Json ensemblePlan(const Scene& scene, const std::vector<SelectedBackend>& backends, const EnsembleOptions& o) {
    const BuildInfo& b = buildInfo();
    return {{"command", "ensemble"}, {"scene", o.source}, {"scene_sha256", scene.source_sha256}, {"backends", backendsJson(backends)},
            {"members", o.members}, {"perturb", {o.perturb.position, o.perturb.velocity, o.perturb.orientation, o.perturb.angular_velocity}},
            {"duration_s", o.duration}, {"frame_dt_s", o.frame_dt}, {"seed", o.seed}, {"series_points", o.series_points},
            {"build", {{"version", b.version}, {"commit", b.commit}}}};
}

Json runEnsemble(const Scene& scene, const std::vector<SelectedBackend>& requested, const EnsembleOptions& o, RunPool& pool) {
    if (o.members < 2) throw InputError("--members: expected at least 2 members per backend");
    if (!(o.duration > 0) || !(o.frame_dt > 0)) throw InputError("--duration and --dt: expected positive seconds");
    Json support;
    const std::vector<SelectedBackend> backends = representableBackends(scene, requested, "ensemble", mpi::isRoot(), support);
    if (backends.size() < 2) throw InputError("vroc ensemble compares backends: give at least two that can represent the scene");

    std::vector<PoolJob> jobs;
    for (const SelectedBackend& b : backends)
        for (int m = 0; m < o.members; ++m)
            jobs.push_back({poolJobId("member-" + b.info->name + "-" + std::to_string(m)), [&scene, &b, &o, m] { return runMember(scene, b, o, m); }});
    const std::vector<Json> results = pool.run(jobs);
    std::map<std::string, std::vector<Json>> members;
    for (std::size_t bi = 0; bi < backends.size(); ++bi)
        for (int m = 0; m < o.members; ++m) members[backends[bi].info->name].push_back(results[bi * static_cast<std::size_t>(o.members) + static_cast<std::size_t>(m)]);

    Json doc = newDocument("ensemble", o.command_line);
    doc["title"] = "ensemble of " + std::to_string(o.members) + " perturbed runs per backend on '" + scene.name + "'";
    doc["scene"] = {{"name", scene.name}, {"source", o.source}, {"sha256", scene.source_sha256}, {"bodies", scene.bodies.size()}};
    doc["backends"] = backendsJson(backends);
    doc["support"] = support;
    doc["parameters"] = {{"members", o.members}, {"duration_s", o.duration}, {"frame_dt_s", o.frame_dt}, {"seed", o.seed},
                         {"perturb", {{"positions_m", o.perturb.position}, {"velocities_m_per_s", o.perturb.velocity},
                                      {"orientations_rad", o.perturb.orientation}, {"angular_rad_per_s", o.perturb.angular_velocity}}},
                         {"alpha", o.alpha}, {"statistic", "energy distance, permutation test, Holm-adjusted"}};

    // Tests: every observable, every backend pair. Enough permutations that the smallest possible
    // p-value, 1 / (permutations + 1), can pass Holm's first threshold alpha / tests twice over:
    // with too few, no observable could ever distinguish the backends.
    const std::vector<Observable> obs = observables(scene);
    const std::size_t family = obs.size() * backends.size() * (backends.size() - 1) / 2;
    const int permutations = o.permutations > 0 ? o.permutations
                                                : std::max(999, static_cast<int>(std::ceil(2.0 * double(family) / o.alpha)));
    struct Test { std::string observable, a, b; PermutationTest t; double w1 = NAN; std::size_t na = 0, nb = 0; };
    std::vector<Test> tests;
    std::uint64_t test_seed = o.seed;
    for (const Observable& ob : obs)
        for (std::size_t i = 0; i < backends.size(); ++i)
            for (std::size_t j = i + 1; j < backends.size(); ++j) {
                const std::string& a = backends[i].info->name;
                const std::string& b = backends[j].info->name;
                const std::vector<Sample> x = samples(members[a], ob.id), y = samples(members[b], ob.id);
                ++test_seed;
                if (x.size() < 2 || y.size() < 2) continue;
                Test t{ob.id, a, b, energyPermutationTest(x, y, permutations, test_seed), NAN, x.size(), y.size()};
                if (x.front().size() == 1) {
                    std::vector<double> xs, ys;
                    for (const Sample& s : x) xs.push_back(s[0]);
                    for (const Sample& s : y) ys.push_back(s[0]);
                    t.w1 = wasserstein1(xs, ys);
                }
                tests.push_back(t);
            }
    doc["parameters"]["permutations"] = permutations;
    doc["parameters"]["tests"] = tests.size();
    std::vector<double> p;
    for (const Test& t : tests) p.push_back(t.t.p_value);
    const std::vector<double> p_holm = holmAdjusted(p);

    auto units = [&](const std::string& id) {
        for (const Observable& ob : obs) if (ob.id == id) return ob.units;
        return std::string();
    };
    Json tests_json = Json::array();
    std::vector<std::vector<Json>> test_rows;
    std::map<std::string, std::pair<std::vector<std::string>, std::vector<std::string>>> verdicts;   // pair -> (yes, no)
    for (std::size_t k = 0; k < tests.size(); ++k) {
        const Test& t = tests[k];
        const bool distinct = p_holm[k] < o.alpha;
        tests_json.push_back({{"observable", t.observable}, {"units", units(t.observable)}, {"a", t.a}, {"b", t.b},
                              {"members_a", t.na}, {"members_b", t.nb}, {"energy_distance", t.t.statistic},
                              {"wasserstein1", number(t.w1)}, {"p_value", t.t.p_value}, {"p_holm", p_holm[k]},
                              {"distinguishable", distinct}});
        test_rows.push_back({t.observable, units(t.observable), t.a + " vs " + t.b, t.t.statistic, number(t.w1), t.t.p_value, p_holm[k],
                             distinct ? "yes" : "no"});
        auto& v = verdicts[t.a + " vs " + t.b];
        (distinct ? v.first : v.second).push_back(t.observable);
    }
    Json verdict_json = Json::object();
    for (const auto& [pair, v] : verdicts) verdict_json[pair] = {{"distinguishable_by", v.first}, {"not_distinguishable_by", v.second}};

    // Per backend: mean and spread of each observable, and determinism facts.
    std::vector<std::vector<Json>> summary_rows;
    Json per_backend = Json::object();
    for (const SelectedBackend& b : backends) {
        const std::string& name = b.info->name;
        Json hashes = Json::array();
        double wall = 0;
        int finite = 0;
        Json stored = Json::array();   // without the series: the charts hold their bands
        for (const Json& m : members[name]) {
            Json copy = m;
            copy.erase("series");
            stored.push_back(copy);
            hashes.push_back(m["state_hash"]);
            wall += m["wall_s"].get<double>();
            finite += m["finite"].get<bool>() ? 1 : 0;
        }
        per_backend[name] = {{"members", stored}, {"finite_members", finite}, {"wall_total_s", wall}};
        for (const Observable& ob : obs) {
            const auto [mean, spread] = meanSpread(samples(members[name], ob.id));
            summary_rows.push_back({ob.id, ob.units, name, number(mean), number(spread)});
        }
    }
    doc["results"] = {{"tests", tests_json}, {"verdicts", verdict_json}, {"backends", per_backend}};
    doc["tables"].push_back(tableJson("ensemble-tests",
        "Are the backends' ensembles distinguishable? Energy distance, permutation p-value, Holm-adjusted over all tests (alpha " +
            [&] { char b[16]; std::snprintf(b, sizeof b, "%g", o.alpha); return std::string(b); }() + ")",
        {"observable", "units", "backends", "energy distance [units]", "Wasserstein-1 [units]", "p", "p (Holm)", "distinguishable"}, test_rows));
    doc["tables"].push_back(tableJson("ensemble-summary", "Per backend: ensemble mean (vectors: norm of the mean) and spread (std; vectors: RMS distance to the mean)",
        {"observable", "units", "backend", "mean", "spread"}, summary_rows));
    ChartSpec ke{"ensemble-kinetic-energy", "Kinetic energy over time: ensemble median and 10-90 % band per backend", "t [s]", "kinetic energy [J]", false, false, {}};
    ChartSpec height{"ensemble-height", "Mean height of the virtual bodies over time: median and 10-90 % band per backend", "t [s]", "mean height [m]", false, false, {}};
    for (const SelectedBackend& b : backends) {
        spreadSeries(members[b.info->name], "kinetic_energy_J", b.info->name, ke);
        spreadSeries(members[b.info->name], "mean_height_m", b.info->name, height);
    }
    doc["charts"].push_back(chartJson(ke));
    doc["charts"].push_back(chartJson(height));
    doc["execution"] = pool.executionJson();
    return doc;
}

std::string ensembleVerdictText(const Json& doc) {
    std::string out;
    auto join = [](const Json& list) {
        std::string s;
        for (const Json& x : list) s += (s.empty() ? "" : ", ") + x.get<std::string>();
        return s.empty() ? std::string("none") : s;
    };
    for (const auto& [pair, v] : doc["results"]["verdicts"].items())
        out += pair + ": distinguishable by " + join(v["distinguishable_by"]) + "; not by " + join(v["not_distinguishable_by"]) + "\n";
    return out;
}

}  // namespace vroc::harness
