// SPDX-License-Identifier: MIT
// ODE's collision pass, as ODE users write it: dSpaceCollide (broad phase) calls back for each
// pair of geoms whose bounding boxes overlap, dCollide (narrow phase) returns up to
// `max_contacts` contact points for the pair, and each point becomes a dContact with the pair's
// surface (contact_material.h). ODE's colliders report only touching or overlapping shapes
// (depth >= 0): a gap, however small, gives no contact.
//
// Friction axes: ODE's dPlaneSpace(normal) by default; with FrictionAxes::Sliding the first axis
// (dContactFDir1) follows the pair's relative tangential velocity at the contact point, so a
// sliding contact's friction opposes its motion with mu x normal force whatever its direction.
//
// Pairs without a dynamic body (real or kinematic tracked bodies on both sides: infinite mass
// against infinite mass) are skipped before the narrow phase.
//
// Normals: ODE's contact normal points into geom g1 (from g2 to g1); each point also carries it
// "from a to b" for the scene bodies a < b (docs/events.md).
#pragma once

#include <cstdint>
#include <vector>

#include <ode/ode.h>

#include "ode_config.h"
#include "vroc/core/scene.h"

namespace vroc::ode {

struct ContactPoint {
    dContact contact{};                    ///< as dJointCreateContact takes it
    int body_a = -1, body_b = -1;          ///< scene body indices, body_a < body_b
    Vec3 normal_a_to_b = Vec3::Zero();     ///< unit, world
};

class ContactGenerator {
public:
    /// Materials per scene body (index = body index); max_contacts, bounce_vel and friction_axes
    /// from `config`.
    ContactGenerator(std::vector<Material> body_materials, const OdeConfig& config);

    /// Collides every geom pair of `space` at the geoms' current poses; replaces points().
    void collide(dSpaceID space);
    const std::vector<ContactPoint>& points() const { return points_; }
    /// Pairs the broad phase passed to the narrow phase in the last collide().
    std::uint64_t broadphasePairs() const { return broadphase_pairs_; }

private:
    static void nearCallback(void* self, dGeomID g1, dGeomID g2);
    void narrowPhase(dGeomID g1, dGeomID g2);

    std::vector<Material> body_materials_;
    int max_contacts_;
    double bounce_vel_;
    FrictionAxes friction_axes_;
    std::vector<dContactGeom> scratch_;   ///< dCollide output, max_contacts_ long
    std::vector<ContactPoint> points_;
    std::uint64_t broadphase_pairs_ = 0;
};

}  // namespace vroc::ode
