// SPDX-License-Identifier: MIT
// Pinned determinism (after Box2D v3): the state hash of every shipped scene on every backend,
// after a fixed number of frames, committed in tests/data/pinned_hashes.json for the compiler,
// flags and floating-point code path of the default build. A change in any backend's results is
// then a decision (re-pin, and say why in the commit), never an accident.
//
// Re-pin:  VROC_PIN_HASHES=write build/bin/vroc_conformance_tests --gtest_filter='PinnedHashes.*'
// A build whose compiler, flags or libm code path differ from the pinned ones skips (and says so):
// the hashes are bit patterns, and another compiler or another libm variant rounds differently.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformance_backends.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/build_info.h"
#include "vroc/core/scene_loader.h"
#include "vroc/core/state_hash.h"
#include "vroc/harness/runs/scene_support.h"

namespace vroc::conformance {
namespace {

namespace fs = std::filesystem;
constexpr int kFrames = 12;   // enough for contacts to form in every scene, short enough for CI

const fs::path kPinFile = fs::path(VROC_SOURCE_DIR) / "tests/data/pinned_hashes.json";

// glibc picks its libm routines (sin, cos, exp, ...) by CPU at run time; the FMA variants round
// differently from the SSE2 ones, so the code path is part of what a hash is pinned for.
std::string libmPath() {
#if defined(__x86_64__) && defined(__GNUC__)
    __builtin_cpu_init();
    return __builtin_cpu_supports("fma") && __builtin_cpu_supports("avx2") ? "x86_64 fma+avx2" : "x86_64 sse2";
#else
    return "other";
#endif
}

std::vector<fs::path> shippedScenes() {
    std::vector<fs::path> out;
    for (const auto& e : fs::recursive_directory_iterator(fs::path(VROC_SOURCE_DIR) / "scenes"))
        if (e.is_regular_file() && e.path().extension() == ".json") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

/// "<scene path below scenes/>/<backend>" -> hash, for every scene each backend can represent.
std::map<std::string, std::string> currentHashes() {
    for (const ConformanceBackend& b : conformanceBackends())
        if (!BackendRegistry::global().find(b.name)) b.register_fn();
    std::map<std::string, std::string> out;
    const fs::path root = fs::path(VROC_SOURCE_DIR) / "scenes";
    for (const fs::path& path : shippedScenes()) {
        const Scene scene = loadScene(path.string());
        for (const ConformanceBackend& b : conformanceBackends()) {
            const BackendInfo& info = BackendRegistry::global().require(b.name);
            if (harness::sceneSupport(scene, info.capabilities).level == Support::Unsupported) continue;
            if (path.parent_path().filename() == "stress" && !runsStressScenes(b.name)) continue;
            auto backend = info.create(scene, resolveSettings(info.settings, {}));
            for (int f = 0; f < kFrames; ++f) backend->stepFrame(scene.frame_dt);
            out[fs::relative(path, root).string() + "/" + b.name] = hashToHex(stateHash(*backend));
        }
    }
    return out;
}

nlohmann::ordered_json pinDocument(const std::map<std::string, std::string>& hashes) {
    nlohmann::ordered_json doc;
    doc["format"] = "vroc-pinned-hashes/1";
    doc["what"] = "state hash after " + std::to_string(kFrames) + " frames of each shipped scene, default settings";
    doc["compiler"] = buildInfo().compiler;
    doc["flags"] = buildInfo().flags;
    doc["libm"] = libmPath();
    doc["frames"] = kFrames;
    doc["hashes"] = hashes;
    return doc;
}

TEST(PinnedHashes, EveryShippedSceneOnEveryBackendKeepsItsStateHash) {
    const char* mode = std::getenv("VROC_PIN_HASHES");
    if (mode && std::string(mode) == "write") {
        const std::map<std::string, std::string> now = currentHashes();
        std::ofstream(kPinFile) << pinDocument(now).dump(2) << "\n";
        GTEST_SKIP() << "wrote " << now.size() << " hashes to " << kPinFile;
    }
    std::ifstream in(kPinFile);
    ASSERT_TRUE(in.good()) << kPinFile << " is missing; pin with VROC_PIN_HASHES=write";
    const nlohmann::json pinned = nlohmann::json::parse(in);
    for (const char* key : {"compiler", "flags", "libm"}) {
        const std::string mine = key == std::string("libm") ? libmPath()
                                 : key == std::string("compiler") ? buildInfo().compiler
                                                                  : buildInfo().flags;
        if (pinned.at(key).get<std::string>() != mine)
            GTEST_SKIP() << "pinned for " << key << " '" << pinned.at(key).get<std::string>() << "', this build has '"
                         << mine << "': bit patterns are not comparable";
    }
    ASSERT_EQ(pinned.at("frames").get<int>(), kFrames);
    // Stepped only now: a build the pins do not apply to (a sanitizer build) skips at once.
    const std::map<std::string, std::string> now = currentHashes();
    const auto was = pinned.at("hashes").get<std::map<std::string, std::string>>();
    std::vector<std::string> changed;
    for (const auto& [key, hash] : now) {
        const auto it = was.find(key);
        if (it == was.end()) changed.push_back(key + ": new (" + hash + ")");
        else if (it->second != hash) changed.push_back(key + ": " + it->second + " -> " + hash);
    }
    for (const auto& [key, hash] : was)
        if (!now.count(key)) changed.push_back(key + ": gone");
    if (!changed.empty()) {
        std::string list;
        for (const std::string& c : changed) list += "\n  " + c;
        ADD_FAILURE() << changed.size() << " of " << now.size() << " pinned results changed:" << list
                      << "\nIf the change is intended, re-pin (and say why in the commit):\n"
                         "  VROC_PIN_HASHES=write build/bin/vroc_conformance_tests --gtest_filter='PinnedHashes.*'\n"
                         "or paste this as tests/data/pinned_hashes.json:\n"
                      << pinDocument(now).dump(2);
    }
}

}  // namespace
}  // namespace vroc::conformance
