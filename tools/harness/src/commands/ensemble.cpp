// SPDX-License-Identifier: MIT
#include "vroc/harness/commands/ensemble.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "vroc/core/backend_vocabulary.h"
#include "vroc/core/build_info.h"
#include "vroc/core/errors.h"
#include "vroc/core/state_hash.h"
#include "vroc/harness/documents/ensemble_document.h"
#include "vroc/harness/metrics/event_timing.h"
#include "vroc/harness/metrics/invariants.h"
#include "vroc/harness/pool/mpi_world.h"
#include "vroc/harness/runs/run_trace.h"
#include "vroc/harness/runs/run_validity.h"
#include "vroc/harness/statistics/timing_stats.h"
#include "vroc/harness/statistics/two_sample_tests.h"

namespace vroc::harness {
namespace {

// Bodies named one by one in the tests; beyond this only their joint rest positions are tested.
constexpr std::size_t kMaxBodiesNamed = 8;

// The observables of a scene, in report order.
std::vector<EnsembleObservable> observables(const Scene& scene) {
    const std::vector<int> bodies = virtualBodyIndices(scene);
    using enum ObservableTiming;
    std::vector<EnsembleObservable> out = {
        {"rest_positions", "rest positions of all virtual bodies (joint)", "m", none},
        {"first_impact_time", "time of the first impact", "s", event},
        {"impacts", "impacts, all virtual bodies", "-", none},
        {"rest_time", "time from which every body rests (end of run if never)", "s", sampled},
        {"final_energy", "mechanical energy at the end", "J", none},
        {"final_kinetic_energy", "kinetic energy at the end", "J", none},
    };
    if (bodies.size() <= kMaxBodiesNamed)
        for (int b : bodies) {
            const std::string& name = scene.bodies[static_cast<std::size_t>(b)].name;
            out.push_back({"rest_position:" + name, "rest position of " + name, "m", none});
            out.push_back({"first_impact_time:" + name, "first impact of " + name, "s", event});
        }
    return out;
}

// Recorded frames of a member: about series_points of them.
std::int64_t recordEvery(const EnsembleOptions& o) {
    return std::max<std::int64_t>(1, frameCount(o.duration, o.frame_dt) / std::max(1, o.series_points));
}

// [s] how finely a run's event times are known: an event is reported at the end of the internal
// step that found it (docs/events.md), so to one mean internal step, never coarser than a frame.
double eventTimeResolution(const RunTrace& t) {
    const auto steps = t.statistics.find(vocabulary::kInternalSteps);
    if (steps == t.statistics.end() || !(steps->second > 0)) return t.frame_dt;
    return std::min(t.frame_dt, t.simulatedTime() / steps->second);
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
    m.valid = j.value("valid", true);
    m.invalid_reason = j.value("invalid_reason", "");
    for (const auto& [id, values] : j.at("observables").items()) m.observables[id] = numbers(values);
    m.not_reached = j.value("not_reached", std::vector<std::string>{});
    m.event_time_resolution = j.value("event_time_resolution_s", 0.0);
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
    ro.record_every = recordEvery(o);
    ro.initial_states = ensembleMemberStates(scene, o.perturb, o.seed, member);
    const RunTrace t = runBackend(*b.info, scene, b.settings, ro);
    const std::vector<int> bodies = virtualBodyIndices(scene);
    const double merge = 2.5 * o.frame_dt;   // contact points of one impact arrive over a few frames
    const double end = t.times.back();
    EnsembleMember m;
    m.member = member;
    m.finite = t.finite;
    const RunValidity validity = runValidity(t);
    m.valid = validity.valid;
    m.invalid_reason = validity.reason;
    m.event_time_resolution = eventTimeResolution(t);
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
            if (hits.empty()) m.not_reached.push_back("first_impact_time:" + body.name);
        }
    }
    m.observables["first_impact_time"] = {first_any};
    if (impacts == 0) m.not_reached.push_back("first_impact_time");
    m.observables["impacts"] = {static_cast<double>(impacts)};
    const std::optional<double> rest = restTime(scene, t);
    m.observables["rest_time"] = {rest ? *rest : end};
    if (!rest) m.not_reached.push_back("rest_time");
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

// Why member m is left out of observable `id`, or nothing when it is used.
std::optional<std::string> droppedReason(const EnsembleMember& m, const std::string& id) {
    if (!m.valid) return invalidLabel(RunValidity{false, m.invalid_reason});
    const auto it = m.observables.find(id);
    if (it == m.observables.end() || it->second.empty()) return "no value";
    if (!std::all_of(it->second.begin(), it->second.end(), [](double v) { return std::isfinite(v); }))
        return "value not finite";
    return std::nullopt;
}

bool reached(const EnsembleMember& m, const std::string& id) {
    return std::find(m.not_reached.begin(), m.not_reached.end(), id) == m.not_reached.end();
}

// Std of a scalar sample; for vectors the RMS distance to the mean vector.
double spreadOf(const std::vector<Sample>& s) {
    Sample mean(s.front().size(), 0.0);
    for (const Sample& x : s)
        for (std::size_t k = 0; k < x.size(); ++k) mean[k] += x[k] / double(s.size());
    double sq = 0;
    for (const Sample& x : s)
        for (std::size_t k = 0; k < x.size(); ++k) sq += (x[k] - mean[k]) * (x[k] - mean[k]) / double(s.size());
    return std::sqrt(sq);
}

// The values of the members usable on both sides, paired by member number (scalars only).
std::pair<std::vector<double>, std::vector<double>> pairedValues(const EnsembleSide& a, const EnsembleSide& b) {
    std::pair<std::vector<double>, std::vector<double>> out;
    if (a.values.empty() || b.values.empty() || a.values.front().size() != 1) return out;
    std::map<int, double> by_member;
    for (std::size_t k = 0; k < b.members.size(); ++k) by_member[b.members[k]] = b.values[k][0];
    for (std::size_t k = 0; k < a.members.size(); ++k) {
        const auto it = by_member.find(a.members[k]);
        if (it == by_member.end()) continue;
        out.first.push_back(a.values[k][0]);
        out.second.push_back(it->second);
    }
    return out;
}

bool testable(const EnsembleObservable& ob, const EnsembleSide& a, const EnsembleSide& b) {
    if (a.values.size() < 2 || b.values.size() < 2) return false;
    return ob.timing == ObservableTiming::none || (a.reached > 0 && b.reached > 0);
}

}  // namespace

