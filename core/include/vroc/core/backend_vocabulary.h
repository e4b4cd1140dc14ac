// SPDX-License-Identifier: MIT
// The shared vocabulary of backend statistics and warnings (docs/backend-contract.md). A backend
// reports a quantity under its shared name when it has it; anything else carries the backend's own
// prefix ("native.walk_steps_mean", "bullet.aabb_overflow"). foreignNames() is what the
// conformance suite uses to hold every backend to this.
#pragma once

#include <string>
#include <vector>

#include "vroc/core/backend.h"

namespace vroc::vocabulary {

// --- statistics (Statistics keys) ---
inline constexpr const char* kFrames = "frames";                      ///< stepFrame calls
inline constexpr const char* kInternalSteps = "internal_steps";       ///< solver steps taken, total
inline constexpr const char* kCollisionEvents = "collision_events";   ///< CollisionEvents reported, total
inline constexpr const char* kContactPoints = "contact_points";       ///< contact points in the last internal step
inline constexpr const char* kContactPointsMean = "contact_points_mean";   ///< contact points per internal step
inline constexpr const char* kBroadphasePairs = "broadphase_pairs";   ///< pairs the broad phase passed on, last internal step
inline constexpr const char* kBroadphasePairsMean = "broadphase_pairs_mean";   ///< per internal step

// --- warnings (WarningCounts keys) ---
/// A state became (or was handed in) non-finite; the body kept or returned to a finite state.
inline constexpr const char* kNonfiniteState = "nonfinite_state";
/// Bodies were moved apart outside the solver to end a penetration.
inline constexpr const char* kPenetrationRecovered = "penetration_recovered";
/// A frame hit the backend's limit of internal steps; the rest of the frame was taken at once.
inline constexpr const char* kInternalStepCap = "internal_step_cap";
/// A contact system was near singular; a fallback solve was used.
inline constexpr const char* kIllConditionedSolve = "ill_conditioned_solve";
/// The engine left out contacts or constraint rows it had found because a buffer was full: the
/// run is not the engine's physics, and the harness marks it not valid (harness/run_validity.h).
inline constexpr const char* kContactsDropped = "contacts_dropped";

/// Every shared statistic name.
const std::vector<std::string>& sharedStatistics();
/// Every shared warning name.
const std::vector<std::string>& sharedWarnings();

/// The same counts with every name that is not shared given the prefix "<backend>." (names that
/// already carry it are kept): a backend counts under short names and reports through this.
WarningCounts prefixed(const WarningCounts& warnings, const std::string& backend);
Statistics prefixed(const Statistics& statistics, const std::string& backend);

/// Names among `names` that are neither shared (in `shared`) nor prefixed "<backend>."; empty
/// when the backend keeps to the vocabulary.
std::vector<std::string> foreignNames(const std::vector<std::string>& names, const std::vector<std::string>& shared,
                                      const std::string& backend);

}  // namespace vroc::vocabulary
