/* SPDX-License-Identifier: MIT
 * VROC device-plugin ABI, versions 1 and 2 (docs/plugin-abi.md). Plain C, usable from C and C++.
 *
 * A plugin is a shared library exporting exactly one symbol, vroc_plugin_negotiate. The host fills
 * a VrocHostInfo (accepted ABI range, version string, services) and an empty VrocPluginInfo whose
 * header says how large the host's struct is; the plugin fills in its chosen ABI version, name,
 * version, device count, capability union and a pointer to its const function table.
 *
 * ABI 2 adds the output direction: a device declaring VROC_CAP_FORCE_OUTPUT receives forces and
 * torques through VrocDeviceApi.send_force (a VrocForceCommand). The table of an ABI-2 plugin is
 * the ABI-1 table with send_force appended. A host accepting 1..2 loads ABI-1 plugins unchanged and
 * never sends them forces (it never calls the ABI-1 set_force either, and never reads past an
 * ABI-1 table's struct_size).
 *
 * Conventions (after OpenXR, CLAP, gz-plugin, MuJoCo):
 * - Every struct starts with struct_type, struct_version, struct_size. The writer of a struct
 *   (host for inputs, the side that allocates for outputs) sets the header; the reader checks it.
 *   Fields are only ever appended (struct_version bump); a reader never touches bytes past
 *   struct_size.
 * - int32 results: negative = failure, 0 = success, positive = qualified success.
 * - Nothing is thrown across the boundary; every function returns.
 * - Memory is never freed across the boundary: strings returned by the plugin are static (live
 *   until the library is unloaded) and text is copied into caller-owned buffers.
 * - Units and frames: metres, seconds, right-handed, quaternion (x, y, z, w); a pose is
 *   base <- sensor (x_base = q * x_sensor + p), as in VRPN and OpenXR. Times are int64 ns on the
 *   host's monotonic clock (services->now_ns).
 */
#ifndef VROC_DEVICE_PLUGIN_H
#define VROC_DEVICE_PLUGIN_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define VROC_PLUGIN_ABI_VERSION 2u     /* the newest version this header describes */
#define VROC_PLUGIN_ABI_VERSION_MIN 1u /* the oldest version a current host still accepts */
#define VROC_PLUGIN_ENTRY_POINT "vroc_plugin_negotiate"

#if defined(__GNUC__)
#define VROC_PLUGIN_EXPORT __attribute__((visibility("default")))
#else
#define VROC_PLUGIN_EXPORT
#endif

/* ---- results ------------------------------------------------------------------------------- */
#define VROC_OK 0
#define VROC_NO_NEW_DATA 1     /* success; the sample is the same as the previous call's */
#define VROC_EXTRAPOLATED 2    /* success; the sample was extrapolated beyond measured data */
#define VROC_ERROR_GENERIC (-1)
#define VROC_ERROR_INVALID_ARGUMENT (-2) /* bad option, index out of range, null pointer */
#define VROC_ERROR_UNSUPPORTED (-3)      /* capability not provided */
#define VROC_ERROR_NO_DATA (-4)          /* no sample available yet */
#define VROC_ERROR_IO (-5)               /* file, socket or device failure */
#define VROC_ERROR_ABI (-6)              /* incompatible struct type, version or size */
#define VROC_ERROR_INTERNAL (-7)         /* a caught exception or broken invariant */

/* ---- struct types -------------------------------------------------------------------------- */
#define VROC_STRUCT_HOST_SERVICES 1u
#define VROC_STRUCT_HOST_INFO 2u
#define VROC_STRUCT_PLUGIN_INFO 3u
#define VROC_STRUCT_DEVICE_API 4u
#define VROC_STRUCT_DEVICE_DESC 5u
#define VROC_STRUCT_POSE_SAMPLE 6u
#define VROC_STRUCT_CONTROL_STATE 7u
#define VROC_STRUCT_FORCE_COMMAND 8u /* ABI 2 */

/* ---- log severities ------------------------------------------------------------------------ */
#define VROC_LOG_DEBUG 0
#define VROC_LOG_INFO 1
#define VROC_LOG_WARNING 2
#define VROC_LOG_ERROR 3

