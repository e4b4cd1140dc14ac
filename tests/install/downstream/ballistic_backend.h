// SPDX-License-Identifier: MIT
// A toy backend written outside VROC against the installed public interface only
// (vroc/core/backend.h, backend_registry.h): every virtual body flies under gravity in closed form
// and nothing collides. It exists to show that a downstream project can add a backend the harness
// runs and compares like the built-in ones.
#pragma once

namespace toy {

/// Adds "ballistic" to vroc::BackendRegistry::global(). Call once at program start.
void registerBallisticBackend();

}  // namespace toy
