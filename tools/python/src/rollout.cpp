// SPDX-License-Identifier: MIT
#include "rollout.h"

#include <sys/mman.h>

#include <algorithm>
#include <chrono>

#include "state_rows.h"
#include "vroc/core/errors.h"
#include "vroc/core/state_hash.h"
#include "vroc/harness/pool/run_pool.h"
#include "vroc/harness/runs/backend_selection.h"
#include "vroc/harness/runs/run_trace.h"

namespace vroc::python {
namespace {

using harness::Json;

Json eventJson(const CollisionEvent& e) {
    return Json::array({e.time, e.body_a, e.body_b, e.point.x(), e.point.y(), e.point.z(), e.normal.x(), e.normal.y(),
                        e.normal.z(), e.impulse});
}

CollisionEvent eventFromJson(const Json& j) {
    CollisionEvent e;
    e.time = j.at(0).get<double>();
    e.body_a = j.at(1).get<int>();
    e.body_b = j.at(2).get<int>();
    e.point = Vec3(j.at(3).get<double>(), j.at(4).get<double>(), j.at(5).get<double>());
    e.normal = Vec3(j.at(6).get<double>(), j.at(7).get<double>(), j.at(8).get<double>());
    e.impulse = j.at(9).get<double>();
    return e;
}

/// Doubles in memory shared with the worker processes the pool forks after it was made: each
/// member's states are written straight into their place, by whichever process ran the member.
class SharedDoubles {
public:
    explicit SharedDoubles(std::size_t count) : bytes_(std::max<std::size_t>(count, 1) * sizeof(double)) {
        void* p = mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED) throw RunError("rollout: cannot map " + std::to_string(bytes_) + " bytes for the states");
        data_ = static_cast<double*>(p);
    }
    ~SharedDoubles() { munmap(data_, bytes_); }
    SharedDoubles(const SharedDoubles&) = delete;
    SharedDoubles& operator=(const SharedDoubles&) = delete;
    double* data() { return data_; }

private:
    std::size_t bytes_;
    double* data_ = nullptr;
};

// One member on one backend: the states of frames 1..T into `rows`; the events and warnings as the
// job's JSON result (doubles round-trip exactly through the pool's text).
Json runMember(const harness::SelectedBackend& backend, const Scene& scene, const std::vector<BodyState>& initial,
               std::int64_t frames, double frame_dt, double* rows) {
    harness::RunOptions o;
    o.frame_dt = frame_dt;
    o.frames = frames;
    o.initial_states = initial;
    const harness::RunTrace trace = harness::runBackend(*backend.info, scene, backend.settings, o);
    const std::size_t n = scene.bodies.size();
    for (std::size_t f = 1; f < trace.states.size(); ++f)
        for (std::size_t b = 0; b < n; ++b) writeStateRow(trace.states[f][b], rows + ((f - 1) * n + b) * kStateWidth);
    Json events = Json::array();
    for (const CollisionEvent& e : trace.events) events.push_back(eventJson(e));
    return {{"events", std::move(events)}, {"warnings", trace.warnings}, {"state_hash", hashToHex(stateHash(trace.states.back()))}};
}

}  // namespace

RolloutResult runRollout(const RolloutRequest& r) {
    const auto start = std::chrono::steady_clock::now();
    if (r.frames < 1) throw InputError("rollout: frames must be >= 1, got " + std::to_string(r.frames));
    if (r.initial.empty()) throw InputError("rollout: initial_states holds no member (expected shape (B, N, 13) with B >= 1)");
    if (r.jobs < 1) throw InputError("rollout: jobs must be >= 1, got " + std::to_string(r.jobs));
    const Scene& scene = *r.scene;
    const double dt = r.frame_dt > 0 ? r.frame_dt : scene.frame_dt;
    const std::vector<harness::SelectedBackend> backends = harness::selectBackends(r.backends, r.assignments);
    for (const harness::SelectedBackend& b : backends) b.info->create(scene, b.settings);   // refuse early, in this process

    const std::size_t per_member = static_cast<std::size_t>(r.frames) * scene.bodies.size() * kStateWidth;
    const std::size_t members = r.initial.size();
    SharedDoubles states(backends.size() * members * per_member);
    std::vector<harness::PoolJob> jobs;
    for (std::size_t bi = 0; bi < backends.size(); ++bi)
        for (std::size_t m = 0; m < members; ++m) {
            double* rows = states.data() + (bi * members + m) * per_member;
            jobs.push_back({harness::poolJobId(backends[bi].info->name + "-" + std::to_string(m)),
                            [&, m, rows, bp = &backends[bi]] { return runMember(*bp, scene, r.initial[m], r.frames, dt, rows); },
                            static_cast<double>(r.frames)});
        }
    // No run files (a rollout is not resumed): the small results travel back over the workers' pipes.
    harness::PoolOptions o;
    o.jobs = r.jobs;
    o.command = "vroc.rollout";
    harness::RunPool pool(std::move(o));
    const std::vector<Json> results = pool.run(jobs);

    RolloutResult out;
    out.states.assign(states.data(), states.data() + backends.size() * members * per_member);
    out.members.resize(backends.size());
    for (std::size_t bi = 0; bi < backends.size(); ++bi) {
        out.backends.push_back(backends[bi].info->name);
        for (std::size_t m = 0; m < members; ++m) {
            const Json& j = results[bi * members + m];
            RolloutMember member;
            for (const Json& e : j.at("events")) member.events.push_back(eventFromJson(e));
            member.warnings = j.at("warnings").get<WarningCounts>();
            member.state_hash = j.at("state_hash").get<std::string>();
            out.members[bi].push_back(std::move(member));
        }
    }
    out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace vroc::python
