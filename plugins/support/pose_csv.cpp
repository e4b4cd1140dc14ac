// SPDX-License-Identifier: MIT
#include "pose_csv.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace vroc::plugin_sdk {

std::string formatPoseCsvRow(const PoseCsvRow& r) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, "%lld,%u,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%llu",
                  static_cast<long long>(r.time_ns), r.sensor, r.position[0], r.position[1], r.position[2],
                  r.orientation[0], r.orientation[1], r.orientation[2], r.orientation[3],
                  static_cast<unsigned long long>(r.buttons));
    return buffer;
}

bool parsePoseCsvRow(const std::string& line, PoseCsvRow& row, std::string& error) {
    static const char* kColumns[] = {"time_ns", "sensor", "x", "y", "z", "qx", "qy", "qz", "qw", "buttons"};
    std::vector<std::string> cells;
    size_t begin = 0;
    while (true) {
        const size_t end = line.find(',', begin);
        cells.push_back(line.substr(begin, end == std::string::npos ? std::string::npos : end - begin));
        if (end == std::string::npos) break;
        begin = end + 1;
    }
    if (!cells.empty() && !cells.back().empty() && cells.back().back() == '\r') cells.back().pop_back();
    if (cells.size() != 10) {
        error = "expected 10 columns (" + std::string(kPoseCsvHeader) + "), found " + std::to_string(cells.size());
        return false;
    }
    auto parseInt = [&](int column, long long lo, long long& value) {
        char* end = nullptr;
        errno = 0;
        value = std::strtoll(cells[column].c_str(), &end, 10);
        if (cells[column].empty() || *end != '\0' || errno != 0 || value < lo) {
            error = std::string("column ") + kColumns[column] + ": expected an integer >= " + std::to_string(lo);
            return false;
        }
        return true;
    };
    long long integer = 0;
    if (!parseInt(0, INT64_MIN, integer)) return false;
    row.time_ns = integer;
    if (!parseInt(1, 0, integer)) return false;
    row.sensor = static_cast<uint32_t>(integer);
    for (int c = 2; c < 9; ++c) {
        char* end = nullptr;
        const double v = std::strtod(cells[c].c_str(), &end);
        if (cells[c].empty() || *end != '\0' || !std::isfinite(v)) {
            error = std::string("column ") + kColumns[c] + ": expected a finite number";
            return false;
        }
        if (c < 5) row.position[c - 2] = v;
        else row.orientation[c - 5] = v;
    }
    char* end = nullptr;
    errno = 0;
    row.buttons = std::strtoull(cells[9].c_str(), &end, 10);
    if (cells[9].empty() || *end != '\0' || errno != 0 || cells[9][0] == '-') {
        error = "column buttons: expected a non-negative integer bitmask";
        return false;
    }
    const double norm = std::sqrt(row.orientation[0] * row.orientation[0] + row.orientation[1] * row.orientation[1] +
                                  row.orientation[2] * row.orientation[2] + row.orientation[3] * row.orientation[3]);
    if (std::fabs(norm - 1.0) > 0.01) {
        error = "columns qx..qw: expected a unit quaternion (norm " + std::to_string(norm) + ")";
        return false;
    }
    return true;
}

}  // namespace vroc::plugin_sdk
