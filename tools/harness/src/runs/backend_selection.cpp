// SPDX-License-Identifier: MIT
#include "vroc/harness/runs/backend_selection.h"

#include <cstdio>
#include <set>
#include <utility>

#include "vroc/core/backend_registry.h"
#include "vroc/core/errors.h"
#include "vroc/harness/runs/scene_support.h"

namespace vroc::harness {

Footing::Kind footingKind(const std::string& word) {
    if (word == "defaults") return Footing::Kind::Defaults;
    if (word == "equal") return Footing::Kind::Equal;
    throw InputError("--footing: '" + word +
                     "' is not a footing (expected defaults or equal; check and compare also take both)");
}

std::string SelectedBackend::label() const {
    if (!both_footings) return info->name;
    return info->name + (footing.kind == Footing::Kind::Equal ? " (equal footing)" : " (own defaults)");
}

std::string SelectedBackend::key() const {
    if (!both_footings) return info->name;
    return info->name + (footing.kind == Footing::Kind::Equal ? "-equal" : "-defaults");
}

std::string footingText(const Footing& footing) {
    if (footing.kind == Footing::Kind::Defaults) return "defaults (each engine at its own defaults, departures listed)";
    return "equal (" + std::to_string(footing.substeps) +
           " internal steps per frame on every engine, isotropic Coulomb friction where the engine has it)";
}

std::vector<SelectedBackend> selectBackends(const std::string& list, const std::vector<std::string>& assignments,
                                            const Footing& footing) {
    if (footing.kind == Footing::Kind::Equal && footing.substeps < 1)
        throw InputError("--footing-substeps: " + std::to_string(footing.substeps) + " (expected 1 or more)");
    const BackendRegistry& registry = BackendRegistry::global();
    std::vector<std::string> names;
    if (list.empty()) {
        for (const BackendInfo* info : registry.all()) names.push_back(info->name);
    } else {
        std::string word;
        for (char c : list + ",") {
            if (c != ',') { word += c; continue; }
            if (word.empty()) throw InputError("--backends: empty name in '" + list + "' (expected a,b,...)");
            names.push_back(word);
            word.clear();
        }
    }
    if (names.empty()) throw InputError("--backends: no backend is registered in this build");
    std::set<std::string> seen;
    std::vector<SelectedBackend> out;
    std::vector<std::vector<std::pair<std::string, std::string>>> overrides(names.size());
    for (const std::string& name : names) {
        if (!seen.insert(name).second) throw InputError("--backends: '" + name + "' given twice");
        SelectedBackend b;
        b.info = &registry.require(name);
        out.push_back(std::move(b));
    }
    for (const std::string& a : assignments) {
        auto kv = splitAssignment(a);
        const std::string prefix = kv.first.substr(0, kv.first.find('.'));
        bool routed = false;
        for (std::size_t i = 0; i < names.size(); ++i)
            if (names[i] == prefix) { overrides[i].push_back(kv); routed = true; }
        if (!routed && !registry.find(prefix))
            throw InputError("--set " + a + ": the key must start with a backend name and '.', e.g. bullet.substeps");
    }
    for (std::size_t i = 0; i < out.size(); ++i) {
        SelectedBackend& b = out[i];
        b.footing = footing;
        if (footing.kind == Footing::Kind::Equal && b.info->equal_footing != nullptr)
            b.footing_settings = b.info->equal_footing(footing.substeps);
        // The footing's keys first, then the user's: a later override of the same key wins.
        std::vector<std::pair<std::string, std::string>> all = b.footing_settings;
        all.insert(all.end(), overrides[i].begin(), overrides[i].end());
        b.settings = resolveSettings(b.info->settings, all);
    }
    return out;
}

std::vector<SelectedBackend> selectBackendsOnFooting(const std::string& list, const std::vector<std::string>& assignments,
                                                     const std::string& word, int substeps, bool both_allowed) {
    if (!(substeps >= 1))
        throw InputError("--footing-substeps: expected a whole number of internal steps per frame >= 1, got " +
                         std::to_string(substeps));
    if (word == "both") {
        if (!both_allowed)
            throw InputError(
                "--footing both: only check and compare run both footings side by side; run this command once "
                "per footing (--footing defaults, --footing equal)");
        return selectBackendsOnBothFootings(list, assignments, substeps);
    }
    Footing f;
    f.kind = footingKind(word);
    f.substeps = substeps;
    return selectBackends(list, assignments, f);
}

std::vector<SelectedBackend> selectBackendsOnBothFootings(const std::string& list,
                                                          const std::vector<std::string>& assignments, int substeps) {
    Footing equal;
    equal.kind = Footing::Kind::Equal;
    equal.substeps = substeps;
    const std::vector<SelectedBackend> own = selectBackends(list, assignments);
    const std::vector<SelectedBackend> equalized = selectBackends(list, assignments, equal);
    std::vector<SelectedBackend> out;
    for (std::size_t i = 0; i < own.size(); ++i)
        for (SelectedBackend b : {own[i], equalized[i]}) {
            b.both_footings = true;
            out.push_back(std::move(b));
        }
    return out;
}

Json backendsJson(const std::vector<SelectedBackend>& backends) {
    Json out = Json::array();
    for (const SelectedBackend& b : backends)
    {
        Json applied = Json::object();
        for (const auto& [key, value] : b.footing_settings) applied[key] = value;
        out.push_back({{"name", b.info->name}, {"version", b.info->version}, {"description", b.info->description},
                       {"settings", b.settings.values()}, {"deviations", b.info->deviations},
                       {"footing", {{"kind", b.footing.kind == Footing::Kind::Equal ? "equal" : "defaults"},
                                    {"substeps_per_frame", b.footing.kind == Footing::Kind::Equal ? Json(b.footing.substeps) : Json()},
                                    {"settings", applied}}}});
        if (b.both_footings) {  // two runs of one engine: which one this entry is
            out.back()["label"] = b.label();
            out.back()["key"] = b.key();
        }
    }
    return out;
}

std::vector<SelectedBackend> representableBackends(const Scene& scene, const std::vector<SelectedBackend>& requested,
                                                   const std::string& command, bool progress, Json& support) {
    std::vector<SelectedBackend> out;
    support = Json::object();
    for (const SelectedBackend& b : requested) {
        const SceneSupport s = sceneSupport(scene, b.info->capabilities);
        support[b.key()] = supportText(s);
        if (s.level != Support::Unsupported) out.push_back(b);
        else if (progress)
            progressLine(command, b.label() + " left out: " + supportText(s));
    }
    if (out.empty()) throw InputError("scene '" + scene.name + "': no selected backend can represent it");
    return out;
}

void progressLine(const std::string& command, const std::string& text) {
    std::fprintf(stderr, "vroc %s: %s\n", command.c_str(), text.c_str());
    std::fflush(stderr);
}

}  // namespace vroc::harness