/* ---- capability bits (VrocPluginInfo.capabilities, VrocDeviceDesc.caps) ---------------------- */
#define VROC_CAP_POSE_SOURCE (1ull << 0)        /* get_pose gives poses */
#define VROC_CAP_BUTTONS (1ull << 1)            /* get_controls gives buttons */
#define VROC_CAP_ANALOG_AXES (1ull << 2)        /* get_controls gives analog axes */
#define VROC_CAP_FORCE_OUTPUT (1ull << 3)       /* takes forces: ABI 2 send_force (ABI 1: set_force) */
#define VROC_CAP_POSITION (1ull << 8)           /* poses carry a position */
#define VROC_CAP_ORIENTATION (1ull << 9)        /* poses carry an orientation */
#define VROC_CAP_VELOCITY (1ull << 10)          /* poses carry linear and angular velocity */
#define VROC_CAP_SOURCE_TIMESTAMPS (1ull << 11) /* time_ns is the measurement time, not arrival */
#define VROC_CAP_PREDICTS (1ull << 12)          /* the device predicts ahead itself */

/* ---- device kinds -------------------------------------------------------------------------- */
#define VROC_DEVICE_HEAD_TRACKER 1u
#define VROC_DEVICE_HAND_TRACKER 2u
#define VROC_DEVICE_SPACE_MOUSE 3u
#define VROC_DEVICE_BUTTONS 4u

/* ---- pose flags (OpenXR XrSpaceLocationFlags values for the first four) --------------------- */
#define VROC_POSE_ORIENTATION_VALID 0x1u
#define VROC_POSE_POSITION_VALID 0x2u
#define VROC_POSE_ORIENTATION_TRACKED 0x4u
#define VROC_POSE_POSITION_TRACKED 0x8u
#define VROC_POSE_LINEAR_VELOCITY_VALID 0x10u
#define VROC_POSE_ANGULAR_VELOCITY_VALID 0x20u
#define VROC_POSE_EXTRAPOLATED 0x40u /* beyond the newest measurement (prediction or hold) */

#define VROC_MAX_AXES 8u

typedef struct VrocDevice* VrocDeviceHandle; /* opaque; owned by the plugin, freed by destroy */

struct VrocDeviceApi;

/* Services the host offers. Owned by the host; valid until the host unloads the library. */
typedef struct VrocHostServices {
    uint32_t struct_type;    /* VROC_STRUCT_HOST_SERVICES */
    uint32_t struct_version; /* 1 */
    uint64_t struct_size;    /* sizeof(VrocHostServices) as the host compiled it */
    void* host_context;      /* opaque; first argument of every service */
    /* Logs one line (no newline needed). plugin_name may be NULL. Thread-safe. */
    void (*log)(void* host_context, int32_t severity, const char* plugin_name, const char* message);
    /* The host's monotonic clock [ns]; every time_ns in this ABI is on this clock. Thread-safe. */
    int64_t (*now_ns)(void* host_context);
    /* Loads another plugin by name or path through the host's search rules (decorators such as
     * `predict` use it). On success *out_api is the validated table and *out_device_count its
     * device count; both live as long as the host. Returns < 0 and logs the reason on failure. */
    int32_t (*load_plugin)(void* host_context, const char* name_or_path,
                           const struct VrocDeviceApi** out_api, uint32_t* out_device_count);
} VrocHostServices;

/* Input of vroc_plugin_negotiate. Owned by the host; valid only during the call, except
 * `services`, which lives until the host unloads the library. */
typedef struct VrocHostInfo {
    uint32_t struct_type;    /* VROC_STRUCT_HOST_INFO */
    uint32_t struct_version; /* 1 */
    uint64_t struct_size;    /* sizeof(VrocHostInfo) */
    uint32_t abi_min;        /* lowest plugin ABI version the host accepts */
    uint32_t abi_max;        /* highest plugin ABI version the host accepts */
    const char* host_version; /* e.g. "vroc 0.1.0" */
    const VrocHostServices* services;
} VrocHostInfo;

struct VrocDeviceDesc;
struct VrocPoseSample;
struct VrocControlState;
struct VrocForceCommand;

