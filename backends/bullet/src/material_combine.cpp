// SPDX-License-Identifier: MIT
#include "material_combine.h"

#include <btBulletCollisionCommon.h>

#include <algorithm>
#include <cmath>

namespace vroc::bullet {
namespace {

btScalar minimumRestitution(const btCollisionObject* a, const btCollisionObject* b) {
    return std::min(a->getRestitution(), b->getRestitution());
}

btScalar geometricMeanFriction(const btCollisionObject* a, const btCollisionObject* b) {
    return std::sqrt(a->getFriction() * b->getFriction());
}

}  // namespace

void installMaterialCombineCallbacks() {
    gCalculateCombinedRestitutionCallback = &minimumRestitution;
    gCalculateCombinedFrictionCallback = &geometricMeanFriction;
}

}  // namespace vroc::bullet
