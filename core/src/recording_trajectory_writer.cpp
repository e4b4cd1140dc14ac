// SPDX-License-Identifier: MIT
#include "vroc/core/recording/trajectory_writer.h"

#include <cmath>

#include "vroc/core/csv.h"
#include "vroc/core/errors.h"

namespace vroc::recording {

using csv::appendNumber;

TrajectoryWriter::TrajectoryWriter(TextSink& sink, const Scene& scene) : sink_(sink) {
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        if (scene.bodies[i].isStatic()) continue;
        bodies_.push_back(static_cast<int>(i));
        names_.push_back(csv::field(scene.bodies[i].name));
    }
    buffer_ = std::string(kTrajectoryHeader) + "\n";
}

void TrajectoryWriter::writeFrame(double t, std::span<const BodyState> states) {
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
        const int index = bodies_[k];
        if (static_cast<std::size_t>(index) >= states.size())
            throw RunError("trajectory: no state for body '" + names_[k] + "'");
        const BodyState& s = states[index];
        const Quat& q = s.pose.orientation;
        const double row[13] = {s.pose.position.x(), s.pose.position.y(), s.pose.position.z(),
                                q.x(), q.y(), q.z(), q.w(),
                                s.linear_velocity.x(), s.linear_velocity.y(), s.linear_velocity.z(),
                                s.angular_velocity.x(), s.angular_velocity.y(), s.angular_velocity.z()};
        // A backend must never report NaN/inf (it counts a warning and recovers instead), so a
        // non-finite number here is a backend failure, not something to write down.
        for (double v : row)
            if (!std::isfinite(v))
                throw RunError("body '" + names_[k] + "' has a non-finite state at t = " + std::to_string(t) + " s");
        appendNumber(buffer_, t);
        buffer_ += ',';
        buffer_ += names_[k];
        for (double v : row) {
            buffer_ += ',';
            appendNumber(buffer_, v);
        }
        buffer_ += '\n';
        ++rows_;
    }
    if (buffer_.size() >= kFlushBytes) flush();
}

void TrajectoryWriter::flush() {
    if (buffer_.empty()) return;
    sink_.write(buffer_);
    buffer_.clear();
}

}  // namespace vroc::recording
