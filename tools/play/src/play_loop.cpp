// SPDX-License-Identifier: MIT
#include "vroc/play/play_loop.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

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

    std::map<std::string, double> total_ms;
    const Clock::time_point wall_start = Clock::now();
    std::vector<Pose> body_poses(scene.bodies.size());
    for (int i = 0; i < options.frames; ++i) {
        const double t = i * scene.frame_dt;
        auto start = Clock::now();
        if (hand) {
            const DeviceReading r = hand->read(t);
            if (r.valid)
                grab.update(t, r.pose, (r.buttons >> options.grab.button) & 1u, *backend,
                            r.has_velocity ? &r.linear_velocity : nullptr, r.has_velocity ? &r.angular_velocity : nullptr);
        }
        total_ms["device"] += msSince(start);

        start = Clock::now();
        backend->stepFrame(scene.frame_dt);
        total_ms["physics"] += msSince(start);

        start = Clock::now();
        const double display_time = backend->time();   // the frame shows the state at this time
        const Pose true_head = measure(display_time);
        const std::vector<Vec3> seen = visiblePoints(rig, true_head, points, options.eye_width, options.eye_height);
        Pose drawn_head;
        for (int k = 0; k < 3; ++k) {
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
    }
    if (video) video->finish();
    const double wall_ms = msSince(wall_start);

    const double n = options.frames;
    report.frames = options.frames;
    for (const auto& [stage, ms] : total_ms) report.stage_ms[stage] = ms / n;
    auto rate = [&](double ms) { return ms > 0 ? 1000.0 * n / ms : 0.0; };
    report.rates_fps["simulation"] = rate(total_ms["physics"]);
    report.rates_fps["render"] = rate(total_ms["render"]);
    report.rates_fps["loop"] = rate(total_ms["device"] + total_ms["physics"] + total_ms["head"] + total_ms["render"]);
    report.rates_fps["loop_with_output"] = rate(wall_ms);
    for (int k = 0; k < 3; ++k) report.registration[hmd::predictorName(kinds[k])] = summarise(errors[k]);
    report.throws = grab.throws();
    report.grabs = grab.grabs();
    report.warnings = backend->warnings();
    if (writing && options.write_frames)
        report.outputs.push_back(options.out_dir + "/frame_00000.png .. " + frameName(options.frames - 1));
    return report;
}

}  // namespace vroc::play
