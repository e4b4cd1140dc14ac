// SPDX-License-Identifier: MIT
#include "contact_generation.h"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "contact_material.h"
#include "ode_convert.h"

namespace vroc::ode {
namespace {

int sceneIndex(dGeomID geom) { return static_cast<int>(reinterpret_cast<std::intptr_t>(dGeomGetData(geom))); }

// [m/s] velocity of the body's material point at world `p` (zero for a body-less geom).
Vec3 pointVelocity(dBodyID body, const dReal* p) {
    if (!body) return Vec3::Zero();
    dVector3 v;
    dBodyGetPointVel(body, p[0], p[1], p[2], v);
    return fromOde(v);
}

}  // namespace

ContactGenerator::ContactGenerator(std::vector<Material> body_materials, const OdeConfig& config)
    : body_materials_(std::move(body_materials)),
      max_contacts_(config.max_contacts),
      bounce_vel_(config.bounce_vel),
      friction_axes_(config.friction_axes),
      scratch_(static_cast<std::size_t>(config.max_contacts)) {}

void ContactGenerator::collide(dSpaceID space) {
    points_.clear();
    broadphase_pairs_ = 0;
    dSpaceCollide(space, this, &ContactGenerator::nearCallback);
}

void ContactGenerator::nearCallback(void* self, dGeomID g1, dGeomID g2) {
    static_cast<ContactGenerator*>(self)->narrowPhase(g1, g2);
}

void ContactGenerator::narrowPhase(dGeomID g1, dGeomID g2) {
    const dBodyID b1 = dGeomGetBody(g1), b2 = dGeomGetBody(g2);
    if (b1 == b2) return;   // two real (body-less) geoms, or two parts of one compound
    // Infinite mass against infinite mass (real or tracked on both sides) has no response.
    const auto dynamic = [](dBodyID b) { return b && !dBodyIsKinematic(b); };
    if (!dynamic(b1) && !dynamic(b2)) return;
    ++broadphase_pairs_;
    const int n = dCollide(g1, g2, max_contacts_, scratch_.data(), sizeof(dContactGeom));
    if (n <= 0) return;
    const int i1 = sceneIndex(g1), i2 = sceneIndex(g2);
    const dSurfaceParameters surface = surfaceFor(body_materials_[static_cast<std::size_t>(i1)],
                                                  body_materials_[static_cast<std::size_t>(i2)], bounce_vel_);
    for (int k = 0; k < n; ++k) {
        ContactPoint p;
        p.contact.surface = surface;
        p.contact.geom = scratch_[static_cast<std::size_t>(k)];
        p.body_a = std::min(i1, i2);
        p.body_b = std::max(i1, i2);
        // ODE's normal points into g1, i.e. from g2 to g1.
        const Vec3 n_into_g1 = fromOde(p.contact.geom.normal);
        p.normal_a_to_b = i1 == p.body_a ? Vec3(-n_into_g1) : n_into_g1;
        if (friction_axes_ == FrictionAxes::Sliding) {
            const Vec3 v = pointVelocity(b1, p.contact.geom.pos) - pointVelocity(b2, p.contact.geom.pos);
            const Vec3 t = v - v.dot(n_into_g1) * n_into_g1;
            if (t.norm() > 1e-9) {   // not sliding: ODE's own axes do as well as any
                const Vec3 dir = t.normalized();
                p.contact.surface.mode |= dContactFDir1;
                for (int i = 0; i < 3; ++i) p.contact.fdir1[i] = dir[i];
            }
        }
        points_.push_back(p);
    }
}

}  // namespace vroc::ode
