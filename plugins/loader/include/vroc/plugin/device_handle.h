// SPDX-License-Identifier: MIT
// An opened device of a loaded plugin (RAII: destroy on destruction). Every sample the plugin
// returns is checked (finite, unit quaternion, right sensor) before the caller sees it; a bad one
// becomes SampleStatus::Rejected, is counted and logged once, and never reaches the simulation.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

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

    const LoadedPlugin& plugin() const { return plugin_; }
    const DeviceDescription& description() const { return plugin_.devices[index_]; }
    /// Samples the host threw away because they failed validation.
    uint64_t rejectedSamples() const { return rejected_.load(); }
    std::string lastError() const;

private:
    PoseResult reject(const std::string& why, int32_t code);

    PluginHost& host_;
    const LoadedPlugin& plugin_;
    uint32_t index_;
    VrocDeviceHandle handle_;
    std::atomic<uint64_t> rejected_{0};
};

}  // namespace vroc::plugins
