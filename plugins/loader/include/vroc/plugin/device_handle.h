// SPDX-License-Identifier: MIT
// An opened device of a loaded plugin (RAII: destroy on destruction). Every sample the plugin
// returns is checked (finite, unit quaternion, right sensor) before the caller sees it; a bad one
// becomes SampleStatus::Rejected, is counted and logged once, and never reaches the simulation.
// The output direction (ABI 2): sendForce hands a force and torque to a device that declared
// VROC_CAP_FORCE_OUTPUT; non-finite input never crosses the boundary.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "vroc/plugin/loaded_plugin.h"
#include "vroc/plugin/pose_sample.h"

namespace vroc::plugins {

class PluginHost;

class DeviceHandle {
public:
    /// Use PluginHost::open. `handle` is owned from here on.
    DeviceHandle(PluginHost& host, const LoadedPlugin& plugin, uint32_t index, VrocDeviceHandle handle);
    ~DeviceHandle();
    DeviceHandle(const DeviceHandle&) = delete;
    DeviceHandle& operator=(const DeviceHandle&) = delete;

    /// Throws RunError with last_error on failure.
    void start();
    void stop();

    /// The pose of `sensor` at host time at_time_ns. Never throws; never returns non-finite data.
    PoseResult pose(uint32_t sensor, int64_t at_time_ns);
    ControlResult controls(int64_t at_time_ns);

    /// True if the device takes forces: its plugin negotiated ABI >= 2 and the device declares
    /// VROC_CAP_FORCE_OUTPUT. ABI-1 plugins never take forces (their set_force is never called).
    bool acceptsForce() const;
    /// Sends the wrench the simulation applies to the user's hand at `sensor`'s origin: force [N]
    /// and torque [N m] about that origin, both in the base frame, computed for host time time_ns.
    /// Returns true if the plugin took it. Never throws. Returns false without calling the plugin
    /// if the device does not accept forces (not counted), or if a value is not finite or the sensor
    /// is out of range (counted in rejectedForces, logged once); returns false and counts if the
    /// plugin fails (its last_error text is logged once).
    bool sendForce(uint32_t sensor, int64_t time_ns, const Eigen::Vector3d& force_N, const Eigen::Vector3d& torque_Nm);

    const LoadedPlugin& plugin() const { return plugin_; }
    const DeviceDescription& description() const { return plugin_.devices[index_]; }
    /// Samples the host threw away because they failed validation.
    uint64_t rejectedSamples() const { return rejected_.load(); }
    /// Force commands refused (non-finite, bad sensor) or failed in the plugin.
    uint64_t rejectedForces() const { return rejected_forces_.load(); }
    /// Force commands the plugin accepted.
    uint64_t sentForces() const { return sent_forces_.load(); }
    std::string lastError() const;

private:
    PoseResult reject(const std::string& why, int32_t code);
    bool rejectForce(const std::string& why);

    PluginHost& host_;
    const LoadedPlugin& plugin_;
    uint32_t index_;
    VrocDeviceHandle handle_;
    std::atomic<uint64_t> rejected_{0};
    std::atomic<uint64_t> rejected_forces_{0};
    std::atomic<uint64_t> sent_forces_{0};
};

}  // namespace vroc::plugins
