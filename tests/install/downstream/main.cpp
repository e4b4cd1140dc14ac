// SPDX-License-Identifier: MIT
// vroc_downstream: a program built outside VROC against the installed package by a C++-only project
// that links vroc::core alone (find_package(vroc) without components; CMakeLists.txt). It registers
// its own backend ("ballistic", ballistic_backend.h) in core's BackendRegistry, loads a shipped
// scene (share/vroc/scenes/ball_drop.json) with core's scene loader, steps the backend through the
// vroc::Backend interface and checks, against the closed form the scene file states, that the
// ball's height is z0 - g t^2 / 2 at every frame of one second.
// The harness's comparison of the same backend with native is ../downstream_harness/.
// Exit 0 when every check holds, 1 otherwise (each failure printed), 2 for bad input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include "ballistic_backend.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/errors.h"
#include "vroc/core/frame_loop.h"
#include "vroc/core/scene_loader.h"
#include "vroc/core/settings.h"

namespace {

int failures = 0;

void check(bool ok, const std::string& what) {
    std::printf("%s  %s\n", ok ? "ok  " : "FAIL", what.c_str());
    if (!ok) ++failures;
}

std::string fmt(const char* format, double a, double b = 0) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, format, a, b);
    return buffer;
}

int run(const std::string& scene_path) {
    toy::registerBallisticBackend();
    const vroc::Scene scene = vroc::loadScene(scene_path);
    const int ball = scene.findBody("ball");
    if (ball < 0) throw vroc::InputError(scene_path + ": expected a body 'ball'");
    const vroc::Body& b = scene.bodies[static_cast<std::size_t>(ball)];
    const double g = -scene.gravity.z();
    const double z0 = b.pose.position.z();
    const double dt = scene.frame_dt;
    std::printf("scene %s: ball from z = %.3f m, g = %.2f m/s^2, frame %.4f s\n", scene.name.c_str(), z0, g, dt);

    const vroc::BackendInfo& info = vroc::BackendRegistry::global().require("ballistic");
    const std::unique_ptr<vroc::Backend> backend = info.create(scene, vroc::Settings{});
    const std::int64_t frames = vroc::frameCount(1.0, dt);
    double max_error = 0;
    bool finite = true;
    for (std::int64_t i = 0; i < frames; ++i) {
        backend->stepFrame(dt);
        const double t = backend->time();
        const double z = backend->bodyState(ball).pose.position.z();
        finite = finite && std::isfinite(z);
        max_error = std::max(max_error, std::fabs(z - (z0 - 0.5 * g * t * t)));
    }
    check(finite && std::fabs(backend->time() - static_cast<double>(frames) * dt) < 1e-9,
          fmt("ballistic through vroc::Backend: %.0f frames to t = %.4f s, all finite", static_cast<double>(frames),
              backend->time()));
    check(max_error < 1e-12, fmt("ballistic free fall: max |z - (z0 - g t^2/2)| = %.1e m (< 1e-12)", max_error));
    std::printf("%s\n", failures == 0 ? "downstream (core): all checks passed" : "downstream (core): checks FAILED");
    return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string scene = argc > 1 ? argv[1] : std::string(VROC_SCENES_DIR) + "/ball_drop.json";
    try {
        return run(scene);
    } catch (const vroc::InputError& e) {
        std::fprintf(stderr, "vroc_downstream: error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vroc_downstream: failure: %s\n", e.what());
        return 3;
    }
}
