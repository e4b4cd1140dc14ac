// SPDX-License-Identifier: MIT
#include "checks/worker_count_check.h"

#include <exception>

#include "checks/check_support.h"
#include "vroc/core/state_hash.h"
#include "vroc/harness/runs/scene_support.h"

namespace vroc::conformance {
namespace {

std::string hashAfter(const BackendInfo& backend, const Scene& scene, int frames, const SettingOverrides& overrides) {
    auto b = createBackend(backend, scene, overrides);
    for (int f = 0; f < frames; ++f) b->stepFrame(scene.frame_dt);
    return hashToHex(stateHash(*b));
}

/// The setting lists to compare: the defaults twice, or one list per worker count in range.
std::vector<SettingOverrides> settingVariants(const BackendInfo& backend, const WorkerCountCheckOptions& options) {
    std::vector<SettingOverrides> out;
    for (const std::string& key : workerSettings(backend))
        for (const SettingSpec& spec : backend.settings)
            if (spec.key == key)
                for (int n : options.worker_counts)
                    if (n >= spec.min && n <= spec.max) out.push_back({{key, std::to_string(n)}});
    if (out.size() < 2) out = {{}, {}};
    return out;
}

std::string describe(const SettingOverrides& overrides) {
    std::string out;
    for (const auto& [k, v] : overrides) out += (out.empty() ? "" : ",") + k + "=" + v;
    return out.empty() ? "defaults" : out;
}

}  // namespace

std::vector<std::string> workerSettings(const BackendInfo& backend) {
    std::vector<std::string> keys;
    for (const SettingSpec& spec : backend.settings) {
        const std::string name = spec.key.substr(spec.key.find('.') + 1);
        if (spec.type == SettingSpec::Type::Integer && (name == "threads" || name == "workers"))
            keys.push_back(spec.key);
    }
    return keys;
}

CheckResult checkWorkerCountDeterminism(const BackendInfo& backend, const WorkerCountCheckOptions& options) {
    CheckResult r{backend.name, {}};
    const std::vector<SettingOverrides> variants = settingVariants(backend, options);
    int compared = 0;
    for (const HashedRun& run : options.runs) {
        try {
            const Scene scene = shippedScene(run.scene);
            if (harness::sceneSupport(scene, backend.capabilities).level == Support::Unsupported) continue;
            ++compared;
            const std::string first = hashAfter(backend, scene, run.frames, variants.front());
            for (std::size_t v = 1; v < variants.size(); ++v) {
                const std::string h = hashAfter(backend, scene, run.frames, variants[v]);
                if (h != first)
                    r.fail("scene ", run.scene, ", ", run.frames, " frames: state hash ", h, " with ",
                           describe(variants[v]), ", ", first, " with ", describe(variants.front()));
            }
        } catch (const std::exception& e) {
            r.fail("scene ", run.scene, ": threw ", e.what());
        }
    }
    if (compared == 0) r.fail("none of the runs' scenes is supported: nothing compared");
    return r;
}

}  // namespace vroc::conformance
