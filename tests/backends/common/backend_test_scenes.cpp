// SPDX-License-Identifier: MIT
#include "backend_test_scenes.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "vroc/core/backend_registry.h"

namespace vroc::test {

TrackedStrike trackedStrike(double e, double speed, double gap) {
    TrackedStrike s;
    s.scene = emptyScene(e, 0.0);
    s.scene.name = "tracked_strike";
    s.scene.gravity = Vec3::Zero();
    s.ball = addBall(s.scene, "ball", 0.1, 1.0, Vec3::Zero());
    s.plate_start = Vec3(-0.1 - gap - 0.05, 0, 0);
    s.plate = addTracked(s.scene, "plate", Shape::box(Vec3(0.05, 0.5, 0.5)), at(s.plate_start), 0, Vec3(speed, 0, 0));
    return s;
}

TrackedStrike staticStrike(double e, double speed, double gap) {
    TrackedStrike s = trackedStrike(e, speed, gap);
    s.scene.name = "static_strike";
    Body& plate = s.scene.bodies[static_cast<std::size_t>(s.plate)];
    plate.role = BodyRole::Real;
    plate.linear_velocity.setZero();
    s.scene.bodies[static_cast<std::size_t>(s.ball)].linear_velocity = Vec3(-speed, 0, 0);
    return s;
}

std::vector<LiftSample> trackedLift(const BackendFactory& make, double speed, double dt, int frames,
                                    const Overrides& overrides) {
    Scene scene = emptyScene(0.2, 0.6);
    scene.name = "tracked_lift";
    const int platform =
        addTracked(scene, "platform", Shape::box(Vec3(0.5, 0.5, 0.05)), at(Vec3(0, 0, -0.05)), 0, Vec3(0, 0, speed));
    const int box = addBox(scene, "box", Vec3(0.1, 0.1, 0.1), 2.0, Vec3(0, 0, 0.1005));
    auto backend = make(scene, overrides);
    std::vector<LiftSample> out;
    for (int f = 0; f < frames; ++f) {
        backend->stepFrame(dt);
        const BodyState b = backend->bodyState(box);
        out.push_back({b.pose.position.z() - 0.1 - (backend->bodyState(platform).pose.position.z() + 0.05),
                       b.linear_velocity.z()});
    }
    return out;
}

StrikeRun runStrike(Backend& backend, const TrackedStrike& strike, double plate_speed, double dt, int frames) {
    const auto gap = [&] {
        return backend.bodyState(strike.ball).pose.position.x() - 0.1 -
               (backend.bodyState(strike.plate).pose.position.x() + 0.05);
    };
    const Vec3 v(plate_speed, 0, 0);
    const Vec3 ball0 = backend.bodyState(strike.ball).linear_velocity;
    StrikeRun r;
    bool moved = false;
    for (int f = 0; f < frames; ++f) {
        const double before = gap();
        backend.stepFrame(dt);
        r.events += static_cast<int>(backend.takeEvents().size());
        if (!moved && backend.bodyState(strike.ball).linear_velocity != ball0) {
            moved = true;
            r.contact_gap = before;
        }
        const BodyState p = backend.bodyState(strike.plate);
        r.plate_error = std::max(r.plate_error, (p.pose.position - (strike.plate_start + v * backend.time())).norm());
        r.plate_velocity_error = std::max(r.plate_velocity_error, (p.linear_velocity - v).norm());
    }
    r.ball_velocity = backend.bodyState(strike.ball).linear_velocity;
    r.ball_angular_velocity = backend.bodyState(strike.ball).angular_velocity;
    return r;
}

std::unique_ptr<Backend> makeRegistered(const std::string& name, const Scene& scene, const Overrides& overrides) {
    const BackendInfo& info = BackendRegistry::global().require(name);
    return info.create(scene, resolveSettings(info.settings, overrides));
}

std::vector<std::filesystem::path> shippedSceneFiles() {
    namespace fs = std::filesystem;
    std::vector<fs::path> files;
    const fs::path dir = fs::path(VROC_SOURCE_DIR) / "scenes";
    if (fs::exists(dir))
        for (const auto& entry : fs::directory_iterator(dir))
            if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

Scene fallingHullCubes() {
    Scene pile = emptyScene(0.5, 0.5);
    addFloor(pile);
    for (int i = 0; i < 64; ++i)
        addHullCuboid(pile, std::string("c").append(std::to_string(i)), Vec3(0.05, 0.05, 0.05), 1.0,
                      Pose{Vec3(0.25 * (i % 4), 0.25 * ((i / 4) % 4), 0.2 + 0.25 * (i / 16)),
                           Quat(Eigen::AngleAxisd(0.1 * i, Vec3(1, 1, 1).normalized()))});
    return pile;
}

double TimedRun::totalSeconds() const {
    double s = 0;
    for (double u : frame_us) s += u * 1e-6;
    return s;
}

double TimedRun::quantileUs(double q) const {
    std::vector<double> sorted = frame_us;
    std::sort(sorted.begin(), sorted.end());
    return sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1))];
}

TimedRun timedRun(Backend& backend, const Scene& scene, int frames) {
    TimedRun r;
    for (int f = 0; f < frames; ++f) {
        const auto t0 = std::chrono::steady_clock::now();
        backend.stepFrame(scene.frame_dt);
        r.frame_us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
        r.events += backend.takeEvents().size();
    }
    return r;
}

DropResult ballDrop(const BackendFactory& make, double e, const Overrides& overrides, int count, ApexReading reading) {
    Scene scene = emptyScene(e, 0.5);
    addFloor(scene);
    const int ball = addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 1.1));
    auto backend = make(scene, overrides);
    DropResult r;
    BodyState prev = backend->bodyState(ball);
    for (int f = 0; f < 60 * 20 && static_cast<int>(r.apexes.size()) < count; ++f) {
        backend->stepFrame(scene.frame_dt);
        r.events += static_cast<int>(backend->takeEvents().size());
        const BodyState now = backend->bodyState(ball);
        if (prev.linear_velocity.z() > 0 && now.linear_velocity.z() <= 0) {
            const double vz = prev.linear_velocity.z();
            r.apexes.push_back(reading == ApexReading::FrameMax
                                   ? std::max(prev.pose.position.z(), now.pose.position.z()) - 0.1
                                   : prev.pose.position.z() - 0.1 + vz * vz / (2 * 9.81));
        }
        prev = now;
    }
    return r;
}

void printApexRow(double e, const char* label, const DropResult& r) {
    std::printf("| %.1f | %s | %d |", e, label, r.events);
    for (std::size_t n = 0; n < 5; ++n) {
        const double ideal = std::pow(e, 2.0 * static_cast<double>(n + 1));
        if (n < r.apexes.size()) std::printf(" %.4f (%+.1f %%) |", r.apexes[n], 100 * (r.apexes[n] / ideal - 1));
        else std::printf(" - |");
    }
    std::printf("\n");
}

}  // namespace vroc::test
