// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "checks/check_result.h"
#include "vroc/core/backend.h"

namespace vroc::conformance {

/// A shipped scene and how many frames the worker-count check runs it.
struct HashedRun {
    std::string scene;  ///< path below scenes/
    int frames = 60;
};

/// What the worker-count check runs.
struct WorkerCountCheckOptions {
    /// Balls bouncing down steps, and 8 boxes sliding and stopping on an incline (resting contact
    /// and friction, with native's pair queries on the workers), 1.5 s each. Small on purpose:
    /// more workers than free cores make native's spin barriers slow (dense scenes take minutes
    /// with 3 workers on a loaded 2-core machine).
    std::vector<HashedRun> runs{{"staircase.json", 90}, {"checks/slide8.json", 90}};
    /// Worker counts tried where the backend has a worker setting (3: more workers than the 2
    /// cores CI has, and not a power of two, so round-robin shares are uneven).
    std::vector<int> worker_counts{1, 2, 3};
};

/// The keys of `backend`'s worker-count settings: integer settings named "<backend>.threads" or
/// "<backend>.workers" (native.threads; Bullet, ODE and MuJoCo have none today).
std::vector<std::string> workerSettings(const BackendInfo& backend);

/// Determinism (docs/backend-contract.md): each run gives the same state hash every time and, for
/// every worker setting, at every worker count in range. A backend with no worker setting is run
/// twice at its defaults. Rejects a backend whose results depend on its worker count
/// (broken_backends/thread_dependent_hash_backend.h).
CheckResult checkWorkerCountDeterminism(const BackendInfo& backend, const WorkerCountCheckOptions& options = {});

}  // namespace vroc::conformance
