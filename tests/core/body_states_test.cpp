// SPDX-License-Identifier: MIT
// setBodyStates: a body already in the given state (bit for bit) is left alone, every other
// non-real body goes through Backend::setBodyState, real bodies never do.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "vroc/core/body_states.h"

namespace vroc {
namespace {

// Keeps states as given and counts the setter's calls per body.
class RecordingBackend final : public Backend {
public:
    explicit RecordingBackend(const Scene& scene) : calls(scene.bodies.size(), 0) {
        for (const Body& b : scene.bodies) states.push_back({b.pose, b.linear_velocity, b.angular_velocity});
    }
    void stepFrame(double) override {}
    double time() const override { return 0; }
    int bodyCount() const override { return static_cast<int>(states.size()); }
    BodyState bodyState(int i) const override { return states[static_cast<std::size_t>(i)]; }
    void setBodyState(int i, const BodyState& s) override {
        ++calls[static_cast<std::size_t>(i)];
        states[static_cast<std::size_t>(i)] = s;
    }
    void applyImpulse(int, const Vec3&, const Vec3&) override {}
    std::vector<CollisionEvent> takeEvents() override { return {}; }
    WarningCounts warnings() const override { return {}; }
    Statistics statistics() const override { return {}; }

    std::vector<BodyState> states;
    std::vector<int> calls;
};

TEST(BodyStates, OnlyBodiesWhoseBitsChangeGoThroughTheSetter) {
    Scene scene;
    Body floor;
    floor.name = "floor";
    floor.role = BodyRole::Real;
    floor.shape = Shape::box(Vec3(1, 1, 1));
    scene.bodies.push_back(floor);
    for (int i = 0; i < 3; ++i) {
        Body b;
        b.name = "b" + std::to_string(i);
        b.shape = Shape::sphere(0.1);
        b.pose.position = Vec3(i, 0, 1);
        scene.bodies.push_back(b);
    }
    RecordingBackend backend(scene);
    std::vector<BodyState> target = backend.states;
    target[0].pose.position.z() = 5;           // a real body: never set
    target[2].linear_velocity.x() = 1e-300;    // changed
    target[3].angular_velocity.z() = -0.0;     // 0.0 -> -0.0: other bits, so set
    setBodyStates(backend, scene, target);
    EXPECT_EQ(backend.calls, (std::vector<int>{0, 0, 1, 1}));
    EXPECT_TRUE(sameStateBits(backend.states[3], target[3]));
    EXPECT_TRUE(std::signbit(backend.states[3].angular_velocity.z()));
    EXPECT_FALSE(sameStateBits(backend.states[0], target[0]));
    setBodyStates(backend, scene, backend.states);   // the current states: nothing is set
    EXPECT_EQ(backend.calls, (std::vector<int>{0, 0, 1, 1}));
}

}  // namespace
}  // namespace vroc
