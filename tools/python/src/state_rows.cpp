// SPDX-License-Identifier: MIT
#include "state_rows.h"

#include <cmath>
#include <cstdio>

#include "vroc/core/errors.h"

namespace vroc::python {

void writeStateRow(const BodyState& s, double* row) {
    const Quat& q = s.pose.orientation;
    const double values[kStateWidth] = {s.pose.position.x(),     s.pose.position.y(),     s.pose.position.z(),
                                        q.x(),                   q.y(),                   q.z(),
                                        q.w(),                   s.linear_velocity.x(),   s.linear_velocity.y(),
                                        s.linear_velocity.z(),   s.angular_velocity.x(),  s.angular_velocity.y(),
                                        s.angular_velocity.z()};
    for (int i = 0; i < kStateWidth; ++i) row[i] = values[i];
}

BodyState readStateRow(const double* row, const std::string& body) {
    for (int i = 0; i < kStateWidth; ++i)
        if (!std::isfinite(row[i]))
            throw InputError("state of body '" + body + "': column " + std::to_string(i) + " is not finite");
    BodyState s;
    s.pose.position = Vec3(row[0], row[1], row[2]);
    s.pose.orientation = Quat(row[6], row[3], row[4], row[5]);   // Eigen takes w first
    const double norm = s.pose.orientation.norm();
    if (std::abs(norm - 1.0) > 1e-6) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.9g", norm);
        throw InputError("state of body '" + body + "': orientation (columns 3-6, x y z w) must be a unit quaternion, norm is " +
                         buf);
    }
    s.linear_velocity = Vec3(row[7], row[8], row[9]);
    s.angular_velocity = Vec3(row[10], row[11], row[12]);
    return s;
}

std::vector<BodyState> readStateRows(std::span<const double> rows, const Scene& scene) {
    const std::size_t n = scene.bodies.size();
    if (rows.size() != n * kStateWidth)
        throw InputError("state: expected " + std::to_string(n) + " rows of " + std::to_string(kStateWidth) +
                         " numbers (one per scene body), got " + std::to_string(rows.size()) + " numbers");
    std::vector<BodyState> states;
    states.reserve(n);
    for (std::size_t i = 0; i < n; ++i) states.push_back(readStateRow(rows.data() + i * kStateWidth, scene.bodies[i].name));
    return states;
}

}  // namespace vroc::python
