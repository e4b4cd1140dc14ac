// SPDX-License-Identifier: MIT
// The analytic suite of `vroc check` (comparison-methodology.md §3): scenes built in code, each
// with closed-form answers, tolerances and a "required for native" flag.
#pragma once

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "vroc/core/scene.h"
#include "vroc/harness/runs/run_trace.h"

namespace vroc::harness {

struct CheckMetric {
    std::string id;            ///< unique in the suite, e.g. "bounce-e0.8.apex-ratio"
    std::string title;         ///< what is measured
    std::string closed_form;   ///< the formula the expected value comes from
    std::string units;         ///< of measured, expected and tolerance
    double expected = 0;
    double tolerance = 0;      ///< pass iff |measured - expected| <= tolerance; +infinity: reported, not judged
    bool required_for_native = false;
    std::function<double(const Scene&, const RunTrace&)> measure;
    /// Why the tolerance is what it is: the physical criterion it comes from (never "so that an
    /// engine passes"). Set for every analytic metric (checkCriterion).
    std::string criterion;

    bool judged() const { return std::isfinite(tolerance); }
};

struct CheckScenario {
    std::string id;
    std::string description;
    std::function<Scene()> build;
    double duration = 1.0;     ///< [s]
    double frame_dt = 1.0 / 240.0;   ///< [s]
    std::vector<CheckMetric> metrics;
};

/// The default set (< 2 min on one core for two backends), or the long set appended to it.
std::vector<CheckScenario> checkScenarios(bool long_set);

/// The stress section (issues 9 and 22): the committed dense-contact scenes
/// `<scenes_dir>/<scene>.json` (scenes/stress/), ids "stress-<scene>", each at its file's frame_dt,
/// with the issues' targets (not closed forms); those with a tolerance from physics or the issue
/// are required for native. `only` non-empty: just those ids. Throws InputError naming the
/// directory or file when one is missing (and the --scenes-dir option), or what loadScene throws.
std::vector<CheckScenario> stressScenarios(const std::filesystem::path& scenes_dir,
                                           const std::vector<std::string>& only = {});

/// Every stress scenario id, in table order (no files read).
std::vector<std::string> stressScenarioIds();

/// True for ids of the stress section ("stress-...").
bool isStressScenarioId(const std::string& id);

/// A scenario by id from the default and long sets (for `vroc sweep check:<id>`); throws InputError.
CheckScenario findCheckScenario(const std::string& id);

}  // namespace vroc::harness
