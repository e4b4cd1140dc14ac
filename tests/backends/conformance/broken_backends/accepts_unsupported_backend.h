// SPDX-License-Identifier: MIT
// Broken on purpose: declares compounds unsupported, yet creates and runs scenes with them (all
// of it native). The harness would report such scenes "not supported" while the backend ran
// them. Rejected by checkShapeSupport (no InputError) and checkShippedScenes (notepad.json and
// drum_boxes200.json are created).
#pragma once

#include "broken_backends/delegating_backend.h"

namespace vroc::conformance {

inline BackendInfo acceptsUnsupportedBackend() {
    BackendInfo info = wrappedNativeInfo("accepts_unsupported", nativeInfo().create);
    info.capabilities.compound = Support::Unsupported;
    return info;
}

}  // namespace vroc::conformance
