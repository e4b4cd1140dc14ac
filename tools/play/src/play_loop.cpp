// SPDX-License-Identifier: MIT
#include "vroc/play/play_loop.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "vroc/audio/sound_recorder.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/errors.h"
#include "vroc/core/scene_loader.h"
#include "vroc/hmd/latency_pipeline.h"
#include "vroc/hmd/registration_study.h"
#include "vroc/play/device_source.h"
#include "vroc/play/scripted_head.h"
#include "vroc/plugin/plugin_host.h"
#include "vroc/render/stereo_renderer.h"
#include "vroc/render/video_writer.h"

namespace vroc::play {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void addShapePoints(const Shape& shape, const Pose& pose, std::vector<Vec3>& out) {
    switch (shape.kind) {
        case Shape::Kind::Sphere: out.push_back(pose.position); break;
        case Shape::Kind::Box:
            for (const Vec3& v : ConvexPolyhedron::box(shape.half_extents).vertices) out.push_back(pose.apply(v));
            break;
        case Shape::Kind::Hull:
            for (const Vec3& v : shape.hull->vertices) out.push_back(pose.apply(v));
            break;
        case Shape::Kind::Compound:
            for (const ShapePart& part : shape.parts) addShapePoints(part.shape, pose * part.pose, out);
            break;
    }
}

/// The real model's vertices (world): the points whose registration is measured.
std::vector<Vec3> realPoints(const Scene& scene) {
    std::vector<Vec3> points;
    for (const Body& body : scene.bodies)
        if (body.isStatic()) addShapePoints(body.shape, body.pose, points);
    return points;
}

/// The points the true left eye sees (all of them if it sees none).
std::vector<Vec3> visiblePoints(const hmd::StereoRig& rig, const Pose& head, const std::vector<Vec3>& points,
                                int width, int height) {
    std::vector<Vec3> seen;
    const Pose eye = rig.eyePose(head, hmd::Eye::Left);
    for (const Vec3& p : points)
        if (rig.project(eye, p, width, height)) seen.push_back(p);
    return seen.empty() ? points : seen;
}

ErrorSummary summarise(const hmd::ErrorStatistics& s) {
    constexpr double deg = 180.0 / 3.14159265358979323846;
    return {s.mean() * deg, s.rms() * deg, s.percentile(95) * deg, s.max() * deg};
}

/// Keeps one frame's reading of a device for the report.
void trace(std::vector<DeviceFrame>& out, int frame, const DeviceReading& r) {
    out.push_back({frame, r.valid, r.sample_time_ns, r.sequence, r.pose});
}

std::string frameName(int i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", i);
    return name;
}

}  // namespace

