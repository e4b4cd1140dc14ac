// SPDX-License-Identifier: MIT
// Registration error (Holloway 1997): the angle, seen from the viewer's true eye, between where
// a real object point is drawn (by an image made from the drawn eye pose) and where it is.
#pragma once

#include <vector>

#include "vroc/core/math.h"

namespace vroc::hmd {

/// [rad] The display puts the point in the direction it has in the drawn eye frame; the eye sees
/// the real point in the direction it has in the true eye frame; both are eye-frame directions.
double registrationError(const Pose& true_eye, const Pose& drawn_eye, const Vec3& world_point);

/// Running statistics of per-frame errors [rad].
class ErrorStatistics {
public:
    void add(double value) { values_.push_back(value); }
    std::size_t count() const { return values_.size(); }
    double mean() const;
    double rms() const;
    double max() const;
    double percentile(double p) const;   ///< p in [0, 100], nearest rank
    const std::vector<double>& values() const { return values_; }

private:
    std::vector<double> values_;
};

}  // namespace vroc::hmd
