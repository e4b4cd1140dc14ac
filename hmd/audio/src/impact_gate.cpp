// SPDX-License-Identifier: MIT
#include "vroc/audio/impact_gate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "vroc/core/errors.h"

namespace vroc::audio {

const char* impactStatusName(ImpactStatus status) {
    switch (status) {
        case ImpactStatus::Sounded: return "sounded";
        case ImpactStatus::Quiet: return "quiet";
        case ImpactStatus::Refractory: return "refractory";
    }
    return "?";
}

ImpactGate::ImpactGate(const Scene& scene, double frame_dt, const SoundSettings& settings)
    : scene_(scene),
      weight_impulse_per_kg_(settings.quiet_weight_frames * scene.gravity.norm() * frame_dt),
      refractory_(settings.refractory) {}

double ImpactGate::threshold(int body_a, int body_b) const {
    double mass = std::numeric_limits<double>::infinity();
    for (int b : {body_a, body_b}) {
        const Body& body = scene_.bodies[static_cast<std::size_t>(b)];
        if (body.role == BodyRole::Virtual) mass = std::min(mass, body.mass_properties.mass);
    }
    return std::isinf(mass) ? 0.0 : weight_impulse_per_kg_ * mass;
}

ImpactStatus ImpactGate::classify(const CollisionEvent& e) {
    const int n = static_cast<int>(scene_.bodies.size());
    if (e.body_a < 0 || e.body_a >= n || e.body_b < 0 || e.body_b >= n)
        throw RunError("collision event names body " + std::to_string(e.body_a) + " / " + std::to_string(e.body_b) +
                       "; the scene has " + std::to_string(n));
    if (!(e.impulse > 0) || e.impulse < threshold(e.body_a, e.body_b)) return ImpactStatus::Quiet;
    const std::pair<int, int> pair{std::min(e.body_a, e.body_b), std::max(e.body_a, e.body_b)};
    const auto last = last_sounded_.find(pair);
    if (last != last_sounded_.end() && e.time - last->second < refractory_) return ImpactStatus::Refractory;
    last_sounded_[pair] = e.time;
    return ImpactStatus::Sounded;
}

}  // namespace vroc::audio
