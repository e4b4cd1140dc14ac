// SPDX-License-Identifier: MIT
#include "vroc/plugin/plugin_host.h"

#include <dlfcn.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <deque>
#include <mutex>

#include "plugin_validation.h"
#include "vroc/core/errors.h"

#ifndef VROC_VERSION_STRING
#define VROC_VERSION_STRING "0"
#endif

namespace vroc::plugins {

// Plugins keep the services pointer for as long as their library stays loaded, and a library
// opened by two hosts stays loaded after the first host goes (its services pointer may be the
// host that went). So a context lives as long as the process: the pool below owns every one (a
// few dozen bytes per host); `host` is cleared when the host dies and the services then fall
// back to stderr / a steady clock / failure.
struct PluginHost::Context {
    std::atomic<PluginHost*> host{nullptr};
    VrocHostServices services{};
};

namespace {

/// Owns every host's context until the process ends (stable addresses: a deque never moves them).
PluginHost::Context& newContext() {
    static std::mutex mutex;
    static std::deque<PluginHost::Context> pool;
    const std::lock_guard<std::mutex> lock(mutex);
    return pool.emplace_back();
}

int64_t steadyNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

void serviceLog(void* context, int32_t severity, const char* plugin, const char* message) {
    try {
        PluginHost* host = static_cast<PluginHost::Context*>(context)->host.load();
        const std::string name = plugin ? plugin : "", text = message ? message : "";
        if (host) host->log(severity, name, text);
        else if (severity >= VROC_LOG_WARNING) std::fprintf(stderr, "vroc plugin %s: %s\n", name.c_str(), text.c_str());
    } catch (...) {
    }
}

int64_t serviceNow(void* context) {
    PluginHost* host = static_cast<PluginHost::Context*>(context)->host.load();
    try {
        return host ? host->nowNs() : steadyNs();
    } catch (...) {
        return steadyNs();
    }
}

int32_t serviceLoad(void* context, const char* name, const VrocDeviceApi** api, uint32_t* count) {
    PluginHost* host = static_cast<PluginHost::Context*>(context)->host.load();
    if (!host || !name || !api) return VROC_ERROR_INVALID_ARGUMENT;
    try {
        const LoadedPlugin& plugin = host->load(name);
        *api = plugin.api;
        if (count) *count = static_cast<uint32_t>(plugin.devices.size());
        return VROC_OK;
    } catch (const std::exception& e) {
        host->log(VROC_LOG_ERROR, "", e.what());
        return VROC_ERROR_GENERIC;
    }
}

void defaultLog(int32_t severity, const std::string& plugin, const std::string& message) {
    if (severity < VROC_LOG_WARNING) return;
    std::fprintf(stderr, "vroc: plugin %s: %s\n", plugin.c_str(), message.c_str());
}

}  // namespace

PluginHost::PluginHost(HostOptions options)
    : options_(std::move(options)), version_(std::string("vroc ") + VROC_VERSION_STRING), context_(&newContext()) {
    if (!options_.log) options_.log = defaultLog;
    if (options_.abi_max < VROC_PLUGIN_ABI_VERSION_MIN || options_.abi_max > VROC_PLUGIN_ABI_VERSION)
        throw InputError("plugin host: abi_max " + std::to_string(options_.abi_max) + " is outside " +
                         std::to_string(VROC_PLUGIN_ABI_VERSION_MIN) + ".." + std::to_string(VROC_PLUGIN_ABI_VERSION));
    dirs_ = pluginSearchDirs(options_.search_dirs, options_.use_environment, options_.use_default_dirs);
    context_->services = {VROC_STRUCT_HOST_SERVICES, 1, sizeof(VrocHostServices), context_,
                          serviceLog, serviceNow, serviceLoad};
    context_->host.store(this);
}

PluginHost::~PluginHost() {
    context_->host.store(nullptr);
    for (auto& [path, plugin] : plugins_)
        if (plugin->library) dlclose(plugin->library);
}

int64_t PluginHost::nowNs() const { return options_.clock ? options_.clock() : steadyNs(); }

void PluginHost::log(int32_t severity, const std::string& plugin, const std::string& message) const {
    options_.log(severity, plugin, message);
}

std::string PluginHost::resolve(const std::string& name_or_path) const {
    if (name_or_path.empty()) throw InputError("plugin: empty plugin name");
    if (name_or_path.find('/') != std::string::npos) return name_or_path;
    const std::string file = pluginFileName(name_or_path);
    std::string searched;
    for (const std::string& dir : dirs_) {
        const std::string candidate = dir + "/" + file;
        if (FILE* f = std::fopen(candidate.c_str(), "rb")) {
            std::fclose(f);
            return candidate;
        }
        searched += (searched.empty() ? "" : ":") + dir;
    }
    throw InputError("plugin '" + name_or_path + "': " + file + " not found in " +
                     (searched.empty() ? std::string("(no directories)") : searched) + " (set " +
                     kPluginPathVariable + " or pass a path)");
}

const LoadedPlugin& PluginHost::load(const std::string& name_or_path) {
    const std::string path = resolve(name_or_path);
    std::lock_guard lock(mutex_);
    if (auto it = plugins_.find(path); it != plugins_.end()) return *it->second;
    void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        const char* why = dlerror();
        throw InputError("plugin " + path + ": cannot load: " + (why ? why : "unknown dlopen error"));
    }
    dlerror();
    void* symbol = dlsym(library, VROC_PLUGIN_ENTRY_POINT);
    if (!symbol) {
        dlclose(library);
        throw InputError("plugin " + path + ": no exported symbol " + VROC_PLUGIN_ENTRY_POINT +
                         " (not a VROC device plugin)");
    }
    return negotiateAndKeep(path, library, reinterpret_cast<VrocNegotiateFn>(symbol));
}

