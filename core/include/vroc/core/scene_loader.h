// SPDX-License-Identifier: MIT
// Strict loader for `vroc-scene/1` JSON files (docs/scene-format.md).
#pragma once

#include <string>

#include "vroc/core/scene.h"

namespace vroc {

/// Loads and validates a scene. Throws InputError with one line naming the file, the JSON path
/// (or line and column for syntax errors) and what was expected. Meshes load relative to the file.
Scene loadScene(const std::string& path);

/// Same, from JSON text; `origin` names the source in messages and anchors relative mesh paths.
Scene loadSceneFromString(const std::string& json_text, const std::string& origin);

}  // namespace vroc
