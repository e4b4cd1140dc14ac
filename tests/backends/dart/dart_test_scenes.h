// SPDX-License-Identifier: MIT
// The dart tests' scenes: the shared builders (tests/backends/common) and makeDart().
#pragma once

#include "backend_test_scenes.h"

namespace vroc::test {

/// Creates the registered "dart" backend (registering it first) with `key=value` overrides.
std::unique_ptr<Backend> makeDart(const Scene& scene, const Overrides& overrides = {});

}  // namespace vroc::test
