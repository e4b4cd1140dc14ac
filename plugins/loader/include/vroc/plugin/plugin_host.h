// SPDX-License-Identifier: MIT
// Loads device plugins (dlopen RTLD_NOW|RTLD_LOCAL), negotiates the ABI, validates everything the
// plugin declares and opens devices. A plugin that fails any check is rejected with one line
// (InputError) naming the file and the problem; nothing the plugin does can crash the host short
// of a crash inside the plugin itself.
//
// Lifetime: the host owns the libraries; every DeviceHandle must be destroyed before its host.
// Not copyable or movable (plugins keep a pointer to its services).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "vroc/plugin/device_handle.h"
#include "vroc/plugin/loaded_plugin.h"
#include "vroc/plugin/plugin_search.h"
#include "vroc/plugin/vroc_device_plugin.h"

namespace vroc::plugins {

/// (severity VROC_LOG_*, plugin name or "", message)
using LogSink = std::function<void(int32_t, const std::string&, const std::string&)>;

struct HostOptions {
    std::vector<std::string> search_dirs;  ///< searched before the standard directories
    bool use_environment = true;           ///< honour VROC_PLUGIN_PATH
    bool use_default_dirs = true;          ///< program-relative and build plugin directories
    LogSink log;                           ///< default: warnings and errors to stderr
    std::function<int64_t()> clock;        ///< default: steady_clock (CLOCK_MONOTONIC) [ns]
    /// Highest plugin ABI offered in negotiation (the host accepts VROC_PLUGIN_ABI_VERSION_MIN up to
    /// this). 1 makes the host behave as an ABI-1 host (compatibility tests); must be 1 or 2.
    uint32_t abi_max = VROC_PLUGIN_ABI_VERSION;
};

class PluginHost {
public:
    explicit PluginHost(HostOptions options = {});
    ~PluginHost();
    PluginHost(const PluginHost&) = delete;
    PluginHost& operator=(const PluginHost&) = delete;

    /// Loads (once per resolved file) and validates a plugin by name or path. Throws InputError.
    const LoadedPlugin& load(const std::string& name_or_path);
    /// The same negotiation and validation for a plugin linked into the program.
    const LoadedPlugin& addStatic(const std::string& label, VrocNegotiateFn negotiate);
    /// Opens device `index` of a plugin. Throws InputError with the plugin's last_error text.
    std::unique_ptr<DeviceHandle> open(const std::string& name_or_path, const std::string& options = "",
                                       uint32_t index = 0);
    std::unique_ptr<DeviceHandle> open(const LoadedPlugin& plugin, const std::string& options, uint32_t index = 0);
    /// "analytic:motion=circle" -> open("analytic", "motion=circle").
    std::unique_ptr<DeviceHandle> openSpec(const std::string& spec);

    /// The file a name or path refers to. Throws InputError listing the directories searched.
    std::string resolve(const std::string& name_or_path) const;
    const std::vector<std::string>& searchDirs() const { return dirs_; }
    int64_t nowNs() const;
    void log(int32_t severity, const std::string& plugin, const std::string& message) const;
    const std::string& hostVersion() const { return version_; }

    struct Context;  // what plugins' services point at; lives as long as the process (plugin_host.cpp)

private:
    const LoadedPlugin& negotiateAndKeep(const std::string& path, void* library, VrocNegotiateFn negotiate);

    HostOptions options_;
    std::vector<std::string> dirs_;
    std::string version_;
    Context* context_;                     // owned by the process-wide pool (plugin_host.cpp)
    mutable std::recursive_mutex mutex_;   // recursive: predict loads its inner plugin from open()
    std::map<std::string, std::unique_ptr<LoadedPlugin>> plugins_;  // by path
};

}  // namespace vroc::plugins
