// SPDX-License-Identifier: MIT
// vroc-icollide-bench: the I-COLLIDE speed target of issue 4 (1,000 moving convex polytopes of
// ~50 faces in a box; target <= 5 ms per frame for broad + narrow phase on one core).
//
// Two measurements on the same scene, same binary, same run:
//  1. "detect": the collision-detection kernel alone, as I-COLLIDE timed it. Bodies fly with
//     constant velocity and spin; each frame the native broad phase (exact world boxes +
//     incremental sweep-and-prune) and the native narrow phase (the V-Clip walk with each pair's
//     cached features, queryParts) run on every overlapping pair. Only those two are timed; the
//     bench's own motion (and a trivial equal-mass elastic bounce that keeps bodies apart, so the
//     queries stay in the separated regime I-COLLIDE measured) is not.
//  2. "step": Backend::stepFrame of the native backend (native.threads=1) and of Bullet, created
//     through BackendRegistry, i.e. the whole frame: scheduling, queries and response.
// Plain timing rather than Google Benchmark: a frame depends on the previous one, so a frame is the
// unit and its distribution is what we report. Each frame is timed twice: wall (steady_clock) and
// process CPU time (CLOCK_PROCESS_CPUTIME_ID). On a loaded machine the wall time counts the time the
// process waited for a core; the CPU time does not, so it is the number to compare there.
//
// Usage: vroc-icollide-bench [SCENE] [--frames N] [--skip-step] [--skip-detect] [--only BACKEND]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include "backend/body_shape.h"
#include "backend/part_query.h"
#include "scheduling/sweep_and_prune.h"
#include "vroc/bullet/bullet_backend.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/errors.h"
#include "vroc/core/scene_loader.h"
#include "vroc/native/native_backend.h"

namespace {

using Clock = std::chrono::steady_clock;
using vroc::Vec3;

struct Options {
    std::string scene = VROC_SOURCE_DIR "/scenes/icollide.json";
    int frames = 120;
    bool detect = true;
    bool step = true;
    std::string only;   // "" = native and bullet
};

struct Summary {
    double p50 = 0, p90 = 0, p99 = 0, mean = 0, max = 0;   // [us]
};

Summary summarise(std::vector<double> us) {
    Summary s;
    if (us.empty()) return s;
    std::sort(us.begin(), us.end());
    auto at = [&](double q) { return us[static_cast<std::size_t>(q * static_cast<double>(us.size() - 1) + 0.5)]; };
    s.p50 = at(0.5), s.p90 = at(0.9), s.p99 = at(0.99), s.max = us.back();
    for (double v : us) s.mean += v / static_cast<double>(us.size());
    return s;
}

void printRow(const char* what, const Summary& s) {
    std::printf("%-34s p50 %10.1f  p90 %10.1f  p99 %10.1f  mean %10.1f  max %10.1f us\n", what, s.p50,
                s.p90, s.p99, s.mean, s.max);
}

double microseconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::micro>(b - a).count();
}

/// [us] CPU time of the whole process (every thread) so far.
double cpuMicroseconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e6 + static_cast<double>(ts.tv_nsec) * 1e-3;
}

// ---- 1. collision-detection kernel ------------------------------------------------------------

struct KernelBody {
    vroc::native::BodyShape shape;
    vroc::Pose frame;        // body frame -> world
    Vec3 com_local;          // [m] centre of mass, body frame
    Vec3 v, w;               // [m/s], [rad/s] world
    bool is_static = false;
};

struct PairCache {
    vroc::native::BodyPair pair;
    std::vector<vroc::native::FeatureCache> caches;   // parts(a) x parts(b)
};

std::vector<KernelBody> kernelBodies(const vroc::Scene& scene) {
    std::vector<KernelBody> out;
    for (const vroc::Body& b : scene.bodies) {
        KernelBody k;
        k.com_local = b.mass_properties.center_of_mass;
        k.shape = vroc::native::BodyShape::fromScene(b.shape, k.com_local);
        k.frame = b.pose;
        k.v = b.linear_velocity;
        k.w = b.angular_velocity;
        k.is_static = b.isStatic();
        out.push_back(std::move(k));
    }
    return out;
}

// Constant velocity and spin about the centre of mass (the kernel's motion; not timed).
void fly(KernelBody& b, double dt) {
    if (b.is_static) return;
    const Vec3 com = b.frame.apply(b.com_local);
    const double angle = b.w.norm() * dt;
    const vroc::Quat dq = angle > 0 ? vroc::Quat(Eigen::AngleAxisd(angle, b.w.normalized())) : vroc::Quat::Identity();
    b.frame.orientation = (dq * b.frame.orientation).normalized();
    b.frame.position = com + b.v * dt - b.frame.orientation * b.com_local;
}

