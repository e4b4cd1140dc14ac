// SPDX-License-Identifier: MIT
// play.json: the only file of vroc_play that includes nlohmann/json (a heavy header).
#include <fstream>

#include <nlohmann/json.hpp>

#include "vroc/core/errors.h"
#include "vroc/play/play_loop.h"

namespace vroc::play {
namespace {
nlohmann::json vec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
}  // namespace

void writePlayJson(const PlayReport& r, const std::string& path) {
    using nlohmann::json;
    json j;
    j["format"] = "vroc-play/1";
    j["scene"] = r.scene_name;
    j["backend"] = r.backend;
    j["device"] = r.device;
    j["head"] = r.head;
    j["gl_renderer"] = r.gl_renderer;
    j["frames"] = r.frames;
    j["frame_dt"] = r.frame_dt;
    j["eye_size"] = {r.eye_width, r.eye_height};
    j["rates_fps"] = r.rates_fps;
    j["stage_ms"] = r.stage_ms;
    const hmd::LatencySettings& l = r.hmd.latency;
    j["latency_model_ms"] = {{"tracker", l.tracker * 1e3}, {"simulation", l.simulation * 1e3},
                             {"render", l.render * 1e3},   {"display", l.display * 1e3},
                             {"total", l.total() * 1e3},   {"tracker_rate_hz", l.tracker_rate}};
    j["hmd"] = {{"ipd", r.hmd.ipd}, {"fov_deg", r.hmd.fov_y_deg}, {"eye_relief", r.hmd.eye_relief},
                {"aspect", r.hmd.aspect}, {"k1", r.hmd.k1}, {"k2", r.hmd.k2},
                {"predictor", hmd::predictorName(r.hmd.predictor)}};
    json reg;
    for (const auto& [name, s] : r.registration)
        reg[name] = {{"mean", s.mean}, {"rms", s.rms}, {"p95", s.p95}, {"max", s.max}};
    j["registration_deg"] = reg;
    j["registration_points"] = r.registration_points;
    j["registration_drawn_with"] = hmd::predictorName(r.hmd.predictor);
    json throws = json::array();
    for (const ThrowRecord& t : r.throws) {
        json e = {{"time", t.time}, {"body", r.body_names.at(t.body)},
                  {"linear_velocity", vec(t.linear_velocity)}, {"angular_velocity", vec(t.angular_velocity)},
                  {"speed", t.linear_velocity.norm()}};
        if (t.device_velocity_known) {
            e["device_linear_velocity"] = vec(t.device_linear_velocity);
            e["device_angular_velocity"] = vec(t.device_angular_velocity);
        }
        throws.push_back(e);
    }
    j["grabs"] = r.grabs;
    j["throws"] = throws;
    j["warnings"] = r.warnings;
    j["outputs"] = r.outputs;
    std::ofstream out(path);
    if (!out) throw RunError(path + ": cannot open for writing");
    out << j.dump(2) << "\n";
    if (!out) throw RunError(path + ": write failed");
}

}  // namespace vroc::play
