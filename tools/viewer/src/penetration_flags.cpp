// SPDX-License-Identifier: MIT
#include "penetration_flags.h"

#include "vroc/harness/metrics/neutral_distance.h"

namespace vroc::viewer {

// Each pair once, and only where the bounding spheres (about the body origins) overlap: a pair
// whose spheres are apart cannot penetrate (harness::maxPenetration prunes the same way).
std::vector<std::vector<bool>> penetrationFlags(const Scene& scene, const ViewerRun& run) {
    std::vector<int> moving_of(scene.bodies.size(), -1);
    std::vector<double> reach(scene.bodies.size());
    int k = 0;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        if (!scene.bodies[i].isStatic()) moving_of[i] = k++;
        reach[i] = scene.bodies[i].shape.boundingRadius();
    }
    std::vector<Pose> poses(scene.bodies.size());
    std::vector<std::vector<bool>> out;
    out.reserve(run.poses.size());
    for (const std::vector<Pose>& frame : run.poses) {
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
            poses[i] = moving_of[i] < 0 ? scene.bodies[i].pose : frame[static_cast<std::size_t>(moving_of[i])];
        std::vector<bool> flags(frame.size(), false);
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
            for (std::size_t j = i + 1; j < scene.bodies.size(); ++j) {
                const bool di = scene.bodies[i].isDynamic(), dj = scene.bodies[j].isDynamic();
                if (!di && !dj) continue;  // tracked bodies follow their device, real ones stay
                if ((poses[i].position - poses[j].position).norm() > reach[i] + reach[j]) continue;
                if (harness::bodyDistance(scene, int(i), poses[i], int(j), poses[j]) >= -scene.collision_distance)
                    continue;
                if (di) flags[static_cast<std::size_t>(moving_of[i])] = true;
                if (dj) flags[static_cast<std::size_t>(moving_of[j])] = true;
            }
        out.push_back(std::move(flags));
    }
    return out;
}

}  // namespace vroc::viewer
