// SPDX-License-Identifier: MIT
// Broken on purpose: declares hulls approximated and never says how (no note), so `vroc backends`
// and a run's "approximated: <note>" have nothing to print. Everything it runs is native's.
// Rejected by checkCapabilityNotes.
#pragma once

#include "broken_backends/delegating_backend.h"

namespace vroc::conformance {

inline BackendInfo unexplainedApproximationBackend() {
    BackendInfo info = wrappedNativeInfo("unexplained_approximation", nativeInfo().create);
    info.capabilities.hull = Support::Approximated;
    info.capabilities.notes.erase("hull");
    return info;
}

}  // namespace vroc::conformance
