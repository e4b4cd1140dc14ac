// SPDX-License-Identifier: MIT
// The ode tests' scenes: the shared builders (tests/backends/common) and makeOde().
#pragma once

#include "backend_test_scenes.h"

namespace vroc::test {

/// Creates the registered "ode" backend (registering it first) with `key=value` overrides.
std::unique_ptr<Backend> makeOde(const Scene& scene, const Overrides& overrides = {});

}  // namespace vroc::test
