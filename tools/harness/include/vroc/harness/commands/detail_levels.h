// SPDX-License-Identifier: MIT
// Model detail for `vroc sweep --detail`: the same scene with its virtual bodies' hulls decimated
// to fewer vertices, or replaced by spheres. Real (static) bodies are the world model: untouched.
#pragma once

#include <string>
#include <vector>

#include "vroc/core/scene.h"

namespace vroc::harness {

/// A level as written on the command line: "full", a fraction in (0, 1] of hull vertices kept,
/// or "sphere" (each virtual body becomes an equal-volume sphere at its centre of mass).
struct DetailLevel {
    std::string name;
    double keep = 1.0;        ///< fraction of hull vertices kept
    bool spheres = false;
};

/// Parses "full,0.5,0.25,sphere"; throws InputError naming the bad word.
std::vector<DetailLevel> parseDetailLevels(const std::string& list);

/// The scene at that level. Masses are kept; mass properties recomputed for the new shapes.
Scene simplifyScene(const Scene& scene, const DetailLevel& level);

/// Hull vertices kept by farthest-point sampling (deterministic, starts at vertex 0), at least 4.
std::vector<Vec3> decimateVertices(const std::vector<Vec3>& vertices, double keep);

/// Faces of all virtual bodies' shapes (box 6, sphere 0, hull its faces), for the detail table.
int virtualFaceCount(const Scene& scene);

}  // namespace vroc::harness
