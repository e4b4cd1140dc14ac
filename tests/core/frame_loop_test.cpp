// SPDX-License-Identifier: MIT
// stepFrames: hooks in order around each frame, events handed over once, the loop stopped on
// request; frameCount's one rounding rule at its edges.
#include <gtest/gtest.h>

#include <limits>
#include <utility>
#include <vector>

#include "vroc/core/errors.h"
#include "vroc/core/frame_loop.h"

namespace vroc {
namespace {

// Counts frames; every second frame reports one event at its end time.
class CountingBackend final : public Backend {
public:
    void stepFrame(double dt) override {
        time_ += dt;
        if (++frames_ % 2 == 0) pending_.push_back({time_, 0, 1, Vec3::Zero(), Vec3::UnitZ(), 1.0});
    }
    double time() const override { return time_; }
    int bodyCount() const override { return 0; }
    BodyState bodyState(int) const override { return {}; }
    void setBodyState(int, const BodyState&) override {}
    void applyImpulse(int, const Vec3&, const Vec3&) override {}
    std::vector<CollisionEvent> takeEvents() override { return std::exchange(pending_, {}); }
    WarningCounts warnings() const override { return {}; }
    Statistics statistics() const override { return {}; }

private:
    double time_ = 0;
    int frames_ = 0;
    std::vector<CollisionEvent> pending_;
};

TEST(StepFrames, HooksSurroundEachFrameAndEventsArriveOnce) {
    CountingBackend backend;
    std::vector<double> starts;
    std::vector<std::int64_t> numbers;
    std::vector<double> event_times;
    FrameHooks hooks;
    hooks.before_frame = [&](Backend& b, double t) {
        EXPECT_EQ(&b, &backend);
        starts.push_back(t);
    };
    hooks.after_frame = [&](std::int64_t frame, double wall, std::vector<CollisionEvent>& events) {
        EXPECT_GE(wall, 0.0);
        numbers.push_back(frame);
        for (const auto& e : events) event_times.push_back(e.time);
        return true;
    };
    EXPECT_EQ(stepFrames(backend, 4, 0.25, hooks), 4);
    EXPECT_EQ(starts, (std::vector<double>{0.0, 0.25, 0.5, 0.75}));
    EXPECT_EQ(numbers, (std::vector<std::int64_t>{1, 2, 3, 4}));
    EXPECT_EQ(event_times, (std::vector<double>{0.5, 1.0}));
    EXPECT_EQ(backend.time(), 1.0);
}

TEST(StepFrames, AfterFrameReturningFalseStopsTheLoop) {
    CountingBackend backend;
    FrameHooks hooks;
    hooks.after_frame = [](std::int64_t frame, double, std::vector<CollisionEvent>&) { return frame < 3; };
    EXPECT_EQ(stepFrames(backend, 10, 0.5, hooks), 3);
    EXPECT_EQ(backend.time(), 1.5);
    EXPECT_EQ(stepFrames(backend, 0, 0.5, {}), 0);
    EXPECT_EQ(backend.time(), 1.5);
}

TEST(FrameCount, RoundsOnlyFloatingNoiseAndCoversTheDuration) {
    EXPECT_EQ(frameCount(5.0, 1.0 / 60.0), 300);
    EXPECT_EQ(frameCount(1.0, 0.3), 4);      // 3.33 frames: up, so the frames cover the second
    EXPECT_EQ(frameCount(0.3, 0.1), 3);      // 2.9999999999999996 is floating noise
    EXPECT_EQ(frameCount(0.7, 0.1), 7);      // 6.999999999999999 likewise
    EXPECT_EQ(frameCount(1e-12, 1.0), 1);    // at least one frame
    EXPECT_EQ(frameCount(1.0 + 1e-6, 1.0), 2);
    EXPECT_THROW(frameCount(0.0, 0.1), InputError);
    EXPECT_THROW(frameCount(1.0, std::numeric_limits<double>::infinity()), InputError);
    EXPECT_THROW(frameCount(2e9, 1.0), InputError);
}

}  // namespace
}  // namespace vroc
