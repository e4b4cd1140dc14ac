// SPDX-License-Identifier: MIT
// Tessellation of scene shapes for drawing: filled triangles with flat normals and the outline
// edges for wireframe, all in the body frame, as flat float arrays ready for glDrawArrays.
#pragma once

#include <vector>

#include "vroc/core/shape.h"

namespace vroc::render {

struct ShapeMesh {
    std::vector<float> triangle_positions;   ///< [m] x y z per vertex, 3 vertices per triangle
    std::vector<float> triangle_normals;     ///< unit normal per vertex
    std::vector<float> edge_positions;       ///< [m] x y z per vertex, 2 vertices per edge
};

/// Spheres become `slices` x `stacks` UV spheres (their wireframe: the equator and 2 meridians);
/// boxes and hulls use their polygonal faces (edges: face boundaries); compounds add their parts.
ShapeMesh tessellate(const Shape& shape, int slices = 24, int stacks = 16);

}  // namespace vroc::render
