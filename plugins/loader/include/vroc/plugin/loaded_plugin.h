// SPDX-License-Identifier: MIT
// What the host knows about a plugin after a successful, validated negotiation.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vroc/plugin/vroc_device_plugin.h"

namespace vroc::plugins {

/// describe() of one device, copied into host-owned strings.
struct DeviceDescription {
    uint32_t kind = 0;            ///< VROC_DEVICE_*
    uint32_t sensor_count = 0;
    uint32_t button_count = 0;
    uint32_t axis_count = 0;
    uint64_t caps = 0;            ///< VROC_CAP_*
    double nominal_rate_hz = 0;   ///< [Hz], 0 = continuous
    int64_t nominal_latency_ns = 0;
    std::string name;
    std::string options_help;
};

struct LoadedPlugin {
    std::string path;             ///< the file, or "static:<label>" for a linked-in plugin
    std::string name;             ///< from the plugin, e.g. "analytic"
    std::string version;
    std::string description;
    uint32_t abi_version = 0;
    uint64_t capabilities = 0;    ///< union of the devices' caps
    const VrocDeviceApi* api = nullptr;  ///< plugin-owned static table, valid while loaded
    std::vector<DeviceDescription> devices;
    void* library = nullptr;      ///< dlopen handle (null for static plugins); owned by PluginHost
};

/// "pose-source,buttons,analog-axes,force-output" style list of the VROC_CAP_* bits set.
std::string capabilityNames(uint64_t caps);
/// "head-tracker", "hand-tracker", "space-mouse", "buttons" or "unknown".
const char* deviceKindName(uint32_t kind);

}  // namespace vroc::plugins
