// SPDX-License-Identifier: MIT
// events.csv: one row per collision as the backend reports it (docs/events.md).
//   t,body_a,body_b,px,py,pz,nx,ny,nz,impulse
// t [s], point p [m] and unit normal n (from a to b) in world frame, normal impulse [N s].
#pragma once

#include <cstdint>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"
#include "vroc/core/recording/text_sink.h"

namespace vroc::recording {

inline constexpr const char* kEventsHeader = "t,body_a,body_b,px,py,pz,nx,ny,nz,impulse";

class EventWriter {
public:
    /// Writes the header. `sink` and `scene` must outlive the writer.
    EventWriter(TextSink& sink, const Scene& scene);

    /// Throws RunError if an event names a body outside the scene or holds a non-finite number.
    void write(std::span<const CollisionEvent> events);
    void flush();

    std::uint64_t count() const { return count_; }
    /// Distinct body pairs that collided at least once.
    std::size_t pairCount() const { return pairs_.size(); }

private:
    TextSink& sink_;
    const Scene& scene_;
    std::vector<std::string> names_;   ///< CSV-quoted body names by scene index
    std::string buffer_;
    std::uint64_t count_ = 0;
    std::set<std::pair<int, int>> pairs_;
};

}  // namespace vroc::recording
