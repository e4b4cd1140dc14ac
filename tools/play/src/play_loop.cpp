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

/// One `vroc play` run: everything a frame touches, built once, and one method per stage of the
/// frame (devices -> physics -> head -> render and write -> pacing), timed stage by stage.
class PlaySession {
public:
    explicit PlaySession(const PlayOptions& options);
    void runFrame(int i);
    PlayReport finish();

private:
    void readDevices(int i, double t);
    void stepPhysics(int i);
    Pose headToDraw();
    void renderAndWrite(int i, const Pose& head);
    void pace(int i);
    void openDevices();
    void openOutputs();

    /// Adds the wall time since `start` to stage `stage` [ms].
    void timed(const char* stage, Clock::time_point start) { total_ms_[stage] += msSince(start); }

    const PlayOptions& options_;
    const Scene scene_;
    std::unique_ptr<Backend> backend_;
    PlayReport report_;
    plugins::PluginHost host_;
    std::unique_ptr<PluginDevice> hand_, head_device_;
    std::optional<TrackedDriver> tracked_;
    ScriptedHead scripted_;
    hmd::HeadMeasurement measure_;
    hmd::StereoRig rig_;
    // One pipeline per predictor: the selected one draws, all three are measured.
    std::vector<hmd::PredictorKind> kinds_{hmd::PredictorKind::None, hmd::PredictorKind::ConstantVelocity,
                                           hmd::PredictorKind::Kalman};
    std::vector<hmd::LatencyPipeline> pipelines_;
    std::vector<hmd::ErrorStatistics> errors_;
    std::vector<Vec3> points_;
    std::optional<render::StereoRenderer> renderer_;
    GrabController grab_;
    std::optional<render::VideoWriter> video_;
    std::optional<audio::SoundRecorder> sound_;
    // Real time: simulation time t is host time host_zero_ + t; every device is read at that time.
    // Otherwise host_zero_ = 0 and the simulation clock drives the devices.
    std::int64_t host_zero_ = 0;
    std::optional<FramePacer> pacer_;
    std::map<std::string, std::vector<double>> latencies_;          // [ms] by device
    std::vector<std::pair<std::string, std::int64_t>> frame_samples_;   // this frame's sample times
    std::map<std::string, double> total_ms_;
    Clock::time_point wall_start_;
    std::vector<Pose> body_poses_;
};

plugins::HostOptions hostOptions(const PlayOptions& options) {
    plugins::HostOptions h;
    h.search_dirs = options.plugin_dirs;
    return h;
}

Scene loadChecked(const PlayOptions& options) {
    if (options.frames < 1) throw InputError("--frames: expected at least 1");
    if (options.eye_width < 16 || options.eye_height < 16) throw InputError("--width/--height: expected at least 16 pixels");
    return loadScene(options.scene_path);
}

hmd::HmdSettings hmdSettings(const PlayOptions& options) {
    hmd::HmdSettings s = hmd::resolveHmdSettings(options.hmd_overrides);
    s.aspect = static_cast<double>(options.eye_width) / options.eye_height;
    return s;
}

PlaySession::PlaySession(const PlayOptions& options)
    : options_(options),
      scene_(loadChecked(options)),
      host_(hostOptions(options)),
      scripted_(ScriptedHead::forScene(scene_)),
      rig_(hmdSettings(options)),
      grab_(scene_, options.grab),
      body_poses_(scene_.bodies.size()) {
    const BackendInfo& info = BackendRegistry::global().require(options.backend);
    backend_ = info.create(scene_, resolveSettings(info.settings, options.backend_settings));

    report_.hmd = hmdSettings(options);
    report_.scene_name = scene_.name;
    report_.backend = options.backend;
    report_.device = options.device_spec.empty() ? "none" : options.device_spec;
    report_.head = options.head_spec.empty() ? "scripted" : options.head_spec;
    report_.frame_dt = scene_.frame_dt;
    report_.eye_width = options.eye_width;
    report_.eye_height = options.eye_height;
    report_.realtime = options.realtime;
    for (const Body& b : scene_.bodies) report_.body_names.push_back(b.name);

    openDevices();
    for (hmd::PredictorKind kind : kinds_) pipelines_.emplace_back(report_.hmd.latency, kind);
    errors_.resize(kinds_.size());
    points_ = realPoints(scene_);
    report_.registration_points = static_cast<int>(points_.size());

    render::RenderSettings render_settings;
    render_settings.eye_width = options.eye_width;
    render_settings.eye_height = options.eye_height;
    renderer_.emplace(scene_, rig_, render_settings);
    report_.gl_renderer = renderer_->glRenderer();
    openOutputs();

    host_zero_ = options.realtime ? host_.nowNs() : 0;
    for (PluginDevice* device : {hand_.get(), head_device_.get()})
        if (device) device->setHostZero(host_zero_);
    tracked_->setHostZero(host_zero_);
    if (options.realtime) pacer_.emplace(scene_.frame_dt, host_zero_);
    wall_start_ = Clock::now();
}

