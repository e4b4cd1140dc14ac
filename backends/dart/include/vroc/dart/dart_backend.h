// SPDX-License-Identifier: MIT
// The DART reference backend (DART 6.12, Debian's libdart-dev: FCL collision, its boxed LCP solver).
#pragma once

namespace vroc::dart {

/// Adds "dart" to BackendRegistry::global(). Call once at program start (calling again is harmless).
void registerBackend();

}  // namespace vroc::dart
