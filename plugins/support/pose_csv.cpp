// SPDX-License-Identifier: MIT
#include "pose_csv.h"

#include <cmath>
#include <string_view>
#include <vector>

#include "vroc/core/csv.h"

namespace vroc::plugin_sdk {

std::string formatPoseCsvRow(const PoseCsvRow& r) {
    std::string out;
    csv::appendInteger(out, r.time_ns);
    out += ',';
    csv::appendInteger(out, r.sensor);
    for (double v : r.position) {
        out += ',';
        csv::appendNumber(out, v);
    }
    for (double v : r.orientation) {
        out += ',';
        csv::appendNumber(out, v);
    }
    out += ',';
    csv::appendInteger(out, r.buttons);
    return out;
}

bool parsePoseCsvRow(const std::string& line, PoseCsvRow& row, std::string& error) {
    static const char* kColumns[] = {"time_ns", "sensor", "x", "y", "z", "qx", "qy", "qz", "qw", "buttons"};
    const std::vector<std::string_view> cells = csv::splitLine(line);
    if (cells.size() != 10) {
        error = "expected 10 columns (" + std::string(kPoseCsvHeader) + "), found " + std::to_string(cells.size());
        return false;
    }
    if (!csv::parseInteger(cells[0], row.time_ns)) {
        error = "column time_ns: expected an integer";
        return false;
    }
    if (!csv::parseInteger(cells[1], row.sensor)) {
        error = "column sensor: expected an integer >= 0";
        return false;
    }
    for (int c = 2; c < 9; ++c) {
        double v = 0;
        if (!csv::parseNumber(cells[c], v) || !std::isfinite(v)) {
            error = std::string("column ") + kColumns[c] + ": expected a finite number";
            return false;
        }
        if (c < 5) row.position[c - 2] = v;
        else row.orientation[c - 5] = v;
    }
    if (!csv::parseInteger(cells[9], row.buttons)) {
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
