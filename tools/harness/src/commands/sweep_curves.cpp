// SPDX-License-Identifier: MIT
#include "vroc/harness/commands/sweep_curves.h"

#include <utility>

#include "vroc/core/errors.h"

namespace vroc::harness {
namespace {

// "5,10,50" -> {"5", "10", "50"}; throws on an empty value.
std::vector<std::string> splitValues(const std::string& arg, const std::string& list) {
    std::vector<std::string> out;
    std::string word;
    for (char c : list + ",") {
        if (c != ',') { word += c; continue; }
        if (word.empty()) throw InputError("--vary " + arg + ": empty value (expected KEY=V1,V2,...)");
        out.push_back(word);
        word.clear();
    }
    return out;
}

// The settings helpers speak of --set; the user typed --vary.
[[noreturn]] void rethrowAsVary(const InputError& e) {
    const std::string m = e.what();
    throw InputError(m.rfind("--set", 0) == 0 ? "--vary" + m.substr(5) : "--vary: " + m);
}

// The base settings of `b` with `key` replaced by `value`, validated against the backend's specs.
Settings withSetting(const SelectedBackend& b, const std::string& key, const std::string& value) {
    std::vector<std::pair<std::string, std::string>> overrides;
    for (const auto& kv : b.settings.values())
        if (kv.first != key) overrides.push_back(kv);
    overrides.emplace_back(key, value);
    try {
        return resolveSettings(b.info->settings, overrides);
    } catch (const InputError& e) {
        rethrowAsVary(e);
    }
}

std::pair<std::string, std::string> splitVary(const std::string& arg) {
    try {
        return splitAssignment(arg);
    } catch (const InputError& e) {
        rethrowAsVary(e);
    }
}

}  // namespace

std::vector<SweepCurve> sweepCurves(const std::vector<SelectedBackend>& backends, const std::vector<std::string>& vary) {
    std::vector<std::vector<SweepCurve>> per(backends.size());
    for (const std::string& arg : vary) {
        const auto [key, list] = splitVary(arg);
        const std::string prefix = key.substr(0, key.find('.'));
        std::size_t bi = 0;
        while (bi < backends.size() && backends[bi].info->name != prefix) ++bi;
        if (bi == backends.size() || key.find('.') == std::string::npos)
            throw InputError("--vary " + arg + ": the key must start with a selected backend's name and '.', e.g. bullet.solver_iterations");
        const std::string name = key.substr(prefix.size() + 1);
        for (const std::string& v : splitValues(arg, list)) {
            SelectedBackend run = backends[bi];   // its footing kept; the varied key on top
            run.settings = withSetting(backends[bi], key, v);
            for (const SweepCurve& c : per[bi])
                if (c.setting == name + "=" + v) throw InputError("--vary " + arg + ": " + key + "=" + v + " given twice");
            per[bi].push_back({bi, std::move(run), prefix + " " + name + "=" + v, name + "=" + v});
        }
    }
    std::vector<SweepCurve> out;
    for (std::size_t bi = 0; bi < backends.size(); ++bi) {
        if (per[bi].empty()) out.push_back({bi, backends[bi], backends[bi].info->name, ""});
        for (SweepCurve& c : per[bi]) out.push_back(std::move(c));
    }
    return out;
}

}  // namespace vroc::harness
