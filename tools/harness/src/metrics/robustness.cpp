// SPDX-License-Identifier: MIT
#include "vroc/harness/metrics/robustness.h"

#include <algorithm>
#include <cmath>

#include "vroc/harness/metrics/event_timing.h"
#include "vroc/harness/metrics/neutral_distance.h"
#include "vroc/harness/metrics/penetration.h"

namespace vroc::harness {
namespace {

constexpr double kBlowUpFloorHeight = 0.01;   // [m]

double lowestRealPoint(const Scene& scene) {
    double low = INFINITY;
    for (const Body& b : scene.bodies)
        if (b.isStatic()) low = std::min(low, b.pose.position.z() - b.shape.boundingRadius());
    return low;
}

bool tunnelled(const Scene& scene, const std::vector<BodyState>& states, double floor_z) {
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const Body& b = scene.bodies[i];
        if (!b.isDynamic()) continue;
        const Vec3 c = states[i].pose.position;
        if (c.z() < floor_z - 1.0) return true;
        for (const Body& real : scene.bodies) {
            if (!real.isStatic()) continue;
            if ((c - real.pose.position).norm() > real.shape.boundingRadius()) continue;
            if (pointSignedDistance(c, real.shape, real.pose) < -b.shape.boundingRadius()) return true;
        }
    }
    return false;
}

bool startsSupportedAtRest(const Scene& scene) {
    const std::vector<BodyState> start = initialStates(scene);
    bool any = false;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const Body& b = scene.bodies[i];
        if (!b.isDynamic()) continue;
        any = true;
        if (b.linear_velocity.norm() > 0 || b.angular_velocity.norm() > 0) return false;
        if (closestDistance(scene, start, static_cast<int>(i)) > std::max(scene.collision_distance, 1e-3)) return false;
    }
    return any;
}

}  // namespace

RobustnessVerdict judgeRobustness(const Scene& scene, const RunTrace& run, const RunTrace& reference) {
    if (!run.finite) return {false, "NaN"};
    for (const auto& [kind, count] : run.warnings)
        if (count > 0 && kind.find("nan") != std::string::npos) return {false, "NaN"};
    const double floor_z = lowestRealPoint(scene);
    for (const auto& s : run.states)
        if (tunnelled(scene, s, floor_z)) return {false, "tunnelling"};
    double ref_ke = 0, run_ke = 0, floor_ke = 0;
    for (const auto& i : reference.invariants) ref_ke = std::max(ref_ke, i.kinetic);
    for (const auto& i : run.invariants) run_ke = std::max(run_ke, i.kinetic);
    // Absolute floor: the kinetic energy of every body after a 1 cm fall, so that resting
    // scenes (reference KE ~ 0) are not failed for solver jitter.
    for (const Body& b : scene.bodies) floor_ke += b.mass_properties.mass * scene.gravity.norm() * kBlowUpFloorHeight;
    if (run_ke > 10 * ref_ke + floor_ke) return {false, "energy blow-up"};
    const std::size_t n = reference.states.back().size();
    // A scene that starts at rest with every virtual body touching something (a stack) must not
    // come apart: judged against the start, since a backend's own reference may collapse too.
    if (startsSupportedAtRest(scene)) {
        for (std::size_t i = 0; i < n; ++i) {
            if (!scene.bodies[i].isDynamic()) continue;
            const double moved = (run.states.back()[i].pose.position - scene.bodies[i].pose.position).norm();
            if (moved > scene.bodies[i].shape.boundingRadius()) return {false, "collapse"};
        }
    }
    const double ref_end = reference.times.back();
    if (restTime(scene, reference) && std::abs(run.times.back() - ref_end) < 1e-6) {
        for (std::size_t i = 0; i < n; ++i) {
            if (!scene.bodies[i].isDynamic()) continue;
            const double moved = (run.states.back()[i].pose.position - reference.states.back()[i].pose.position).norm();
            if (moved > scene.bodies[i].shape.boundingRadius()) return {false, "collapse"};
        }
    }
    return {};
}

}  // namespace vroc::harness
