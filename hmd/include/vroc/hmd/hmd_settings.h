// SPDX-License-Identifier: MIT
// Settings of the head-mounted display model (`vroc play --hmd key=value`). SI units except the
// field of view, which is in degrees as displays are specified.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "vroc/core/settings.h"

namespace vroc::hmd {

enum class PredictorKind { None, ConstantVelocity, Kalman };
PredictorKind predictorFromName(const std::string& name);   ///< throws InputError
const char* predictorName(PredictorKind kind);

/// Delays between a head measurement and the photons that show it (Holloway 1997's chain).
struct LatencySettings {
    double tracker = 0.015;      ///< [s] measurement -> pose available to the host
    double simulation = 0.010;   ///< [s] pose available -> physics frame done
    double render = 0.015;       ///< [s] physics done -> image rendered
    double display = 0.010;      ///< [s] image rendered -> shown (scan-out, persistence)
    double tracker_rate = 60.0;  ///< [Hz] tracker measurement rate; 0 = continuous
    double total() const { return tracker + simulation + render + display; }   ///< [s]
};

struct HmdSettings {
    double ipd = 0.064;           ///< [m] interpupillary distance
    double fov_y_deg = 60.0;      ///< [deg] vertical field of view of each eye (the paper's era)
    double eye_relief = 0.02;     ///< [m] eye centre behind the lens plane (the tracked head frame)
    double aspect = 4.0 / 3.0;    ///< [-] width / height of each eye's image
    double near_plane = 0.05;     ///< [m] near clip distance
    double far_plane = 100.0;     ///< [m] far clip distance
    double k1 = 0.0;              ///< [-] radial distortion r_d = r (1 + k1 r^2 + k2 r^4)
    double k2 = 0.0;              ///< [-] (r in units of the half image height)
    LatencySettings latency;
    PredictorKind predictor = PredictorKind::None;   ///< pose used to draw: delayed or predicted
};

/// The `--hmd` keys with their types, ranges, defaults and help.
const std::vector<SettingSpec>& hmdSettingSpecs();
/// Applies `key=value` overrides (throws InputError naming the key for unknown keys or bad values).
HmdSettings resolveHmdSettings(const std::vector<std::pair<std::string, std::string>>& overrides);

}  // namespace vroc::hmd
