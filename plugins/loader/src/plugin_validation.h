// SPDX-License-Identifier: MIT
// Checks what a plugin declared during negotiation; each failure is one line for InputError.
#pragma once

#include <string>

#include "vroc/plugin/loaded_plugin.h"

namespace vroc::plugins {

/// Validates `info` (after a successful negotiate) and fills `out` (name, version, api, devices).
/// Returns "" if acceptable, else the reason (without the file name).
std::string validatePluginInfo(const VrocPluginInfo& info, uint32_t abi_min, uint32_t abi_max, LoadedPlugin& out);

/// Checks a sample a plugin returned for `sensor`; normalises the quaternion. "" if acceptable.
std::string validatePoseSample(VrocPoseSample& sample, uint32_t sensor, uint32_t sensor_count);

/// Checks a force command before it is handed to a plugin (finite, sensor in range). "" if acceptable.
std::string validateForceCommand(const VrocForceCommand& command, uint32_t sensor_count);

}  // namespace vroc::plugins
