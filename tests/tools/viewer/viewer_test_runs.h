// SPDX-License-Identifier: MIT
// A small scene and its runs for the viewer tests: a real floor, a ball thrown sideways (it moves
// across the picture), a ball resting on the floor (it does not move) and a tracked box gliding
// along y, recorded by `vroc run` (on the native backend unless a test asks for another).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "subprocess.h"
#include "test_scenes.h"

namespace vroc::test {

inline const char* kViewerScene = R"({
  "format": "vroc-scene/1",
  "name": "viewer_test",
  "description": "viewer test: a thrown ball, a resting ball and a tracked box over a floor",
  "gravity": [0.0, 0.0, -9.81],
  "frame_dt": 0.02,
  "collision_distance": 0.001,
  "materials": {"m": {"restitution": 0.3, "friction": 0.6}},
  "bodies": [
    {"name": "floor", "role": "real", "material": "m",
     "shape": {"box": {"half_extents": [2.0, 2.0, 0.1]}}, "position": [0.0, 0.0, -0.1]},
    {"name": "thrown", "role": "virtual", "material": "m", "mass": 1.0,
     "shape": {"sphere": {"radius": 0.15}}, "position": [-1.0, 0.0, 0.8],
     "linear_velocity": [2.0, 0.0, 1.0]},
    {"name": "resting", "role": "virtual", "material": "m", "mass": 1.0,
     "shape": {"sphere": {"radius": 0.15}}, "position": [0.0, 1.2, 0.15]},
    {"name": "glider", "role": "tracked", "material": "m",
     "shape": {"box": {"half_extents": [0.1, 0.1, 0.1]}}, "position": [-1.2, -1.2, 0.3],
     "linear_velocity": [0.0, 0.5, 0.0]}
  ]
})";

inline constexpr int kViewerSceneBodies = 4;  // as written above: floor, thrown, resting, glider

/// Writes the scene into `dir` and records a `vroc run` of `seconds` on `backend` into dir/<name>
/// (with its view.html unless `extra` says --no-view).
inline std::filesystem::path recordViewerRun(const std::filesystem::path& dir, const std::string& name,
                                             double seconds = 1.0, const std::string& backend = "native",
                                             const std::vector<std::string>& extra = {}) {
    const auto scene = writeFile(dir / "viewer_test.json", kViewerScene);
    std::vector<std::string> args{"run",        scene.string(),          "--backend", backend,
                                  "--duration", std::to_string(seconds), "-o",        (dir / name).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const ProcessResult r = runVroc(args, dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return dir / name;
}

/// The page's embedded data ("vroc-view/1", docs/viewer.md) as JSON.
inline nlohmann::json pageData(const std::filesystem::path& page) {
    const std::string html = readText(page.string());
    const std::size_t at = html.find('>', html.find("id=\"vroc-data\"")) + 1;
    return nlohmann::json::parse(html.substr(at, html.find("</script>", at) - at));
}

}  // namespace vroc::test
