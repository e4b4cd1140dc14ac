// SPDX-License-Identifier: MIT
// Reads back trajectory.csv and events.csv as the recording writers wrote them
// (trajectory_writer.h, event_writer.h): the one reader of both files. A file that does not hold
// what its writer writes (wrong header, a row cut short, a body out of scene order, a frame with
// rows missing, fewer frames than expected) is an InputError naming the file, the line and what
// was expected.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"

namespace vroc::recording {

/// The poses of trajectory.csv. Rows per frame are the scene's moving (virtual and tracked) bodies
/// in scene order, as TrajectoryWriter writes them.
struct RecordedTrajectory {
    std::vector<int> bodies;               ///< scene indices of the moving bodies, in file order
    std::vector<double> times;             ///< [s] per frame; times[0] = start
    std::vector<std::vector<Pose>> poses;  ///< [frame][k]: body frame -> world of bodies[k];
                                           ///< the file's quaternion [qx, qy, qz, qw] -> Quat(w, x, y, z)

    std::size_t frames() const { return times.size(); }
};

/// Reads `file` against `scene`. `expected_frames` > 0: fewer frames is an InputError (a truncated
/// run); 0 accepts any number of whole frames.
RecordedTrajectory readTrajectory(const std::filesystem::path& file, const Scene& scene,
                                  std::size_t expected_frames = 0);

/// Reads events.csv against `scene` (body names resolved to scene indices), in file order.
std::vector<CollisionEvent> readEvents(const std::filesystem::path& file, const Scene& scene);

}  // namespace vroc::recording
