// SPDX-License-Identifier: MIT
#include "spacemouse_script.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "analog_fly.h"
#include "options.h"

namespace vroc::plugins::spacemouse_sim {
using namespace plugin_sdk;

std::vector<MouseSegment> parseMouseScript(const std::string& text) {
    std::string normalised = text;
    for (char& c : normalised)
        if (c == '/') c = '\n';
    std::istringstream lines(normalised);
    std::string line;
    std::vector<MouseSegment> segments;
    while (std::getline(lines, line)) {
        if (const size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        std::vector<std::string> fields;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ':');) fields.push_back(cell);
        const std::string where = "spacemouse-sim: script segment " + std::to_string(segments.size() + 1) + " '" + line + "': ";
        if (fields.size() != 7 && fields.size() != 8) throw OptionError(where + "expected DURATION:tx:ty:tz:rx:ry:rz[:BUTTONS]");
        double values[7];
        for (int i = 0; i < 7; ++i) {
            char* end = nullptr;
            values[i] = std::strtod(fields[i].c_str(), &end);
            if (fields[i].empty() || *end != '\0' || !std::isfinite(values[i])) throw OptionError(where + "field " + std::to_string(i + 1) + " is not a number");
        }
        MouseSegment segment;
        segment.duration = values[0];
        if (segment.duration <= 0) throw OptionError(where + "duration must be > 0");
        for (int i = 0; i < 6; ++i) {
            if (std::fabs(values[i + 1]) > 1.0) throw OptionError(where + "axis deflections must be in [-1, 1]");
            segment.axes[i] = values[i + 1];
        }
        if (fields.size() == 8) {
            char* end = nullptr;
            segment.buttons = std::strtoull(fields[7].c_str(), &end, 0);
            if (fields[7].empty() || *end != '\0') throw OptionError(where + "buttons must be an integer bitmask");
        }
        segments.push_back(segment);
    }
    return segments;
}

MouseScript::MouseScript(std::vector<MouseSegment> segments, const Eigen::Vector3d& start, double max_speed,
                         double max_rate)
    : segments_(std::move(segments)), max_speed_(max_speed), max_rate_(max_rate) {
    MouseState state{start, Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    double time = 0;
    for (const MouseSegment& segment : segments_) {
        starts_.push_back(state);
        start_times_.push_back(time);
        state = advance(state, segment, segment.duration);
        time += segment.duration;
    }
    state.linear_velocity.setZero();
    state.angular_velocity.setZero();
    state.axes = {};
    state.buttons = 0;
    starts_.push_back(state);
    start_times_.push_back(time);
}

MouseState MouseScript::advance(const MouseState& from, const MouseSegment& s, double dt) const {
    const AnalogFly fly{max_speed_, max_rate_};
    MouseState out;
    out.position = from.position;
    out.orientation = from.orientation;
    fly.advance(out.position, out.orientation, s.axes, dt);
    out.linear_velocity = fly.linearVelocity(s.axes);
    out.angular_velocity = fly.angularVelocity(out.orientation, s.axes);  // body rate constant: world rate turns with q
    out.axes = s.axes;
    out.buttons = s.buttons;
    return out;
}

MouseState MouseScript::at(double t) const {
    if (segments_.empty() || t >= start_times_.back()) return starts_.back();
    if (t < 0) {
        MouseState rest = starts_.front();
        rest.linear_velocity.setZero();
        rest.angular_velocity.setZero();
        rest.axes = {};
        rest.buttons = 0;
        return rest;
    }
    size_t i = 0;
    while (i + 1 < segments_.size() && start_times_[i + 1] <= t) ++i;
    return advance(starts_[i], segments_[i], t - start_times_[i]);
}

}  // namespace vroc::plugins::spacemouse_sim
