// SPDX-License-Identifier: MIT
// Mesh files (OBJ, STL, PLY, glTF, ...) read through assimp, reduced to point sets (internal).
// Only vertex positions matter: the scene loader turns them into convex hulls.
#pragma once

#include <string>
#include <vector>

#include "vroc/core/math.h"

namespace vroc {

/// One mesh of a file: its vertices [m], in the file's root frame (node transforms applied),
/// then scaled component-wise by `scale`.
struct MeshPoints {
    std::string name;            ///< the mesh's name in the file ("" if none)
    std::vector<Vec3> vertices;
};

/// Reads every mesh instance of the file, in node-hierarchy order (depth first, as stored).
/// Throws InputError naming the file if it is missing, unreadable or has no vertices;
/// `context` (e.g. "scenes/chair.json: bodies[0].shape.mesh.file") prefixes the message.
std::vector<MeshPoints> importMeshPoints(const std::string& file, const Vec3& scale,
                                         const std::string& context);

}  // namespace vroc
