// SPDX-License-Identifier: MIT
#include "vroc/harness/metrics/event_timing.h"

#include <map>

namespace vroc::harness {

std::vector<double> impactTimes(const std::vector<CollisionEvent>& events, int body, double merge_window) {
    std::vector<double> out;
    std::map<std::pair<int, int>, double> last_by_pair;   // [s] last event of each pair
    for (const CollisionEvent& e : events) {
        if (e.body_a != body && e.body_b != body) continue;
        const auto pair = std::make_pair(e.body_a, e.body_b);
        auto it = last_by_pair.find(pair);
        const bool merged = it != last_by_pair.end() && e.time - it->second < merge_window;
        last_by_pair[pair] = e.time;
        if (!merged) out.push_back(e.time);
    }
    return out;
}

std::optional<double> restTime(const Scene& scene, const RunTrace& trace, RestThreshold threshold) {
    std::optional<double> since;
    for (std::size_t f = 0; f < trace.states.size(); ++f) {
        bool rest = true;
        for (std::size_t i = 0; i < scene.bodies.size() && rest; ++i) {
            if (!scene.bodies[i].isDynamic()) continue;
            const BodyState& s = trace.states[f][i];
            rest = s.linear_velocity.norm() < threshold.linear && s.angular_velocity.norm() < threshold.angular;
        }
        if (!rest) since.reset();
        else if (!since) since = trace.times[f];
    }
    return since;
}

}  // namespace vroc::harness
