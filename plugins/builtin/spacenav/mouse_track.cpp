// SPDX-License-Identifier: MIT
#include "mouse_track.h"

#include <algorithm>

namespace vroc::plugins::spacenav {

using plugin_sdk::secondsOf;

MouseTrack::MouseTrack(const AnalogFly& fly, const Eigen::Vector3d& start, int64_t t0, size_t max_history)
    : fly_(fly), max_history_(std::max<size_t>(2, max_history)) {
    segments_.push_back({t0, start, Eigen::Quaterniond::Identity(), MouseAxes{}, 0, 0});
}

void MouseTrack::push(int64_t t, const MouseAxes& axes, uint64_t buttons) {
    const Segment& last = segments_.back();
    t = std::max(t, last.t0);
    Segment next{t, last.position, last.orientation, axes, buttons, last.sequence + 1};
    fly_.advance(next.position, next.orientation, last.axes, secondsOf(t - last.t0));
    segments_.push_back(next);
    if (segments_.size() > max_history_) segments_.pop_front();
}

void MouseTrack::setAxes(int64_t t, const MouseAxes& axes) { push(t, axes, segments_.back().buttons); }

void MouseTrack::setButton(int64_t t, int button, bool pressed) {
    const uint64_t bit = uint64_t{1} << button;
    const uint64_t buttons = pressed ? (segments_.back().buttons | bit) : (segments_.back().buttons & ~bit);
    push(t, segments_.back().axes, buttons);
}

MouseSample MouseTrack::at(int64_t t) const {
    // The newest segment starting at or before t (the oldest one if t precedes them all).
    auto it = std::upper_bound(segments_.begin(), segments_.end(), t,
                               [](int64_t time, const Segment& s) { return time < s.t0; });
    const Segment& s = it == segments_.begin() ? segments_.front() : *std::prev(it);
    MouseSample out;
    out.event_time_ns = s.t0;
    out.sequence = s.sequence;
    out.position = s.position;
    out.orientation = s.orientation;
    if (t > s.t0) fly_.advance(out.position, out.orientation, s.axes, secondsOf(t - s.t0));
    out.linear_velocity = fly_.linearVelocity(s.axes);
    out.angular_velocity = fly_.angularVelocity(out.orientation, s.axes);
    out.axes = s.axes;
    out.buttons = s.buttons;
    return out;
}

}  // namespace vroc::plugins::spacenav