void PlaySession::openDevices() {
    if (!options_.device_spec.empty()) hand_ = std::make_unique<PluginDevice>(host_, options_.device_spec);
    if (!options_.head_spec.empty()) head_device_ = std::make_unique<PluginDevice>(host_, options_.head_spec);
    tracked_.emplace(scene_, host_, options_.track, /*use_scene_devices=*/true, options_.grab.velocity_window,
                     options_.grab.velocity_degree);
    report_.hand_accepts_force = hand_ && hand_->acceptsForce();
    measure_ = [this](double t) {
        if (!head_device_) return scripted_.at(t);
        const DeviceReading r = head_device_->read(t);
        return r.valid ? headFromSensor(r.pose) : scripted_.base;
    };
}

void PlaySession::openOutputs() {
    if (!options_.out_dir.empty()) {
        std::filesystem::create_directories(options_.out_dir);
        if (options_.mp4) {
            const std::string path = options_.out_dir + "/play.mp4";
            video_.emplace(path, renderer_->width(), renderer_->height(), 1.0 / scene_.frame_dt);
            report_.outputs.push_back(path);
        }
    }
    // --sound: the impacts of the frames (nothing else in the loop takes the backend's events).
    if (!options_.sound_path.empty())
        sound_.emplace(scene_, scene_.frame_dt, options_.frames * scene_.frame_dt, options_.sound_path, options_.sound);
}

void PlaySession::runFrame(int i) {
    readDevices(i, i * scene_.frame_dt);
    stepPhysics(i);
    const Pose head = headToDraw();
    renderAndWrite(i, head);
    pace(i);
}

void PlaySession::readDevices(int i, double t) {
    const auto start = Clock::now();
    frame_samples_.clear();
    if (hand_) {
        const DeviceReading r = hand_->read(t);
        trace(report_.hand_trace, i, r);
        if (r.valid) {
            frame_samples_.emplace_back("hand", r.sample_time_ns);
            HandInput in;
            in.t = t;
            in.dt = scene_.frame_dt;
            in.pose = r.pose;
            in.button = ((r.buttons >> options_.grab.button) & 1u) != 0;
            // A live device's samples come at its own rate: fit its velocity at their times.
            if (options_.realtime) in.sample_time = static_cast<double>(r.sample_time_ns - host_zero_) * 1e-9;
            if (r.has_velocity) {
                in.device_linear = r.linear_velocity;
                in.device_angular = r.angular_velocity;
            }
            grab_.update(in, *backend_);
            const HandWrench& wrench = grab_.handWrench();
            if (wrench.active && report_.hand_accepts_force) hand_->sendForce(t, wrench.force, wrench.torque);
        }
    }
    if (head_device_) {
        const DeviceReading r = head_device_->read(t);
        trace(report_.head_trace, i, r);
        if (r.valid) frame_samples_.emplace_back("head", r.sample_time_ns);
    }
    tracked_->update(t, *backend_);
    for (const TrackedDriver::Driven& d : tracked_->driven())
        if (d.last.valid) frame_samples_.emplace_back("track:" + scene_.bodies[d.body].name, d.last.sample_time_ns);
    timed("device", start);
}

void PlaySession::stepPhysics(int i) {
    const auto start = Clock::now();
    backend_->stepFrame(scene_.frame_dt);
    if (sound_) sound_->addEvents(backend_->takeEvents());
    timed("physics", start);
    if (options_.on_frame) options_.on_frame(i, *backend_);
}

