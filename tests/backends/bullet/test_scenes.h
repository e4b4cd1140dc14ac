// SPDX-License-Identifier: MIT
// The bullet tests' scenes: the shared builders (tests/backends/common) and makeBullet().
#pragma once

#include "backend_test_scenes.h"

namespace vroc::test {

/// Creates the registered "bullet" backend (registering it first) with `key=value` overrides.
std::unique_ptr<Backend> makeBullet(const Scene& scene, const Overrides& overrides = {});

}  // namespace vroc::test
