// SPDX-License-Identifier: MIT
// An ensemble's members replayed (`vroc ensemble` keeps no trajectories): each member's perturbed
// initial states (harness::ensembleMemberStates, the same seed and perturbation) run again on its
// backend with the settings metrics.json lists. The runs are deterministic, so a replayed member
// is the member the ensemble ran.
#pragma once

#include <string>
#include <vector>

#include "run_directory.h"
#include "vroc/core/recording/trajectory_reader.h"
#include "vroc/core/scene.h"

namespace vroc::viewer {

struct ReplayedMember {
    std::string backend;                       ///< registry name
    int member = 0;                            ///< index in the ensemble
    recording::RecordedTrajectory trajectory;  ///< every frame
    std::vector<CollisionEvent> events;
    std::string state_hash;  ///< of the final state (vroc::stateHash), to check against the record
};

/// Members 0 .. min(plan.members, max_members) - 1 of every backend of the plan. Throws InputError
/// for a backend this build does not have. A member whose final state hash differs from the one the
/// ensemble recorded (a changed build or backend) is named in `mismatches` ("bullet #3").

std::vector<ReplayedMember> replayEnsemble(const Scene& scene, const EnsembleReplayPlan& plan, int max_members,
                                           std::vector<std::string>& mismatches);

}  // namespace vroc::viewer
