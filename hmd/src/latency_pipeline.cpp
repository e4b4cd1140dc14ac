// SPDX-License-Identifier: MIT
#include "vroc/hmd/latency_pipeline.h"

#include <cmath>

namespace vroc::hmd {

LatencyPipeline::LatencyPipeline(const LatencySettings& latency, PredictorKind predictor,
                                 const KalmanTuning& tuning)
    : latency_(latency), kind_(predictor), predictor_(makePredictor(predictor, tuning)) {}

double LatencyPipeline::measurementTime(double display_time) const {
    const double t = display_time - latency_.total();
    if (latency_.tracker_rate <= 0.0) return t;
    // Newest grid sample at or before t (a small tolerance absorbs rounding of k / rate).
    const double k = std::floor(t * latency_.tracker_rate + 1e-9);
    return k / latency_.tracker_rate;
}

Pose LatencyPipeline::poseToDraw(double display_time, const HeadMeasurement& measure) {
    const double newest = measurementTime(display_time);
    if (latency_.tracker_rate <= 0.0) {
        if (!started_) {   // two earlier samples, so the predictors have a velocity at once
            predictor_->addSample(newest - 2e-3, measure(newest - 2e-3));
            predictor_->addSample(newest - 1e-3, measure(newest - 1e-3));
            started_ = true;
        }
        predictor_->addSample(newest, measure(newest));
    } else {
        if (!started_) {
            // Start a few samples back so the predictors have a velocity from the first frame.
            next_index_ = static_cast<long long>(std::llround(newest * latency_.tracker_rate)) - 3;
            started_ = true;
        }
        for (;; ++next_index_) {
            const double t = static_cast<double>(next_index_) / latency_.tracker_rate;
            if (t > newest + 1e-12) break;
            predictor_->addSample(t, measure(t));
        }
    }
    if (kind_ == PredictorKind::None) return predictor_->predict(newest);
    return predictor_->predict(display_time);
}

}  // namespace vroc::hmd
