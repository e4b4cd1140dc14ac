// SPDX-License-Identifier: MIT
// vroc.plugins(): the device plugins found, as `vroc plugins` lists them (docs/plugin-abi.md).
// Listing only: streaming poses from Python is not offered (a plugin's devices are driven by
// `vroc play` and `vroc run --track`).
#include <pybind11/stl.h>

#include "bindings.h"
#include "vroc/core/errors.h"
#include "vroc/plugin/plugin_host.h"
#include "vroc/plugin/plugin_search.h"

namespace vroc::python {
namespace {

py::dict pluginDict(const plugins::LoadedPlugin& p) {
    py::dict d;
    d["name"] = p.name;
    d["version"] = p.version;
    d["description"] = p.description;
    d["path"] = p.path;
    d["abi_version"] = p.abi_version;
    d["capabilities"] = plugins::capabilityNames(p.capabilities);
    py::list devices;
    for (const plugins::DeviceDescription& dev : p.devices) {
        py::dict x;
        x["name"] = dev.name;
        x["kind"] = plugins::deviceKindName(dev.kind);
        x["sensors"] = dev.sensor_count;
        x["buttons"] = dev.button_count;
        x["axes"] = dev.axis_count;
        x["options"] = dev.options_help;
        devices.append(x);
    }
    d["devices"] = devices;
    d["rejected"] = py::none();
    return d;
}

}  // namespace

void bindPlugins(py::module_& m) {
    m.def(
        "_plugins",
        [](const std::vector<std::string>& search_dirs, const std::vector<std::string>& explicit_plugins) {
            plugins::HostOptions options;
            options.search_dirs = search_dirs;
            options.log = [](int32_t, const std::string&, const std::string&) {};   // listing only
            plugins::PluginHost host(options);
            py::list out;
            auto show = [&](const std::string& what, bool is_explicit) {
                try {
                    out.append(pluginDict(host.load(what)));
                } catch (const InputError& e) {
                    if (is_explicit) throw;
                    py::dict d;
                    d["path"] = what;
                    d["rejected"] = e.what();
                    out.append(d);
                }
            };
            for (const std::string& file : plugins::findPluginFiles(host.searchDirs())) show(file, false);
            for (const std::string& p : explicit_plugins) show(p, true);
            return out;
        },
        py::arg("search_dirs"), py::arg("plugins"));
}

}  // namespace vroc::python
