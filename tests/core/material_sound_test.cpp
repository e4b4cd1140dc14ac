// SPDX-License-Identifier: MIT
// A material's optional `sound` object (docs/scene-format.md#materials): read as written, the
// stated defaults without it, and one test per bad input, each an InputError of one line naming
// the file and the field and saying what was expected (as scene_bad_input_test.cpp does).
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "vroc/core/errors.h"
#include "vroc/core/scene_loader.h"

namespace vroc {
namespace {

const std::string kOrigin = "sound.json";

std::string sceneWithRubber(const std::string& rubber) {
    return R"({"format": "vroc-scene/1", "name": "t", "materials": {"rubber": )" + rubber +
           R"(, "steel": {"restitution": 0.9, "friction": 0.4}}, "bodies": [
             {"name": "floor", "role": "real", "material": "steel", "position": [0, 0, 0],
              "shape": {"box": {"half_extents": [1, 1, 1]}}}]})";
}

std::string withSound(const std::string& sound) {
    return sceneWithRubber(R"({"restitution": 0.5, "friction": 0.8, "sound": )" + sound + "}");
}

void expectError(const std::string& text, std::initializer_list<std::string> parts) {
    try {
        loadSceneFromString(text, kOrigin);
        ADD_FAILURE() << "expected InputError for:\n" << text;
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(kOrigin, 0), 0u) << "message does not start with the file: " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "message is not one line: " << message;
        for (const std::string& p : parts)
            EXPECT_NE(message.find(p), std::string::npos) << "'" << p << "' not in: " << message;
    }
}

TEST(MaterialSound, ReadAsWrittenAndStatedDefaultsWithout) {
    const Scene scene =
        loadSceneFromString(withSound(R"({"modes_hz": [220, 19999.5], "decay_per_s": [3, 0.5], "gains": [1, 0]})"),
                            kOrigin);
    const MaterialSound& rubber = scene.materials[0].sound;
    EXPECT_EQ(rubber.modes_hz, (std::vector<double>{220, 19999.5}));
    EXPECT_EQ(rubber.decay_per_s, (std::vector<double>{3, 0.5}));
    EXPECT_EQ(rubber.gains, (std::vector<double>{1, 0}));
    // Without `sound`: the free-free bar's first four modes on 600 Hz (ratios 1 : 2.756 : 5.404 : 8.933).
    const MaterialSound& steel = scene.materials[1].sound;
    ASSERT_EQ(steel.modes_hz.size(), 4u);
    const double ratios[] = {1.0, 2.756, 5.404, 8.933};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(steel.modes_hz[i], 600 * ratios[i], 1e-9) << i;
    EXPECT_EQ(steel.decay_per_s, (std::vector<double>{40, 60, 90, 130}));
    EXPECT_EQ(steel.gains, (std::vector<double>{1, 0.5, 0.25, 0.125}));
}

TEST(MaterialSound, NotAnObjectOrUnknownKey) {
    expectError(withSound("[1, 2]"), {"materials.rubber.sound", "expected an object"});
    expectError(withSound(R"({"modes_hz": [100], "decay_per_s": [1], "gains": [1], "damping": 1})"),
                {"materials.rubber.sound", "unknown key `damping`", "decay_per_s"});
}

TEST(MaterialSound, MissingField) {
    expectError(withSound(R"({"modes_hz": [100], "gains": [1]})"),
                {"materials.rubber.sound", "missing required key `decay_per_s`"});
}

TEST(MaterialSound, NotAnArrayOrEmptyOrTooMany) {
    expectError(withSound(R"({"modes_hz": 100, "decay_per_s": [1], "gains": [1]})"),
                {"materials.rubber.sound.modes_hz", "expected an array"});
    expectError(withSound(R"({"modes_hz": [], "decay_per_s": [], "gains": []})"),
                {"materials.rubber.sound.modes_hz", "1 to 32", "got 0 entries"});
    std::string many = "[";
    for (int i = 0; i < 33; ++i) many += (i ? ", " : "") + std::to_string(100 + i);
    many += "]";
    expectError(withSound(R"({"modes_hz": )" + many + R"(, "decay_per_s": [1], "gains": [1]})"),
                {"materials.rubber.sound.modes_hz", "1 to 32", "got 33 entries"});
}

TEST(MaterialSound, UnequalLengths) {
    expectError(withSound(R"({"modes_hz": [100, 200, 300], "decay_per_s": [1, 2], "gains": [1, 1, 1]})"),
                {"materials.rubber.sound.decay_per_s", "expected 3 entries (one per entry of modes_hz), got 2"});
    expectError(withSound(R"({"modes_hz": [100, 200], "decay_per_s": [1, 2], "gains": [1, 1, 1]})"),
                {"materials.rubber.sound.gains", "expected 2 entries", "got 3"});
}

TEST(MaterialSound, FrequencyNotPositiveOrAboveNyquist) {
    expectError(withSound(R"({"modes_hz": [100, 0], "decay_per_s": [1, 1], "gains": [1, 1]})"),
                {"materials.rubber.sound.modes_hz[1]", "expected a number > 0 [Hz], got 0"});
    expectError(withSound(R"({"modes_hz": [-5], "decay_per_s": [1], "gains": [1]})"),
                {"materials.rubber.sound.modes_hz[0]", "> 0 [Hz]", "-5"});
    expectError(withSound(R"({"modes_hz": [20001], "decay_per_s": [1], "gains": [1]})"),
                {"materials.rubber.sound.modes_hz[0]", "(0, 20000] Hz", "Nyquist", "44.1 kHz", "20001"});
    expectError(withSound(R"({"modes_hz": ["440"], "decay_per_s": [1], "gains": [1]})"),
                {"materials.rubber.sound.modes_hz[0]", "expected a number", "the string \"440\""});
}

TEST(MaterialSound, DecayOutOfRange) {
    expectError(withSound(R"({"modes_hz": [100], "decay_per_s": [0], "gains": [1]})"),
                {"materials.rubber.sound.decay_per_s[0]", "[0.5, 100000] [1/s]", "got 0"});
    expectError(withSound(R"({"modes_hz": [100], "decay_per_s": [1e6], "gains": [1]})"),
                {"materials.rubber.sound.decay_per_s[0]", "[0.5, 100000]"});
}

TEST(MaterialSound, NegativeGain) {
    expectError(withSound(R"({"modes_hz": [100, 200], "decay_per_s": [1, 1], "gains": [1, -0.5]})"),
                {"materials.rubber.sound.gains[1]", "expected a number >= 0", "-0.5"});
}

}  // namespace
}  // namespace vroc
