// SPDX-License-Identifier: MIT
// `vroc backends`: what can be passed to --backend, with versions and --set keys.
#include <cstdio>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "command.h"
#include "vroc/core/backend_registry.h"

namespace vroc::cli {
namespace {

struct BackendsOptions {
    bool names_only = false;
};

void printCapabilities(const BackendCapabilities& c) {
    std::printf("  shapes: sphere %s, box %s, hull %s, compound %s; restitution %s; tracked bodies %s; friction %s; "
                "continuous collision %s; %s precision; %s\n",
                supportName(c.sphere), supportName(c.box), supportName(c.hull), supportName(c.compound),
                supportName(c.restitution), supportName(c.tracked), frictionName(c.friction),
                c.continuous_collision ? "yes" : "no",
                c.precision.c_str(), c.deterministic ? "deterministic" : "not deterministic");
    for (const auto& [feature, note] : c.notes) std::printf("    %s: %s\n", feature.c_str(), note.c_str());
}

int listBackends(const BackendsOptions& options) {
    const auto backends = BackendRegistry::global().all();
    for (const BackendInfo* info : backends) {
        if (options.names_only) {
            std::printf("%s\n", info->name.c_str());
            continue;
        }
        std::printf("%s  %s\n  %s\n", info->name.c_str(), info->version.c_str(), info->description.c_str());
        printCapabilities(info->capabilities);
        if (!info->deviations.empty()) {
            std::printf("  deviations from the engine's own defaults:\n");
            for (const std::string& d : info->deviations) std::printf("    - %s\n", d.c_str());
        }
        if (info->settings.empty()) std::printf("  settings: none\n");
        else std::printf("  settings (--set key=value):\n");
        for (const SettingSpec& spec : info->settings) std::printf("    %s\n", spec.describe().c_str());
    }
    if (backends.empty() && !options.names_only) std::printf("(no backends registered)\n");
    return 0;
}

Action setupBackends(CLI::App& sub, const Context&) {
    auto options = std::make_shared<BackendsOptions>();
    sub.add_flag("--names", options->names_only, "Print only the backend names, one per line (for scripts)");
    return [options] { return listBackends(*options); };
}

}  // namespace

Command makeBackendsCommand() {
    return {"backends", "List the registered physics backends: description, version and --set keys", &setupBackends};
}

}  // namespace vroc::cli
