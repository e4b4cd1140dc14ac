// SPDX-License-Identifier: MIT
// A 64-bit hash over the exact bit patterns of body states, so two runs compare by one number.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "vroc/core/backend.h"

namespace vroc {

/// FNV-1a 64 over, per body in order: position xyz, quaternion xyzw, linear and angular velocity.
/// -0.0 and 0.0 hash differently (bit patterns are the point).
std::uint64_t stateHash(std::span<const BodyState> states);
std::uint64_t stateHash(const Backend& backend);
std::string hashToHex(std::uint64_t hash);   ///< 16 lowercase hex digits

}  // namespace vroc
