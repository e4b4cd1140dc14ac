// SPDX-License-Identifier: MIT
#include "vroc/plugin/loaded_plugin.h"

namespace vroc::plugins {

std::string capabilityNames(uint64_t caps) {
    static const struct {
        uint64_t bit;
        const char* name;
    } kNames[] = {{VROC_CAP_POSE_SOURCE, "pose-source"},   {VROC_CAP_BUTTONS, "buttons"},
                  {VROC_CAP_ANALOG_AXES, "analog-axes"},   {VROC_CAP_FORCE_OUTPUT, "force-output"},
                  {VROC_CAP_POSITION, "position"},         {VROC_CAP_ORIENTATION, "orientation"},
                  {VROC_CAP_VELOCITY, "velocity"},         {VROC_CAP_SOURCE_TIMESTAMPS, "source-timestamps"},
                  {VROC_CAP_PREDICTS, "predicts"}};
    std::string out;
    for (const auto& entry : kNames)
        if (caps & entry.bit) out += (out.empty() ? "" : ",") + std::string(entry.name);
    return out.empty() ? "none" : out;
}

const char* deviceKindName(uint32_t kind) {
    switch (kind) {
        case VROC_DEVICE_HEAD_TRACKER: return "head-tracker";
        case VROC_DEVICE_HAND_TRACKER: return "hand-tracker";
        case VROC_DEVICE_SPACE_MOUSE: return "space-mouse";
        case VROC_DEVICE_BUTTONS: return "buttons";
        default: return "unknown";
    }
}

}  // namespace vroc::plugins
