// SPDX-License-Identifier: MIT
// The native dynamics tests' own pieces (random bodies, the backend with settings), next to the
// scene builders every suite shares.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "backend/native_backend.h"
#include "dynamics/rigid_body.h"
#include "test_scene_builder.h"
#include "vroc/core/mass_properties.h"
#include "vroc/core/scene.h"

namespace vroc::native::test {

// The shared builders (tests/support/test_scene_builder.h), by their names here.
using vroc::test::addBody;
using vroc::test::addFloor;
using vroc::test::addMaterial;
using vroc::test::addTracked;
using vroc::test::at;
using vroc::test::bareScene;

/// A box of random size, mass, pose and velocity within a few metres of the origin.
inline RigidBody randomBody(std::mt19937_64& rng, bool is_static = false) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Body b;
    b.name = "b";
    b.role = is_static ? BodyRole::Real : BodyRole::Virtual;
    b.shape = Shape::box(Vec3(0.1 + 0.5 * std::abs(u(rng)), 0.1 + 0.5 * std::abs(u(rng)),
                              0.1 + 0.5 * std::abs(u(rng))));
    if (!is_static) b.mass_properties = massProperties(b.shape, 0.5 + 5 * std::abs(u(rng)));
    b.pose = at(Vec3(u(rng), u(rng), u(rng)) * 3,
                Quat(Eigen::AngleAxisd(3 * u(rng), Vec3(u(rng), u(rng), u(rng)).normalized())));
    b.linear_velocity = Vec3(u(rng), u(rng), u(rng)) * 4;
    b.angular_velocity = Vec3(u(rng), u(rng), u(rng)) * 3;
    return RigidBody::fromScene(b);
}

// [m] how far the deepest corner of a box of half extents h lies below the floor's top (z = 0);
// <= 0 if none does (the box's corners from its pose: an independent ruler).
inline double depthBelowFloor(const BodyState& st, const Vec3& h) {
    double lowest = 1e9;
    for (int c = 0; c < 8; ++c) {
        const Vec3 corner((c & 1 ? 1 : -1) * h.x(), (c & 2 ? 1 : -1) * h.y(), (c & 4 ? 1 : -1) * h.z());
        lowest = std::min(lowest, st.pose.apply(corner).z());
    }
    return -lowest;
}

// [m] the deepest overlap of neighbours in a row of cubes of half extent `half` along x (from their
// positions: an independent ruler); <= 0 if every neighbour is apart.
inline double rowOverlap(const Backend& be, const std::vector<int>& row, double half) {
    double overlap = -1e9;
    for (std::size_t k = 1; k < row.size(); ++k)
        overlap = std::max(overlap, 2 * half - (be.bodyState(row[k]).pose.position.x() -
                                                be.bodyState(row[k - 1]).pose.position.x()));
    return overlap;
}

inline std::unique_ptr<NativeBackend> makeBackend(const Scene& s, NativeSettings settings = {}) {
    return std::make_unique<NativeBackend>(s, settings);
}

}  // namespace vroc::native::test
