// SPDX-License-Identifier: MIT
// Linear and angular velocity of a tracked pose at the newest sample, by a least-squares
// polynomial fit over a short window of recent samples (degree 2 by default, so a steadily
// accelerating throw is not read with the half-window lag of a straight-line fit).
#pragma once

#include <deque>
#include <functional>

#include "vroc/core/math.h"

namespace vroc::play {

class VelocityEstimator {
public:
    /// `window` samples (>= degree + 1), polynomial `degree` 1 or 2.
    explicit VelocityEstimator(int window = 6, int degree = 2);

    void add(double t, const Pose& pose);   ///< times strictly increasing [s]
    void clear() { samples_.clear(); }
    bool ready() const { return static_cast<int>(samples_.size()) >= degree_ + 1; }
    /// [m/s] world, at the newest sample's time (zero until ready()).
    Vec3 linearVelocity() const;
    /// [rad/s] world: fit of the rotation vectors of q_i * q_newest^-1 (zero until ready()).
    Vec3 angularVelocity() const;

private:
    struct Sample {
        double t;
        Pose pose;
    };
    /// Slope at the newest time of the least-squares polynomial through (t_i, value(i)).
    Vec3 slope(const std::function<Vec3(const Sample&)>& value) const;

    int window_;
    int degree_;
    std::deque<Sample> samples_;
};

}  // namespace vroc::play
