// SPDX-License-Identifier: MIT
#include "vroc/core/state_hash.h"

#include <bit>
#include <cstdio>
#include <vector>

namespace vroc {
namespace {

constexpr std::uint64_t kFnvOffset = 0xcbf29ce484222325ull;
constexpr std::uint64_t kFnvPrime = 0x100000001b3ull;

void mix(std::uint64_t& h, double value) {
    std::uint64_t bits = std::bit_cast<std::uint64_t>(value);
    for (int i = 0; i < 8; ++i) {
        h ^= (bits >> (8 * i)) & 0xffu;
        h *= kFnvPrime;
    }
}

}  // namespace

std::uint64_t stateHash(std::span<const BodyState> states) {
    std::uint64_t h = kFnvOffset;
    for (const auto& s : states) {
        for (int i = 0; i < 3; ++i) mix(h, s.pose.position[i]);
        const Quat& q = s.pose.orientation;
        for (double c : {q.x(), q.y(), q.z(), q.w()}) mix(h, c);
        for (int i = 0; i < 3; ++i) mix(h, s.linear_velocity[i]);
        for (int i = 0; i < 3; ++i) mix(h, s.angular_velocity[i]);
    }
    return h;
}

std::uint64_t stateHash(const Backend& backend) {
    std::vector<BodyState> states;
    for (int i = 0; i < backend.bodyCount(); ++i) states.push_back(backend.bodyState(i));
    return stateHash(states);
}

std::string hashToHex(std::uint64_t hash) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash));
    return buf;
}

}  // namespace vroc
