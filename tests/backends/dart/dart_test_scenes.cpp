// SPDX-License-Identifier: MIT
#include "dart_test_scenes.h"

#include "vroc/dart/dart_backend.h"

namespace vroc::test {

std::unique_ptr<Backend> makeDart(const Scene& scene, const Overrides& overrides) {
    dart::registerBackend();
    return makeRegistered("dart", scene, overrides);
}

}  // namespace vroc::test
