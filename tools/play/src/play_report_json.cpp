// SPDX-License-Identifier: MIT
// play.json: the only file of vroc_play that includes nlohmann/json (a heavy header).

#include <nlohmann/json.hpp>

#include "vroc/core/errors.h"
#include "vroc/core/recording/atomic_output.h"
#include "vroc/play/play_loop.h"

namespace vroc::play {
namespace {
nlohmann::json vec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json latency(const LatencySummary& s) {
    return {{"count", s.count}, {"mean", s.mean}, {"p50", s.p50}, {"p95", s.p95}, {"max", s.max}};
}

/// Frames with a valid sample and distinct samples (sequence numbers) of a device's trace.
nlohmann::json traceSummary(const std::vector<DeviceFrame>& trace) {
    int valid = 0, distinct = 0;
    bool any = false;
    std::uint64_t last = 0;
    for (const DeviceFrame& f : trace) {
        if (!f.valid) continue;
        ++valid;
        if (!any || f.sequence != last) ++distinct;
        any = true;
        last = f.sequence;
    }
    return {{"frames_with_sample", valid}, {"distinct_samples", distinct}};
}
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
    j["force_output"] = {{"hand_accepts_force", r.hand_accepts_force}, {"forces_sent", r.forces_sent},
                         {"forces_rejected", r.forces_rejected}};
    json realtime = {{"enabled", r.realtime}};
    if (r.realtime) {
        realtime["frames_missed"] = r.frames_missed;
        realtime["worst_lateness_ms"] = r.worst_lateness_ms;
        json lat = json::object();
        for (const auto& [device, s] : r.latency_ms) lat[device] = latency(s);
        realtime["latency_ms"] = lat;
    }
    j["realtime"] = realtime;
    json devices = json::object();
    if (!r.hand_trace.empty()) devices["hand"] = traceSummary(r.hand_trace);
    if (!r.head_trace.empty()) devices["head"] = traceSummary(r.head_trace);
    j["device_samples"] = devices;
    json tracked = json::array();
    for (const TrackedReport& t : r.tracked)
        tracked.push_back({{"body", t.body}, {"device", t.device}, {"sensor", t.sensor}, {"frames_set", t.frames_set},
                           {"frames_without_sample", t.frames_without_sample},
                           {"velocities_estimated", t.velocities_estimated}});
    j["tracked"] = tracked;
    j["warnings"] = r.warnings;
    j["outputs"] = r.outputs;
    if (!r.sound.empty()) j["sound"] = r.sound;   // --sound: format, impacts, output stage
    // Atomically (<path>.tmp renamed into place): a play.json is never half written.
    recording::AtomicFile out(path);
    out.write(j.dump(2) + "\n");
    out.commit();
}

}  // namespace vroc::play
