// SPDX-License-Identifier: MIT
#include <cmath>

#include "vroc/play/device_source.h"
#include "vroc/plugin/plugin_host.h"

namespace vroc::play {

PluginDevice::PluginDevice(plugins::PluginHost& host, const std::string& spec, std::uint32_t sensor)
    : spec_(spec), sensor_(sensor), handle_(host.openSpec(spec)) {
    handle_->start();
}

PluginDevice::~PluginDevice() {
    if (handle_) handle_->stop();
}

std::int64_t PluginDevice::hostTime(double t) const {
    return host_zero_ns_ + static_cast<std::int64_t>(std::llround(t * 1e9));
}

DeviceReading PluginDevice::read(double t) {
    const std::int64_t ns = hostTime(t);
    DeviceReading r;
    const plugins::PoseResult pose = handle_->pose(sensor_, ns);
    if (pose.ok()) {
        r.valid = true;
        r.pose = pose.sample.pose;
        r.has_velocity = pose.sample.has(VROC_POSE_LINEAR_VELOCITY_VALID | VROC_POSE_ANGULAR_VELOCITY_VALID);
        r.linear_velocity = pose.sample.linear_velocity;
        r.angular_velocity = pose.sample.angular_velocity;
        r.sample_time_ns = pose.sample.time_ns;
        r.sequence = pose.sample.sequence;
    }
    const plugins::ControlResult controls = handle_->controls(ns);
    if (controls.ok()) r.buttons = controls.state.buttons;
    return r;
}

bool PluginDevice::acceptsForce() const { return handle_->acceptsForce(); }

bool PluginDevice::sendForce(double t, const Vec3& force_N, const Vec3& torque_Nm) {
    if (!handle_->acceptsForce()) return false;
    return handle_->sendForce(sensor_, hostTime(t), force_N, torque_Nm);
}

std::uint64_t PluginDevice::forcesSent() const { return handle_->sentForces(); }
std::uint64_t PluginDevice::forcesRejected() const { return handle_->rejectedForces(); }

}  // namespace vroc::play
