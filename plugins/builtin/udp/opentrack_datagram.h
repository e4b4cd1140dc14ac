// SPDX-License-Identifier: MIT
// The opentrack "UDP over network" datagram: 48 bytes, six doubles in native byte order, no
// header, in opentrack's axis order TX, TY, TZ [cm], yaw, pitch, roll [deg]
// (opentrack tracker-udp / proto-udp sources).
//
// Mapping to VROC's base frame (z up, x forward, y left; our choice, documented in
// docs/plugin-abi.md): opentrack X is right, Y up, Z towards the viewer, so
// position = (-TZ, -TX, TY) / 100 m; orientation = Rz(yaw) * Ry(pitch) * Rx(roll) in radians
// (yaw about up, pitch about left, roll about forward).
#pragma once

#include <array>
#include <cstddef>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vroc::plugins::udp {

inline constexpr size_t kOpentrackDatagramSize = 48;

struct OpentrackPose {
    Eigen::Vector3d position;       ///< [m] VROC base frame
    Eigen::Quaterniond orientation; ///< sensor -> base
};

OpentrackPose opentrackToPose(const std::array<double, 6>& values);

/// What the receiver accepts: exactly kOpentrackDatagramSize bytes, every value finite. Returns ""
/// and fills `values`, or why the datagram is dropped (then `values` is unspecified).
std::string decodeOpentrackDatagram(const unsigned char* data, size_t size, std::array<double, 6>& values);

}  // namespace vroc::plugins::udp
