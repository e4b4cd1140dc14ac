// SPDX-License-Identifier: MIT
// Which backends a harness command runs, with the `--set key=value` overrides routed to each by
// the key's prefix ("bullet.substeps" goes to bullet).
#pragma once

#include <string>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"
#include "vroc/core/settings.h"
#include "vroc/harness/metrics_document.h"

namespace vroc::harness {

struct SelectedBackend {
    const BackendInfo* info = nullptr;   ///< from BackendRegistry::global(); not owned
    Settings settings;                   ///< resolved: defaults plus the routed overrides
};

/// `list` is "a,b,..." (empty: every registered backend, in name order). Throws InputError for an
/// unknown backend, a repeated one, an empty list, or a --set key that names no known backend.
std::vector<SelectedBackend> selectBackends(const std::string& list, const std::vector<std::string>& assignments);

/// [{name, version, description, settings{key: value}}] for metrics.json.
Json backendsJson(const std::vector<SelectedBackend>& backends);

/// The backends of `requested` that can represent `scene` by their declared capabilities
/// (scene_support.h); the others are left out and, with `progress`, named on stderr. `support` gets
/// every requested backend's supportText. Throws InputError when none can.
std::vector<SelectedBackend> representableBackends(const Scene& scene, const std::vector<SelectedBackend>& requested,
                                                   const std::string& command, bool progress, Json& support);

/// Prints "vroc <command>: <text>" on stderr (progress of long commands).
void progressLine(const std::string& command, const std::string& text);

}  // namespace vroc::harness
