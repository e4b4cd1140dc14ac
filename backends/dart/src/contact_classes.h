// SPDX-License-Identifier: MIT
// The scene's material rule (scene.h: combineMaterials: restitution = min, friction = geometric
// mean) in DART, which has no per-pair material: ContactConstraint combines the two ShapeNodes'
// coefficients as friction = min(mu_a, mu_b) and restitution = e_a x e_b (DART 6.12,
// ContactConstraint.cpp). So the bodies' materials are grouped into classes of equal
// (restitution, friction), and each body gets one ShapeNode set per class it may touch (its
// "partner" class), all of the same geometry. A collision filter lets a node of body A (class a)
// meant for partner class b meet only nodes of class b meant for partner class a; both carry
//   friction    = sqrt(mu_a mu_b)          (DART's min of two equal values: the geometric mean)
//   restitution = sqrt(min(e_a, e_b))      (DART's product of two equal values: the minimum),
// so every pair DART solves has exactly the scene's combined material. With one class (most
// scenes) a body has one node set and the filter only drops pairs with no virtual body.
#pragma once

#include <dart/collision/CollisionFilter.hpp>
#include <dart/collision/CollisionObject.hpp>
#include <unordered_map>
#include <vector>

#include "vroc/core/scene.h"

namespace vroc::dart {

/// The material classes of a scene: distinct (restitution, friction) pairs among its bodies.
class MaterialClasses {
public:
    explicit MaterialClasses(const Scene& scene);
    int count() const { return static_cast<int>(classes_.size()); }
    int classOf(int body) const { return body_class_[static_cast<std::size_t>(body)]; }
    /// What DART's rule must be fed on both nodes of a pair of classes `a`, `b` (see above).
    double friction(int a, int b) const;
    double restitution(int a, int b) const;

private:
    std::vector<Material> classes_;
    std::vector<int> body_class_;  ///< by scene body index
};

/// What a ShapeNode stands for.
struct NodeTag {
    int body = -1;          ///< scene body index
    int own_class = 0;      ///< the body's material class
    int partner_class = 0;  ///< the class of the bodies this node is meant to touch
    bool dynamic = false;   ///< the body is virtual (moved by contacts)
};

/// Lets two collision objects meet only if they stand for two different bodies, at least one of
/// them virtual, with matching classes (above). Objects it has no tag for are ignored.
class ClassFilter final : public ::dart::collision::CollisionFilter {
public:
    void tag(const ::dart::dynamics::ShapeFrame* frame, const NodeTag& tag) { tags_[frame] = tag; }
    /// Null if `frame` has no tag.
    const NodeTag* find(const ::dart::dynamics::ShapeFrame* frame) const;
    bool ignoresCollision(const ::dart::collision::CollisionObject* a,
                          const ::dart::collision::CollisionObject* b) const override;

private:
    std::unordered_map<const ::dart::dynamics::ShapeFrame*, NodeTag> tags_;
};

}  // namespace vroc::dart