// Equal-mass elastic exchange of the normal velocity (walls: reflection). Not timed.
void bounce(KernelBody& a, KernelBody& b, const Vec3& n_ab) {
    const double approach = (a.v - b.v).dot(n_ab);
    if (approach <= 0) return;
    if (a.is_static) b.v += 2 * approach * n_ab;
    else if (b.is_static) a.v -= 2 * approach * n_ab;
    else a.v -= approach * n_ab, b.v += approach * n_ab;
}

PairCache& cacheFor(std::vector<PairCache>& caches, const vroc::native::BodyPair& p,
                    const std::vector<KernelBody>& bodies) {
    auto it = std::lower_bound(caches.begin(), caches.end(), p,
                               [](const PairCache& c, const vroc::native::BodyPair& q) { return c.pair < q; });
    if (it == caches.end() || !(it->pair == p)) {
        const std::size_t n = bodies[p.a].shape.parts.size() * bodies[p.b].shape.parts.size();
        it = caches.insert(it, PairCache{p, std::vector<vroc::native::FeatureCache>(n)});
    }
    return *it;
}

// The scene as the backends see it: faces per polytope and the smallest gap at t = 0 (> 0: no
// two bodies start overlapping).
void describeStart(const std::vector<KernelBody>& bodies, const vroc::native::SweepAndPrune& sap,
                   std::vector<PairCache>& caches) {
    int min_faces = 1 << 30, max_faces = 0;
    for (const KernelBody& b : bodies)
        for (const auto& part : b.shape.parts)
            if (!b.is_static && part.mesh) {
                min_faces = std::min(min_faces, part.mesh->faceCount());
                max_faces = std::max(max_faces, part.mesh->faceCount());
            }
    double min_gap = 1e300;
    for (const vroc::native::BodyPair& p : sap.pairs()) {
        PairCache& pc = cacheFor(caches, p, bodies);
        const KernelBody &a = bodies[p.a], &b = bodies[p.b];
        std::size_t slot = 0;
        for (const auto& pa : a.shape.parts)
            for (const auto& pb : b.shape.parts)
                min_gap = std::min(min_gap, vroc::native::queryParts(pa, a.frame * pa.local, pb, b.frame * pb.local,
                                                                     pc.caches[slot++]).distance);
    }
    if (sap.pairs().empty())
        std::printf("start: faces per virtual polytope %d..%d, no two boxes overlap (no body touches another)\n",
                    min_faces, max_faces);
    else
        std::printf("start: faces per virtual polytope %d..%d, %zu overlapping boxes, smallest gap %.4g m\n",
                    min_faces, max_faces, sap.pairs().size(), min_gap);
}

void runDetectKernel(const vroc::Scene& scene, int frames) {
    std::vector<KernelBody> bodies = kernelBodies(scene);
    vroc::native::SweepAndPrune sap;
    const double margin = scene.collision_distance;
    for (const KernelBody& b : bodies) sap.addBody(b.shape.worldAabb(b.frame).inflated(margin), b.is_static);
    sap.update();
    std::vector<PairCache> caches;   // sorted by pair: persistent feature caches (coherence)
    describeStart(bodies, sap, caches);
    std::vector<double> broad_us, narrow_us, total_us, broad_cpu, narrow_cpu, total_cpu;
    long long queries = 0, walk_steps = 0, touching = 0, penetrating = 0, max_walk = 0;
    std::vector<std::pair<vroc::native::BodyPair, Vec3>> contacts;
    // Bounce when a pair could close its gap within the next frame, so that (like I-COLLIDE's
    // demo) bodies essentially never interpenetrate and the queries stay in the separated regime.
    double max_speed = 0.0;
    for (const KernelBody& b : bodies)
        if (!b.is_static) max_speed = std::max(max_speed, b.v.norm() + b.w.norm() * b.shape.outer_radius);
    const double bounce_distance = 2.0 * max_speed * scene.frame_dt;   // [m]
    for (int f = 0; f < frames; ++f) {
        for (KernelBody& b : bodies) fly(b, scene.frame_dt);
        const double c0 = cpuMicroseconds();
        const auto t0 = Clock::now();
        for (std::size_t i = 0; i < bodies.size(); ++i)
            if (!bodies[i].is_static)
                sap.setAabb(static_cast<int>(i), bodies[i].shape.worldAabb(bodies[i].frame).inflated(margin));
        sap.update();
        const auto t1 = Clock::now();
        const double c1 = cpuMicroseconds();
        contacts.clear();
        for (const vroc::native::BodyPair& p : sap.pairs()) {
            PairCache& pc = cacheFor(caches, p, bodies);
            const KernelBody &a = bodies[p.a], &b = bodies[p.b];
            std::size_t slot = 0;
            for (const auto& pa : a.shape.parts)
                for (const auto& pb : b.shape.parts) {
                    const auto r = vroc::native::queryParts(pa, a.frame * pa.local, pb, b.frame * pb.local,
                                                            pc.caches[slot++]);
                    ++queries, walk_steps += r.walk_steps, max_walk = std::max<long long>(max_walk, r.walk_steps);
                    penetrating += r.penetrating ? 1 : 0;
                    if (r.distance < bounce_distance) contacts.emplace_back(p, r.normal);
                }
        }
        const auto t2 = Clock::now();
        const double c2 = cpuMicroseconds();
        broad_cpu.push_back(c1 - c0), narrow_cpu.push_back(c2 - c1), total_cpu.push_back(c2 - c0);
        broad_us.push_back(microseconds(t0, t1));
        narrow_us.push_back(microseconds(t1, t2));
        total_us.push_back(microseconds(t0, t2));
        touching += static_cast<long long>(contacts.size());
        for (const auto& [p, n] : contacts) bounce(bodies[p.a], bodies[p.b], n);
    }
    std::printf("\n[detect] %zu bodies, %d frames of %.6g s: broad phase (world boxes + sweep-and-prune) "
                "and narrow phase (V-Clip walk, cached features) only\n",
                bodies.size(), frames, scene.frame_dt);
    printRow("broad phase per frame", summarise(broad_us));
    printRow("narrow phase per frame", summarise(narrow_us));
    printRow("broad + narrow per frame", summarise(total_us));
    printRow("broad phase per frame, CPU", summarise(broad_cpu));
    printRow("narrow phase per frame, CPU", summarise(narrow_cpu));
    printRow("broad + narrow per frame, CPU", summarise(total_cpu));
    const double q = static_cast<double>(std::max(1LL, queries));
    std::printf("  narrow queries/frame %.1f, walk steps mean %.3f max %lld, contacts/frame %.2f, "
                "penetrating queries %lld, sweep-and-prune swaps/frame %.1f\n",
                q / frames, static_cast<double>(walk_steps) / q, max_walk,
                static_cast<double>(touching) / frames, penetrating,
                static_cast<double>(sap.stats().swaps) / (frames + 1));
}

