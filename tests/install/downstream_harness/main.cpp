// SPDX-License-Identifier: MIT
// vroc_downstream_harness: a program built outside VROC by a C++-only project against the installed
// package's harness and native backend (find_package(vroc COMPONENTS harness backend_native)). It
// registers its own backend ("ballistic", ballistic_backend.h) next to the installed native
// backend, loads a shipped scene (share/vroc/scenes/ball_drop.json) and checks, against closed
// forms the scene file states:
//   1. runBackend: the ballistic ball's height is z0 - g t^2 / 2 at every frame;
//   2. the harness's comparison (representableBackends, runBackend with twin runs, divergence,
//      significantDivergence): native and ballistic agree until the ball reaches the floor at
//      t = sqrt(2 h / g) and differ significantly from the first frame after it (native bounces,
//      the toy falls through); the harness reports the toy as "approximated" for the scene.
// Exit 0 when every check holds, 1 otherwise (each failure printed), 2 for bad input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "ballistic_backend.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/errors.h"
#include "vroc/core/scene_loader.h"
#include "vroc/harness/metrics/divergence.h"
#include "vroc/harness/runs/backend_selection.h"
#include "vroc/harness/runs/run_trace.h"
#include "vroc/native/native_backend.h"

namespace {

int failures = 0;

void check(bool ok, const std::string& what) {
    std::printf("%s  %s\n", ok ? "ok  " : "FAIL", what.c_str());
    if (!ok) ++failures;
}

std::string fmt(const char* format, double a, double b = 0, double c = 0) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, format, a, b, c);
    return buffer;
}

int run(const std::string& scene_path) {
    vroc::native::registerBackend();
    toy::registerBallisticBackend();
    const vroc::Scene scene = vroc::loadScene(scene_path);

    // The scene as its description states it: a sphere dropped from rest above a box floor.
    const int ball = scene.findBody("ball");
    const int floor = scene.findBody("floor");
    if (ball < 0 || floor < 0) throw vroc::InputError(scene_path + ": expected bodies 'ball' and 'floor'");
    const vroc::Body& b = scene.bodies[static_cast<std::size_t>(ball)];
    const vroc::Body& f = scene.bodies[static_cast<std::size_t>(floor)];
    const double g = -scene.gravity.z();
    const double z0 = b.pose.position.z();
    const double floor_top = f.pose.position.z() + f.shape.half_extents.z();
    const double t_hit = std::sqrt(2.0 * (z0 - b.shape.radius - floor_top) / g);   // [s] first contact
    const double dt = scene.frame_dt;
    std::printf("scene %s: ball from z = %.3f m, floor top z = %.3f m, contact at t = %.4f s\n",
                scene.name.c_str(), z0, floor_top, t_hit);

    // 1. The toy backend through the harness runner, against the closed form.
    const vroc::BackendInfo& ballistic = vroc::BackendRegistry::global().require("ballistic");
    vroc::harness::RunOptions run_options;
    run_options.frame_dt = dt;
    run_options.frames = vroc::frameCount(1.0, dt);
    const vroc::harness::RunTrace trace = vroc::harness::runBackend(ballistic, scene, vroc::Settings{}, run_options);
    double max_error = 0;
    for (std::size_t i = 0; i < trace.frames(); ++i) {
        const double t = trace.times[i];
        const double z = trace.states[i][static_cast<std::size_t>(ball)].pose.position.z();
        max_error = std::max(max_error, std::fabs(z - (z0 - 0.5 * g * t * t)));
    }
    check(trace.frames() == static_cast<std::size_t>(run_options.frames + 1) && trace.finite,
          fmt("runBackend(ballistic): %.0f frames, all finite", static_cast<double>(trace.frames())));
    check(max_error < 1e-12, fmt("ballistic free fall: max |z - (z0 - g t^2/2)| = %.1e m (< 1e-12)", max_error));

    // 2. The harness's comparison of it with the installed native backend (the reference, listed
    //    first): capabilities, main runs, twin runs (every virtual body moved by 1 nm along x: each
    //    backend's own noise floor) and the divergence counted only above both floors.
    namespace h = vroc::harness;
    vroc::harness::Json support;
    const auto backends = h::representableBackends(scene, h::selectBackends("native,ballistic", {}), "downstream",
                                                   /*progress=*/false, support);
    check(backends.size() == 2, fmt("harness: %.0f of 2 backends can represent the scene",
                                    static_cast<double>(backends.size())));
    const std::string toy_support = support.value("ballistic", std::string());
    check(toy_support.rfind("approximated: restitution", 0) == 0,
          "harness: ballistic on this scene is \"" + toy_support + "\"");
    if (backends.size() != 2) return 1;
    h::RunOptions twin_options = run_options;
    twin_options.initial_states = h::initialStates(scene);
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        if (scene.bodies[i].isDynamic()) (*twin_options.initial_states)[i].pose.position.x() += 1e-9;
    h::RunTrace main_runs[2], twin_runs[2];
    for (int k = 0; k < 2; ++k) {
        main_runs[k] = h::runBackend(*backends[k].info, scene, backends[k].settings, run_options);
        twin_runs[k] = h::runBackend(*backends[k].info, scene, backends[k].settings, twin_options);
    }
    const h::Divergence d = h::divergence(scene, main_runs[0], main_runs[1]);
    const h::Divergence floor_native = h::divergence(scene, main_runs[0], twin_runs[0]);
    const h::Divergence floor_toy = h::divergence(scene, main_runs[1], twin_runs[1]);
    const h::Significance significance =
        h::significantDivergence(d.distance, floor_native.distance, floor_toy.distance, d.t);
    double before = 0, after = 0;
    for (std::size_t i = 0; i < d.t.size(); ++i) {
        if (d.t[i] < t_hit) before = std::max(before, d.distance[i]);
        else after = std::max(after, d.distance[i]);
    }
    check(before < 1e-9, fmt("native and ballistic agree before contact: max distance %.1e m (< 1e-9)", before));
    check(after > 1.0, fmt("after contact native bounces and ballistic falls through: %.2f m apart (> 1)", after));
    const auto& first = significance.first_time;
    check(first && *first > t_hit && *first <= t_hit + dt + 1e-12,
          fmt("significant divergence from t = %.4f s, the first frame after contact (%.4f s, frame %.4f s)",
              first ? *first : NAN, t_hit, dt));
    std::printf("%s\n",
                failures == 0 ? "downstream (harness): all checks passed" : "downstream (harness): checks FAILED");
    return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string scene = argc > 1 ? argv[1] : std::string(VROC_SCENES_DIR) + "/ball_drop.json";
    try {
        return run(scene);
    } catch (const vroc::InputError& e) {
        std::fprintf(stderr, "vroc_downstream_harness: error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vroc_downstream_harness: failure: %s\n", e.what());
        return 3;
    }
}
