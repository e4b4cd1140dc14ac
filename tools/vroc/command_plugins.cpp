// SPDX-License-Identifier: MIT
// `vroc plugins [--plugin PATH]...`: the device plugins found (search path, VROC_PLUGIN_PATH, the
// build's plugin directory, and each --plugin), with name, version, capabilities, devices and
// file. A plugin that fails negotiation is listed as rejected with the loader's one-line reason;
// a rejected --plugin makes the exit code 2.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "command.h"
#include "vroc/core/errors.h"
#include "vroc/plugin/plugin_host.h"

namespace vroc::cli {
namespace {

struct PluginsOptions {
    std::vector<std::string> plugins;  // explicit files or names
    bool names_only = false;
};

void printPlugin(const plugins::LoadedPlugin& p) {
    std::printf("%s  %s  (ABI %u)\n  %s\n  file: %s\n  capabilities: %s\n", p.name.c_str(), p.version.c_str(),
                p.abi_version, p.description.c_str(), p.path.c_str(), plugins::capabilityNames(p.capabilities).c_str());
    for (size_t i = 0; i < p.devices.size(); ++i) {
        const plugins::DeviceDescription& d = p.devices[i];
        std::printf("  device %zu: %s (%s; sensors %u, buttons %u, axes %u)\n", i, d.name.c_str(),
                    plugins::deviceKindName(d.kind), d.sensor_count, d.button_count, d.axis_count);
        if (!d.options_help.empty()) std::printf("    options: %s\n", d.options_help.c_str());
    }
}

int listPlugins(const PluginsOptions& options) {
    plugins::HostOptions host_options;
    host_options.log = [](int32_t, const std::string&, const std::string&) {};  // listing only
    plugins::PluginHost host(host_options);
    std::vector<std::string> files = plugins::findPluginFiles(host.searchDirs());
    if (!options.names_only) {
        std::string dirs;
        for (const auto& dir : host.searchDirs()) dirs += (dirs.empty() ? "" : ":") + dir;
        std::printf("search path (%s first): %s\n\n", plugins::kPluginPathVariable, dirs.c_str());
    }
    int status = 0;
    auto show = [&](const std::string& what, bool explicit_plugin) {
        try {
            const plugins::LoadedPlugin& p = host.load(what);
            if (options.names_only) std::printf("%s\n", p.name.c_str());
            else printPlugin(p);
        } catch (const InputError& e) {
            if (!options.names_only) std::printf("REJECTED  %s\n", e.what());
            if (explicit_plugin) {
                std::fprintf(stderr, "vroc: error: %s\n", e.what());
                status = 2;
            }
        }
        if (!options.names_only) std::printf("\n");
    };
    for (const std::string& file : files) show(file, false);
    for (const std::string& plugin : options.plugins) show(plugin, true);
    if (files.empty() && options.plugins.empty() && !options.names_only) std::printf("(no plugins found)\n");
    return status;
}

Action setupPlugins(CLI::App& sub, const Context&) {
    auto options = std::make_shared<PluginsOptions>();
    sub.add_option("--plugin", options->plugins, "Also load this plugin file (or name); repeatable");
    sub.add_flag("--names", options->names_only, "Print only the plugin names, one per line (for scripts)");
    return [options] { return listPlugins(*options); };
}

}  // namespace

Command makePluginsCommand() {
    return {"plugins", "List the device plugins found: name, version, capabilities, devices and file", &setupPlugins};
}

}  // namespace vroc::cli
