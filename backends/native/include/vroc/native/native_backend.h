// SPDX-License-Identifier: MIT
// The native backend: Lin–Canny/V-Clip closest features, impulse response, exact time of contact.
#pragma once

namespace vroc::native {

/// Adds "native" to BackendRegistry::global(). Call once at program start.
void registerBackend();

}  // namespace vroc::native