Pose PlaySession::headToDraw() {
    const auto start = Clock::now();
    const double display_time = backend_->time();   // the frame shows the state at this time
    const Pose true_head = measure_(display_time);
    // In real time the chain's latency is real (measured in pace), and a live tracker cannot be
    // read in the past, so the modelled pipeline would compare the newest sample with itself:
    // the newest head pose is drawn and no modelled registration error is reported.
    Pose drawn_head = true_head;
    if (!options_.realtime) {
        const std::vector<Vec3> seen = visiblePoints(rig_, true_head, points_, options_.eye_width, options_.eye_height);
        const auto drawn_index = static_cast<std::size_t>(report_.hmd.predictor);
        for (std::size_t k = 0; k < pipelines_.size(); ++k) {
            const Pose drawn = pipelines_[k].poseToDraw(display_time, measure_);
            errors_[k].add(hmd::frameRegistrationError(rig_, true_head, drawn, seen));
            if (k == drawn_index) drawn_head = drawn;
        }
    }
    for (int b = 0; b < backend_->bodyCount(); ++b) body_poses_[static_cast<std::size_t>(b)] = backend_->bodyState(b).pose;
    timed("head", start);
    return drawn_head;
}

void PlaySession::renderAndWrite(int i, const Pose& head) {
    auto start = Clock::now();
    renderer_->render({rig_.eyePose(head, hmd::Eye::Left), rig_.eyePose(head, hmd::Eye::Right)}, body_poses_);
    timed("render", start);
    if (options_.out_dir.empty()) return;
    start = Clock::now();
    const render::Image image = renderer_->image();
    timed("readback", start);
    start = Clock::now();
    if (options_.write_frames) render::writePng(options_.out_dir + "/" + frameName(i), image);
    if (video_) video_->addFrame(image);
    timed("write", start);
}

void PlaySession::pace(int i) {
    if (!pacer_) return;
    // Frame done: measure the latencies, then wait for the deadline.
    const std::int64_t done = host_.nowNs();
    for (const auto& [device, sample_ns] : frame_samples_)
        latencies_[device].push_back(static_cast<double>(done - sample_ns) * 1e-6);
    pacer_->finishFrame(i, done);
}

PlayReport PlaySession::finish() {
    if (video_) video_->finish();
    if (sound_) {
        const audio::SoundSummary summary = sound_->finish(backend_->time());
        report_.sound = summary.describe();
        report_.outputs.push_back(summary.wav.string());
        report_.outputs.push_back(summary.events_csv.string());
    }
    const double wall_ms = msSince(wall_start_);
    const double n = options_.frames;
    report_.frames = options_.frames;
    for (const auto& [stage, ms] : total_ms_) report_.stage_ms[stage] = ms / n;
    auto rate = [&](double ms) { return ms > 0 ? 1000.0 * n / ms : 0.0; };
    report_.rates_fps["simulation"] = rate(total_ms_["physics"]);
    report_.rates_fps["render"] = rate(total_ms_["render"]);
    report_.rates_fps["loop"] = rate(total_ms_["device"] + total_ms_["physics"] + total_ms_["head"] + total_ms_["render"]);
    report_.rates_fps["loop_with_output"] = rate(wall_ms);
    if (!options_.realtime)
        for (std::size_t k = 0; k < kinds_.size(); ++k) report_.registration[hmd::predictorName(kinds_[k])] = summarise(errors_[k]);
    report_.throws = grab_.throws();
    report_.grabs = grab_.grabs();
    report_.warnings = backend_->warnings();
    if (hand_) {
        report_.forces_sent = static_cast<std::int64_t>(hand_->forcesSent());
        report_.forces_rejected = static_cast<std::int64_t>(hand_->forcesRejected());
    }
    if (pacer_) {
        report_.frames_missed = pacer_->missed();
        report_.worst_lateness_ms = pacer_->worstLateness();
    }
    for (auto& [device, ms] : latencies_) report_.latency_ms[device] = summariseLatencies(std::move(ms));
    for (const TrackedDriver::Driven& d : tracked_->driven())
        report_.tracked.push_back({scene_.bodies[d.body].name, d.device, d.sensor, d.frames_set, d.frames_without_sample,
                                   d.velocities_estimated});
    if (!options_.out_dir.empty() && options_.write_frames)
        report_.outputs.push_back(options_.out_dir + "/frame_00000.png .. " + frameName(options_.frames - 1));
    return std::move(report_);
}

}  // namespace

PlayReport runPlay(const PlayOptions& options) {
    PlaySession session(options);
    for (int i = 0; i < options.frames; ++i) session.runFrame(i);
    return session.finish();
}

}  // namespace vroc::play
