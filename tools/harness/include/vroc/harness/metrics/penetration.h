// SPDX-License-Identifier: MIT
// Penetration of a frame judged by the neutral distance query (M15), the same for every backend.
#pragma once

#include <span>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"

namespace vroc::harness {

/// [m] deepest penetration (>= 0) over all body pairs with at least one virtual body.
/// Pairs whose bounding spheres are apart are skipped (they cannot overlap).
double maxPenetration(const Scene& scene, std::span<const BodyState> states);

/// [m] smallest signed distance (gap > 0, penetration < 0) between virtual body `body` and any other body.
double closestDistance(const Scene& scene, std::span<const BodyState> states, int body);

}  // namespace vroc::harness
