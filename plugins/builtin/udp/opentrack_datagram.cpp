// SPDX-License-Identifier: MIT
#include "opentrack_datagram.h"

namespace vroc::plugin_sdk {

OpentrackPose opentrackToPose(const std::array<double, 6>& v) {
    constexpr double kDeg = 3.14159265358979323846 / 180;
    OpentrackPose pose;
    pose.position = Eigen::Vector3d(-v[2], -v[0], v[1]) / 100.0;
    pose.orientation = Eigen::AngleAxisd(v[3] * kDeg, Eigen::Vector3d::UnitZ()) *
                       Eigen::AngleAxisd(v[4] * kDeg, Eigen::Vector3d::UnitY()) *
                       Eigen::AngleAxisd(v[5] * kDeg, Eigen::Vector3d::UnitX());
    return pose;
}

}  // namespace vroc::plugin_sdk
