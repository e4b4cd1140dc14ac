// SPDX-License-Identifier: MIT
#include "pose_track.h"

#include <algorithm>

#include "pose_math.h"

namespace vroc::plugins::replay {
using namespace plugin_sdk;

namespace {

// [ns] from a to b >= a, exact: the difference of two int64 times can exceed the int64 range (a
// recording may span any times the CSV holds), never the uint64 one.
uint64_t nsFrom(int64_t a, int64_t b) { return static_cast<uint64_t>(b) - static_cast<uint64_t>(a); }

}  // namespace

TrackPose PoseTrack::at(int64_t t) const {
    const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
    if (t <= samples_.front().time_ns) {
        const TrackSample& s = samples_.front();
        return {s.position, s.orientation, zero, zero, s.buttons, 0, t == s.time_ns};
    }
    if (t >= samples_.back().time_ns) {
        const TrackSample& s = samples_.back();
        return {s.position, s.orientation, zero, zero, s.buttons, samples_.size() - 1, t == s.time_ns};
    }
    // First sample strictly after t; the one before it is at or before t.
    auto upper = std::upper_bound(samples_.begin(), samples_.end(), t,
                                  [](int64_t time, const TrackSample& s) { return time < s.time_ns; });
    const TrackSample& b = *upper;
    const TrackSample& a = *(upper - 1);
    const double span_ns = static_cast<double>(nsFrom(a.time_ns, b.time_ns));
    const double dt = span_ns * 1e-9;
    const double f = static_cast<double>(nsFrom(a.time_ns, t)) / span_ns;
    TrackPose pose;
    pose.position = a.position + f * (b.position - a.position);
    pose.orientation = a.orientation.slerp(f, b.orientation);
    pose.linear_velocity = (b.position - a.position) / dt;
    pose.angular_velocity = rotationVectorFromQuat(b.orientation * a.orientation.conjugate()) / dt;
    pose.buttons = a.buttons;
    pose.index = static_cast<uint64_t>(upper - samples_.begin() - 1);
    pose.inside = true;
    return pose;
}

}  // namespace vroc::plugins::replay
