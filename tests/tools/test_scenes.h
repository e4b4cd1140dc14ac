// SPDX-License-Identifier: MIT
// Small scenes for the tools tests, written here so they do not depend on scenes/ changing.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace vroc::test {

/// A real floor (top face z = 0), a ball thrown sideways (lands at t = 0.37 s) and a rotated box falling: two virtual
/// bodies, so row counts and body order are checked, with non-trivial initial velocities.
inline const char* kTwoBodyScene = R"({
  "format": "vroc-scene/1",
  "name": "two_bodies",
  "description": "tools test: a ball and a box over a floor",
  "gravity": [0.0, 0.0, -9.81],
  "frame_dt": 0.01,
  "collision_distance": 0.001,
  "materials": {"m": {"restitution": 0.5, "friction": 0.5}},
  "bodies": [
    {"name": "floor", "role": "real", "material": "m",
     "shape": {"box": {"half_extents": [5.0, 5.0, 0.5]}}, "position": [0.0, 0.0, -0.5]},
    {"name": "ball", "role": "virtual", "material": "m", "mass": 1.0,
     "shape": {"sphere": {"radius": 0.1}}, "position": [0.25, -0.5, 0.6],
     "linear_velocity": [1.5, 0.0, 0.5], "angular_velocity": [0.0, 3.0, 0.0]},
    {"name": "box", "role": "virtual", "material": "m", "mass": 2.0,
     "shape": {"box": {"half_extents": [0.1, 0.2, 0.15]}}, "position": [1.0, 1.0, 0.5],
     "orientation": [0.0, 0.0, 0.6, 0.8], "linear_velocity": [0.0, -1.0, 0.0],
     "angular_velocity": [0.5, 0.0, 1.0]}
  ]
})";

/// Writes `text` to `path` (creating parents) and returns the path.
inline std::filesystem::path writeFile(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path) << text;
    return path;
}

/// A fresh, empty directory under the system temp dir, unique per test process and name.
inline std::filesystem::path freshTempDir(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() /
               ("vroc-tools-test-" + std::to_string(::getpid()) + "-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace vroc::test
