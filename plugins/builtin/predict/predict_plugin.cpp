// SPDX-License-Identifier: MIT
// `predict`: a decorator. Loads another plugin by name through the host, opens one of its devices
// and serves its poses predicted ahead, to hide latency (Azuma & Bishop 1994; cf. VRPN
// DeadReckoning, Monado m_relation_history). Each new inner measurement updates a per-sensor
// PosePredictor; get_pose(t) returns the prediction for t (or, with ahead=S, for the measurement
// time + S), extrapolating at most max_ahead seconds.
#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "plugin_sdk.h"
#include "pose_math.h"
#include "pose_predictor.h"

namespace vroc::plugins::predict {
using namespace plugin_sdk;

namespace {

constexpr const char* kHelp =
    "inner=NAME: the plugin to wrap (required); inner.KEY=VALUE: its options; inner_device=0; "
    "method=kalman: none|cv|kalman; ahead=S: predict S seconds past each measurement (default: "
    "to the asked time); max_ahead=0.1 [s]; q_pos=50, r_pos=0.001, r_vel=0.05, q_rot=500, "
    "r_rot=0.002, r_angvel=0.05: Kalman tuning (SI)";

bool finiteSample(const VrocPoseSample& s) {
    for (double v : s.position) if (!std::isfinite(v)) return false;
    for (double v : s.orientation) if (!std::isfinite(v)) return false;
    for (double v : s.linear_velocity) if (!std::isfinite(v)) return false;
    for (double v : s.angular_velocity) if (!std::isfinite(v)) return false;
    return orientationOf(s).norm() > 0.5;
}

class PredictDevice final : public Device {
public:
    PredictDevice(const VrocDeviceApi* inner, VrocDeviceHandle handle, PredictMethod method, const KalmanTuning& tuning,
                  std::optional<int64_t> ahead_ns, int64_t max_ahead_ns)
        : inner_(inner), handle_(handle), method_(method), tuning_(tuning), ahead_ns_(ahead_ns), max_ahead_ns_(max_ahead_ns) {}
    ~PredictDevice() override { inner_->destroy(handle_); }

    int32_t start() override { return forward(inner_->start(handle_)); }
    int32_t stop() override { return forward(inner_->stop(handle_)); }

    int32_t pose(uint32_t sensor, int64_t at_time_ns, VrocPoseSample& out) override {
        VrocPoseSample m;
        initPoseSample(m);
        const int32_t rc = inner_->get_pose(handle_, sensor, at_time_ns, &m);
        if (rc < 0) return forward(rc);
        if (!finiteSample(m)) return setError(VROC_ERROR_GENERIC, "predict: the inner device returned a non-finite pose");
        std::lock_guard lock(mutex_);
        auto [it, inserted] = predictors_.try_emplace(sensor, method_, tuning_);
        PosePredictor& predictor = it->second;
        predictor.add(toMeasurement(m));
        const int64_t target = ahead_ns_ ? predictor.lastTime() + *ahead_ns_ : at_time_ns;
        const int64_t ahead = std::clamp(target - predictor.lastTime(), -max_ahead_ns_, max_ahead_ns_);
        const Prediction p = predictor.predict(secondsOf(ahead));
        uint32_t flags = m.flags & (kPoseValidTracked);
        if (ahead > 0 && method_ != PredictMethod::None) flags |= VROC_POSE_EXTRAPOLATED;
        writePose(out, method_ == PredictMethod::None ? predictor.lastTime() : predictor.lastTime() + ahead, sensor,
                  p.position, p.orientation, flags, &p.linear_velocity, &p.angular_velocity);
        out.sequence = m.sequence;
        return VROC_OK;
    }

    int32_t controls(int64_t at_time_ns, VrocControlState& out) override {
        return forward(inner_->get_controls(handle_, at_time_ns, &out));
    }

private:
    static Measurement toMeasurement(const VrocPoseSample& s) {
        Measurement m{s.time_ns, positionOf(s), orientationOf(s).normalized(), std::nullopt, std::nullopt};
        if (s.flags & VROC_POSE_LINEAR_VELOCITY_VALID)
            m.linear_velocity = Eigen::Vector3d(s.linear_velocity[0], s.linear_velocity[1], s.linear_velocity[2]);
        if (s.flags & VROC_POSE_ANGULAR_VELOCITY_VALID)
            m.angular_velocity = Eigen::Vector3d(s.angular_velocity[0], s.angular_velocity[1], s.angular_velocity[2]);
        return m;
    }

