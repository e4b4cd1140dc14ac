// SPDX-License-Identifier: MIT
// The latency pipeline: for the frame shown at display time t, the newest head measurement that
// can have reached the image was taken at t - total latency (on the tracker's sample grid). The
// pose used to draw is that delayed measurement, or a prediction from it to time t.
#pragma once

#include <functional>
#include <memory>

#include "vroc/core/math.h"
#include "vroc/hmd/head_predictor.h"
#include "vroc/hmd/hmd_settings.h"

namespace vroc::hmd {

/// The head frame -> world pose measured at time t [s] (a device plugin, a script).
using HeadMeasurement = std::function<Pose(double t)>;

class LatencyPipeline {
public:
    LatencyPipeline(const LatencySettings& latency, PredictorKind predictor, const KalmanTuning& tuning = {});

    /// [s] time of the newest measurement usable for the frame displayed at `display_time`.
    double measurementTime(double display_time) const;
    /// The pose to draw the frame shown at `display_time` (non-decreasing between calls): feeds
    /// the predictor every tracker sample up to measurementTime(display_time), then predicts.
    Pose poseToDraw(double display_time, const HeadMeasurement& measure);
    const LatencySettings& latency() const { return latency_; }

private:
    LatencySettings latency_;
    PredictorKind kind_;
    std::unique_ptr<HeadPredictor> predictor_;
    long long next_index_ = 0;        // grid index of next_sample_ (exact times: index / rate)
    bool started_ = false;
};

}  // namespace vroc::hmd
