// SPDX-License-Identifier: MIT
// `replay`: plays back a pose recording (CSV time_ns,sensor,x,y,z,qx,qy,qz,qw,buttons, as written
// by vroc::plugins::PoseRecorder). get_pose(t) interpolates between the samples around t
// (position linearly, orientation by slerp) and reports the velocity between them; before the
// first and after the last sample it holds the end pose, valid but not tracked.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>

#include "plugin_sdk.h"
#include "pose_csv.h"
#include "pose_math.h"
#include "pose_track.h"

namespace vroc::plugins::replay {
using namespace plugin_sdk;

namespace {

constexpr uint32_t kMaxSensors = 16;
// [m] largest |coordinate| of a recorded position, as for scenes (core scene_limits.h): within it
// interpolation and velocities stay finite even 1 ns apart (beyond it, 1e308 then -1e308 gave an
// infinite pose the host rejects at run time; found with tests/fuzz/pose_csv_fuzz, docs/fuzzing.md).
constexpr double kMaxCoordinate = 1e6;
constexpr const char* kHelp =
    "file=PATH: the recording (required); offset=0: seconds added to the recorded times; "
    "loop=0: repeat the recording";

class ReplayDevice final : public Device {
public:
    ReplayDevice(std::vector<PoseTrack> tracks, int64_t offset_ns, bool loop)
        : tracks_(std::move(tracks)), offset_ns_(offset_ns), loop_(loop) {}

    int32_t pose(uint32_t sensor, int64_t at_time_ns, VrocPoseSample& out) override {
        if (sensor >= tracks_.size() || tracks_[sensor].empty())
            return setError(VROC_ERROR_NO_DATA, "replay: the recording has no sensor " + std::to_string(sensor));
        const PoseTrack& track = tracks_[sensor];
        const int64_t t = recordingTime(track, at_time_ns);
        const TrackPose p = track.at(t);
        const uint32_t flags = p.inside ? kPoseValidTracked : kPoseValid;
        writePose(out, at_time_ns, sensor, p.position, p.orientation, flags | (p.inside ? 0u : VROC_POSE_EXTRAPOLATED),
                  &p.linear_velocity, &p.angular_velocity);
        out.sequence = p.index;
        return p.inside ? VROC_OK : VROC_EXTRAPOLATED;
    }

    int32_t controls(int64_t at_time_ns, VrocControlState& out) override {
        if (tracks_.empty() || tracks_[0].empty()) return setError(VROC_ERROR_NO_DATA, "replay: no sensor 0");
        out.time_ns = at_time_ns;
        out.buttons = tracks_[0].at(recordingTime(tracks_[0], at_time_ns)).buttons;
        out.axis_count = 0;
        return VROC_OK;
    }

private:
    // In 128 bits: host time, offset and the recording's times are each any int64, and their
    // differences need not be. A time beyond the int64 range is beyond the recording: held there.
    int64_t recordingTime(const PoseTrack& track, int64_t host_ns) const {
        __int128 t = static_cast<__int128>(host_ns) - offset_ns_;
        const __int128 first = track.firstTime(), length = track.lastTime() - first;
        if (loop_ && length > 0 && t > track.lastTime()) t = first + (t - first) % length;
        return static_cast<int64_t>(std::clamp<__int128>(t, INT64_MIN, INT64_MAX));
    }

    std::vector<PoseTrack> tracks_;
    int64_t offset_ns_;
    bool loop_;
};

std::vector<PoseTrack> readRecording(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw OptionError("replay: cannot open recording '" + path + "'");
    std::string line;
    if (!std::getline(in, line) || line.rfind(kPoseCsvHeader, 0) != 0)
        throw OptionError("replay: " + path + ":1: expected the header '" + std::string(kPoseCsvHeader) + "'");
    std::vector<PoseTrack> tracks(kMaxSensors);
    std::vector<int64_t> last(kMaxSensors, INT64_MIN);
    for (int number = 2; std::getline(in, line); ++number) {
        if (line.empty() || line == "\r") continue;
        PoseCsvRow row;
        std::string error;
        const std::string where = "replay: " + path + ":" + std::to_string(number) + ": ";
        if (!parsePoseCsvRow(line, row, error)) throw OptionError(where + error);
        if (row.sensor >= kMaxSensors) throw OptionError(where + "sensor " + std::to_string(row.sensor) + " >= 16");
        for (int i = 0; i < 3; ++i)
            if (!(std::abs(row.position[i]) <= kMaxCoordinate))
                throw OptionError(where + "column " + "xyz"[i] + ": expected a position within +-1e6 m, got " +
                                  std::to_string(row.position[i]));
        if (row.time_ns < last[row.sensor]) throw OptionError(where + "time_ns goes backwards for this sensor");
        last[row.sensor] = row.time_ns;
        const auto& q = row.orientation;
        tracks[row.sensor].add({row.time_ns, {row.position[0], row.position[1], row.position[2]},
                                Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized(), row.buttons});
    }
    bool any = false;
    for (const PoseTrack& t : tracks) any = any || !t.empty();
    if (!any) throw OptionError("replay: " + path + ": no samples");
    return tracks;
}

void describe(uint32_t, VrocDeviceDesc& out) {
    out.kind = VROC_DEVICE_HAND_TRACKER;
    out.sensor_count = kMaxSensors;
    out.button_count = 64;
    out.axis_count = 0;
    out.caps = VROC_CAP_POSE_SOURCE | VROC_CAP_BUTTONS | VROC_CAP_POSITION | VROC_CAP_ORIENTATION |
               VROC_CAP_VELOCITY | VROC_CAP_SOURCE_TIMESTAMPS;
    out.nominal_rate_hz = 0;
    out.nominal_latency_ns = 0;
    out.name = "pose recording";
    out.options_help = kHelp;
}

std::unique_ptr<Device> create(uint32_t, Options& o) {
    if (!o.has("file")) throw OptionError("replay: option file=PATH is required");
    auto tracks = readRecording(o.getString("file", ""));
    const int64_t offset = nsOf(o.getDouble("offset", 0.0));
    return std::make_unique<ReplayDevice>(std::move(tracks), offset, o.getBool("loop", false));
}

const PluginDefinition kDefinition = {"replay", "1.0.0", "plays back a pose recording (CSV), interpolating with slerp",
                                      1, describe, create};

}  // namespace
}  // namespace vroc::plugins::replay

VROC_DEFINE_PLUGIN(vroc::plugins::replay::kDefinition)
