// SPDX-License-Identifier: MIT
// Which collision events make a sound. The event definition (docs/events.md) already gives a
// resting or sliding contact one event when it starts and none while it lasts; the gate silences
// what is left of contact noise: impacts too weak to hear next to the body's own weight, and a
// pair's impacts that follow its previous sounded one too closely (chatter).
#pragma once

#include <map>
#include <utility>

#include "vroc/audio/sound_settings.h"
#include "vroc/core/backend.h"
#include "vroc/core/scene.h"

namespace vroc::audio {

enum class ImpactStatus {
    Sounded,
    Quiet,        ///< impulse below the pair's threshold (or <= 0)
    Refractory,   ///< within SoundSettings::refractory of the pair's previous sounded impact
};
/// "sounded", "quiet", "refractory".
const char* impactStatusName(ImpactStatus status);

class ImpactGate {
public:
    /// `scene` must outlive the gate; `frame_dt` [s] > 0 is the frame step of the run.
    ImpactGate(const Scene& scene, double frame_dt, const SoundSettings& settings);

    /// [N s] quiet_weight_frames * m |g| frame_dt, m the mass of the lighter Virtual body of the
    /// pair (a body of another role has infinite mass; a pair with no Virtual body has threshold 0).
    double threshold(int body_a, int body_b) const;
    /// Classifies one event; events must come in time order (a Sounded one starts the pair's
    /// refractory time). Throws RunError for a body index outside the scene.
    ImpactStatus classify(const CollisionEvent& event);

private:
    const Scene& scene_;
    double weight_impulse_per_kg_;   ///< [N s / kg] quiet_weight_frames |g| frame_dt
    double refractory_;
    std::map<std::pair<int, int>, double> last_sounded_;   ///< [s] by pair
};

}  // namespace vroc::audio
