// SPDX-License-Identifier: MIT
#include "vroc/play/tracked_driver.h"

#include <charconv>
#include <map>

#include "vroc/core/errors.h"
#include "vroc/plugin/plugin_host.h"

namespace vroc::play {

TrackOverride parseTrackOption(const std::string& text) {
    const std::string what = "--track '" + text + "': ";
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw InputError(what + "expected BODY=PLUGIN_SPEC[#SENSOR], e.g. paddle=udp:port=4242");
    TrackOverride o;
    o.body = text.substr(0, eq);
    std::string spec = text.substr(eq + 1);
    const std::size_t hash = spec.rfind('#');
    if (hash != std::string::npos) {
        const std::string digits = spec.substr(hash + 1);
        int sensor = -1;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), sensor);
        if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() || sensor < 0)
            throw InputError(what + "expected a sensor index (a non-negative integer) after '#', got '" + digits + "'");
        o.source.sensor = sensor;
        spec.resize(hash);
    }
    if (spec.empty()) throw InputError(what + "expected a plugin spec after '='");
    o.source.device = spec;
    return o;
}

TrackedDriver::TrackedDriver(const Scene& scene, plugins::PluginHost& host, const std::vector<TrackOverride>& overrides,
                             bool use_scene_devices, int velocity_window, int velocity_degree) {
    std::map<int, TrackingSource> sources;
    if (use_scene_devices)
        for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b)
            if (scene.bodies[b].isTracked() && !scene.bodies[b].tracking.device.empty()) sources[b] = scene.bodies[b].tracking;
    std::map<int, bool> overridden;
    for (const TrackOverride& o : overrides) {
        const int b = scene.findBody(o.body);
        if (b < 0) throw InputError("--track " + o.body + "=...: the scene has no body '" + o.body + "'");
        if (!scene.bodies[b].isTracked())
            throw InputError("--track " + o.body + "=...: body '" + o.body +
                             "' is not tracked (its role must be \"tracked\" to follow a device)");
        if (overridden[b]) throw InputError("--track " + o.body + "=...: given twice for the same body");
        overridden[b] = true;
        sources[b] = o.source;
    }
    for (const auto& [body, source] : sources) {   // in body order: deterministic calls
        Driven d;
        d.body = body;
        d.device = source.device;
        d.sensor = source.sensor;
        devices_.push_back(std::make_unique<PluginDevice>(host, source.device, static_cast<std::uint32_t>(source.sensor)));
        driven_.push_back(d);
        estimators_.emplace_back(velocity_window, velocity_degree);
    }
}

TrackedDriver::~TrackedDriver() = default;

void TrackedDriver::setHostZero(std::int64_t ns) {
    host_zero_ns_ = ns;
    for (auto& device : devices_) device->setHostZero(ns);
}

void TrackedDriver::update(double t, Backend& backend) {
    for (std::size_t i = 0; i < driven_.size(); ++i) {
        Driven& d = driven_[i];
        const DeviceReading r = devices_[i]->read(t);
        d.last = r;
        if (!r.valid) {
            ++d.frames_without_sample;
            continue;
        }
        VelocityEstimator& fit = estimators_[i];
        fit.add(static_cast<double>(r.sample_time_ns - host_zero_ns_) * 1e-9, r.pose);
        BodyState s;
        s.pose = r.pose;
        if (r.has_velocity) {
            s.linear_velocity = r.linear_velocity;
            s.angular_velocity = r.angular_velocity;
        } else {
            s.linear_velocity = fit.linearVelocity();
            s.angular_velocity = fit.angularVelocity();
            ++d.velocities_estimated;
        }
        backend.setBodyState(d.body, s);
        ++d.frames_set;
    }
}

}  // namespace vroc::play
