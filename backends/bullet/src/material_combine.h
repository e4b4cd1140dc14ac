// SPDX-License-Identifier: MIT
// Bullet's default contact material is the product of the two restitutions and of the two
// frictions. VROC's rule (scene.h: combineMaterials) is restitution = min, friction = geometric
// mean. Bullet exposes the rule only as process-wide callbacks (btManifoldResult.h), which this
// installs; every collision object carries its own material's restitution and friction.
#pragma once

namespace vroc::bullet {

/// Sets gCalculateCombinedRestitutionCallback and gCalculateCombinedFrictionCallback to VROC's
/// rule. Idempotent; every Bullet backend in the process wants the same rule.
void installMaterialCombineCallbacks();

}  // namespace vroc::bullet