/* The plugin's function table: static const data in the plugin. handle arguments come from
 * create. Every function is callable from any thread; get_pose, get_controls and send_force never
 * block. A reader of a table (the host, or a decorator reading an inner plugin's table) touches
 * send_force only if struct_size >= VROC_DEVICE_API_SIZE_V2: an ABI-1 table ends before it. */
typedef struct VrocDeviceApi {
    uint32_t struct_type;    /* VROC_STRUCT_DEVICE_API */
    uint32_t struct_version; /* 1 for an ABI-1 table, 2 with send_force */
    uint64_t struct_size;    /* sizeof(VrocDeviceApi) as the plugin compiled it */
    /* Fills *out (header set by the host) for device index < device_count. */
    int32_t (*describe)(uint32_t device_index, struct VrocDeviceDesc* out);
    /* Opens a device with options "key=value,key=value" (may be NULL or empty). On failure
     * returns < 0, sets *out_handle = NULL and last_error(NULL, ...) explains why. */
    int32_t (*create)(uint32_t device_index, const char* options, VrocDeviceHandle* out_handle);
    /* Starts data flow (threads, sockets). Idempotent. */
    int32_t (*start)(VrocDeviceHandle handle);
    /* Stops data flow; the handle can be started again. Idempotent. */
    int32_t (*stop)(VrocDeviceHandle handle);
    /* Stops if needed and frees the device. NULL is ignored. */
    void (*destroy)(VrocDeviceHandle handle);
    /* The pose of `sensor` for the host time at_time_ns: the newest measurement at or before it,
     * or an interpolation/prediction at it. *out's header is set by the host. */
    int32_t (*get_pose)(VrocDeviceHandle handle, uint32_t sensor, int64_t at_time_ns,
                        struct VrocPoseSample* out);
    /* Buttons and analog axes at host time at_time_ns. */
    int32_t (*get_controls)(VrocDeviceHandle handle, int64_t at_time_ns, struct VrocControlState* out);
    /* Copies the last error text of `handle` (or of the last failed create when handle is NULL)
     * into buffer (always NUL-terminated when size > 0). Returns the full text length. */
    int32_t (*last_error)(VrocDeviceHandle handle, char* buffer, uint64_t size);
    /* ABI 1 only: force/torque feedback [N, N m, base frame], non-null if an ABI-1 device declares
     * VROC_CAP_FORCE_OUTPUT. No VROC host calls it; ABI-2 plugins leave it NULL. */
    int32_t (*set_force)(VrocDeviceHandle handle, uint32_t sensor, const double force[3],
                         const double torque[3]);
    /* ---- ABI 2 ---- */
    /* Hands the device one force command (header set by the host, see VrocForceCommand). Required
     * (non-null) if any device declares VROC_CAP_FORCE_OUTPUT, else may be NULL. Returns < 0 and
     * sets last_error on failure (bad header, non-finite value, sensor out of range, I/O). The host
     * sends forces only to ABI-2 devices whose caps include VROC_CAP_FORCE_OUTPUT, and only finite
     * values. The plugin copies what it needs; *command is valid only during the call. */
    int32_t (*send_force)(VrocDeviceHandle handle, const struct VrocForceCommand* command);
} VrocDeviceApi;

/* Table sizes: an ABI-1 table ends after set_force, an ABI-2 table after send_force. */
#define VROC_DEVICE_API_SIZE_V1 (offsetof(VrocDeviceApi, set_force) + sizeof(void (*)(void)))
#define VROC_DEVICE_API_SIZE_V2 (offsetof(VrocDeviceApi, send_force) + sizeof(void (*)(void)))

/* Output of vroc_plugin_negotiate. The host sets the header (its struct size); the plugin must
 * not write past struct_size and fails with VROC_ERROR_ABI if it is smaller than it needs. */
typedef struct VrocPluginInfo {
    uint32_t struct_type;    /* VROC_STRUCT_PLUGIN_INFO */
    uint32_t struct_version; /* 1 */
    uint64_t struct_size;
    uint32_t abi_version;    /* chosen by the plugin, within [abi_min, abi_max] */
    uint32_t device_count;   /* devices the table serves (index 0 .. device_count-1) */
    const char* name;        /* static, [a-z0-9-], e.g. "analytic" */
    const char* version;     /* static, e.g. "1.0.0" */
    const char* description; /* static, one line */
    uint64_t capabilities;   /* union of the devices' VROC_CAP_* bits */
    const VrocDeviceApi* api; /* static const table; must not be NULL */
} VrocPluginInfo;

