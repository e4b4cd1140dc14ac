// SPDX-License-Identifier: MIT
#include "vroc/hmd/registration_study.h"

#include <cmath>

namespace vroc::hmd {

double frameRegistrationError(const StereoRig& rig, const Pose& true_head, const Pose& drawn_head,
                              const std::vector<Vec3>& points) {
    if (points.empty()) return 0.0;
    double sum = 0.0;
    for (Eye eye : {Eye::Left, Eye::Right}) {
        const Pose true_eye = rig.eyePose(true_head, eye);
        const Pose drawn_eye = rig.eyePose(drawn_head, eye);
        for (const Vec3& p : points) sum += registrationError(true_eye, drawn_eye, p);
    }
    return sum / (2.0 * static_cast<double>(points.size()));
}

ErrorStatistics studyRegistration(const HmdSettings& settings, PredictorKind predictor,
                                  const HeadMeasurement& measured, const HeadMeasurement& truth,
                                  const std::vector<Vec3>& points, const StudyRun& run) {
    const StereoRig rig(settings);
    LatencyPipeline pipeline(settings.latency, predictor);
    ErrorStatistics stats;
    const long frames = std::lround(run.duration * run.display_rate);
    for (long i = 0; i < frames; ++i) {
        const double t = run.start + static_cast<double>(i) / run.display_rate;
        const Pose drawn = pipeline.poseToDraw(t, measured);
        stats.add(frameRegistrationError(rig, truth(t), drawn, points));
    }
    return stats;
}

}  // namespace vroc::hmd
