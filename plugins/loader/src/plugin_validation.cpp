// SPDX-License-Identifier: MIT
#include "plugin_validation.h"

#include <cmath>
#include <cstddef>
#include <cstdio>

namespace vroc::plugins {
namespace {

// The table a plugin must provide for the ABI version it chose: ABI 1 ends with set_force, ABI 2
// with send_force.
uint64_t requiredApiSize(uint32_t abi_version) {
    return abi_version >= 2 ? VROC_DEVICE_API_SIZE_V2 : VROC_DEVICE_API_SIZE_V1;
}

bool validName(const char* name) {
    if (!name || !*name) return false;
    for (const char* c = name; *c; ++c)
        if (!((*c >= 'a' && *c <= 'z') || (*c >= '0' && *c <= '9') || *c == '-' || *c == '_')) return false;
    return true;
}

std::string checkTable(const VrocDeviceApi* api, uint32_t abi_version) {
    if (!api) return "null function table (VrocPluginInfo.api)";
    if (api->struct_type != VROC_STRUCT_DEVICE_API)
        return "function table has struct_type " + std::to_string(api->struct_type) + ", expected " +
               std::to_string(VROC_STRUCT_DEVICE_API);
    if (api->struct_size < requiredApiSize(abi_version))
        return "function table is too small for ABI " + std::to_string(abi_version) + " (struct_size " +
               std::to_string(api->struct_size) + " bytes, host needs at least " +
               std::to_string(requiredApiSize(abi_version)) + ")";
    const struct {
        const char* name;
        bool present;
    } entries[] = {{"describe", api->describe != nullptr}, {"create", api->create != nullptr},
                   {"start", api->start != nullptr},       {"stop", api->stop != nullptr},
                   {"destroy", api->destroy != nullptr},   {"get_pose", api->get_pose != nullptr},
                   {"get_controls", api->get_controls != nullptr}, {"last_error", api->last_error != nullptr}};
    for (const auto& entry : entries)
        if (!entry.present) return std::string("function table entry '") + entry.name + "' is null";
    return {};
}

std::string describeDevice(const VrocDeviceApi& api, uint32_t abi_version, uint32_t index, DeviceDescription& out) {
    VrocDeviceDesc desc{};
    desc.struct_type = VROC_STRUCT_DEVICE_DESC;
    desc.struct_version = 1;
    desc.struct_size = sizeof desc;
    const int32_t rc = api.describe(index, &desc);
    const std::string which = "device " + std::to_string(index) + ": ";
    if (rc < 0) return which + "describe failed with code " + std::to_string(rc);
    if (desc.axis_count > VROC_MAX_AXES) return which + "axis_count " + std::to_string(desc.axis_count) + " > 8";
    if (desc.button_count > 64) return which + "button_count " + std::to_string(desc.button_count) + " > 64";
    if ((desc.caps & VROC_CAP_POSE_SOURCE) && desc.sensor_count == 0) return which + "pose source with no sensors";
    // Force output needs the function of the chosen ABI (send_force exists only in an ABI-2 table,
    // whose size checkTable has already confirmed).
    if ((desc.caps & VROC_CAP_FORCE_OUTPUT) && abi_version >= 2 && !api.send_force)
        return which + "force output declared but send_force is null";
    if ((desc.caps & VROC_CAP_FORCE_OUTPUT) && abi_version == 1 && !api.set_force)
        return which + "force output declared but set_force is null (ABI 1)";
    if (!std::isfinite(desc.nominal_rate_hz) || desc.nominal_rate_hz < 0) return which + "nominal_rate_hz is not a finite rate";
    out = {desc.kind, desc.sensor_count, desc.button_count, desc.axis_count, desc.caps, desc.nominal_rate_hz,
           desc.nominal_latency_ns, desc.name ? desc.name : "", desc.options_help ? desc.options_help : ""};
    return {};
}

std::string finiteCheck(const char* what, const double* v, int n) {
    for (int i = 0; i < n; ++i)
        if (!std::isfinite(v[i])) {
            char text[160];
            std::snprintf(text, sizeof text, "%s is not finite (component %d = %g)", what, i, v[i]);
            return text;
        }
    return {};
}

}  // namespace

std::string validatePluginInfo(const VrocPluginInfo& info, uint32_t abi_min, uint32_t abi_max, LoadedPlugin& out) {
    if (info.abi_version < abi_min || info.abi_version > abi_max)
        return "ABI version " + std::to_string(info.abi_version) + " not supported (host accepts " +
               std::to_string(abi_min) + ".." + std::to_string(abi_max) + ")";
    if (std::string why = checkTable(info.api, info.abi_version); !why.empty()) return why;
    if (!validName(info.name)) return "plugin name is missing or not [a-z0-9-_]";
    if (!info.version) return "plugin version string is null";
    if (info.device_count == 0) return "plugin declares no devices";
    out.name = info.name;
    out.version = info.version;
    out.description = info.description ? info.description : "";
    out.abi_version = info.abi_version;
    out.api = info.api;
    out.devices.assign(info.device_count, {});
    out.capabilities = 0;
    for (uint32_t i = 0; i < info.device_count; ++i) {
        if (std::string why = describeDevice(*info.api, info.abi_version, i, out.devices[i]); !why.empty()) return why;
        out.capabilities |= out.devices[i].caps;
    }
    return {};
}

std::string validatePoseSample(VrocPoseSample& s, uint32_t sensor, uint32_t sensor_count) {
    if (s.struct_type != VROC_STRUCT_POSE_SAMPLE || s.struct_size != sizeof(VrocPoseSample))
        return "the plugin overwrote the sample header";
    if (s.sensor != sensor)
        return "sample is for sensor " + std::to_string(s.sensor) + ", asked for " + std::to_string(sensor);
    if (sensor >= sensor_count) return "sensor " + std::to_string(sensor) + " out of range";
    if (s.flags & VROC_POSE_POSITION_VALID)
        if (std::string why = finiteCheck("position", s.position, 3); !why.empty()) return why;
    if (s.flags & VROC_POSE_ORIENTATION_VALID) {
        if (std::string why = finiteCheck("orientation", s.orientation, 4); !why.empty()) return why;
        const double norm = std::sqrt(s.orientation[0] * s.orientation[0] + s.orientation[1] * s.orientation[1] +
                                      s.orientation[2] * s.orientation[2] + s.orientation[3] * s.orientation[3]);
        if (std::fabs(norm - 1.0) > 0.01)  // OpenXR's XR_ERROR_POSE_INVALID threshold
            return "orientation is not a unit quaternion (norm " + std::to_string(norm) + ")";
        for (double& c : s.orientation) c /= norm;
    }
    if (s.flags & VROC_POSE_LINEAR_VELOCITY_VALID)
        if (std::string why = finiteCheck("linear velocity", s.linear_velocity, 3); !why.empty()) return why;
    if (s.flags & VROC_POSE_ANGULAR_VELOCITY_VALID)
        if (std::string why = finiteCheck("angular velocity", s.angular_velocity, 3); !why.empty()) return why;
    return {};
}

std::string validateForceCommand(const VrocForceCommand& c, uint32_t sensor_count) {
    // A force-only device may have no pose sensors; its sensor 0 is the handle itself.
    const uint32_t sensors = sensor_count > 0 ? sensor_count : 1;
    if (c.sensor >= sensors)
        return "sensor " + std::to_string(c.sensor) + " out of range (device has " + std::to_string(sensors) + ")";
    if (std::string why = finiteCheck("force", c.force, 3); !why.empty()) return why;
    if (std::string why = finiteCheck("torque", c.torque, 3); !why.empty()) return why;
    return {};
}

}  // namespace vroc::plugins
