// SPDX-License-Identifier: MIT
// Fuzz target: the host's checks of what crosses the plugin ABI (plugins/loader/src/
// plugin_validation.h): validatePoseSample on any bytes taken as a VrocPoseSample, and
// validateForceCommand on any bytes taken as a VrocForceCommand (docs/fuzzing.md).
// Input: requested sensor (4 bytes), the device's sensor count (4 bytes), a mode byte (bit 0:
// write a correct struct header over the bytes, so most inputs reach the value checks; bit 1:
// force command instead of pose sample), then the struct's bytes (missing ones are zero).
// Contract: a sample is accepted exactly when its header is right, it is for the sensor asked, that
// sensor exists, and each part its flags declare valid is finite, the quaternion's norm within 0.01
// of 1 (decided here in long double; inputs within 1e-12 of that threshold are not judged); an
// accepted sample is left unchanged except for the quaternion, which becomes a unit quaternion
// (within 1e-12) along the same direction. A force command is accepted exactly when its sensor is
// below max(sensor count, 1) and its force and torque are finite.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "fuzz_require.h"
#include "plugin_validation.h"

namespace {

bool allFinite(const double* v, int n) {
    for (int i = 0; i < n; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

void checkPose(const uint8_t* bytes, size_t size, uint32_t sensor, uint32_t sensor_count, bool fix_header) {
    VrocPoseSample sample{};
    std::memcpy(&sample, bytes, std::min(size, sizeof sample));
    if (fix_header) {
        sample.struct_type = VROC_STRUCT_POSE_SAMPLE;
        sample.struct_size = sizeof sample;
    }
    const VrocPoseSample before = sample;
    const std::string why = vroc::plugins::validatePoseSample(sample, sensor, sensor_count);

    bool expected = sample.struct_type == VROC_STRUCT_POSE_SAMPLE && sample.struct_size == sizeof(VrocPoseSample) &&
                    sample.sensor == sensor && sensor < sensor_count;
    const uint32_t flags = before.flags;
    if (flags & VROC_POSE_POSITION_VALID) expected = expected && allFinite(before.position, 3);
    if (flags & VROC_POSE_LINEAR_VELOCITY_VALID) expected = expected && allFinite(before.linear_velocity, 3);
    if (flags & VROC_POSE_ANGULAR_VELOCITY_VALID) expected = expected && allFinite(before.angular_velocity, 3);
    long double norm = 0;
    if (flags & VROC_POSE_ORIENTATION_VALID) {
        expected = expected && allFinite(before.orientation, 4);
        for (double c : before.orientation) norm += static_cast<long double>(c) * c;
        norm = std::sqrt(norm);
        if (expected && std::fabs(std::fabs(norm - 1) - 0.01L) < 1e-12L) return;   // on the threshold
        expected = expected && std::fabs(norm - 1) <= 0.01L;
    }
    VROC_FUZZ_REQUIRE(why.empty() == expected);
    if (!expected) return;

    VrocPoseSample unchanged = sample;
    std::memcpy(unchanged.orientation, before.orientation, sizeof before.orientation);
    VROC_FUZZ_REQUIRE(std::memcmp(&unchanged, &before, sizeof before) == 0);
    if (!(flags & VROC_POSE_ORIENTATION_VALID)) {
        VROC_FUZZ_REQUIRE(std::memcmp(sample.orientation, before.orientation, sizeof before.orientation) == 0);
        return;
    }
    long double unit = 0;
    for (double c : sample.orientation) unit += static_cast<long double>(c) * c;
    VROC_FUZZ_REQUIRE(std::fabs(std::sqrt(unit) - 1) <= 1e-12L);
    for (int i = 0; i < 4; ++i)   // same direction: each component is the input's over its norm
        VROC_FUZZ_REQUIRE(std::fabs(sample.orientation[i] - static_cast<double>(before.orientation[i] / norm)) <= 1e-15);
}

void checkForce(const uint8_t* bytes, size_t size, uint32_t sensor_count, bool fix_header) {
    VrocForceCommand command{};
    std::memcpy(&command, bytes, std::min(size, sizeof command));
    if (fix_header) {
        command.struct_type = VROC_STRUCT_FORCE_COMMAND;
        command.struct_size = sizeof command;
    }
    const std::string why = vroc::plugins::validateForceCommand(command, sensor_count);
    const bool expected = command.sensor < std::max<uint32_t>(sensor_count, 1) && allFinite(command.force, 3) &&
                          allFinite(command.torque, 3);
    VROC_FUZZ_REQUIRE(why.empty() == expected);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 9) return 0;
    uint32_t sensor, sensor_count;
    std::memcpy(&sensor, data, 4);
    std::memcpy(&sensor_count, data + 4, 4);
    const uint8_t mode = data[8];
    if (mode & 2) checkForce(data + 9, size - 9, sensor_count, mode & 1);
    else checkPose(data + 9, size - 9, sensor, sensor_count, mode & 1);
    return 0;
}
