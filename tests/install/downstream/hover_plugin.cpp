// SPDX-License-Identifier: MIT
// `hover`: a device plugin in C++ on the installed plugin SDK (vroc::plugin_sdk), built by the
// downstream project. One head tracker at a fixed position given by its options x,y,z [m]
// (default 0, 0, 1.6), identity orientation. The install test loads it with the installed
// `vroc plugins --plugin` (negotiation, validation, description).
#include <memory>

#include "vroc/plugin_sdk/plugin_sdk.h"
#include "vroc/plugin_sdk/pose_math.h"

namespace hover {
namespace {

using vroc::plugin_sdk::Device;
using vroc::plugin_sdk::Options;

class HoverDevice final : public Device {
public:
    explicit HoverDevice(const Eigen::Vector3d& position) : position_(position) {}
    int32_t pose(uint32_t sensor, int64_t at_time_ns, VrocPoseSample& out) override {
        if (sensor != 0) return setError(VROC_ERROR_INVALID_ARGUMENT, "hover: only sensor 0 exists");
        vroc::plugin_sdk::writePose(out, at_time_ns, 0, position_, Eigen::Quaterniond::Identity(),
                                    vroc::plugin_sdk::kPoseValidTracked, nullptr, nullptr);
        return VROC_OK;
    }

private:
    Eigen::Vector3d position_;
};

void describe(uint32_t, VrocDeviceDesc& out) {
    out.kind = VROC_DEVICE_HEAD_TRACKER;
    out.sensor_count = 1;
    out.button_count = 0;
    out.axis_count = 0;
    out.caps = VROC_CAP_POSE_SOURCE | VROC_CAP_POSITION | VROC_CAP_ORIENTATION;
    out.nominal_rate_hz = 0;
    out.nominal_latency_ns = 0;
    out.name = "hovering head";
    out.options_help = "x,y,z=0,0,1.6: position [m]";
}

std::unique_ptr<Device> create(uint32_t, Options& o) {
    const Eigen::Vector3d p(o.getDouble("x", 0.0), o.getDouble("y", 0.0), o.getDouble("z", 1.6));
    return std::make_unique<HoverDevice>(p);
}

const vroc::plugin_sdk::PluginDefinition kDefinition = {
    "hover", "1.0.0", "a head tracker hovering at a fixed position (C++ plugin SDK, downstream build)", 1, describe,
    create};

}  // namespace
}  // namespace hover

VROC_DEFINE_PLUGIN(hover::kDefinition)
