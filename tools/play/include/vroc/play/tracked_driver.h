// SPDX-License-Identifier: MIT
// Drives the scene's tracked bodies (BodyRole::Tracked) from device plugins: each frame, before
// Backend::stepFrame, every driven body's device is read and its pose and velocities are handed to
// the backend with Backend::setBodyState (a tracker sample: the body takes that pose now and moves
// at those velocities until the next one). Velocities are the device's when it reports them, else
// a least-squares fit over its recent samples (VelocityEstimator). Used by `vroc play` and by
// `vroc run --track`.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"
#include "vroc/play/device_source.h"
#include "vroc/play/velocity_estimator.h"

namespace vroc::plugins {
class PluginHost;
}

namespace vroc::play {

/// One `--track BODY=SPEC[#SENSOR]` option: the tracking source of a tracked body, by name.
struct TrackOverride {
    std::string body;          ///< the tracked body's name
    TrackingSource source;     ///< plugin spec and sensor (default 0)
};

/// Parses "BODY=SPEC[#SENSOR]" (the first '=' ends the body name; a trailing "#N" is the sensor).
/// Throws InputError naming the option and what was expected.
TrackOverride parseTrackOption(const std::string& text);

class TrackedDriver {
public:
    struct Driven {
        int body = -1;                 ///< scene body index
        std::string device;            ///< plugin spec
        int sensor = 0;
        std::int64_t frames_set = 0;   ///< frames whose sample was handed to the backend
        std::int64_t frames_without_sample = 0;   ///< frames the device had no valid sample (the
                                                  ///< body kept its last motion)
        std::int64_t velocities_estimated = 0;    ///< frames whose velocity came from the fit
        DeviceReading last;            ///< the newest reading
    };

    /// Opens a device for every tracked body of `scene` that has a source: the override naming it,
    /// else (when use_scene_devices) the scene's `tracking.device`. Overrides must name tracked
    /// bodies, each at most once (InputError otherwise); a device that cannot be opened throws
    /// InputError. `host` must outlive the driver.
    TrackedDriver(const Scene& scene, plugins::PluginHost& host, const std::vector<TrackOverride>& overrides,
                  bool use_scene_devices, int velocity_window = 6, int velocity_degree = 2);
    ~TrackedDriver();

    /// [ns] host time of simulation time 0 for every device (PluginDevice::setHostZero).
    void setHostZero(std::int64_t ns);
    /// Reads every device at simulation time t [s] and sets its body's state. Call before stepFrame.
    void update(double t, Backend& backend);

    bool empty() const { return driven_.empty(); }
    const std::vector<Driven>& driven() const { return driven_; }

private:
    std::int64_t host_zero_ns_ = 0;
    std::vector<Driven> driven_;
    std::vector<std::unique_ptr<PluginDevice>> devices_;
    std::vector<VelocityEstimator> estimators_;
};

}  // namespace vroc::play
