// SPDX-License-Identifier: MIT
#include "vroc/play/scripted_head.h"

#include <cmath>
#include <numbers>

#include "vroc/hmd/stereo_rig.h"

namespace vroc::play {
namespace {
/// Centre of a body's shape in its frame: the mean of hull vertices (compounds: of all parts).
Vec3 shapeCentre(const Shape& shape) {
    switch (shape.kind) {
        case Shape::Kind::Hull: {
            Vec3 sum = Vec3::Zero();
            for (const Vec3& v : shape.hull->vertices) sum += v;
            return sum / static_cast<double>(shape.hull->vertices.size());
        }
        case Shape::Kind::Compound: {
            Vec3 sum = Vec3::Zero();
            for (const ShapePart& part : shape.parts) sum += part.pose.apply(shapeCentre(part.shape));
            return shape.parts.empty() ? sum : Vec3(sum / static_cast<double>(shape.parts.size()));
        }
        default: return Vec3::Zero();
    }
}
}  // namespace

ScriptedHead ScriptedHead::forScene(const Scene& scene) {
    Eigen::AlignedBox3d box;
    for (const Body& body : scene.bodies) {
        if (body.shape.boundingRadius() > 3.0) continue;   // floors and walls: not the subject
        box.extend(body.pose.apply(shapeCentre(body.shape)));
    }
    const Vec3 target = box.isEmpty() ? Vec3(0, 0, 0.5) : box.center();
    ScriptedHead head;
    head.base = hmd::lookAt(target + Vec3(0.0, -2.7, 0.5), target);
    return head;
}

Pose ScriptedHead::at(double t) const {
    const double two_pi = 2.0 * std::numbers::pi;
    const double yaw = yaw_amplitude * std::sin(two_pi * yaw_frequency * t);
    const double pitch = pitch_amplitude * std::sin(two_pi * pitch_frequency * t);
    // Yaw about world up, pitch about the head's own x axis.
    const Quat q = Quat(Eigen::AngleAxisd(yaw, Vec3::UnitZ())) * base.orientation *
                   Quat(Eigen::AngleAxisd(pitch, Vec3::UnitX()));
    return {base.position, q.normalized()};
}

Pose headFromSensor(const Pose& sensor) {
    Mat3 mount;   // columns: head x, y, z in sensor coordinates
    mount.col(0) = Vec3::UnitX();
    mount.col(1) = Vec3::UnitZ();
    mount.col(2) = -Vec3::UnitY();
    return sensor * Pose{Vec3::Zero(), Quat(mount)};
}

}  // namespace vroc::play