PlayReport runPlay(const PlayOptions& options) {
    if (options.frames < 1) throw InputError("--frames: expected at least 1");
    if (options.eye_width < 16 || options.eye_height < 16) throw InputError("--width/--height: expected at least 16 pixels");
    const Scene scene = loadScene(options.scene_path);
    const BackendInfo& info = BackendRegistry::global().require(options.backend);
    std::unique_ptr<Backend> backend = info.create(scene, resolveSettings(info.settings, options.backend_settings));

    PlayReport report;
    report.hmd = hmd::resolveHmdSettings(options.hmd_overrides);
    report.hmd.aspect = static_cast<double>(options.eye_width) / options.eye_height;
    report.scene_name = scene.name;
    report.backend = options.backend;
    report.device = options.device_spec.empty() ? "none" : options.device_spec;
    report.head = options.head_spec.empty() ? "scripted" : options.head_spec;
    report.frame_dt = scene.frame_dt;
    report.eye_width = options.eye_width;
    report.eye_height = options.eye_height;
    for (const Body& b : scene.bodies) report.body_names.push_back(b.name);

    // Devices: plugins through the loader, or the scripted head.
    plugins::HostOptions host_options;
    host_options.search_dirs = options.plugin_dirs;
    plugins::PluginHost host(host_options);
    std::unique_ptr<PluginDevice> hand, head_device;
    if (!options.device_spec.empty()) hand = std::make_unique<PluginDevice>(host, options.device_spec);
    if (!options.head_spec.empty()) head_device = std::make_unique<PluginDevice>(host, options.head_spec);
    TrackedDriver tracked(scene, host, options.track, /*use_scene_devices=*/true, options.grab.velocity_window,
                          options.grab.velocity_degree);
    report.hand_accepts_force = hand && hand->acceptsForce();
    const ScriptedHead scripted = ScriptedHead::forScene(scene);
    const hmd::HeadMeasurement measure = [&](double t) {
        if (!head_device) return scripted.at(t);
        const DeviceReading r = head_device->read(t);
        return r.valid ? headFromSensor(r.pose) : scripted.base;
    };

    const hmd::StereoRig rig(report.hmd);
    // One pipeline per predictor: the selected one draws, all three are measured.
    const hmd::PredictorKind kinds[] = {hmd::PredictorKind::None, hmd::PredictorKind::ConstantVelocity,
                                        hmd::PredictorKind::Kalman};
    std::vector<hmd::LatencyPipeline> pipelines;
    std::vector<hmd::ErrorStatistics> errors(3);
    for (auto kind : kinds) pipelines.emplace_back(report.hmd.latency, kind);
    const int drawn_index = static_cast<int>(report.hmd.predictor);
    const std::vector<Vec3> points = realPoints(scene);
    report.registration_points = static_cast<int>(points.size());

    render::RenderSettings render_settings;
    render_settings.eye_width = options.eye_width;
    render_settings.eye_height = options.eye_height;
    render::StereoRenderer renderer(scene, rig, render_settings);
    report.gl_renderer = renderer.glRenderer();

    GrabController grab(scene, options.grab);
    const bool writing = !options.out_dir.empty();
    std::optional<render::VideoWriter> video;
    if (writing) {
        std::filesystem::create_directories(options.out_dir);
        if (options.mp4) {
            const std::string path = options.out_dir + "/play.mp4";
            video.emplace(path, renderer.width(), renderer.height(), 1.0 / scene.frame_dt);
            report.outputs.push_back(path);
        }
    }

    // --sound: the impacts of the frames below (nothing else in the loop takes the backend's events).
    std::optional<audio::SoundRecorder> sound;
    if (!options.sound_path.empty())
        sound.emplace(scene, scene.frame_dt, options.frames * scene.frame_dt, options.sound_path, options.sound);

    // Real time: simulation time t is host time host_zero + t; every device is read at that time.
    // Otherwise host_zero = 0 and the simulation clock drives the devices.
    const std::int64_t host_zero = options.realtime ? host.nowNs() : 0;
    for (PluginDevice* device : {hand.get(), head_device.get()})
        if (device) device->setHostZero(host_zero);
    tracked.setHostZero(host_zero);
    std::optional<FramePacer> pacer;
    if (options.realtime) pacer.emplace(scene.frame_dt, host_zero);
    std::map<std::string, std::vector<double>> latencies;          // [ms] by device
    std::vector<std::pair<std::string, std::int64_t>> frame_samples;   // this frame's sample times

    std::map<std::string, double> total_ms;
    const Clock::time_point wall_start = Clock::now();
    std::vector<Pose> body_poses(scene.bodies.size());
    for (int i = 0; i < options.frames; ++i) {
        const double t = i * scene.frame_dt;
        auto start = Clock::now();
        frame_samples.clear();
        if (hand) {
            const DeviceReading r = hand->read(t);
            trace(report.hand_trace, i, r);
            if (r.valid) {
                frame_samples.emplace_back("hand", r.sample_time_ns);
                HandInput in;
                in.t = t;
                in.dt = scene.frame_dt;
                in.pose = r.pose;
                in.button = ((r.buttons >> options.grab.button) & 1u) != 0;
                // A live device's samples come at its own rate: fit its velocity at their times.
                if (options.realtime) in.sample_time = static_cast<double>(r.sample_time_ns - host_zero) * 1e-9;
                if (r.has_velocity) {
                    in.device_linear = r.linear_velocity;
                    in.device_angular = r.angular_velocity;
                }
                grab.update(in, *backend);
                const HandWrench& wrench = grab.handWrench();
                if (wrench.active && report.hand_accepts_force) hand->sendForce(t, wrench.force, wrench.torque);
            }
        }
        if (head_device) {
            const DeviceReading r = head_device->read(t);
            trace(report.head_trace, i, r);
            if (r.valid) frame_samples.emplace_back("head", r.sample_time_ns);
        }
        tracked.update(t, *backend);
        for (const TrackedDriver::Driven& d : tracked.driven())
            if (d.last.valid) frame_samples.emplace_back("track:" + scene.bodies[d.body].name, d.last.sample_time_ns);
        total_ms["device"] += msSince(start);

        start = Clock::now();
        backend->stepFrame(scene.frame_dt);
        if (sound) sound->addEvents(backend->takeEvents());
        total_ms["physics"] += msSince(start);
        if (options.on_frame) options.on_frame(i, *backend);

        start = Clock::now();
        const double display_time = backend->time();   // the frame shows the state at this time
        const Pose true_head = measure(display_time);
        const std::vector<Vec3> seen = visiblePoints(rig, true_head, points, options.eye_width, options.eye_height);
        // In real time the chain's latency is real (measured below), and a live tracker cannot be
        // read in the past, so the modelled pipeline would compare the newest sample with itself:
        // the newest head pose is drawn and no modelled registration error is reported.
        Pose drawn_head = true_head;
        for (int k = 0; k < 3 && !options.realtime; ++k) {
            const Pose drawn = pipelines[k].poseToDraw(display_time, measure);
            errors[k].add(hmd::frameRegistrationError(rig, true_head, drawn, seen));
            if (k == drawn_index) drawn_head = drawn;
        }
        for (int b = 0; b < backend->bodyCount(); ++b) body_poses[b] = backend->bodyState(b).pose;
        total_ms["head"] += msSince(start);

        start = Clock::now();
        renderer.render({rig.eyePose(drawn_head, hmd::Eye::Left), rig.eyePose(drawn_head, hmd::Eye::Right)}, body_poses);
        total_ms["render"] += msSince(start);

        if (writing) {
            start = Clock::now();
            const render::Image image = renderer.image();
            total_ms["readback"] += msSince(start);
            start = Clock::now();
            if (options.write_frames) render::writePng(options.out_dir + "/" + frameName(i), image);
            if (video) video->addFrame(image);
            total_ms["write"] += msSince(start);
        }
        if (pacer) {   // frame done: measure the latencies, then wait for the deadline
            const std::int64_t done = host.nowNs();
            for (const auto& [device, sample_ns] : frame_samples)
                latencies[device].push_back(static_cast<double>(done - sample_ns) * 1e-6);
            pacer->finishFrame(i, done);
        }
    }
    if (video) video->finish();
    if (sound) {
        const audio::SoundSummary summary = sound->finish(backend->time());
        report.sound = summary.describe();
        report.outputs.push_back(summary.wav.string());
        report.outputs.push_back(summary.events_csv.string());
    }
    const double wall_ms = msSince(wall_start);

    const double n = options.frames;
    report.frames = options.frames;
    for (const auto& [stage, ms] : total_ms) report.stage_ms[stage] = ms / n;
    auto rate = [&](double ms) { return ms > 0 ? 1000.0 * n / ms : 0.0; };
    report.rates_fps["simulation"] = rate(total_ms["physics"]);
    report.rates_fps["render"] = rate(total_ms["render"]);
    report.rates_fps["loop"] = rate(total_ms["device"] + total_ms["physics"] + total_ms["head"] + total_ms["render"]);
    report.rates_fps["loop_with_output"] = rate(wall_ms);
    if (!options.realtime)
        for (int k = 0; k < 3; ++k) report.registration[hmd::predictorName(kinds[k])] = summarise(errors[k]);
    report.throws = grab.throws();
    report.grabs = grab.grabs();
    report.warnings = backend->warnings();
    if (hand) {
        report.forces_sent = static_cast<std::int64_t>(hand->forcesSent());
        report.forces_rejected = static_cast<std::int64_t>(hand->forcesRejected());
    }
    report.realtime = options.realtime;
    if (pacer) {
        report.frames_missed = pacer->missed();
        report.worst_lateness_ms = pacer->worstLateness();
    }
    for (auto& [device, ms] : latencies) report.latency_ms[device] = summariseLatencies(std::move(ms));
    for (const TrackedDriver::Driven& d : tracked.driven())
        report.tracked.push_back({scene.bodies[d.body].name, d.device, d.sensor, d.frames_set, d.frames_without_sample,
                                  d.velocities_estimated});
    if (writing && options.write_frames)
        report.outputs.push_back(options.out_dir + "/frame_00000.png .. " + frameName(options.frames - 1));
    return report;
}

}  // namespace vroc::play
