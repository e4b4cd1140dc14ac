// SPDX-License-Identifier: MIT
// `force-log`: a decorator with force output (ABI 2). Loads another plugin through the host (like
// `predict`), opens one of its devices and serves its poses and controls unchanged; every force
// command the host sends is appended to a CSV (force_csv_file.h). The forces are recorded, not
// passed on to the inner device. The log is written to OUT.partial, flushed row by row, and renamed
// to OUT when the device is destroyed, so OUT exists only when complete.
#include <memory>

#include "force_csv_file.h"
#include "plugin_sdk.h"

namespace vroc::plugins::force_log {
using namespace plugin_sdk;

namespace {

constexpr const char* kHelp =
    "out=PATH: the force log to write (required; written as PATH.partial, renamed to PATH when the "
    "device is closed); inner=NAME: the plugin whose poses and controls are served (required); "
    "inner.KEY=VALUE: its options; inner_device=0";

class ForceLogDevice final : public Device {
public:
    ForceLogDevice(const VrocDeviceApi* inner, VrocDeviceHandle handle, std::unique_ptr<ForceCsvFile> file)
        : inner_(inner), handle_(handle), file_(std::move(file)) {}
    ~ForceLogDevice() override {
        inner_->destroy(handle_);
        if (std::string why = file_->finish(); !why.empty()) log(VROC_LOG_ERROR, "force-log: " + why);
    }

    int32_t start() override { return forward(inner_->start(handle_)); }
    int32_t stop() override { return forward(inner_->stop(handle_)); }

    int32_t pose(uint32_t sensor, int64_t at_time_ns, VrocPoseSample& out) override {
        return forward(inner_->get_pose(handle_, sensor, at_time_ns, &out));
    }
    int32_t controls(int64_t at_time_ns, VrocControlState& out) override {
        return forward(inner_->get_controls(handle_, at_time_ns, &out));
    }

    int32_t force(const VrocForceCommand& command) override {
        if (std::string why = file_->append(command); !why.empty()) return setError(VROC_ERROR_IO, "force-log: " + why);
        return VROC_OK;
    }

private:
    int32_t forward(int32_t rc) {
        if (rc >= 0) return rc;
        char text[400] = "";
        inner_->last_error(handle_, text, sizeof text);
        return setError(rc, std::string("force-log: inner device: ") + text);
    }

    const VrocDeviceApi* inner_;
    VrocDeviceHandle handle_;
    std::unique_ptr<ForceCsvFile> file_;
};

void describe(uint32_t, VrocDeviceDesc& out) {
    out.kind = VROC_DEVICE_HAND_TRACKER;
    out.sensor_count = 16;  // whatever the inner device has; its own checks answer for the rest
    out.button_count = 64;
    out.axis_count = VROC_MAX_AXES;
    out.caps = VROC_CAP_POSE_SOURCE | VROC_CAP_BUTTONS | VROC_CAP_ANALOG_AXES | VROC_CAP_POSITION |
               VROC_CAP_ORIENTATION | VROC_CAP_VELOCITY | VROC_CAP_SOURCE_TIMESTAMPS | VROC_CAP_FORCE_OUTPUT;
    out.nominal_rate_hz = 0;
    out.nominal_latency_ns = 0;
    out.name = "force-logging decorator";
    out.options_help = kHelp;
}

std::unique_ptr<Device> create(uint32_t, Options& o) {
    if (!o.has("out")) throw OptionError("force-log: option out=PATH is required");
    if (!o.has("inner")) throw OptionError("force-log: option inner=PLUGIN is required");
    const std::string out = o.getString("out", "");
    if (out.empty()) throw OptionError("force-log: option out='': expected a file path");
    const std::string inner_name = o.getString("inner", "");
    if (inner_name == "force-log") throw OptionError("force-log: inner=force-log would wrap itself");
    const auto index = static_cast<uint32_t>(o.getInt("inner_device", 0, 0, 1000));
    const std::string inner_options = o.takePrefixed("inner.");
    o.finish();  // reject typos before touching files or the inner device

    uint32_t count = 0;
    const VrocDeviceApi* inner = loadPlugin(inner_name.c_str(), &count);
    if (!inner) throw OptionError("force-log: cannot load inner plugin '" + inner_name + "' (see the log)");
    if (index >= count)
        throw OptionError("force-log: inner plugin '" + inner_name + "' has no device " + std::to_string(index));
    auto file = std::make_unique<ForceCsvFile>(out);  // before the inner device: nothing to undo if it fails
    VrocDeviceHandle handle = nullptr;
    if (inner->create(index, inner_options.c_str(), &handle) < 0 || !handle) {
        char text[400] = "";
        inner->last_error(nullptr, text, sizeof text);
        file->abandon();  // no device, no log
        throw OptionError("force-log: inner " + inner_name + ": " + text);
    }
    return std::make_unique<ForceLogDevice>(inner, handle, std::move(file));
}

const PluginDefinition kDefinition = {"force-log", "1.0.0",
                                      "wraps a device and records every force sent to it (CSV); ABI 2 force output",
                                      1, describe, create};

}  // namespace
}  // namespace vroc::plugins::force_log

VROC_DEFINE_PLUGIN(vroc::plugins::force_log::kDefinition)