const char* verdictName(EnsembleVerdict v) {
    switch (v) {
        case EnsembleVerdict::distinguishable:
            return "distinguishable";
        case EnsembleVerdict::not_distinguishable:
            return "not distinguishable";
        case EnsembleVerdict::within_resolution:
            return "within resolution";
        case EnsembleVerdict::not_reached:
            return "not reached";
        case EnsembleVerdict::too_few_members:
            return "too few members";
    }
    return "?";
}

const char* effectClassName(EffectClass c) {
    switch (c) {
        case EffectClass::none:
            return "none";
        case EffectClass::small:
            return "small";
        case EffectClass::medium:
            return "medium";
        case EffectClass::large:
            return "large";
        case EffectClass::not_applicable:
            return "n/a";
    }
    return "?";
}

std::vector<Sample> ensembleSamples(const std::vector<EnsembleMember>& members, const std::string& id) {
    std::vector<Sample> out;
    for (const EnsembleMember& m : members)
        if (!droppedReason(m, id)) out.push_back(m.observables.at(id));
    return out;
}

std::vector<DroppedMember> droppedMembers(const std::vector<EnsembleMember>& members, const std::string& id) {
    std::vector<DroppedMember> out;
    for (const EnsembleMember& m : members)
        if (const auto reason = droppedReason(m, id)) out.push_back({m.member, *reason});
    return out;
}

EnsembleSide ensembleSide(const std::string& backend, const std::vector<EnsembleMember>& members,
                          const EnsembleObservable& ob, double sampled_resolution) {
    EnsembleSide side;
    side.backend = backend;
    for (const EnsembleMember& m : members) {
        if (const auto reason = droppedReason(m, ob.id)) {
            side.dropped.push_back({m.member, *reason});
            continue;
        }
        side.values.push_back(m.observables.at(ob.id));
        side.members.push_back(m.member);
        side.reached += reached(m, ob.id) ? 1 : 0;
        if (ob.timing == ObservableTiming::event) side.resolution = std::max(side.resolution, m.event_time_resolution);
    }
    if (ob.timing == ObservableTiming::sampled) side.resolution = sampled_resolution;
    return side;
}

std::size_t ensembleHypotheses(const EnsembleObservable& ob, const EnsembleSide& a, const EnsembleSide& b) {
    if (!testable(ob, a, b)) return 0;
    return pairedValues(a, b).first.size() >= 2 ? 2 : 1;
}

