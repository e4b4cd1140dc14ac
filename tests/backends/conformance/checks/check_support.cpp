// SPDX-License-Identifier: MIT
#include "checks/check_support.h"

#include <algorithm>
#include <limits>

#include "vroc/core/scene_loader.h"
#include "vroc/core/settings.h"

namespace vroc::conformance {

std::unique_ptr<Backend> createBackend(const BackendInfo& backend, const Scene& scene,
                                       const SettingOverrides& overrides) {
    return backend.create(scene, resolveSettings(backend.settings, overrides));
}

std::vector<BodyState> statesOf(const Backend& b) {
    std::vector<BodyState> out;
    for (int i = 0; i < b.bodyCount(); ++i) out.push_back(b.bodyState(i));
    return out;
}

bool finite(const BodyState& s) {
    return s.pose.position.allFinite() && s.pose.orientation.coeffs().allFinite() && s.linear_velocity.allFinite() &&
           s.angular_velocity.allFinite();
}

bool sameRotation(const Quat& a, const Quat& b, double tol) {
    return (a.coeffs() - b.coeffs()).cwiseAbs().maxCoeff() <= tol ||
           (a.coeffs() + b.coeffs()).cwiseAbs().maxCoeff() <= tol;
}

Vec3 centreOfMass(const Body& body, const BodyState& s) { return s.pose.apply(body.mass_properties.center_of_mass); }

double lowestZ(const Shape& shape, const Pose& pose) {
    double low = std::numeric_limits<double>::infinity();
    switch (shape.kind) {
        case Shape::Kind::Sphere:
            return pose.position.z() - shape.radius;
        case Shape::Kind::Box:
            for (int i = 0; i < 8; ++i) {
                const Vec3 h = shape.half_extents;
                low = std::min(
                    low, pose.apply(Vec3(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z())).z());
            }
            return low;
        case Shape::Kind::Hull:
            for (const Vec3& v : shape.hull->vertices) low = std::min(low, pose.apply(v).z());
            return low;
        case Shape::Kind::Compound:
            for (const ShapePart& part : shape.parts) low = std::min(low, lowestZ(part.shape, pose * part.pose));
            return low;
    }
    return low;
}

std::vector<std::filesystem::path> shippedScenes() {
    std::vector<std::filesystem::path> out;
    for (const auto& e :
         std::filesystem::recursive_directory_iterator(std::filesystem::path(VROC_SOURCE_DIR) / "scenes"))
        if (e.is_regular_file() && e.path().extension() == ".json") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

const std::vector<ShippedScene>& loadedShippedScenes() {
    static const std::vector<ShippedScene> scenes = [] {
        std::vector<ShippedScene> out;
        for (const std::filesystem::path& path : shippedScenes()) out.push_back({path, loadScene(path.string())});
        return out;
    }();
    return scenes;
}

Scene shippedScene(const std::string& relative_path) {
    return loadScene(std::string(VROC_SOURCE_DIR) + "/scenes/" + relative_path);
}

}  // namespace vroc::conformance
