// SPDX-License-Identifier: MIT
#include "event_detection.h"

#include <set>

namespace vroc::mujoco {

void EventDetector::afterStep(const mjModel& m, const mjData& d, double h, double time) {
    std::vector<SolvedContact> solved;
    std::set<std::pair<int, int>> touching;
    points_total_ += static_cast<std::uint64_t>(d.ncon);
    for (int i = 0; i < d.ncon; ++i) {
        const mjContact& c = d.contact[i];
        const int b1 = geom_body_[static_cast<std::size_t>(c.geom1)];
        const int b2 = geom_body_[static_cast<std::size_t>(c.geom2)];
        if (b1 == b2) continue;
        // MuJoCo's contact normal (frame row 0) points from geom1 to geom2; flip to "from a to b".
        const double to_b = b1 < b2 ? 1.0 : -1.0;
        const auto [a, b] = pairKey(b1, b2);
        double force = 0.0;
        if (c.efc_address >= 0) {
            mjtNum f[6];
            mj_contactForce(&m, &d, i, f);
            force = f[0];
        }
        if (c.dist < collision_distance_ || force > 0.0) touching.insert({a, b});
        if (force <= 0.0) continue;
        solved.push_back(
            {a, b, Vec3(c.pos[0], c.pos[1], c.pos[2]), to_b * Vec3(c.frame[0], c.frame[1], c.frame[2]), force * h});
    }
    tracker_.afterStep(solved, touching, time);
}

}  // namespace vroc::mujoco