const LoadedPlugin& PluginHost::addStatic(const std::string& label, VrocNegotiateFn negotiate) {
    std::lock_guard lock(mutex_);
    const std::string path = "static:" + label;
    if (auto it = plugins_.find(path); it != plugins_.end()) return *it->second;
    if (!negotiate) throw InputError("plugin " + path + ": null negotiate function");
    return negotiateAndKeep(path, nullptr, negotiate);
}

const LoadedPlugin& PluginHost::negotiateAndKeep(const std::string& path, void* library, VrocNegotiateFn negotiate) {
    VrocHostInfo host{VROC_STRUCT_HOST_INFO, 1, sizeof(VrocHostInfo), VROC_PLUGIN_ABI_VERSION_MIN,
                      options_.abi_max, version_.c_str(), &context_->services};
    VrocPluginInfo info{};
    info.struct_type = VROC_STRUCT_PLUGIN_INFO;
    info.struct_version = 1;
    info.struct_size = sizeof info;
    auto plugin = std::make_unique<LoadedPlugin>();
    std::string why;
    int32_t rc = VROC_ERROR_INTERNAL;
    try {
        rc = negotiate(&host, &info);
    } catch (...) {
        why = "vroc_plugin_negotiate threw an exception across the C boundary";
    }
    if (why.empty() && rc < 0) why = "vroc_plugin_negotiate failed with code " + std::to_string(rc);
    if (why.empty()) why = validatePluginInfo(info, host.abi_min, host.abi_max, *plugin);
    if (!why.empty()) {
        if (library) dlclose(library);
        throw InputError("plugin " + path + ": " + why);
    }
    plugin->path = path;
    plugin->library = library;
    auto& kept = plugins_[path];
    kept = std::move(plugin);
    return *kept;
}

std::unique_ptr<DeviceHandle> PluginHost::open(const std::string& name_or_path, const std::string& options,
                                               uint32_t index) {
    return open(load(name_or_path), options, index);
}

std::unique_ptr<DeviceHandle> PluginHost::open(const LoadedPlugin& plugin, const std::string& options, uint32_t index) {
    if (index >= plugin.devices.size())
        throw InputError("plugin " + plugin.name + ": no device " + std::to_string(index) + " (it has " +
                         std::to_string(plugin.devices.size()) + ")");
    VrocDeviceHandle handle = nullptr;
    const int32_t rc = plugin.api->create(index, options.c_str(), &handle);
    if (rc < 0 || !handle) {
        char text[512] = "";
        plugin.api->last_error(nullptr, text, sizeof text);
        if (handle) plugin.api->destroy(handle);
        throw InputError("plugin " + plugin.name + " (" + plugin.path + "): cannot open device " + std::to_string(index) +
                         ": " + (text[0] ? text : "create failed with code " + std::to_string(rc)));
    }
    auto device = std::make_unique<DeviceHandle>(*this, plugin, index, handle);
    device->start();
    return device;
}

std::unique_ptr<DeviceHandle> PluginHost::openSpec(const std::string& spec) {
    const DeviceSpec parsed = parseDeviceSpec(spec);
    return open(parsed.plugin, parsed.options);
}

}  // namespace vroc::plugins
