// SPDX-License-Identifier: MIT
// Setting many bodies' states at once, by one rule for every caller (the harness's re-anchored and
// perturbed runs, the Python module's set_state and rollouts).
#pragma once

#include <span>

#include "vroc/core/backend.h"

namespace vroc {

/// True when the two states have the same bits (-0.0 and 0.0 differ, as in stateHash).
bool sameStateBits(const BodyState& a, const BodyState& b);

/// Sets every virtual and tracked body to `states[i]` (indexed like Scene::bodies) through
/// Backend::setBodyState, except a body whose state already has those bits: it is left alone, so
/// that setting the current states changes no bit (a backend's own representation, a rotation
/// matrix or a momentum, may round the last bit of a state set through it). Real bodies are
/// skipped.
void setBodyStates(Backend& backend, const Scene& scene, std::span<const BodyState> states);

}  // namespace vroc
