/* SPDX-License-Identifier: MIT
 * The ABI header compiled as C: layout pinned with static_assert (C11 _Static_assert) so that an
 * accidental change of a field is a compile error, and sizes reported to the C++ side, which
 * checks that both languages agree. */
#include <stddef.h>
#include <stdint.h>

#include "vroc/plugin/vroc_device_plugin.h"

#define HEADER_CHECK(T)                                              \
    _Static_assert(offsetof(T, struct_type) == 0, #T " type");       \
    _Static_assert(offsetof(T, struct_version) == 4, #T " version"); \
    _Static_assert(offsetof(T, struct_size) == 8, #T " size")

HEADER_CHECK(VrocHostServices);
HEADER_CHECK(VrocHostInfo);
HEADER_CHECK(VrocPluginInfo);
HEADER_CHECK(VrocDeviceApi);
HEADER_CHECK(VrocDeviceDesc);
HEADER_CHECK(VrocPoseSample);
HEADER_CHECK(VrocControlState);
HEADER_CHECK(VrocForceCommand);

/* Pointer-free structs: the same on every platform with 8-byte-aligned int64/double. */
_Static_assert(sizeof(VrocPoseSample) == 144, "VrocPoseSample size");
_Static_assert(offsetof(VrocPoseSample, time_ns) == 16, "time_ns");
_Static_assert(offsetof(VrocPoseSample, sensor) == 24, "sensor");
_Static_assert(offsetof(VrocPoseSample, flags) == 28, "flags");
_Static_assert(offsetof(VrocPoseSample, sequence) == 32, "sequence");
_Static_assert(offsetof(VrocPoseSample, position) == 40, "position");
_Static_assert(offsetof(VrocPoseSample, orientation) == 64, "orientation");
_Static_assert(offsetof(VrocPoseSample, linear_velocity) == 96, "linear_velocity");
_Static_assert(offsetof(VrocPoseSample, angular_velocity) == 120, "angular_velocity");
_Static_assert(sizeof(VrocControlState) == 104, "VrocControlState size");
_Static_assert(offsetof(VrocControlState, buttons) == 24, "buttons");
_Static_assert(offsetof(VrocControlState, axis_count) == 32, "axis_count");
_Static_assert(offsetof(VrocControlState, axes) == 40, "axes");
_Static_assert(sizeof(VrocForceCommand) == 80, "VrocForceCommand size");
_Static_assert(offsetof(VrocForceCommand, time_ns) == 16, "force time_ns");
_Static_assert(offsetof(VrocForceCommand, sensor) == 24, "force sensor");
_Static_assert(offsetof(VrocForceCommand, flags) == 28, "force flags");
_Static_assert(offsetof(VrocForceCommand, force) == 32, "force");
_Static_assert(offsetof(VrocForceCommand, torque) == 56, "torque");

#if UINTPTR_MAX == 0xFFFFFFFFFFFFFFFFu /* LP64 */
_Static_assert(sizeof(VrocHostServices) == 48, "VrocHostServices size");
_Static_assert(sizeof(VrocHostInfo) == 40, "VrocHostInfo size");
_Static_assert(offsetof(VrocHostInfo, abi_min) == 16, "abi_min");
_Static_assert(offsetof(VrocHostInfo, services) == 32, "services");
_Static_assert(sizeof(VrocPluginInfo) == 64, "VrocPluginInfo size");
_Static_assert(offsetof(VrocPluginInfo, abi_version) == 16, "abi_version");
_Static_assert(offsetof(VrocPluginInfo, capabilities) == 48, "capabilities");
_Static_assert(offsetof(VrocPluginInfo, api) == 56, "api");
/* ABI 2 appended send_force; everything before it keeps its ABI-1 offset. */
_Static_assert(sizeof(VrocDeviceApi) == 96, "VrocDeviceApi size");
_Static_assert(offsetof(VrocDeviceApi, describe) == 16, "describe");
_Static_assert(offsetof(VrocDeviceApi, get_pose) == 56, "get_pose");
_Static_assert(offsetof(VrocDeviceApi, set_force) == 80, "set_force");
_Static_assert(offsetof(VrocDeviceApi, send_force) == 88, "send_force");
_Static_assert(VROC_DEVICE_API_SIZE_V1 == 88, "ABI-1 table size");
_Static_assert(VROC_DEVICE_API_SIZE_V2 == 96, "ABI-2 table size");
_Static_assert(sizeof(VrocDeviceDesc) == 72, "VrocDeviceDesc size");
_Static_assert(offsetof(VrocDeviceDesc, caps) == 32, "caps");
_Static_assert(offsetof(VrocDeviceDesc, name) == 56, "name");
#endif

/* Sizes as the C compiler sees them, in a fixed order (compared from C++). */
void vroc_abi_sizes_from_c(uint64_t out[8]) {
    out[0] = sizeof(VrocHostServices);
    out[1] = sizeof(VrocHostInfo);
    out[2] = sizeof(VrocPluginInfo);
    out[3] = sizeof(VrocDeviceApi);
    out[4] = sizeof(VrocDeviceDesc);
    out[5] = sizeof(VrocPoseSample);
    out[6] = sizeof(VrocControlState);
    out[7] = sizeof(VrocForceCommand);
}
