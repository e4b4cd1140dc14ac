// SPDX-License-Identifier: MIT
// From spacenavd's axes to VROC's. spacenavd reports a motion event as six counts x, y, z, rx, ry,
// rz in its left-handed device frame (x right, y up, z forward, into the screen); libspnav's own
// spnav_posrot_moveobj moves an object by (x, y, -z) and turns it about (rx, ry, -rz) in a
// right-handed y-up frame, so the cap's push and twist carry over as vectors. In VROC's base frame
// (x forward, y left, z up) that is translation (z, -x, y) and rotation (rz, -rx, ry). Each count
// is divided by the full-scale count (the deflection at the stop, about 350 for a SpaceNavigator)
// and clamped to [-1, 1].
#pragma once

#include <array>

#include "analog_fly.h"

namespace vroc::plugins::spacenav {

using plugin_sdk::MouseAxes;

/// counts = x, y, z, rx, ry, rz as spacenavd sends them; full_scale > 0.
MouseAxes spacenavToVrocAxes(const std::array<int, 6>& counts, double full_scale);

}  // namespace vroc::plugins::spacenav
