// SPDX-License-Identifier: MIT
#include "vroc/hmd/hmd_settings.h"

#include "vroc/core/errors.h"

namespace vroc::hmd {

PredictorKind predictorFromName(const std::string& name) {
    if (name == "none") return PredictorKind::None;
    if (name == "constant-velocity") return PredictorKind::ConstantVelocity;
    if (name == "kalman") return PredictorKind::Kalman;
    throw InputError("--hmd predictor: unknown predictor '" + name +
                     "' (expected none, constant-velocity or kalman)");
}

const char* predictorName(PredictorKind kind) {
    switch (kind) {
        case PredictorKind::ConstantVelocity: return "constant-velocity";
        case PredictorKind::Kalman: return "kalman";
        default: return "none";
    }
}

namespace {
SettingSpec real(const char* key, const char* value, double min, double max, const char* help) {
    SettingSpec spec;
    spec.key = key;
    spec.type = SettingSpec::Type::Real;
    spec.default_value = value;
    spec.min = min;
    spec.max = max;
    spec.help = help;
    return spec;
}
}  // namespace

const std::vector<SettingSpec>& hmdSettingSpecs() {
    static const std::vector<SettingSpec> specs = [] {
        std::vector<SettingSpec> s;
        s.push_back(real("ipd", "0.064", 0.0, 0.2, "interpupillary distance [m]"));
        s.push_back(real("fov", "60", 1.0, 170.0, "vertical field of view per eye [deg]"));
        s.push_back(real("eye_relief", "0.02", 0.0, 0.2, "eye centre behind the tracked lens plane [m]"));
        s.push_back(real("near", "0.05", 1e-4, 10.0, "near clip distance [m]"));
        s.push_back(real("far", "100", 0.1, 1e6, "far clip distance [m]"));
        s.push_back(real("k1", "0", -0.5, 1.0, "radial distortion coefficient of r^3 [-]"));
        s.push_back(real("k2", "0", -0.5, 1.0, "radial distortion coefficient of r^5 [-]"));
        s.push_back(real("tracker_latency", "0.015", 0.0, 1.0, "measurement to host delay [s]"));
        s.push_back(real("simulation_latency", "0.010", 0.0, 1.0, "host to physics done delay [s]"));
        s.push_back(real("render_latency", "0.015", 0.0, 1.0, "physics to image delay [s]"));
        s.push_back(real("display_latency", "0.010", 0.0, 1.0, "image to photons delay [s]"));
        s.push_back(real("tracker_rate", "60", 0.0, 1e5, "tracker rate [Hz], 0 = continuous"));
        SettingSpec predictor;
        predictor.key = "predictor";
        predictor.type = SettingSpec::Type::Choice;
        predictor.default_value = "none";
        predictor.choices = {"none", "constant-velocity", "kalman"};
        predictor.help = "head pose used to draw: delayed (none) or predicted to display time";
        s.push_back(predictor);
        return s;
    }();
    return specs;
}

HmdSettings resolveHmdSettings(const std::vector<std::pair<std::string, std::string>>& overrides) {
    Settings values;
    try {
        values = resolveSettings(hmdSettingSpecs(), overrides);
    } catch (const InputError& e) {   // the core names the option --set; here it is --hmd
        std::string message = e.what();
        if (message.rfind("--set", 0) == 0) message.replace(0, 5, "--hmd");
        throw InputError(message);
    }
    HmdSettings h;
    h.ipd = values.real("ipd");
    h.fov_y_deg = values.real("fov");
    h.eye_relief = values.real("eye_relief");
    h.near_plane = values.real("near");
    h.far_plane = values.real("far");
    if (h.far_plane <= h.near_plane) throw InputError("--hmd far: must be greater than near");
    h.k1 = values.real("k1");
    h.k2 = values.real("k2");
    h.latency.tracker = values.real("tracker_latency");
    h.latency.simulation = values.real("simulation_latency");
    h.latency.render = values.real("render_latency");
    h.latency.display = values.real("display_latency");
    h.latency.tracker_rate = values.real("tracker_rate");
    h.predictor = predictorFromName(values.text("predictor"));
    return h;
}

}  // namespace vroc::hmd
