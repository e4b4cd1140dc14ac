// SPDX-License-Identifier: MIT
// Registers every backend this build has with BackendRegistry::global(): the one place that names
// them (tools may know the backends; core never does). Used by the `vroc` program and the Python
// module.
#pragma once

namespace vroc::registration {

/// Adds bullet, mujoco, native and ode to the global registry. Safe to call more than once: a
/// backend already registered is left as it is.
void registerBackends();

}  // namespace vroc::registration
