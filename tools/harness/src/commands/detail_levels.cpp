// SPDX-License-Identifier: MIT
#include "vroc/harness/commands/detail_levels.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "vroc/core/errors.h"
#include "vroc/core/mass_properties.h"

namespace vroc::harness {

std::vector<DetailLevel> parseDetailLevels(const std::string& list) {
    std::vector<DetailLevel> out;
    std::string word;
    for (char c : list + ",") {
        if (c != ',') { word += c; continue; }
        if (word == "full") out.push_back({word, 1.0, false});
        else if (word == "sphere") out.push_back({word, 1.0, true});
        else {
            char* end = nullptr;
            const double f = std::strtod(word.c_str(), &end);
            if (word.empty() || *end != '\0' || !(f > 0 && f <= 1))
                throw InputError("--detail: '" + word + "': expected full, sphere or a fraction in (0, 1]");
            out.push_back({word, f, false});
        }
        word.clear();
    }
    return out;
}

std::vector<Vec3> decimateVertices(const std::vector<Vec3>& v, double keep) {
    const std::size_t n = v.size();
    const std::size_t want = std::min(n, std::max<std::size_t>(4, static_cast<std::size_t>(std::ceil(keep * n))));
    std::vector<Vec3> out = {v[0]};
    std::vector<double> dist(n, INFINITY);
    while (out.size() < want) {
        std::size_t far = 0;
        for (std::size_t i = 0; i < n; ++i) {
            dist[i] = std::min(dist[i], (v[i] - out.back()).squaredNorm());
            if (dist[i] > dist[far]) far = i;
        }
        out.push_back(v[far]);
    }
    return out;
}

namespace {

Shape simplifyShape(const Shape& s, double keep) {
    if (s.kind == Shape::Kind::Hull && keep < 1) {
        const auto pts = decimateVertices(s.hull->vertices, keep);
        try {
            return Shape::convexHull(ConvexPolyhedron::fromPoints(pts));
        } catch (const GeometryError&) {
            return s;   // too few independent points left: keep the original
        }
    }
    if (s.kind == Shape::Kind::Compound) {
        std::vector<ShapePart> parts;
        for (const ShapePart& p : s.parts) parts.push_back({simplifyShape(p.shape, keep), p.pose});
        return Shape::compound(std::move(parts));
    }
    return s;
}

}  // namespace

Scene simplifyScene(const Scene& scene, const DetailLevel& level) {
    Scene out = scene;
    out.name = scene.name + " @" + level.name;
    for (Body& b : out.bodies) {
        if (!b.isDynamic()) continue;
        const double mass = b.mass_properties.mass;
        if (level.spheres) {
            const double r = std::cbrt(3 * b.mass_properties.volume / (4 * std::numbers::pi));
            b.shape = b.mass_properties.center_of_mass.norm() == 0
                          ? Shape::sphere(r)
                          : Shape::compound({ShapePart{Shape::sphere(r), Pose{b.mass_properties.center_of_mass, Quat::Identity()}}});
        } else {
            b.shape = simplifyShape(b.shape, level.keep);
        }
        b.mass_properties = massProperties(b.shape, mass);
    }
    return out;
}

int virtualFaceCount(const Scene& scene) {
    auto faces = [](const Shape& s, auto&& self) -> int {
        switch (s.kind) {
            case Shape::Kind::Sphere: return 0;
            case Shape::Kind::Box: return 6;
            case Shape::Kind::Hull: return static_cast<int>(s.hull->faces.size());
            case Shape::Kind::Compound: { int n = 0; for (const auto& p : s.parts) n += self(p.shape, self); return n; }
        }
        return 0;
    };
    int n = 0;
    for (const Body& b : scene.bodies)
        if (b.isDynamic()) n += faces(b.shape, faces);
    return n;
}

}  // namespace vroc::harness
