// SPDX-License-Identifier: MIT
#include "checks/shipped_scenes_check.h"

#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <string>

#include "checks/check_support.h"
#include "vroc/core/errors.h"
#include "vroc/harness/runs/scene_support.h"

namespace vroc::conformance {
namespace {

/// ", while counting <name> <n>, ..." for the warnings counted between two readings ("" if none):
/// a backend that cannot step says so through them, and the failure line should show it.
std::string warningsSince(const WarningCounts& before, const WarningCounts& after) {
    std::string out;
    for (const auto& [name, n] : after) {
        const auto was = before.find(name);
        const std::uint64_t d = n - (was == before.end() ? 0 : was->second);
        if (d > 0) out += (out.empty() ? ", while counting " : ", ") + name + " " + std::to_string(d);
    }
    return out;
}

/// Index of the virtual body whose centre of mass is highest along `up`, or -1 if there is none.
int highestVirtualBody(const Scene& scene, const Backend& b, const Vec3& up) {
    int best = -1;
    double best_height = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < b.bodyCount(); ++i) {
        const Body& body = scene.bodies[static_cast<std::size_t>(i)];
        if (!body.isDynamic()) continue;
        const double h = centreOfMass(body, b.bodyState(i)).dot(up);
        if (h > best_height) best = i, best_height = h;
    }
    return best;
}

/// The body kicked upward at t = 0 and what it has done since.
struct KickedBody {
    int index = -1;  ///< -1: the scene has no virtual body
    bool gravity = false;
    Vec3 up = Vec3::UnitZ();   ///< against gravity (+z without)
    Vec3 com0 = Vec3::Zero();  ///< [m] centre of mass at the kick
    double rise = 0.0;         ///< [m] highest rise of the centre of mass so far
    bool fell_back = false;    ///< its upward velocity has turned negative after min_rise

    void observe(const Body& body, const BodyState& s, const ShippedScenesCheckOptions& options) {
        rise = std::max(rise, (centreOfMass(body, s) - com0).dot(up));
        if (rise >= options.min_rise && s.linear_velocity.dot(up) < 0.0) fell_back = true;
    }
    bool done(const ShippedScenesCheckOptions& options) const {
        return index < 0 || (rise >= options.min_rise && (fell_back || !gravity));
    }
};

/// Sets the highest virtual body's upward velocity to options.kick_speed (setBodyState, so that
/// this check does not lean on applyImpulse, checkImpulse's clause).
KickedBody kickHighestBody(const Scene& scene, Backend& b, const ShippedScenesCheckOptions& options) {
    KickedBody k;
    k.gravity = scene.gravity.norm() > 0.0;
    if (k.gravity) k.up = -scene.gravity.normalized();
    k.index = highestVirtualBody(scene, b, k.up);
    if (k.index < 0) return k;
    BodyState s = b.bodyState(k.index);
    s.linear_velocity += (options.kick_speed - s.linear_velocity.dot(k.up)) * k.up;
    b.setBodyState(k.index, s);
    k.com0 = centreOfMass(scene.bodies[static_cast<std::size_t>(k.index)], s);
    return k;
}

void reportKick(const Scene& scene, const KickedBody& k, const ShippedScenesCheckOptions& options,
                const std::string& where, const std::string& warnings, CheckResult& r) {
    const std::string& name = scene.bodies[static_cast<std::size_t>(k.index)].name;
    if (k.rise < options.min_rise)
        r.fail(where, ": body '", name, "' given ", options.kick_speed, " m/s upward rose ", k.rise, " m (at least ",
               options.min_rise, " m expected)", warnings);
    else if (k.gravity && !k.fell_back)
        r.fail(where, ": body '", name, "' given ", options.kick_speed, " m/s upward never fell back in ",
               options.max_time, " s of gravity ", scene.gravity, warnings);
}

void checkScene(const BackendInfo& backend, const ShippedScene& shipped, const ShippedScenesCheckOptions& options,
                CheckResult& r) {
    const std::string where = "scene " + shipped.path.string();
    const Scene& scene = shipped.scene;
    const harness::SceneSupport support = harness::sceneSupport(scene, backend.capabilities);
    if (support.level == Support::Unsupported) {
        try {
            createBackend(backend, scene);
            r.fail(where, ": ", harness::supportText(support), ", yet it was created (InputError expected)");
        } catch (const InputError&) {}
        return;
    }
    auto b = createBackend(backend, scene);
    if (b->bodyCount() != static_cast<int>(scene.bodies.size()))
        return r.fail(where, ": bodyCount ", b->bodyCount(), ", the scene has ", scene.bodies.size());
    KickedBody kick = kickHighestBody(scene, *b, options);
    const WarningCounts warnings_before = b->warnings();
    const int max_frames =
        std::max(options.finite_frames, static_cast<int>(std::ceil(options.max_time / scene.frame_dt)));
    for (int f = 0; f < max_frames && (f < options.finite_frames || !kick.done(options)); ++f) {
        b->stepFrame(scene.frame_dt);
        if (kick.index >= 0)
            kick.observe(scene.bodies[static_cast<std::size_t>(kick.index)], b->bodyState(kick.index), options);
        if (f + 1 != options.finite_frames) continue;
        if (std::abs(b->time() - options.finite_frames * scene.frame_dt) > 1e-12)
            r.fail(where, ": time ", b->time(), " after ", options.finite_frames, " frames of ", scene.frame_dt, " s");
        for (int i = 0; i < b->bodyCount(); ++i)
            if (!finite(b->bodyState(i)))
                return r.fail(where, ": body ", i, " is not finite after ", options.finite_frames, " frames");
    }
    if (kick.index >= 0) reportKick(scene, kick, options, where, warningsSince(warnings_before, b->warnings()), r);
}

}  // namespace

CheckResult checkShippedScenes(const BackendInfo& backend, const ShippedScenesCheckOptions& options) {
    CheckResult r{backend.name, {}};
    const std::vector<ShippedScene>& scenes = loadedShippedScenes();
    if (scenes.size() < 20u) r.fail("only ", scenes.size(), " scenes found under ", VROC_SOURCE_DIR, "/scenes");
    for (const ShippedScene& shipped : scenes) {
        if (!options.stress_scenes && shipped.path.parent_path().filename() == "stress") continue;
        try {
            checkScene(backend, shipped, options, r);
        } catch (const std::exception& e) {
            r.fail("scene ", shipped.path.string(), ": threw ", e.what());
        }
    }
    return r;
}

}  // namespace vroc::conformance
