// SPDX-License-Identifier: MIT
// The scene's material rule (restitution = min, friction = geometric mean; scene.h) in MuJoCo.
// MuJoCo mixes the parameters of two colliding geoms its own way (friction: the larger; solref:
// a weighted mean), which equals the scene's rule only when both geoms carry the same values.
// So bodies are grouped by their material's (restitution, friction) values: a pair within a group
// collides through MuJoCo's broad phase with the geoms' own values, and a pair across groups is
// excluded from it and given explicit <pair> elements carrying the combined values.
#pragma once

#include <map>
#include <vector>

#include "restitution_mapping.h"
#include "vroc/core/scene.h"

namespace vroc::mujoco {

/// What a contact gets in MuJoCo.
struct PairMaterial {
    double friction = 0.0;     ///< [-] sliding friction coefficient
    double restitution = 0.0;  ///< [-] the scene's, before mapping
    ContactSpring spring;      ///< solref = (-stiffness, -damping) unless default_solref
    bool default_solref = false;   ///< use MuJoCo's default solref (0.02, 1) instead of `spring`
};

class ContactMaterials {
public:
    /// `timeconst` [s]: contact spring time constant; `max_step` [s]: largest internal step (caps
    /// the damping, see contactSpring); `map_restitution` false: MuJoCo's default solref everywhere.
    ContactMaterials(const Scene& scene, double timeconst, double max_step, bool map_restitution);

    /// Group of a body: equal groups mean equal (restitution, friction) values.
    int group(int body) const { return groups_.at(static_cast<std::size_t>(body)); }
    /// The body's own material, written on its geoms (used by MuJoCo for pairs within a group).
    PairMaterial ofBody(int body) const;
    /// The scene's combined material of a pair of bodies (written on explicit pairs).
    PairMaterial ofPair(int body_a, int body_b) const;

private:
    PairMaterial make(double restitution, double friction) const;

    const Scene& scene_;
    double timeconst_, max_step_;
    bool map_restitution_;
    std::vector<int> groups_;
    mutable std::map<double, ContactSpring> springs_;   ///< by restitution (the inversion is iterative)
};

}  // namespace vroc::mujoco
