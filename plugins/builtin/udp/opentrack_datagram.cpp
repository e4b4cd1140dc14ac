// SPDX-License-Identifier: MIT
#include "opentrack_datagram.h"

#include <cmath>
#include <cstring>

namespace vroc::plugins::udp {
OpentrackPose opentrackToPose(const std::array<double, 6>& v) {
    constexpr double kDeg = 3.14159265358979323846 / 180;
    OpentrackPose pose;
    pose.position = Eigen::Vector3d(-v[2], -v[0], v[1]) / 100.0;
    pose.orientation = Eigen::AngleAxisd(v[3] * kDeg, Eigen::Vector3d::UnitZ()) *
                       Eigen::AngleAxisd(v[4] * kDeg, Eigen::Vector3d::UnitY()) *
                       Eigen::AngleAxisd(v[5] * kDeg, Eigen::Vector3d::UnitX());
    return pose;
}

std::string decodeOpentrackDatagram(const unsigned char* data, size_t size, std::array<double, 6>& values) {
    if (size != kOpentrackDatagramSize)
        return "datagram of " + std::to_string(size) + " bytes, expected " + std::to_string(kOpentrackDatagramSize);
    std::memcpy(values.data(), data, kOpentrackDatagramSize);
    for (double v : values)
        if (!std::isfinite(v)) return "datagram with a non-finite value";
    return {};
}

}  // namespace vroc::plugins::udp
