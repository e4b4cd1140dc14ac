// SPDX-License-Identifier: MIT
// The recorded-pose CSV format shared by the recorder (loader library) and the replay plugin:
//   time_ns,sensor,x,y,z,qx,qy,qz,qw,buttons
// one sample per line after that header line; time on the host clock [ns], position [m] in the
// base frame, unit quaternion sensor -> base, buttons as a decimal bitmask. Numbers are written and
// read with vroc/core/csv.h: 17 significant digits (an exact round trip), whatever the locale.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace vroc::plugin_sdk {

inline constexpr const char* kPoseCsvHeader = "time_ns,sensor,x,y,z,qx,qy,qz,qw,buttons";

struct PoseCsvRow {
    int64_t time_ns = 0;
    uint32_t sensor = 0;
    std::array<double, 3> position{};              ///< [m]
    std::array<double, 4> orientation{0, 0, 0, 1}; ///< x, y, z, w
    uint64_t buttons = 0;
};

std::string formatPoseCsvRow(const PoseCsvRow& row);
/// Parses one data line; returns false with `error` set ("column qw: expected a finite number").
bool parsePoseCsvRow(const std::string& line, PoseCsvRow& row, std::string& error);

}  // namespace vroc::plugin_sdk
