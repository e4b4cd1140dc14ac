// SPDX-License-Identifier: MIT
#include "vroc/plugin/device_handle.h"

#include "plugin_validation.h"
#include "vroc/core/errors.h"
#include "vroc/plugin/plugin_host.h"

namespace vroc::plugins {

DeviceHandle::DeviceHandle(PluginHost& host, const LoadedPlugin& plugin, uint32_t index, VrocDeviceHandle handle)
    : host_(host), plugin_(plugin), index_(index), handle_(handle) {}

DeviceHandle::~DeviceHandle() { plugin_.api->destroy(handle_); }

std::string DeviceHandle::lastError() const {
    char text[512] = "";
    plugin_.api->last_error(handle_, text, sizeof text);
    return text;
}

void DeviceHandle::start() {
    if (const int32_t rc = plugin_.api->start(handle_); rc < 0)
        throw RunError("plugin " + plugin_.name + ": start failed (" + std::to_string(rc) + "): " + lastError());
}

void DeviceHandle::stop() {
    if (const int32_t rc = plugin_.api->stop(handle_); rc < 0)
        throw RunError("plugin " + plugin_.name + ": stop failed (" + std::to_string(rc) + "): " + lastError());
}

PoseResult DeviceHandle::reject(const std::string& why, int32_t code) {
    PoseResult result;
    result.status = SampleStatus::Rejected;
    result.code = code;
    result.message = "plugin " + plugin_.name + ": sample rejected: " + why;
    if (rejected_.fetch_add(1) == 0)
        host_.log(VROC_LOG_WARNING, plugin_.name, result.message + " (further rejections are only counted)");
    return result;
}

bool DeviceHandle::acceptsForce() const {
    // The validator has confirmed that an ABI-2 table is large enough and that a device declaring
    // force output has send_force; the check of the pointer is belt and braces.
    return plugin_.abi_version >= 2 && (description().caps & VROC_CAP_FORCE_OUTPUT) &&
           plugin_.api->struct_size >= VROC_DEVICE_API_SIZE_V2 && plugin_.api->send_force;
}

bool DeviceHandle::rejectForce(const std::string& why) {
    if (rejected_forces_.fetch_add(1) == 0)
        host_.log(VROC_LOG_WARNING, plugin_.name,
                  "plugin " + plugin_.name + ": force not sent: " + why + " (further failures are only counted)");
    return false;
}

bool DeviceHandle::sendForce(uint32_t sensor, int64_t time_ns, const Eigen::Vector3d& force_N,
                             const Eigen::Vector3d& torque_Nm) {
    if (!acceptsForce()) return false;
    try {
        VrocForceCommand command{};
        command.struct_type = VROC_STRUCT_FORCE_COMMAND;
        command.struct_version = 1;
        command.struct_size = sizeof command;
        command.time_ns = time_ns;
        command.sensor = sensor;
        for (int i = 0; i < 3; ++i) {
            command.force[i] = force_N[i];
            command.torque[i] = torque_Nm[i];
        }
        if (std::string why = validateForceCommand(command, description().sensor_count); !why.empty())
            return rejectForce(why);
        const int32_t rc = plugin_.api->send_force(handle_, &command);
        if (rc < 0) return rejectForce("send_force failed (" + std::to_string(rc) + "): " + lastError());
        sent_forces_.fetch_add(1);
        return true;
    } catch (...) {  // logging or string allocation failed: still never throw
        rejected_forces_.fetch_add(1);
        return false;
    }
}

PoseResult DeviceHandle::pose(uint32_t sensor, int64_t at_time_ns) {
    VrocPoseSample raw{};
    raw.struct_type = VROC_STRUCT_POSE_SAMPLE;
    raw.struct_version = 1;
    raw.struct_size = sizeof raw;
    PoseResult result;
    result.code = plugin_.api->get_pose(handle_, sensor, at_time_ns, &raw);
    if (result.code < 0) {
        result.status = result.code == VROC_ERROR_NO_DATA ? SampleStatus::NoData : SampleStatus::Failed;
        result.message = lastError();
        return result;
    }
    if (std::string why = validatePoseSample(raw, sensor, description().sensor_count); !why.empty())
        return reject(why, result.code);
    PoseSample& s = result.sample;
    s.time_ns = raw.time_ns;
    s.sensor = raw.sensor;
    s.flags = raw.flags;
    s.sequence = raw.sequence;
    s.pose.position = Vec3(raw.position[0], raw.position[1], raw.position[2]);
    s.pose.orientation = Quat(raw.orientation[3], raw.orientation[0], raw.orientation[1], raw.orientation[2]);
    if (s.has(VROC_POSE_LINEAR_VELOCITY_VALID))
        s.linear_velocity = Vec3(raw.linear_velocity[0], raw.linear_velocity[1], raw.linear_velocity[2]);
    if (s.has(VROC_POSE_ANGULAR_VELOCITY_VALID))
        s.angular_velocity = Vec3(raw.angular_velocity[0], raw.angular_velocity[1], raw.angular_velocity[2]);
    result.status = SampleStatus::Ok;
    return result;
}

ControlResult DeviceHandle::controls(int64_t at_time_ns) {
    VrocControlState raw{};
    raw.struct_type = VROC_STRUCT_CONTROL_STATE;
    raw.struct_version = 1;
    raw.struct_size = sizeof raw;
    ControlResult result;
    result.code = plugin_.api->get_controls(handle_, at_time_ns, &raw);
    if (result.code < 0) {
        result.status = result.code == VROC_ERROR_NO_DATA ? SampleStatus::NoData : SampleStatus::Failed;
        result.message = lastError();
        return result;
    }
    if (raw.axis_count > VROC_MAX_AXES) {
        result.status = SampleStatus::Rejected;
        result.message = "plugin " + plugin_.name + ": axis_count " + std::to_string(raw.axis_count) + " > 8";
        return result;
    }
    for (uint32_t i = 0; i < raw.axis_count; ++i) {
        if (!std::isfinite(raw.axes[i])) {
            result.status = SampleStatus::Rejected;
            result.message = "plugin " + plugin_.name + ": axis " + std::to_string(i) + " is not finite";
            return result;
        }
        result.state.axes.push_back(raw.axes[i]);
    }
    result.state.time_ns = raw.time_ns;
    result.state.buttons = raw.buttons;
    result.status = SampleStatus::Ok;
    return result;
}

}  // namespace vroc::plugins
