// SPDX-License-Identifier: MIT
// What a single-point impulse model returns.
#pragma once

#include "vroc/core/math.h"

namespace vroc::native {

enum class ImpulseTrouble { None, IllConditioned, Degenerate };

struct ImpulseResult {
    Vec3 impulse = Vec3::Zero();        ///< [N s] applied to B at the point; A receives -impulse
    ImpulseTrouble trouble = ImpulseTrouble::None;   ///< counted as a warning by the caller
};

}  // namespace vroc::native
