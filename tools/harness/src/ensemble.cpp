// SPDX-License-Identifier: MIT
#include "vroc/harness/ensemble.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "vroc/core/build_info.h"
#include "vroc/core/errors.h"
#include "vroc/core/state_hash.h"
#include "vroc/harness/ensemble_document.h"
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

// The observables of a scene, in report order.
std::vector<EnsembleObservable> observables(const Scene& scene) {
    const std::vector<int> bodies = virtualBodyIndices(scene);
    std::vector<EnsembleObservable> out = {
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

std::vector<double> numbers(const Json& list) {
    std::vector<double> out;
    for (const Json& v : list) out.push_back(v.is_null() ? NAN : v.get<double>());
    return out;
}

EnsembleMember memberFromJson(const Json& j) {
    EnsembleMember m;
    m.member = j.at("member").get<int>();
    m.finite = j.at("finite").get<bool>();
    for (const auto& [id, values] : j.at("observables").items()) m.observables[id] = numbers(values);
    const Json& series = j.at("series");
    m.t = numbers(series.at("t_s"));
    m.kinetic_energy = numbers(series.at("kinetic_energy_J"));
    m.mean_height = numbers(series.at("mean_height_m"));
    m.state_hash = j.at("state_hash").get<std::string>();
    m.wall_s = j.at("wall_s").get<double>();
    return m;
}

// One member on one backend: the observables, a decimated time series, and the final state hash.
EnsembleMember runMember(const Scene& scene, const SelectedBackend& b, const EnsembleOptions& o, int member) {
    RunOptions ro;
    ro.frame_dt = o.frame_dt;
    ro.frames = frameCount(o.duration, o.frame_dt);
    ro.record_every = std::max<std::int64_t>(1, ro.frames / std::max(1, o.series_points));
    ro.initial_states = ensembleMemberStates(scene, o.perturb, o.seed, member);
    const RunTrace t = runBackend(*b.info, scene, b.settings, ro);
    const std::vector<int> bodies = virtualBodyIndices(scene);
    const double merge = 2.5 * o.frame_dt;   // contact points of one impact arrive over a few frames
    const double end = t.times.back();
    EnsembleMember m;
    m.member = member;
    m.finite = t.finite;
    std::vector<double>& all_rest = m.observables["rest_positions"];
    double first_any = end;
    int impacts = 0;
    for (int bi : bodies) {
        const Body& body = scene.bodies[static_cast<std::size_t>(bi)];
        const Vec3 rest = centerOfMass(body, t.states.back()[static_cast<std::size_t>(bi)]);
        for (int k = 0; k < 3; ++k) all_rest.push_back(rest[k]);
        const std::vector<double> hits = impactTimes(t.events, bi, merge);
        impacts += static_cast<int>(hits.size());
        const double first = hits.empty() ? end : hits.front();
        first_any = std::min(first_any, first);
        if (bodies.size() <= kMaxBodiesNamed) {
            m.observables["rest_position:" + body.name] = {rest.x(), rest.y(), rest.z()};
            m.observables["first_impact_time:" + body.name] = {first};
        }
    }
    m.observables["first_impact_time"] = {first_any};
    m.observables["impacts"] = {static_cast<double>(impacts)};
    const std::optional<double> rest = restTime(scene, t);
    m.observables["rest_time"] = {rest ? *rest : end};
    m.observables["final_energy"] = {t.invariants.back().energy()};
    m.observables["final_kinetic_energy"] = {t.invariants.back().kinetic};
    for (std::size_t f = 0; f < t.times.size(); ++f) {
        m.t.push_back(t.times[f]);
        m.kinetic_energy.push_back(t.invariants[f].kinetic);
        double z = 0;
        for (int bi : bodies) z += centerOfMass(scene.bodies[static_cast<std::size_t>(bi)], t.states[f][static_cast<std::size_t>(bi)]).z();
        m.mean_height.push_back(bodies.empty() ? 0 : z / double(bodies.size()));
    }
    m.state_hash = hashToHex(stateHash(t.states.back()));
    m.wall_s = t.wallTotal();
    return m;
}

}  // namespace

std::vector<Sample> ensembleSamples(const std::vector<EnsembleMember>& members, const std::string& id) {
    std::vector<Sample> out;
    for (const EnsembleMember& m : members) {
        const auto it = m.observables.find(id);
        if (it == m.observables.end() || it->second.empty()) continue;
        if (std::all_of(it->second.begin(), it->second.end(), [](double v) { return std::isfinite(v); })) out.push_back(it->second);
    }
    return out;
}

namespace {

// Every observable between every backend pair. Enough permutations that the smallest possible
// p-value, 1 / (permutations + 1), can pass Holm's first threshold alpha / tests twice over:
// with too few, no observable could ever distinguish the backends.
void runTests(EnsembleResult& r) {
    const EnsembleOptions& o = r.options;
    const std::size_t n = r.backends.size();
    const std::size_t family = r.observables.size() * n * (n - 1) / 2;
    r.permutations = o.permutations > 0 ? o.permutations : std::max(999, static_cast<int>(std::ceil(2.0 * double(family) / o.alpha)));
    std::uint64_t test_seed = o.seed;
    for (const EnsembleObservable& ob : r.observables)
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j) {
                const std::vector<Sample> x = ensembleSamples(r.members[i], ob.id), y = ensembleSamples(r.members[j], ob.id);
                ++test_seed;
                if (x.size() < 2 || y.size() < 2) continue;
                EnsembleTest t{ob.id, r.backends[i].info->name, r.backends[j].info->name, x.size(), y.size(),
                               energyPermutationTest(x, y, r.permutations, test_seed), NAN, NAN, false};
                if (x.front().size() == 1) {
                    std::vector<double> xs, ys;
                    for (const Sample& s : x) xs.push_back(s[0]);
                    for (const Sample& s : y) ys.push_back(s[0]);
                    t.wasserstein1 = wasserstein1(xs, ys);
                }
                r.tests.push_back(t);
            }
    std::vector<double> p;
    for (const EnsembleTest& t : r.tests) p.push_back(t.test.p_value);
    const std::vector<double> p_holm = holmAdjusted(p);
    for (std::size_t k = 0; k < r.tests.size(); ++k) {
        r.tests[k].p_holm = p_holm[k];
        r.tests[k].distinguishable = p_holm[k] < o.alpha;
    }
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

EnsembleResult runEnsemble(const Scene& scene, const std::vector<SelectedBackend>& requested, const EnsembleOptions& o, RunPool& pool) {
    if (o.members < 2) throw InputError("--members: expected at least 2 members per backend");
    if (!(o.duration > 0) || !(o.frame_dt > 0)) throw InputError("--duration and --dt: expected positive seconds");
    EnsembleResult r;
    r.scene = scene;
    r.options = o;
    r.backends = representableBackends(scene, requested, "ensemble", mpi::isRoot(), r.support);
    if (r.backends.size() < 2) throw InputError("vroc ensemble compares backends: give at least two that can represent the scene");
    r.observables = observables(scene);
    std::vector<PoolJob> jobs;
    for (const SelectedBackend& b : r.backends)
        for (int m = 0; m < o.members; ++m)
            jobs.push_back({poolJobId("member-" + b.info->name + "-" + std::to_string(m)),
                            [&scene, &b, &o, m] { return ensembleMemberJson(runMember(scene, b, o, m), true); }});
    const std::vector<Json> done = pool.run(jobs);
    r.members.resize(r.backends.size());
    for (std::size_t bi = 0; bi < r.backends.size(); ++bi)
        for (int m = 0; m < o.members; ++m)
            r.members[bi].push_back(memberFromJson(done[bi * static_cast<std::size_t>(o.members) + static_cast<std::size_t>(m)]));
    runTests(r);
    r.execution = pool.execution();
    return r;
}

}  // namespace vroc::harness