/* What one device offers. Filled by describe; strings are static. */
typedef struct VrocDeviceDesc {
    uint32_t struct_type;    /* VROC_STRUCT_DEVICE_DESC */
    uint32_t struct_version; /* 1 */
    uint64_t struct_size;
    uint32_t kind;           /* VROC_DEVICE_* */
    uint32_t sensor_count;   /* poses available for sensor 0 .. sensor_count-1 */
    uint32_t button_count;   /* <= 64 */
    uint32_t axis_count;     /* <= VROC_MAX_AXES */
    uint64_t caps;           /* VROC_CAP_* */
    double nominal_rate_hz;  /* measurement rate [Hz]; 0 = continuous (analytic) */
    int64_t nominal_latency_ns; /* measurement-to-availability delay [ns] */
    const char* name;        /* static, e.g. "circle hand" */
    const char* options_help; /* static, "key=default: meaning; ..." */
} VrocDeviceDesc;

/* One pose of one sensor. */
typedef struct VrocPoseSample {
    uint32_t struct_type;    /* VROC_STRUCT_POSE_SAMPLE */
    uint32_t struct_version; /* 1 */
    uint64_t struct_size;
    int64_t time_ns;         /* measurement time on the host clock (not arrival time) [ns] */
    uint32_t sensor;
    uint32_t flags;          /* VROC_POSE_* */
    uint64_t sequence;       /* increases with each new measurement */
    double position[3];      /* [m] sensor origin in the base frame */
    double orientation[4];   /* unit quaternion (x, y, z, w), sensor -> base */
    double linear_velocity[3];  /* [m/s] base frame; valid if LINEAR_VELOCITY_VALID */
    double angular_velocity[3]; /* [rad/s] base frame; valid if ANGULAR_VELOCITY_VALID */
} VrocPoseSample;

/* Buttons and analog axes. */
typedef struct VrocControlState {
    uint32_t struct_type;    /* VROC_STRUCT_CONTROL_STATE */
    uint32_t struct_version; /* 1 */
    uint64_t struct_size;
    int64_t time_ns;         /* measurement time [ns] */
    uint64_t buttons;        /* bit i = button i pressed */
    uint32_t axis_count;     /* valid entries of axes */
    uint32_t reserved;       /* 0 */
    double axes[VROC_MAX_AXES]; /* normalised deflections in [-1, 1] */
} VrocControlState;

/* ABI 2: a force and torque for a device to display (a haptic handle, a force-feedback arm) or
 * record. The wrench is the one the simulation applies to the user's hand: it acts at the origin
 * of `sensor` (the tracked point whose pose get_pose reports) and the torque is taken about that
 * origin; both are expressed in the base frame. time_ns is the host time the wrench was computed
 * for (the simulation time of the step). Successive commands replace each other: the device
 * displays the newest one until the next arrives; a zero wrench ends contact. */
typedef struct VrocForceCommand {
    uint32_t struct_type;    /* VROC_STRUCT_FORCE_COMMAND */
    uint32_t struct_version; /* 1 */
    uint64_t struct_size;    /* sizeof(VrocForceCommand) as the host compiled it */
    int64_t time_ns;         /* host time the wrench applies at [ns] */
    uint32_t sensor;         /* the sensor whose origin the wrench acts at */
    uint32_t flags;          /* 0 (reserved) */
    double force[3];         /* [N] base frame, acting at the sensor origin */
    double torque[3];        /* [N m] base frame, about the sensor origin */
} VrocForceCommand;

/* The one exported symbol. Returns >= 0 on success; the host still validates *out. */
typedef int32_t (*VrocNegotiateFn)(const VrocHostInfo* host, VrocPluginInfo* out);
VROC_PLUGIN_EXPORT int32_t vroc_plugin_negotiate(const VrocHostInfo* host, VrocPluginInfo* out);

#ifdef __cplusplus
}
#endif

#endif /* VROC_DEVICE_PLUGIN_H */
