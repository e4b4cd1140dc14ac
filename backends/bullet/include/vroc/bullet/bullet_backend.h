// SPDX-License-Identifier: MIT
// The Bullet reference backend (Bullet 3 in double precision).
#pragma once

namespace vroc::bullet {

/// Adds "bullet" to BackendRegistry::global(). Call once at program start.
void registerBackend();

}  // namespace vroc::bullet
