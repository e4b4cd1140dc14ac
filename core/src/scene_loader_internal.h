// SPDX-License-Identifier: MIT
// Pieces of the `vroc-scene/1` loader shared between its source files (internal).
#pragma once

#include <filesystem>

#include "json_reader.h"
#include "vroc/core/scene.h"
#include "vroc/core/shape.h"

namespace vroc {

/// Reads a `shape` value: exactly one of sphere, box, hull, mesh, compound. Meshes load relative
/// to `base_dir`; mesh "parts" and nested compounds are flattened into one compound of convex parts.
Shape readShape(const JsonReader& shape, const std::filesystem::path& base_dir);

/// Reads an `inertia` override: [Ixx, Iyy, Izz] (principal, body axes) or a 3x3 symmetric
/// positive-definite matrix; either way the principal moments must satisfy the triangle
/// inequality (I1 <= I2 + I3), as every real rigid body does. [kg m^2], about the COM.
Mat3 readInertia(const JsonReader& inertia);

/// Reads a material's `sound` object: modes_hz, decay_per_s and gains, equal lengths
/// (scene_loader_sound.cpp; limits in MaterialSound).
MaterialSound readMaterialSound(const JsonReader& sound);

}  // namespace vroc
