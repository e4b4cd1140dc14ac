// SPDX-License-Identifier: MIT
#include <cmath>

#include "vroc/play/device_source.h"
#include "vroc/plugin/plugin_host.h"

namespace vroc::play {

PluginDevice::PluginDevice(plugins::PluginHost& host, const std::string& spec)
    : spec_(spec), handle_(host.openSpec(spec)) {
    handle_->start();
}

PluginDevice::~PluginDevice() {
    if (handle_) handle_->stop();
}

DeviceReading PluginDevice::read(double t) {
    const auto ns = static_cast<std::int64_t>(std::llround(t * 1e9));
    DeviceReading r;
    const plugins::PoseResult pose = handle_->pose(0, ns);
    if (pose.ok()) {
        r.valid = true;
        r.pose = pose.sample.pose;
        r.has_velocity = pose.sample.has(VROC_POSE_LINEAR_VELOCITY_VALID | VROC_POSE_ANGULAR_VELOCITY_VALID);
        r.linear_velocity = pose.sample.linear_velocity;
        r.angular_velocity = pose.sample.angular_velocity;
    }
    const plugins::ControlResult controls = handle_->controls(ns);
    if (controls.ok()) r.buttons = controls.state.buttons;
    return r;
}

}  // namespace vroc::play
