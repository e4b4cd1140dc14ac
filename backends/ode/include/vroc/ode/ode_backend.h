// SPDX-License-Identifier: MIT
// The ODE reference backend (Open Dynamics Engine 0.16 in double precision).
#pragma once

namespace vroc::ode {

/// Adds "ode" to BackendRegistry::global(). Call once at program start (calling again is harmless).
void registerBackend();

}  // namespace vroc::ode
