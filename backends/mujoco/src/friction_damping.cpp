// SPDX-License-Identifier: MIT
#include "friction_damping.h"

#include <algorithm>

namespace vroc::mujoco {

void setFrictionDamping(mjData* d, double damping) {
    for (int i = d->ne + d->nf; i < d->nefc; ++i) {
        if (d->efc_type[i] != mjCNSTR_CONTACT_ELLIPTIC) continue;
        const mjContact& con = d->contact[d->efc_id[i]];
        const mjtNum dmax = std::clamp(con.solimp[1], mjMINIMP, mjMAXIMP);  // as getsolparam clamps it
        for (int j = 1; j < con.dim; ++j) d->efc_KBIP[4 * (i + j) + 1] = damping / dmax;
        i += con.dim - 1;  // the contact's rows are consecutive
    }
}

}  // namespace vroc::mujoco
