// SPDX-License-Identifier: MIT
// The reader of trajectory.csv and events.csv (core/recording/trajectory_reader.h) against what the
// writers write: every number back exactly, quoted names, and cut files as InputErrors naming the line.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "test_scenes.h"
#include "vroc/core/errors.h"
#include "vroc/core/recording/event_writer.h"
#include "vroc/core/recording/trajectory_reader.h"
#include "vroc/core/recording/trajectory_writer.h"
#include "vroc/core/scene_loader.h"

namespace vroc::recording {
namespace {

namespace fs = std::filesystem;

Scene quotedScene() {  // the ball named ba,l"l: written quoted, read back unquoted
    std::string text = test::kTwoBodyScene;
    text.replace(text.find("\"ball\", \"role\""), 6, "\"ba,l\\\"l\"");
    return loadSceneFromString(text, "quoted.json");
}

TEST(TrajectoryReader, ReadsBackWhatTheWriterWroteExactly) {
    const Scene scene = quotedScene();
    StringSink sink;
    TrajectoryWriter writer(sink, scene);
    std::vector<BodyState> states(scene.bodies.size());
    for (std::size_t i = 0; i < states.size(); ++i) states[i].pose = scene.bodies[i].pose;
    writer.writeFrame(0.0, states);
    states[1].pose.position.z() = 0.1 + 0.2;  // not a short decimal: must round-trip exactly
    writer.writeFrame(0.01, states);
    writer.flush();
    const fs::path file = test::writeFile(test::freshTempDir("reader-trajectory") / "trajectory.csv", sink.text);
    const RecordedTrajectory t = readTrajectory(file, scene, 2);
    ASSERT_EQ(t.frames(), 2u);
    EXPECT_EQ(t.bodies, (std::vector<int>{1, 2}));
    EXPECT_EQ(t.times[1], 0.01);
    EXPECT_EQ(t.poses[1][0].position.z(), 0.1 + 0.2);
    // The box's file orientation [0, 0, 0.6, 0.8] is [x, y, z, w]: w = 0.8.
    EXPECT_DOUBLE_EQ(t.poses[0][1].orientation.w(), 0.8);
    EXPECT_DOUBLE_EQ(t.poses[0][1].orientation.z(), 0.6);
    EXPECT_THROW(readTrajectory(file, scene, 3), InputError);  // fewer frames than expected

    std::ofstream(file, std::ios::trunc) << sink.text.substr(0, sink.text.size() - 1);  // last line end missing
    try {
        readTrajectory(file, scene);
        FAIL() << "a cut file must not read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("trajectory.csv:5:"), std::string::npos) << e.what();
    }
}

TEST(EventReader, ReadsQuotedNamesBackToSceneIndices) {
    const Scene scene = quotedScene();
    StringSink sink;
    EventWriter writer(sink, scene);
    const std::vector<CollisionEvent> events = {{0.25, 0, 1, Vec3(1, 2, 3), Vec3(0, 0, 1), 0.5}};
    writer.write(events);
    writer.flush();
    const fs::path file = test::writeFile(test::freshTempDir("reader-events") / "events.csv", sink.text);
    const std::vector<CollisionEvent> back = readEvents(file, scene);
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(back[0].body_a, 0);
    EXPECT_EQ(back[0].body_b, 1);
    EXPECT_EQ(back[0].time, 0.25);
    EXPECT_EQ(back[0].point, Vec3(1, 2, 3));
    EXPECT_EQ(back[0].impulse, 0.5);
}

}  // namespace
}  // namespace vroc::recording
