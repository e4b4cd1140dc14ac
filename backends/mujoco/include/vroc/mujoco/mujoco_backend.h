// SPDX-License-Identifier: MIT
// The MuJoCo reference backend (MuJoCo 2.2, double precision, soft contacts).
#pragma once

namespace vroc::mujoco {

/// Adds "mujoco" to BackendRegistry::global(). Call once at program start (twice is harmless).
void registerBackend();

}  // namespace vroc::mujoco
