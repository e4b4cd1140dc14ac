// SPDX-License-Identifier: MIT
// The ode tests' scenes: the shared builders (tests/backends/common) and makeOde().
#pragma once

#include "backend_test_scenes.h"

namespace vroc::test {

/// Creates the registered "ode" backend (registering it first) with `key=value` overrides.
std::unique_ptr<Backend> makeOde(const Scene& scene, const Overrides& overrides = {});

/// A 0.2 m cube of `shape` (1 kg, e = 0) released face-down at `at` over the floor box, or over a
/// 2 x 2 x 0.2 m hull slab with `hull_floor`; its state after 2 s.
BodyState restedCube(const Shape& shape, const Vec3& at, const Overrides& overrides = {}, bool hull_floor = false);

}  // namespace vroc::test
