// SPDX-License-Identifier: MIT
// Registration error of a head motion through the latency pipeline, frame by frame, without
// rendering: the building block of the latency x speed table (docs/hmd.md) and of `vroc play`.
#pragma once

#include <vector>

#include "vroc/hmd/latency_pipeline.h"
#include "vroc/hmd/registration_error.h"
#include "vroc/hmd/stereo_rig.h"

namespace vroc::hmd {

struct StudyRun {
    double start = 0.0;          ///< [s] first display time
    double duration = 1.0;       ///< [s]
    double display_rate = 60.0;  ///< [Hz] frames shown
};

/// For every displayed frame: the drawn pose comes from `measured` through the pipeline (with
/// `predictor`); the true pose is `truth` at display time. Each frame's error is the mean over
/// `points` (world, [m]) and both eyes [rad].
ErrorStatistics studyRegistration(const HmdSettings& settings, PredictorKind predictor,
                                  const HeadMeasurement& measured, const HeadMeasurement& truth,
                                  const std::vector<Vec3>& points, const StudyRun& run);

/// Mean registration error [rad] over `points` and both eyes for one frame.
double frameRegistrationError(const StereoRig& rig, const Pose& true_head, const Pose& drawn_head,
                              const std::vector<Vec3>& points);

}  // namespace vroc::hmd
