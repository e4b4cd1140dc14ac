// SPDX-License-Identifier: MIT
// The mujoco tests' scenes: the shared builders (tests/backends/common) and makeMujoco().
#pragma once

#include "backend_test_scenes.h"

namespace vroc::test {

/// Creates the registered "mujoco" backend (registering it first) with `key=value` overrides.
std::unique_ptr<Backend> makeMujoco(const Scene& scene, const Overrides& overrides = {});

/// Steps `frames` frames of the scene's frame dt.
void run(Backend& backend, const Scene& scene, int frames);

}  // namespace vroc::test
