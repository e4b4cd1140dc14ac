// SPDX-License-Identifier: MIT
#include "vroc/core/backend_vocabulary.h"

#include <algorithm>

namespace vroc {

const char* supportName(Support s) {
    switch (s) {
        case Support::Exact: return "exact";
        case Support::Approximated: return "approximated";
        case Support::Unsupported: return "unsupported";
    }
    return "unsupported";
}

const char* frictionName(FrictionModel f) { return f == FrictionModel::Cone ? "cone" : "pyramid"; }

namespace vocabulary {

const std::vector<std::string>& sharedStatistics() {
    static const std::vector<std::string> names{kFrames,        kInternalSteps,    kCollisionEvents,
                                                kContactPoints, kContactPointsMean, kBroadphasePairs,
                                                kBroadphasePairsMean};
    return names;
}

const std::vector<std::string>& sharedWarnings() {
    static const std::vector<std::string> names{kNonfiniteState, kPenetrationRecovered, kInternalStepCap,
                                                kIllConditionedSolve, kContactsDropped};
    return names;
}

namespace {

template <class Map>
Map withPrefix(const Map& in, const std::vector<std::string>& shared, const std::string& backend) {
    Map out;
    const std::string prefix = backend + ".";
    for (const auto& [name, value] : in) {
        const bool keep = std::find(shared.begin(), shared.end(), name) != shared.end() ||
                          name.compare(0, prefix.size(), prefix) == 0;
        out[keep ? name : prefix + name] += value;
    }
    return out;
}

}  // namespace

WarningCounts prefixed(const WarningCounts& warnings, const std::string& backend) {
    return withPrefix(warnings, sharedWarnings(), backend);
}

Statistics prefixed(const Statistics& statistics, const std::string& backend) {
    return withPrefix(statistics, sharedStatistics(), backend);
}

std::vector<std::string> foreignNames(const std::vector<std::string>& names, const std::vector<std::string>& shared,
                                      const std::string& backend) {
    std::vector<std::string> out;
    const std::string prefix = backend + ".";
    for (const std::string& n : names) {
        const bool is_shared = std::find(shared.begin(), shared.end(), n) != shared.end();
        const bool is_own = n.size() > prefix.size() && n.compare(0, prefix.size(), prefix) == 0;
        if (!is_shared && !is_own) out.push_back(n);
    }
    return out;
}

}  // namespace vocabulary
}  // namespace vroc
