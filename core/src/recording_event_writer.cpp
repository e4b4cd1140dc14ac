// SPDX-License-Identifier: MIT
#include "vroc/core/recording/event_writer.h"

#include <cmath>

#include "vroc/core/csv.h"
#include "vroc/core/errors.h"

namespace vroc::recording {

using csv::appendNumber;

EventWriter::EventWriter(TextSink& sink, const Scene& scene) : sink_(sink), scene_(scene) {
    for (const auto& body : scene.bodies) names_.push_back(csv::field(body.name));
    buffer_ = std::string(kEventsHeader) + "\n";
}

void EventWriter::write(std::span<const CollisionEvent> events) {
    const int n = static_cast<int>(scene_.bodies.size());
    for (const CollisionEvent& e : events) {
        if (e.body_a < 0 || e.body_a >= n || e.body_b < 0 || e.body_b >= n || e.body_a == e.body_b)
            throw RunError("backend reported a collision between body indices " + std::to_string(e.body_a) +
                           " and " + std::to_string(e.body_b) + " (scene has " + std::to_string(n) + " bodies)");
        const double row[7] = {e.point.x(), e.point.y(), e.point.z(),
                               e.normal.x(), e.normal.y(), e.normal.z(), e.impulse};
        for (double v : row)
            if (!std::isfinite(v) || !std::isfinite(e.time))
                throw RunError("backend reported a non-finite collision between '" + scene_.bodies[e.body_a].name +
                               "' and '" + scene_.bodies[e.body_b].name + "'");
        appendNumber(buffer_, e.time);
        buffer_ += ',';
        buffer_ += names_[e.body_a];
        buffer_ += ',';
        buffer_ += names_[e.body_b];
        for (double v : row) {
            buffer_ += ',';
            appendNumber(buffer_, v);
        }
        buffer_ += '\n';
        ++count_;
        pairs_.insert({std::min(e.body_a, e.body_b), std::max(e.body_a, e.body_b)});
    }
    if (buffer_.size() >= kFlushBytes) flush();
}

void EventWriter::flush() {
    if (buffer_.empty()) return;
    sink_.write(buffer_);
    buffer_.clear();
}

}  // namespace vroc::recording
