// SPDX-License-Identifier: MIT
#include "plugin_sdk.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

namespace vroc::plugin_sdk {
namespace {

// Set once by negotiate; the host keeps `services` alive while the library is loaded.
std::atomic<const PluginDefinition*> g_definition{nullptr};
std::atomic<const VrocHostServices*> g_services{nullptr};
std::atomic<uint32_t> g_abi_version{VROC_PLUGIN_ABI_VERSION};  // as negotiated last

std::mutex g_create_error_mutex;
std::string g_create_error;  // last_error(NULL): why the last create failed

Device* fromHandle(VrocDeviceHandle handle) { return reinterpret_cast<Device*>(handle); }

void setCreateError(const std::string& text) {
    std::lock_guard lock(g_create_error_mutex);
    g_create_error = text;
}

int32_t apiDescribe(uint32_t index, VrocDeviceDesc* out) noexcept {
    const PluginDefinition* def = g_definition.load();
    if (!def || !out) return VROC_ERROR_INVALID_ARGUMENT;
    if (index >= def->device_count) return VROC_ERROR_INVALID_ARGUMENT;
    if (out->struct_type != VROC_STRUCT_DEVICE_DESC || out->struct_size < sizeof(VrocDeviceDesc)) return VROC_ERROR_ABI;
    try {
        def->describe(index, *out);
        if (g_abi_version.load() < 2) out->caps &= ~VROC_CAP_FORCE_OUTPUT;  // no send_force in ABI 1
        return VROC_OK;
    } catch (...) {
        return VROC_ERROR_INTERNAL;
    }
}

int32_t apiCreate(uint32_t index, const char* options, VrocDeviceHandle* out_handle) noexcept {
    if (!out_handle) return VROC_ERROR_INVALID_ARGUMENT;
    *out_handle = nullptr;
    const PluginDefinition* def = g_definition.load();
    if (!def) return VROC_ERROR_GENERIC;
    if (index >= def->device_count) {
        setCreateError(std::string(def->name) + ": no device " + std::to_string(index));
        return VROC_ERROR_INVALID_ARGUMENT;
    }
    try {
        Options parsed(def->name, options);
        std::unique_ptr<Device> device = def->create(index, parsed);
        parsed.finish();
        *out_handle = reinterpret_cast<VrocDeviceHandle>(device.release());
        return VROC_OK;
    } catch (const OptionError& e) {
        setCreateError(e.what());
        return VROC_ERROR_INVALID_ARGUMENT;
    } catch (const std::exception& e) {
        setCreateError(std::string(def->name) + ": " + e.what());
        return VROC_ERROR_IO;
    } catch (...) {
        setCreateError(std::string(def->name) + ": unknown failure while opening");
        return VROC_ERROR_INTERNAL;
    }
}

template <class F>
int32_t guarded(VrocDeviceHandle handle, F&& body) noexcept {
    if (!handle) return VROC_ERROR_INVALID_ARGUMENT;
    Device* device = fromHandle(handle);
    try {
        return body(*device);
    } catch (const std::exception& e) {
        return device->setError(VROC_ERROR_INTERNAL, e.what());
    } catch (...) {
        return device->setError(VROC_ERROR_INTERNAL, "unknown exception");
    }
}

int32_t apiStart(VrocDeviceHandle h) noexcept { return guarded(h, [](Device& d) { return d.start(); }); }
int32_t apiStop(VrocDeviceHandle h) noexcept { return guarded(h, [](Device& d) { return d.stop(); }); }

void apiDestroy(VrocDeviceHandle h) noexcept {
    if (!h) return;
    try {
        fromHandle(h)->stop();
    } catch (...) {
    }
    delete fromHandle(h);
}

int32_t apiGetPose(VrocDeviceHandle h, uint32_t sensor, int64_t t, VrocPoseSample* out) noexcept {
    if (!out) return VROC_ERROR_INVALID_ARGUMENT;
    if (out->struct_type != VROC_STRUCT_POSE_SAMPLE || out->struct_size < sizeof(VrocPoseSample)) return VROC_ERROR_ABI;
    return guarded(h, [&](Device& d) { return d.pose(sensor, t, *out); });
}

int32_t apiGetControls(VrocDeviceHandle h, int64_t t, VrocControlState* out) noexcept {
    if (!out) return VROC_ERROR_INVALID_ARGUMENT;
    if (out->struct_type != VROC_STRUCT_CONTROL_STATE || out->struct_size < sizeof(VrocControlState))
        return VROC_ERROR_ABI;
    return guarded(h, [&](Device& d) { return d.controls(t, *out); });
}

int32_t apiSendForce(VrocDeviceHandle h, const VrocForceCommand* command) noexcept {
    if (!command) return VROC_ERROR_INVALID_ARGUMENT;
    if (command->struct_type != VROC_STRUCT_FORCE_COMMAND || command->struct_size < sizeof(VrocForceCommand))
        return VROC_ERROR_ABI;
    return guarded(h, [&](Device& d) {
        for (int i = 0; i < 3; ++i)
            if (!std::isfinite(command->force[i]) || !std::isfinite(command->torque[i]))
                return d.setError(VROC_ERROR_INVALID_ARGUMENT, "force command with a non-finite value");
        return d.force(*command);
    });
}

int32_t apiLastError(VrocDeviceHandle h, char* buffer, uint64_t size) noexcept {
    try {
        if (!h) {
            std::lock_guard lock(g_create_error_mutex);
            return copyText(g_create_error, buffer, size);
        }
        return copyText(fromHandle(h)->lastError(), buffer, size);
    } catch (...) {
        return 0;
    }
}

const VrocDeviceApi kApi = {
    VROC_STRUCT_DEVICE_API, 2, sizeof(VrocDeviceApi),
    apiDescribe, apiCreate, apiStart, apiStop, apiDestroy, apiGetPose, apiGetControls, apiLastError,
    nullptr,  // set_force: ABI 1 only, never called by a VROC host
    apiSendForce,
};

}  // namespace

int32_t Device::controls(int64_t, VrocControlState&) {
    return setError(VROC_ERROR_UNSUPPORTED, "this device has no buttons or axes");
}

int32_t Device::force(const VrocForceCommand&) {
    return setError(VROC_ERROR_UNSUPPORTED, "this device takes no forces");
}

int32_t Device::setError(int32_t code, const std::string& text) {
    std::lock_guard lock(error_mutex_);
    error_ = text;
    return code;
}

std::string Device::lastError() const {
    std::lock_guard lock(error_mutex_);
    return error_;
}

int32_t negotiate(const PluginDefinition& definition, const VrocHostInfo* host, VrocPluginInfo* out) noexcept {
    if (!host || !out) return VROC_ERROR_INVALID_ARGUMENT;
    if (host->struct_type != VROC_STRUCT_HOST_INFO || host->struct_size < sizeof(VrocHostInfo)) return VROC_ERROR_ABI;
    if (out->struct_type != VROC_STRUCT_PLUGIN_INFO || out->struct_size < sizeof(VrocPluginInfo)) return VROC_ERROR_ABI;
    // The highest version both know; ABI 1 is the oldest this SDK still speaks.
    const uint32_t chosen = std::min<uint32_t>(host->abi_max, VROC_PLUGIN_ABI_VERSION);
    if (chosen < host->abi_min || chosen < VROC_PLUGIN_ABI_VERSION_MIN) return VROC_ERROR_ABI;
    const VrocHostServices* services = host->services;
    if (services && (services->struct_type != VROC_STRUCT_HOST_SERVICES || services->struct_size < sizeof(VrocHostServices)))
        services = nullptr;  // run without services rather than read past the host's struct
    g_services.store(services);
    g_definition.store(&definition);
    g_abi_version.store(chosen);

    uint64_t caps = 0;
    for (uint32_t i = 0; i < definition.device_count; ++i) {
        VrocDeviceDesc desc{};
        desc.struct_type = VROC_STRUCT_DEVICE_DESC;
        desc.struct_version = 1;
        desc.struct_size = sizeof desc;
        if (apiDescribe(i, &desc) == VROC_OK) caps |= desc.caps;
    }
    out->abi_version = chosen;
    out->device_count = definition.device_count;
    out->name = definition.name;
    out->version = definition.version;
    out->description = definition.description;
    out->capabilities = caps;
    out->api = &kApi;
    return VROC_OK;
}

void log(int32_t severity, const std::string& message) {
    const VrocHostServices* s = g_services.load();
    const PluginDefinition* def = g_definition.load();
    if (s && s->log) s->log(s->host_context, severity, def ? def->name : nullptr, message.c_str());
}

int64_t nowNs() {
    const VrocHostServices* s = g_services.load();
    return s && s->now_ns ? s->now_ns(s->host_context) : 0;
}

const VrocDeviceApi* loadPlugin(const char* name_or_path, uint32_t* device_count) {
    const VrocHostServices* s = g_services.load();
    if (!s || !s->load_plugin) return nullptr;
    const VrocDeviceApi* api = nullptr;
    if (s->load_plugin(s->host_context, name_or_path, &api, device_count) < 0) return nullptr;
    return api;
}

int32_t copyText(const std::string& text, char* buffer, uint64_t size) {
    if (buffer && size > 0) {
        const size_t n = std::min<uint64_t>(text.size(), size - 1);
        std::memcpy(buffer, text.data(), n);
        buffer[n] = '\0';
    }
    return static_cast<int32_t>(text.size());
}

void initPoseSample(VrocPoseSample& sample) {
    sample = VrocPoseSample{};
    sample.struct_type = VROC_STRUCT_POSE_SAMPLE;
    sample.struct_version = 1;
    sample.struct_size = sizeof sample;
    sample.orientation[3] = 1.0;
}

void initControlState(VrocControlState& state) {
    state = VrocControlState{};
    state.struct_type = VROC_STRUCT_CONTROL_STATE;
    state.struct_version = 1;
    state.struct_size = sizeof state;
}

}  // namespace vroc::plugin_sdk
