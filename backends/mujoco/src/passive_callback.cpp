// SPDX-License-Identifier: MIT
#include "passive_callback.h"

#include "box_depth_bound.h"
#include "friction_damping.h"

namespace vroc::mujoco {

void installPassiveCallback() { mjcb_passive = &onPassive; }

double modelNumeric(const mjModel* m, const char* name, double fallback) {
    const int id = mj_name2id(m, mjOBJ_NUMERIC, name);
    if (id < 0 || m->numeric_size[id] < 1) return fallback;
    return m->numeric_data[m->numeric_adr[id]];
}

void onPassive(const mjModel* m, mjData* d) {
    if (m->nnumeric == 0) return;  // MuJoCo's own model: nothing to do
    if (modelNumeric(m, kBoxDepthBoundName, 0.0) != 0.0) {
        const int changed = boundBoxDepths(m, d);
        if (m->nuserdata > 0) d->userdata[0] += changed;
    }
    const double damping = modelNumeric(m, kFrictionDampingName, 0.0);
    if (damping > 0.0 && m->opt.cone == mjCONE_ELLIPTIC) setFrictionDamping(d, damping);
}

}  // namespace vroc::mujoco
