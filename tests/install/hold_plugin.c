/* SPDX-License-Identifier: MIT
 * `hold`: a device plugin in plain C, built outside VROC by tests/install/install_test.sh with only
 * the installed ABI header (cc $(pkg-config --cflags vroc-plugin) -shared ...). One hand tracker
 * holding a fixed pose, position (0.25, 1.5, 0.75) m, orientation 90 degrees about z, with zero
 * velocities; the test drives a tracked body with it through the installed `vroc run --track` and
 * reads that pose back from trajectory.csv. ABI 2, no force output.
 */
#include <string.h>

#include "vroc/plugin/vroc_device_plugin.h"

static int32_t hold_describe(uint32_t index, VrocDeviceDesc* out) {
    if (index != 0 || !out || out->struct_size < sizeof(VrocDeviceDesc)) return VROC_ERROR_INVALID_ARGUMENT;
    out->kind = VROC_DEVICE_HAND_TRACKER;
    out->sensor_count = 1;
    out->button_count = 0;
    out->axis_count = 0;
    out->caps = VROC_CAP_POSE_SOURCE | VROC_CAP_POSITION | VROC_CAP_ORIENTATION | VROC_CAP_VELOCITY;
    out->nominal_rate_hz = 0.0;
    out->nominal_latency_ns = 0;
    out->name = "held hand";
    out->options_help = "";
    return VROC_OK;
}

static int32_t hold_create(uint32_t index, const char* options, VrocDeviceHandle* out) {
    static int device; /* the handle points here: nothing to allocate */
    if (!out) return VROC_ERROR_INVALID_ARGUMENT;
    *out = NULL;
    if (index != 0 || (options && options[0] != '\0')) return VROC_ERROR_INVALID_ARGUMENT;
    *out = (VrocDeviceHandle)&device;
    return VROC_OK;
}

static int32_t hold_start(VrocDeviceHandle h) { return h ? VROC_OK : VROC_ERROR_INVALID_ARGUMENT; }
static int32_t hold_stop(VrocDeviceHandle h) { return h ? VROC_OK : VROC_ERROR_INVALID_ARGUMENT; }
static void hold_destroy(VrocDeviceHandle h) { (void)h; }

static int32_t hold_get_pose(VrocDeviceHandle h, uint32_t sensor, int64_t t, VrocPoseSample* out) {
    if (!h || !out || sensor != 0 || out->struct_size < sizeof(VrocPoseSample)) return VROC_ERROR_INVALID_ARGUMENT;
    out->time_ns = t;
    out->sensor = 0;
    out->flags = VROC_POSE_POSITION_VALID | VROC_POSE_ORIENTATION_VALID | VROC_POSE_POSITION_TRACKED |
                 VROC_POSE_ORIENTATION_TRACKED | VROC_POSE_LINEAR_VELOCITY_VALID | VROC_POSE_ANGULAR_VELOCITY_VALID;
    out->sequence = 1;
    out->position[0] = 0.25;
    out->position[1] = 1.5;
    out->position[2] = 0.75;
    out->orientation[0] = 0.0; /* (x, y, z, w): 90 degrees about z */
    out->orientation[1] = 0.0;
    out->orientation[2] = 0.70710678118654752;
    out->orientation[3] = 0.70710678118654752;
    memset(out->linear_velocity, 0, sizeof out->linear_velocity);
    memset(out->angular_velocity, 0, sizeof out->angular_velocity);
    return VROC_OK;
}

static int32_t hold_get_controls(VrocDeviceHandle h, int64_t t, VrocControlState* out) {
    if (!h || !out) return VROC_ERROR_INVALID_ARGUMENT;
    out->time_ns = t; /* no buttons, no axes */
    out->buttons = 0;
    out->axis_count = 0;
    return VROC_OK;
}

static int32_t hold_last_error(VrocDeviceHandle h, char* buffer, uint64_t size) {
    static const char text[] = "hold: takes no options and has one device";
    (void)h;
    if (buffer && size > 0) {
        const size_t n = size - 1 < sizeof text - 1 ? (size_t)(size - 1) : sizeof text - 1;
        memcpy(buffer, text, n);
        buffer[n] = '\0';
    }
    return (int32_t)(sizeof text - 1);
}

static const VrocDeviceApi kApi = {VROC_STRUCT_DEVICE_API, 2, sizeof(VrocDeviceApi), hold_describe, hold_create,
                                   hold_start, hold_stop, hold_destroy, hold_get_pose, hold_get_controls,
                                   hold_last_error, NULL, NULL};

VROC_PLUGIN_EXPORT int32_t vroc_plugin_negotiate(const VrocHostInfo* host, VrocPluginInfo* out) {
    if (!host || !out || out->struct_size < sizeof(VrocPluginInfo)) return VROC_ERROR_ABI;
    if (host->abi_min > 2 || host->abi_max < 2) return VROC_ERROR_ABI;
    out->abi_version = 2;
    out->device_count = 1;
    out->name = "hold";
    out->version = "1.0.0";
    out->description = "a hand held still at a fixed pose (C, built against the installed ABI header)";
    out->capabilities = VROC_CAP_POSE_SOURCE | VROC_CAP_POSITION | VROC_CAP_ORIENTATION | VROC_CAP_VELOCITY;
    out->api = &kApi;
    return VROC_OK;
}
