// SPDX-License-Identifier: MIT
#include "ode_test_scenes.h"

#include "vroc/ode/ode_backend.h"

namespace vroc::test {

std::unique_ptr<Backend> makeOde(const Scene& scene, const Overrides& overrides) {
    ode::registerBackend();
    return makeRegistered("ode", scene, overrides);
}

}  // namespace vroc::test
