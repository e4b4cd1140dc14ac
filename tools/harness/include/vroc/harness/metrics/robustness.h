// SPDX-License-Identifier: MIT
// Did a run survive its step size (M17)? Judged against the same backend's tiny-step reference.
#pragma once

#include <string>

#include "vroc/core/scene.h"
#include "vroc/harness/runs/run_trace.h"

namespace vroc::harness {

struct RobustnessVerdict {
    bool ok = true;
    std::string reason;   ///< "" when ok; else "NaN", "tunnelling", "energy blow-up" or "collapse"
};

/// Failure when: a state is not finite (or the backend counted a NaN warning); a virtual body's
/// centre lies inside a real body deeper than its own bounding radius, or fell more than 1 m below
/// every real body (tunnelling); kinetic energy exceeds 10x the reference's largest plus
/// the energy of every body after a 1 cm fall (blow-up; the floor spares resting scenes);
/// or collapse: when the scene starts at rest with every virtual body touching something, a body
/// ends farther than its bounding radius from its start; when the reference ends at rest, a body ends farther than its bounding radius from the
/// reference's final position (collapse).
RobustnessVerdict judgeRobustness(const Scene& scene, const RunTrace& run, const RunTrace& reference);

}  // namespace vroc::harness
