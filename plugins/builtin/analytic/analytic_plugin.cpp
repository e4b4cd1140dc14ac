// SPDX-License-Identifier: MIT
// `analytic`: one sensor following a closed-form motion (analytic_motion.h), with an optional
// tracker model on top: a measurement latency, a sampling rate and deterministic noise. The pose
// returned for host time t is the measurement taken at t - latency (on the rate grid), stamped
// with that measurement time, so the result is a pure function of t.
#include <cmath>
#include <cstdint>

#include "analytic_motion.h"
#include "plugin_sdk.h"
#include "pose_math.h"

namespace vroc::plugins::analytic {
using namespace plugin_sdk;

namespace {

constexpr const char* kHelp =
    "motion=circle: static|circle|figure8|throw|head-turn|spin|line; x,y,z=0,0,1.2: centre (line: start) "
    "[m]; radius=0.3 [m]; period=2 [s]; speed_deg=200: head-turn peak / spin rate [deg/s]; "
    "amplitude_deg=30: head-turn amplitude; throw_speed=3: release speed [m/s]; line only: "
    "vx,vy,vz=0,0,0 [m/s], qx,qy,qz,qw=0,0,0,1 fixed orientation, press_at=0: button 0 held from [s], "
    "duration=0: seconds of motion, then at rest (0 = unbounded); latency=0 [s]; "
    "rate=0: measurements per second (0 = continuous); noise_pos=0 [m]; noise_rot=0 [rad]; "
    "velocities=1: report velocities";

struct TrackerModel {
    int64_t latency_ns = 0;
    int64_t period_ns = 0;  // 0 = continuous
    double noise_pos = 0;   // standard deviation [m]
    double noise_rot = 0;   // standard deviation [rad]
    bool velocities = true;
};

// splitmix64: a stateless hash, so noise depends only on (measurement time, component).
double uniformNoise(int64_t time_ns, int component) {
    uint64_t z = static_cast<uint64_t>(time_ns) * 0x9E3779B97F4A7C15ull + static_cast<uint64_t>(component) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    const double u = static_cast<double>(z >> 11) * 0x1.0p-53;  // [0, 1)
    return (2.0 * u - 1.0) * std::sqrt(3.0);                     // zero mean, unit variance
}

int64_t floorDiv(int64_t a, int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }

class AnalyticDevice final : public Device {
public:
    AnalyticDevice(const MotionParams& motion, const TrackerModel& tracker) : motion_(motion), tracker_(tracker) {}

    int32_t pose(uint32_t sensor, int64_t at_time_ns, VrocPoseSample& out) override {
        if (sensor != 0) return setError(VROC_ERROR_INVALID_ARGUMENT, "analytic: only sensor 0 exists");
        int64_t measured = at_time_ns - tracker_.latency_ns;
        uint64_t sequence = static_cast<uint64_t>(measured);
        if (tracker_.period_ns > 0) {
            const int64_t index = floorDiv(measured, tracker_.period_ns);
            measured = index * tracker_.period_ns;
            sequence = static_cast<uint64_t>(index);
        }
        const MotionState s = evaluateMotion(motion_, secondsOf(measured));
        Eigen::Vector3d p = s.position, noise_rv;
        for (int i = 0; i < 3; ++i) {
            p[i] += tracker_.noise_pos * uniformNoise(measured, i);
            noise_rv[i] = tracker_.noise_rot * uniformNoise(measured, 3 + i);
        }
        const Eigen::Quaterniond q = quatFromRotationVector(noise_rv) * s.orientation;
        const bool v = tracker_.velocities;
        writePose(out, measured, 0, p, q, kPoseValidTracked, v ? &s.linear_velocity : nullptr,
                  v ? &s.angular_velocity : nullptr);
        out.sequence = sequence;
        return VROC_OK;
    }

