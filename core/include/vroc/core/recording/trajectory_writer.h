// SPDX-License-Identifier: MIT
// trajectory.csv: one row per virtual body per frame, in scene order, starting at t = 0.
//   t,body,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz
// Pose is the body frame as the scene defines it (world); v is the centre of mass's linear velocity
// and w the angular velocity, both world frame. Numbers are round-trip exact (%.17g).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"
#include "vroc/core/recording/text_sink.h"

namespace vroc::recording {

inline constexpr const char* kTrajectoryHeader = "t,body,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz";

class TrajectoryWriter {
public:
    /// Writes the header. Records the scene's virtual bodies; `sink` must outlive the writer.
    TrajectoryWriter(TextSink& sink, const Scene& scene);

    /// One row per virtual body. `states` holds every scene body, indexed like Scene::bodies.
    /// Throws RunError if a state is not finite (a backend must never produce one).
    void writeFrame(double t, std::span<const BodyState> states);
    /// Hands buffered text to the sink; call before committing the file.
    void flush();

    std::size_t rowsWritten() const { return rows_; }

private:
    TextSink& sink_;
    std::vector<int> bodies_;          ///< scene indices of the virtual bodies
    std::vector<std::string> names_;   ///< their CSV-quoted names
    std::string buffer_;
    std::size_t rows_ = 0;
};

}  // namespace vroc::recording