// ---- 2. whole frames through the backend interface -------------------------------------------

void runStep(const vroc::Scene& scene, const std::string& name, int frames) {
    const vroc::BackendInfo& info = vroc::BackendRegistry::global().require(name);
    std::vector<std::pair<std::string, std::string>> overrides;
    if (name == "native") overrides.emplace_back("native.threads", "1");
    const vroc::Settings settings = vroc::resolveSettings(info.settings, overrides);
    const auto c0 = Clock::now();
    std::unique_ptr<vroc::Backend> backend = info.create(scene, settings);
    const auto c1 = Clock::now();
    std::vector<double> us, cpu;
    for (int f = 0; f < frames; ++f) {
        const double c0 = cpuMicroseconds();
        const auto t0 = Clock::now();
        backend->stepFrame(scene.frame_dt);
        us.push_back(microseconds(t0, Clock::now()));
        cpu.push_back(cpuMicroseconds() - c0);
    }
    std::printf("\n[step] %s (%s), created in %.1f ms, %d frames:\n", name.c_str(), info.version.c_str(),
                microseconds(c0, c1) / 1000.0, frames);
    printRow(("stepFrame " + name).c_str(), summarise(us));
    printRow(("stepFrame " + name + ", CPU").c_str(), summarise(cpu));
    std::printf("  statistics:");
    for (const auto& [key, value] : backend->statistics()) std::printf(" %s=%g", key.c_str(), value);
    std::printf("\n  warnings:");
    for (const auto& [key, value] : backend->warnings()) std::printf(" %s=%llu", key.c_str(), static_cast<unsigned long long>(value));
    std::printf("\n");
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--frames" && i + 1 < argc) o.frames = std::max(1, std::atoi(argv[++i]));
        else if (a == "--skip-step") o.step = false;
        else if (a == "--skip-detect") o.detect = false;
        else if (a == "--only" && i + 1 < argc) o.only = argv[++i];
        else if (!a.empty() && a[0] != '-') o.scene = a;
        else throw vroc::InputError("vroc-icollide-bench: unknown argument `" + a +
                                    "` (usage: [SCENE] [--frames N] [--skip-step] [--skip-detect] [--only BACKEND])");
    }
    return o;
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    in >> one >> five >> fifteen;
    return one + " " + five + " " + fifteen;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const Options o = parse(argc, argv);
        vroc::native::registerBackend();
        vroc::bullet::registerBackend();
        const vroc::Scene scene = vroc::loadScene(o.scene);
        std::printf("vroc-icollide-bench: %s (%zu bodies, %zu virtual), one core, load average %s\n",
                    o.scene.c_str(), scene.bodies.size(), scene.virtualBodyCount(), loadAverage().c_str());
        if (o.detect) runDetectKernel(scene, o.frames);
        if (o.step)
            for (const char* name : {"native", "bullet"})
                if (o.only.empty() || o.only == name) runStep(scene, name, o.frames);
        std::printf("\nload average at the end: %s\n", loadAverage().c_str());
        return 0;
    } catch (const vroc::InputError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vroc-icollide-bench: %s\n", e.what());
        return 3;
    }
}