    int32_t controls(int64_t at_time_ns, VrocControlState& out) override {
        const int64_t measured = at_time_ns - tracker_.latency_ns;
        out.time_ns = measured;
        out.buttons = evaluateMotion(motion_, secondsOf(measured)).button ? 1u : 0u;
        out.axis_count = 0;
        return VROC_OK;
    }

private:
    MotionParams motion_;
    TrackerModel tracker_;
};

void describe(uint32_t, VrocDeviceDesc& out) {
    out.kind = VROC_DEVICE_HAND_TRACKER;
    out.sensor_count = 1;
    out.button_count = 1;
    out.axis_count = 0;
    out.caps = VROC_CAP_POSE_SOURCE | VROC_CAP_BUTTONS | VROC_CAP_POSITION | VROC_CAP_ORIENTATION |
               VROC_CAP_VELOCITY | VROC_CAP_SOURCE_TIMESTAMPS;
    out.nominal_rate_hz = 0;
    out.nominal_latency_ns = 0;
    out.name = "analytic motion";
    out.options_help = kHelp;
}

std::unique_ptr<Device> create(uint32_t, Options& o) {
    constexpr double kDeg = 3.14159265358979323846 / 180;
    MotionParams m;
    const std::string kind = o.getString("motion", "circle");
    if (!parseMotionKind(kind, m.kind))
        throw OptionError("analytic: option motion='" + kind +
                          "': expected static, circle, figure8, throw, head-turn, spin or line");
    m.center = {o.getDouble("x", 0.0), o.getDouble("y", 0.0), o.getDouble("z", 1.2)};
    m.radius = o.getDouble("radius", m.kind == MotionKind::Throw ? 0.6 : 0.3, 1e-6, 1e6);
    m.period = o.getDouble("period", 2.0, 1e-3, 1e6);
    m.amplitude = o.getDouble("amplitude_deg", 30.0, 1e-3, 180.0) * kDeg;
    m.speed = m.kind == MotionKind::Throw ? o.getDouble("throw_speed", 3.0, 1e-3, 1e3)
                                          : o.getDouble("speed_deg", 200.0, -1e6, 1e6) * kDeg;
    if (m.kind == MotionKind::Throw) o.getDouble("speed_deg", 0.0);  // accepted, unused
    else o.getDouble("throw_speed", 0.0);
    if (m.kind == MotionKind::Line) {  // read only for a line, so a stray vx elsewhere is an unknown option
        m.velocity = {o.getDouble("vx", 0.0), o.getDouble("vy", 0.0), o.getDouble("vz", 0.0)};
        const Eigen::Vector4d q(o.getDouble("qx", 0.0), o.getDouble("qy", 0.0), o.getDouble("qz", 0.0),
                                o.getDouble("qw", 1.0));
        if (std::fabs(q.norm() - 1.0) > 0.01)
            throw OptionError("analytic: options qx,qy,qz,qw: expected a unit quaternion [x, y, z, w] (norm " +
                              std::to_string(q.norm()) + ")");
        m.orientation = Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized();
        m.press_at = o.getDouble("press_at", 0.0);
        m.duration = o.getDouble("duration", 0.0, 0.0, 1e9);
    }
    TrackerModel t;
    t.latency_ns = nsOf(o.getDouble("latency", 0.0, 0.0, 10.0));
    const double rate = o.getDouble("rate", 0.0, 0.0, 1e6);
    t.period_ns = rate > 0 ? std::max<int64_t>(1, nsOf(1.0 / rate)) : 0;
    t.noise_pos = o.getDouble("noise_pos", 0.0, 0.0, 1.0);
    t.noise_rot = o.getDouble("noise_rot", 0.0, 0.0, 1.0);
    t.velocities = o.getBool("velocities", true);
    return std::make_unique<AnalyticDevice>(m, t);
}

const PluginDefinition kDefinition = {
    "analytic", "1.1.0", "scripted closed-form motion (circle, figure-eight, throw, head turn, spin, line)", 1,
    describe, create};

}  // namespace
}  // namespace vroc::plugins::analytic

VROC_DEFINE_PLUGIN(vroc::plugins::analytic::kDefinition)
