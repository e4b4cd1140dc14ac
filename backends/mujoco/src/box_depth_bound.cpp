// SPDX-License-Identifier: MIT
#include "box_depth_bound.h"

#include <cmath>

namespace vroc::mujoco {
namespace {

// Support radius of a box geom along n: sum_i h_i |u_i . n|, u_i the columns of geom_xmat.
double radius(const mjModel* m, const mjData* d, int g, const mjtNum n[3]) {
    const mjtNum* R = d->geom_xmat + 9 * g;
    const mjtNum* h = m->geom_size + 3 * g;
    double r = 0.0;
    for (int i = 0; i < 3; ++i) r += h[i] * std::abs(R[i] * n[0] + R[3 + i] * n[1] + R[6 + i] * n[2]);
    return r;
}

}  // namespace

double boxOverlap(const mjModel* m, const mjData* d, int geom_a, int geom_b, const mjtNum n[3]) {
    const mjtNum* a = d->geom_xpos + 3 * geom_a;
    const mjtNum* b = d->geom_xpos + 3 * geom_b;
    const double centres = std::abs((b[0] - a[0]) * n[0] + (b[1] - a[1]) * n[1] + (b[2] - a[2]) * n[2]);
    return radius(m, d, geom_a, n) + radius(m, d, geom_b, n) - centres;
}

int boundBoxDepths(const mjModel* m, mjData* d) {
    int changed = 0;
    for (int c = 0; c < d->ncon; ++c) {
        mjContact& con = d->contact[c];
        if (m->geom_type[con.geom1] != mjGEOM_BOX || m->geom_type[con.geom2] != mjGEOM_BOX) continue;
        const double deepest = boxOverlap(m, d, con.geom1, con.geom2, con.frame);
        // Real contacts reach the overlap only up to rounding; a phantom is about a box width deeper.
        const mjtNum* ha = m->geom_size + 3 * con.geom1;
        const mjtNum* hb = m->geom_size + 3 * con.geom2;
        const double slack = 1e-6 * (ha[0] + ha[1] + ha[2] + hb[0] + hb[1] + hb[2]);
        if (-con.dist <= deepest + slack) continue;
        con.dist = -deepest;
        if (con.exclude == 0 && !(con.dist < con.includemargin)) con.exclude = 1;  // mj_collision's rule
        ++changed;
    }
    if (changed > 0) {
        // The rows were made from the phantom depths: make them again (a full row list was
        // already counted once by the first mj_makeConstraint of this step).
        const int full = d->warning[mjWARN_CNSTRFULL].number;
        mj_makeConstraint(m, d);
        mj_projectConstraint(m, d);
        d->warning[mjWARN_CNSTRFULL].number = full;
    }
    return changed;
}

}  // namespace vroc::mujoco
