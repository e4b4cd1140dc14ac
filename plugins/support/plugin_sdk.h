// SPDX-License-Identifier: MIT
// Helper for writing a device plugin in C++ over the C ABI (vroc/plugin/vroc_device_plugin.h).
// A plugin derives its devices from plugin_sdk::Device, fills a PluginDefinition and expands
// VROC_DEFINE_PLUGIN(definition) once. The SDK owns the C function table: it converts handles,
// checks output struct headers, catches every exception at the boundary (-> negative result +
// last_error text) and keeps the host services for logging and the clock.
#pragma once

#include <memory>
#include <mutex>
#include <string>

#include "options.h"
#include "vroc/plugin/vroc_device_plugin.h"

namespace vroc::plugin_sdk {

/// One opened device. Subclasses implement pose() (and controls() for buttons/axes). Called
/// from any thread: implementations keep their own locking.
class Device {
public:
    virtual ~Device() = default;
    virtual int32_t start() { return VROC_OK; }
    virtual int32_t stop() { return VROC_OK; }
    /// `out` has a valid v1 header; fill time_ns, flags, sequence, pose and velocities.
    virtual int32_t pose(uint32_t sensor, int64_t at_time_ns, VrocPoseSample& out) = 0;
    virtual int32_t controls(int64_t at_time_ns, VrocControlState& out);
    /// ABI 2 output: one force command, header checked and every value finite (the SDK checks both
    /// before calling). Devices that declare VROC_CAP_FORCE_OUTPUT override it.
    virtual int32_t force(const VrocForceCommand& command);

    /// Records the error text for last_error and returns `code` (for `return setError(...)`).
    int32_t setError(int32_t code, const std::string& text);
    std::string lastError() const;

private:
    mutable std::mutex error_mutex_;
    std::string error_;
};

struct PluginDefinition {
    const char* name;          ///< static, [a-z0-9-]
    const char* version;       ///< static
    const char* description;   ///< static, one line
    uint32_t device_count;
    /// Fills kind, counts, caps, rates, name and options_help of device `index`.
    void (*describe)(uint32_t index, VrocDeviceDesc& out);
    /// Opens device `index`; throws OptionError (or anything) on failure.
    std::unique_ptr<Device> (*create)(uint32_t index, Options& options);
};

/// The negotiate implementation behind VROC_DEFINE_PLUGIN. Chooses the highest ABI both sides
/// know (2 with a current host). With an ABI-1 host the same table is offered as ABI 1 and
/// describe() drops VROC_CAP_FORCE_OUTPUT, since ABI 1 has no send_force (the SDK leaves the
/// ABI-1 set_force NULL).
int32_t negotiate(const PluginDefinition& definition, const VrocHostInfo* host, VrocPluginInfo* out) noexcept;

/// Host services (no-ops before negotiation).
void log(int32_t severity, const std::string& message);
int64_t nowNs();
/// Loads another plugin through the host; returns null (and logs) on failure.
const VrocDeviceApi* loadPlugin(const char* name_or_path, uint32_t* device_count);

/// Copies `text` into a C buffer the way last_error does; returns the full length.
int32_t copyText(const std::string& text, char* buffer, uint64_t size);
/// A pose sample's v1 header.
void initPoseSample(VrocPoseSample& sample);
void initControlState(VrocControlState& state);

}  // namespace vroc::plugin_sdk

#define VROC_DEFINE_PLUGIN(definition)                                                            \
    extern "C" VROC_PLUGIN_EXPORT int32_t vroc_plugin_negotiate(const VrocHostInfo* host,         \
                                                                VrocPluginInfo* out) {            \
        return ::vroc::plugin_sdk::negotiate((definition), host, out);                            \
    }
