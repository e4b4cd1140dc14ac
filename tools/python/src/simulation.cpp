// SPDX-License-Identifier: MIT
#include "simulation.h"

#include <chrono>
#include <cmath>

#include "vroc/core/backend_registry.h"
#include "vroc/core/body_states.h"
#include "vroc/core/errors.h"
#include "vroc/core/frame_loop.h"
#include "vroc/core/state_hash.h"

namespace vroc::python {
namespace {

double steadySeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

std::string fullSettingKey(const std::string& backend, const std::string& key) {
    return key.find('.') == std::string::npos ? backend + "." + key : key;
}

Simulation::Simulation(std::shared_ptr<const Scene> scene, const std::string& backend,
                       const std::vector<std::pair<std::string, std::string>>& settings, double frame_dt)
    : scene_(std::move(scene)), info_(&BackendRegistry::global().require(backend)) {
    std::vector<std::pair<std::string, std::string>> overrides;
    for (const auto& [key, value] : settings) overrides.emplace_back(fullSettingKey(backend, key), value);
    settings_ = resolveSettings(info_->settings, overrides);
    frame_dt_ = frame_dt > 0 ? frame_dt : scene_->frame_dt;
    if (!std::isfinite(frame_dt_) || frame_dt_ <= 0) throw InputError("dt: expected a positive number of seconds");
    backend_ = info_->create(*scene_, settings_);
}

void Simulation::step(std::int64_t frames) {
    if (frames < 0) throw InputError("step: frames must be >= 0, got " + std::to_string(frames));
    FrameHooks hooks;
    hooks.after_frame = [this](std::int64_t, double wall_s, std::vector<CollisionEvent>& events) {
        step_wall_s_.push_back(wall_s);
        events_.insert(events_.end(), events.begin(), events.end());
        ++frames_;
        return true;
    };
    const double start = steadySeconds();
    stepFrames(*backend_, frames, frame_dt_, hooks);
    last_span_ = {start, steadySeconds()};
}

std::int64_t Simulation::run(double seconds) {
    const std::int64_t n = frameCount(seconds, frame_dt_);
    step(n);
    return n;
}

void Simulation::checkBody(int body, const char* what) const {
    if (body < 0 || body >= bodyCount())
        throw InputError(std::string(what) + ": body index " + std::to_string(body) + " out of range [0, " +
                         std::to_string(bodyCount()) + ")");
}

void Simulation::setStates(std::span<const BodyState> states) {
    if (states.size() != scene_->bodies.size())
        throw InputError("set_state: expected " + std::to_string(scene_->bodies.size()) + " bodies, got " +
                         std::to_string(states.size()));
    // Every real body first, so that a refused state changes nothing.
    for (std::size_t i = 0; i < states.size(); ++i)
        if (scene_->bodies[i].isStatic() && !sameStateBits(states[i], backend_->bodyState(static_cast<int>(i))))
            throw InputError("set_state: body '" + scene_->bodies[i].name +
                             "' is real (static): its row must equal its current state");
    setBodyStates(*backend_, *scene_, states);
    inputs_.push_back({frames_, std::vector<BodyState>(states.begin(), states.end()), -1, Vec3::Zero(), Vec3::Zero()});
}

void Simulation::restore(const Snapshot& snapshot) {
    backend_ = info_->create(*scene_, settings_);
    frames_ = 0;
    inputs_.clear();
    std::size_t next = 0;
    while (true) {
        while (next < snapshot.inputs.size() && snapshot.inputs[next].frame == frames_) {
            const Snapshot::Input& in = snapshot.inputs[next++];
            if (in.states.empty()) applyImpulse(in.body, in.impulse, in.point);
            else setStates(in.states);
        }
        if (frames_ == snapshot.frames) break;
        step(1);
    }
    events_.clear();
    step_wall_s_.clear();
}

void Simulation::applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) {
    checkBody(body, "apply_impulse");
    if (!impulse.allFinite() || !world_point.allFinite()) throw InputError("apply_impulse: impulse and point must be finite");
    backend_->applyImpulse(body, impulse, world_point);
    inputs_.push_back({frames_, {}, body, impulse, world_point});
}

std::vector<CollisionEvent> Simulation::takeEvents() {
    std::vector<CollisionEvent> out;
    out.swap(events_);
    return out;
}

std::string Simulation::stateHash() const { return hashToHex(vroc::stateHash(*backend_)); }

}  // namespace vroc::python
