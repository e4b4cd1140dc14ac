// SPDX-License-Identifier: MIT
// Fuzz target: vroc::loadSceneFromString on arbitrary bytes (docs/fuzzing.md).
// Contract: the loader either throws InputError whose message is one line starting with the
// origin, or returns a scene that is whole and inside the accepted ranges (docs/scene-format.md):
// finite constants in range, at least one material and body, unique non-empty body names, valid
// material indices, unit quaternions, shapes and mass properties as shape_contract.h states, real
// bodies static, tracked bodies massless, and a SHA-256 of the text. Any other exception, or a
// scene breaking one of these, traps. The origin sits in scenes/, so "meshes/chair.obj" loads the
// shipped mesh as a real scene's would.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <set>
#include <string>

#include "fuzz_require.h"
#include "shape_contract.h"
#include "vroc/core/errors.h"
#include "vroc/core/scene_loader.h"

namespace {

const std::string kOrigin = VROC_SOURCE_DIR "/scenes/fuzz_input.json";

bool within(const vroc::Vec3& v, double max_abs) { return v.allFinite() && v.cwiseAbs().maxCoeff() <= max_abs; }

void checkScene(const vroc::Scene& scene) {
    using namespace vroc;
    VROC_FUZZ_REQUIRE(within(scene.gravity, 1e4));
    VROC_FUZZ_REQUIRE(scene.frame_dt >= 1e-6 && scene.frame_dt <= 10.0);
    VROC_FUZZ_REQUIRE(scene.collision_distance >= 1e-9 && scene.collision_distance <= 1.0);
    VROC_FUZZ_REQUIRE(scene.source_sha256.size() == 64 &&
                      scene.source_sha256.find_first_not_of("0123456789abcdef") == std::string::npos);
    VROC_FUZZ_REQUIRE(!scene.materials.empty());
    std::set<std::string> material_names;
    for (const Material& m : scene.materials) {
        VROC_FUZZ_REQUIRE(!m.name.empty() && material_names.insert(m.name).second);
        VROC_FUZZ_REQUIRE(m.restitution >= 0 && m.restitution <= 1);
        VROC_FUZZ_REQUIRE(std::isfinite(m.friction) && m.friction >= 0);
        const MaterialSound& s = m.sound;
        VROC_FUZZ_REQUIRE(!s.modes_hz.empty() && s.modes_hz.size() <= MaterialSound::kMaxSoundModes);
        VROC_FUZZ_REQUIRE(s.decay_per_s.size() == s.modes_hz.size() && s.gains.size() == s.modes_hz.size());
        for (std::size_t i = 0; i < s.modes_hz.size(); ++i) {
            VROC_FUZZ_REQUIRE(s.modes_hz[i] > 0 && s.modes_hz[i] <= MaterialSound::kMaxModeHz);
            VROC_FUZZ_REQUIRE(s.decay_per_s[i] >= MaterialSound::kMinDecayPerS &&
                              s.decay_per_s[i] <= MaterialSound::kMaxDecayPerS);
            VROC_FUZZ_REQUIRE(std::isfinite(s.gains[i]) && s.gains[i] >= 0);
        }
    }
    VROC_FUZZ_REQUIRE(!scene.bodies.empty());
    std::set<std::string> body_names;
    for (const Body& b : scene.bodies) {
        VROC_FUZZ_REQUIRE(!b.name.empty() && body_names.insert(b.name).second);
        VROC_FUZZ_REQUIRE(b.material >= 0 && b.material < static_cast<int>(scene.materials.size()));
        fuzz::checkPose(b.pose, 1e6);
        fuzz::checkShape(b.shape);
        VROC_FUZZ_REQUIRE(within(b.linear_velocity, 1e4) && within(b.angular_velocity, 1e5));
        VROC_FUZZ_REQUIRE(b.tracking.sensor >= 0 && b.tracking.sensor <= 1000000);
        switch (b.role) {
        case BodyRole::Real:
            VROC_FUZZ_REQUIRE(b.linear_velocity.isZero(0) && b.angular_velocity.isZero(0));
            [[fallthrough]];
        case BodyRole::Tracked:
            VROC_FUZZ_REQUIRE(b.mass_properties.mass == 0 && b.mass_properties.inertia.isZero(0));
            VROC_FUZZ_REQUIRE(b.role == BodyRole::Tracked || b.tracking.device.empty());
            break;
        case BodyRole::Virtual:
            VROC_FUZZ_REQUIRE(b.tracking.device.empty());
            VROC_FUZZ_REQUIRE(b.mass_properties.mass >= 1e-9 && b.mass_properties.mass <= 1e9);
            fuzz::checkMassProperties(b.mass_properties, b.mass_properties.mass);
            break;
        }
    }
    VROC_FUZZ_REQUIRE(scene.findBody(scene.bodies.front().name) == 0);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    vroc::Scene scene;
    try {
        scene = vroc::loadSceneFromString(text, kOrigin);
    } catch (const vroc::InputError& e) {
        const std::string message = e.what();
        VROC_FUZZ_REQUIRE(message.rfind(kOrigin, 0) == 0);              // names the file
        VROC_FUZZ_REQUIRE(message.size() > kOrigin.size() + 2);         // and says something
        VROC_FUZZ_REQUIRE(message.find('\n') == std::string::npos);     // on one line
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vroc fuzz: loadSceneFromString threw a non-InputError: %s\n", e.what());
        VROC_FUZZ_REQUIRE(!"only InputError may leave the scene loader");
    }
    checkScene(scene);
    return 0;
}