    int32_t forward(int32_t rc) {
        if (rc >= 0) return rc;
        char text[400] = "";
        inner_->last_error(handle_, text, sizeof text);
        return setError(rc, std::string("predict: inner device: ") + text);
    }

    const VrocDeviceApi* inner_;
    VrocDeviceHandle handle_;
    PredictMethod method_;
    KalmanTuning tuning_;
    std::optional<int64_t> ahead_ns_;
    int64_t max_ahead_ns_;
    std::mutex mutex_;
    std::map<uint32_t, PosePredictor> predictors_;
};

void describe(uint32_t, VrocDeviceDesc& out) {
    out.kind = VROC_DEVICE_HEAD_TRACKER;
    out.sensor_count = 16;
    out.button_count = 64;
    out.axis_count = VROC_MAX_AXES;
    out.caps = VROC_CAP_POSE_SOURCE | VROC_CAP_BUTTONS | VROC_CAP_ANALOG_AXES | VROC_CAP_POSITION |
               VROC_CAP_ORIENTATION | VROC_CAP_VELOCITY | VROC_CAP_SOURCE_TIMESTAMPS | VROC_CAP_PREDICTS;
    out.nominal_rate_hz = 0;
    out.nominal_latency_ns = 0;
    out.name = "predicting decorator";
    out.options_help = kHelp;
}

PredictMethod parseMethod(Options& o) {
    const std::string text = o.getString("method", "kalman");
    if (text == "none") return PredictMethod::None;
    if (text == "cv" || text == "constant-velocity") return PredictMethod::ConstantVelocity;
    if (text == "kalman") return PredictMethod::Kalman;
    throw OptionError("predict: option method='" + text + "': expected none, cv or kalman");
}

std::unique_ptr<Device> create(uint32_t, Options& o) {
    if (!o.has("inner")) throw OptionError("predict: option inner=PLUGIN is required");
    const std::string inner_name = o.getString("inner", "");
    if (inner_name == "predict") throw OptionError("predict: inner=predict would wrap itself");
    const auto index = static_cast<uint32_t>(o.getInt("inner_device", 0, 0, 1000));
    const std::string inner_options = o.takePrefixed("inner.");
    const PredictMethod method = parseMethod(o);
    KalmanTuning t;
    t.q_pos = o.getDouble("q_pos", t.q_pos, 1e-12, 1e12);
    t.r_pos = o.getDouble("r_pos", t.r_pos, 1e-9, 1e3);
    t.r_vel = o.getDouble("r_vel", t.r_vel, 1e-9, 1e3);
    t.q_rot = o.getDouble("q_rot", t.q_rot, 1e-12, 1e12);
    t.r_rot = o.getDouble("r_rot", t.r_rot, 1e-9, 1e3);
    t.r_angvel = o.getDouble("r_angvel", t.r_angvel, 1e-9, 1e3);
    std::optional<int64_t> ahead;
    if (o.has("ahead")) ahead = nsOf(o.getDouble("ahead", 0.0, -1.0, 1.0));
    const int64_t max_ahead = nsOf(o.getDouble("max_ahead", 0.1, 0.0, 1.0));
    o.finish();  // reject typos before opening the inner device

    uint32_t count = 0;
    const VrocDeviceApi* inner = loadPlugin(inner_name.c_str(), &count);
    if (!inner) throw OptionError("predict: cannot load inner plugin '" + inner_name + "' (see the log)");
    if (index >= count) throw OptionError("predict: inner plugin '" + inner_name + "' has no device " + std::to_string(index));
    VrocDeviceHandle handle = nullptr;
    if (inner->create(index, inner_options.c_str(), &handle) < 0 || !handle) {
        char text[400] = "";
        inner->last_error(nullptr, text, sizeof text);
        throw OptionError("predict: inner " + inner_name + ": " + text);
    }
    return std::make_unique<PredictDevice>(inner, handle, method, t, ahead, max_ahead);
}

const PluginDefinition kDefinition = {"predict", "1.0.0",
                                      "wraps a device and predicts its pose ahead (constant velocity or Kalman filter)",
                                      1, describe, create};

}  // namespace
}  // namespace vroc::plugins::predict

VROC_DEFINE_PLUGIN(vroc::plugins::predict::kDefinition)