EnsembleTest ensembleTest(const EnsembleObservable& ob, const EnsembleSide& a, const EnsembleSide& b, int permutations,
                          std::uint64_t seed) {
    EnsembleTest t;
    t.observable = ob.id;
    t.a = a.backend;
    t.b = b.backend;
    t.members_a = a.values.size();
    t.members_b = b.values.size();
    t.reached_a = a.reached;
    t.reached_b = b.reached;
    t.dropped_a = a.dropped;
    t.dropped_b = b.dropped;
    t.resolution_a = a.resolution;
    t.resolution_b = b.resolution;
    t.floor = std::max(a.resolution, b.resolution);
    if (a.values.size() < 2 || b.values.size() < 2) return t;  // too few members
    if (!testable(ob, a, b)) {
        t.verdict = EnsembleVerdict::not_reached;
        for (const EnsembleSide* s : {&a, &b})
            if (s->reached == 0) t.not_reached_by.push_back(s->backend);
        return t;
    }
    t.verdict = EnsembleVerdict::not_distinguishable;  // until concludeEnsembleTests
    t.test = energyPermutationTest(a.values, b.values, permutations, seed);
    t.effect = marginalWasserstein1(a.values, b.values);
    if (a.values.front().size() == 1) t.wasserstein1 = t.effect;
    const double sa = spreadOf(a.values), sb = spreadOf(b.values);
    t.spread = std::sqrt(0.5 * (sa * sa + sb * sb));
    const double scale = std::max(t.floor, t.spread);
    t.standardized_effect = scale > 0 ? t.effect / scale : (t.effect > 0 ? INFINITY : 0.0);
    const auto [pa, pb] = pairedValues(a, b);
    // Its own stream of flips, so the paired test does not reuse the energy test's shuffles.
    if (pa.size() >= 2) t.paired = pairedSignFlipTest(pa, pb, permutations, seed ^ 0x632BE59BD9B4E019ull);
    return t;
}

void concludeEnsembleTests(std::vector<EnsembleTest>& tests, double alpha) {
    auto tested = [](const EnsembleTest& t) {
        return t.verdict != EnsembleVerdict::not_reached && t.verdict != EnsembleVerdict::too_few_members;
    };
    std::vector<double> p;
    for (const EnsembleTest& t : tests) {
        if (!tested(t)) continue;
        p.push_back(t.test.p_value);
        if (t.paired.pairs >= 2) p.push_back(t.paired.p_value);
    }
    const std::vector<double> adjusted = holmAdjusted(p);
    std::size_t k = 0;
    for (EnsembleTest& t : tests) {
        if (!tested(t)) continue;
        t.p_holm_unpaired = adjusted[k++];
        if (t.paired.pairs >= 2) t.p_holm_paired = adjusted[k++];
        t.p_holm = std::isnan(t.p_holm_paired) ? t.p_holm_unpaired : std::min(t.p_holm_unpaired, t.p_holm_paired);
        if (!(t.p_holm < alpha))
            t.verdict = EnsembleVerdict::not_distinguishable;
        else if (!(t.effect > t.floor))
            t.verdict = EnsembleVerdict::within_resolution;
        else
            t.verdict = EnsembleVerdict::distinguishable;
        t.distinguishable = t.verdict == EnsembleVerdict::distinguishable;
        // Effect relative to the larger of the floor and the pooled spread: below 1 the ensembles
        // overlap more than they differ, from 3 on they barely overlap.
        t.effect_class = !t.distinguishable            ? EffectClass::none
                         : t.standardized_effect < 1.0 ? EffectClass::small
                         : t.standardized_effect < 3.0 ? EffectClass::medium
                                                       : EffectClass::large;
    }
}

namespace {

// Every observable between every backend pair. Enough permutations that the smallest possible
// p-value, 1 / (permutations + 1), can pass Holm's first threshold alpha / hypotheses twice over:
// with too few, no observable could ever distinguish the backends.
void runTests(EnsembleResult& r) {
    const EnsembleOptions& o = r.options;
    const std::size_t n = r.backends.size();
    const double sampled_resolution = double(recordEvery(o)) * o.frame_dt;  // [s] rest time: recorded frames
    std::vector<std::vector<EnsembleSide>> sides(r.observables.size());     // [observable][backend]
    std::size_t family = 0;
    for (std::size_t k = 0; k < r.observables.size(); ++k) {
        for (std::size_t i = 0; i < n; ++i)
            sides[k].push_back(
                ensembleSide(r.backends[i].info->name, r.members[i], r.observables[k], sampled_resolution));
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                family += ensembleHypotheses(r.observables[k], sides[k][i], sides[k][j]);
    }
    r.permutations = o.permutations > 0 ? o.permutations : std::max(999, static_cast<int>(std::ceil(2.0 * double(family) / o.alpha)));
    std::uint64_t test_seed = o.seed;
    for (std::size_t k = 0; k < r.observables.size(); ++k)
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                r.tests.push_back(
                    ensembleTest(r.observables[k], sides[k][i], sides[k][j], r.permutations, ++test_seed));
    concludeEnsembleTests(r.tests, o.alpha);
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
