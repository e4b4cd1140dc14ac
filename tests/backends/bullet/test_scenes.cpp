// SPDX-License-Identifier: MIT
#include "test_scenes.h"

#include "vroc/bullet/bullet_backend.h"

namespace vroc::test {

std::unique_ptr<Backend> makeBullet(const Scene& scene, const Overrides& overrides) {
    bullet::registerBackend();
    return makeRegistered("bullet", scene, overrides);
}

}  // namespace vroc::test
