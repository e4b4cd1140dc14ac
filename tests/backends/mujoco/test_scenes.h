// SPDX-License-Identifier: MIT
// The mujoco tests' scenes: the shared builders (tests/backends/common) and makeMujoco().
#pragma once

#include "backend_test_scenes.h"

namespace vroc::test {

/// Creates the registered "mujoco" backend (registering it first) with `key=value` overrides.
std::unique_ptr<Backend> makeMujoco(const Scene& scene, const Overrides& overrides = {});

/// Steps `frames` frames of the scene's frame dt.
void run(Backend& backend, const Scene& scene, int frames);

/// A 2 kg ball of radius 0.1 m thrown from x0 at v0 in an empty scene (no floor), with the closed
/// forms of its flight: after n internal steps of h by semi-implicit Euler, and on the parabola.
struct FreeFlight {
    Scene scene;
    Vec3 x0 = Vec3(0.5, -1.0, 10.0);   ///< [m]
    Vec3 v0 = Vec3(1.0, 0.25, 3.0);    ///< [m/s]
    int ball = -1;
    FreeFlight();
    Vec3 euler(double h, double n) const { return x0 + n * h * v0 + scene.gravity * (h * h * n * (n + 1) / 2); }
    Vec3 parabola(double t) const { return x0 + v0 * t + 0.5 * scene.gravity * t * t; }
};

}  // namespace vroc::test
