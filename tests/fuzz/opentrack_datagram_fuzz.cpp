// SPDX-License-Identifier: MIT
// Fuzz target: the `udp` plugin's opentrack datagram path (plugins/builtin/udp/
// opentrack_datagram.h): decodeOpentrackDatagram, then opentrackToPose, then the pose as the
// plugin writes it (docs/fuzzing.md). Inputs of any length; 48 bytes is a datagram.
// Contract: a datagram is accepted exactly when it is 48 bytes of six finite doubles; for an
// accepted one the position is exactly (-TZ, -TX, TY) / 100 m, the orientation a finite unit
// quaternion (within 1e-12) equal, as a rotation, to Rz(yaw) Ry(pitch) Rx(roll) built here from
// sines and cosines (within 1e-9), and the sample the plugin would hand over passes the host's
// check (plugins/loader/src/plugin_validation.h).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "fuzz_require.h"
#include "opentrack_datagram.h"
#include "plugin_validation.h"
#include "pose_math.h"

namespace {

// Rz(yaw) Ry(pitch) Rx(roll), angles in degrees, written out element by element.
Eigen::Matrix3d expectedRotation(double yaw_deg, double pitch_deg, double roll_deg) {
    constexpr double kDeg = 3.14159265358979323846 / 180;
    const double cy = std::cos(yaw_deg * kDeg), sy = std::sin(yaw_deg * kDeg);
    const double cp = std::cos(pitch_deg * kDeg), sp = std::sin(pitch_deg * kDeg);
    const double cr = std::cos(roll_deg * kDeg), sr = std::sin(roll_deg * kDeg);
    Eigen::Matrix3d r;
    r << cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,
         sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,
         -sp, cp * sr, cp * cr;
    return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace vroc::plugins::udp;
    using vroc::plugin_sdk::kPoseValidTracked;
    using vroc::plugin_sdk::writePose;
    std::array<double, 6> values{};
    const std::string why = decodeOpentrackDatagram(data, size, values);
    bool expected_ok = size == kOpentrackDatagramSize;
    std::array<double, 6> raw{};
    if (expected_ok) {
        std::memcpy(raw.data(), data, sizeof raw);
        for (double v : raw) expected_ok = expected_ok && std::isfinite(v);
    }
    VROC_FUZZ_REQUIRE(why.empty() == expected_ok);
    if (!expected_ok) {
        VROC_FUZZ_REQUIRE(why.rfind("datagram", 0) == 0);
        return 0;
    }
    VROC_FUZZ_REQUIRE(std::memcmp(values.data(), raw.data(), sizeof raw) == 0);

    const OpentrackPose pose = opentrackToPose(values);
    VROC_FUZZ_REQUIRE(pose.position.x() == -values[2] / 100.0);
    VROC_FUZZ_REQUIRE(pose.position.y() == -values[0] / 100.0);
    VROC_FUZZ_REQUIRE(pose.position.z() == values[1] / 100.0);
    VROC_FUZZ_REQUIRE(pose.orientation.coeffs().allFinite());
    VROC_FUZZ_REQUIRE(std::abs(pose.orientation.norm() - 1) <= 1e-12);
    const Eigen::Matrix3d difference = pose.orientation.toRotationMatrix() - expectedRotation(values[3], values[4], values[5]);
    VROC_FUZZ_REQUIRE(difference.cwiseAbs().maxCoeff() <= 1e-9);

    // What UdpDevice::pose writes (sensor 0, tracked), checked as the host checks it.
    VrocPoseSample sample{};
    sample.struct_type = VROC_STRUCT_POSE_SAMPLE;
    sample.struct_version = 1;
    sample.struct_size = sizeof sample;
    writePose(sample, 0, 0, pose.position, pose.orientation, kPoseValidTracked);
    VROC_FUZZ_REQUIRE(vroc::plugins::validatePoseSample(sample, 0, 1).empty());
    return 0;
}
