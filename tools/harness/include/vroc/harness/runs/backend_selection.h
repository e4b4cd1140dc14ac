// SPDX-License-Identifier: MIT
// Which backends a harness command runs, with the `--set key=value` overrides routed to each by
// the key's prefix ("bullet.substeps" goes to bullet).
#pragma once

#include <string>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"
#include "vroc/core/settings.h"
#include "vroc/harness/documents/metrics_document.h"

namespace vroc::harness {

/// On what footing the engines are compared (issue 23; docs/harness.md, "Footing").
struct Footing {
    enum class Kind {
        Defaults,   ///< each engine as its users run it, every departure listed with why
        Equal,      ///< the same internal steps per frame, Coulomb's isotropic friction where an engine has it
    };
    Kind kind = Kind::Defaults;
    int substeps = 4;   ///< [steps per frame] Equal: every engine's internal steps (Box2D v3's 4 by default)
};

/// "defaults" or "equal"; throws InputError naming --footing otherwise ("both" is not one footing:
/// selectBackendsOnBothFootings).
Footing::Kind footingKind(const std::string& word);
/// "defaults" / "equal (4 internal steps per frame, isotropic friction)".
std::string footingText(const Footing& footing);

struct SelectedBackend {
    const BackendInfo* info = nullptr;   ///< from BackendRegistry::global(); not owned
    Settings settings;                   ///< resolved: defaults, then the footing's, then the routed overrides
    Footing footing;                     ///< the footing it was selected on
    /// What the equal footing set (before the user's --set, which wins); empty on the defaults footing.
    std::vector<std::pair<std::string, std::string>> footing_settings;
    /// Selected with both footings side by side (`--footing both`): this backend runs twice in the
    /// command, once per footing, and its label and key say which run this is.
    bool both_footings = false;

    /// How tables, charts and verdicts name the run: "bullet", or with both footings side by side
    /// "bullet (own defaults)" / "bullet (equal footing)".
    std::string label() const;
    /// The run's key (pool job ids, its output folder, its keys in metrics.json): "bullet", or with
    /// both footings "bullet-defaults" / "bullet-equal".
    std::string key() const;
};

/// `list` is "a,b,..." (empty: every registered backend, in name order). Throws InputError for an
/// unknown backend, a repeated one, an empty list, or a --set key that names no known backend.
/// On the equal footing each backend's BackendInfo::equal_footing settings go over its defaults and
/// under the user's --set.
std::vector<SelectedBackend> selectBackends(const std::string& list, const std::vector<std::string>& assignments,
                                            const Footing& footing = {});

/// `--footing both`: every backend of `list` twice, first on its own defaults, then on the equal
/// footing of `substeps` internal steps per frame, the two runs of one backend side by side in list
/// order; the user's --set goes to both. Throws as selectBackends.
std::vector<SelectedBackend> selectBackendsOnBothFootings(const std::string& list,
                                                          const std::vector<std::string>& assignments, int substeps);

/// The backends of `list` on the footing named `word` (the command line's --footing and the Python
/// module's footing=): "defaults" or "equal" (`substeps` internal steps per frame), or, where
/// `both_allowed` (check and compare), "both" (selectBackendsOnBothFootings). Throws InputError for
/// another word, for "both" where it is not allowed, and for substeps < 1.
std::vector<SelectedBackend> selectBackendsOnFooting(const std::string& list, const std::vector<std::string>& assignments,
                                                     const std::string& word, int substeps, bool both_allowed);

/// [{name, version, description, settings{key: value}, deviations, footing{kind, substeps, settings}}]
/// for metrics.json; with both footings each entry also has the run's `label` and `key`.
Json backendsJson(const std::vector<SelectedBackend>& backends);

/// The backends of `requested` that can represent `scene` by their declared capabilities
/// (scene_support.h); the others are left out and, with `progress`, named on stderr. `support` gets
/// every requested backend's supportText. Throws InputError when none can.
std::vector<SelectedBackend> representableBackends(const Scene& scene, const std::vector<SelectedBackend>& requested,
                                                   const std::string& command, bool progress, Json& support);

/// Prints "vroc <command>: <text>" on stderr (progress of long commands).
void progressLine(const std::string& command, const std::string& text);

}  // namespace vroc::harness
