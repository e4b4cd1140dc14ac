// SPDX-License-Identifier: MIT
// The curves of `vroc sweep`: one per backend, or, with `--vary KEY=V1,V2,...`, one per value of
// each varied setting of that backend ("bullet solver_iterations=50"). Every curve keeps its
// backend's base settings (defaults plus --set) as the accuracy reference.
#pragma once

#include <string>
#include <vector>

#include "vroc/harness/runs/backend_selection.h"

namespace vroc::harness {

struct SweepCurve {
    std::size_t backend = 0;   ///< index into the selected backends (whose settings are the reference's)
    SelectedBackend run;       ///< the backend with this curve's settings
    std::string label;         ///< "bullet" or "bullet solver_iterations=50"; key in metrics.json results
    std::string setting;       ///< "solver_iterations=50", or empty for the base settings
};

/// Expands `--vary` arguments ("bullet.solver_iterations=5,10,50", repeatable) into curves. A
/// backend without a varied key gives one curve with its base settings. Throws InputError for a
/// key whose prefix names no selected backend, an unknown key or a bad value (via resolveSettings).
std::vector<SweepCurve> sweepCurves(const std::vector<SelectedBackend>& backends, const std::vector<std::string>& vary);

}  // namespace vroc::harness
