// SPDX-License-Identifier: MIT
#include "vroc/core/backend_registry.h"

#include <algorithm>
#include <stdexcept>

#include "vroc/core/errors.h"

namespace vroc {

BackendRegistry& BackendRegistry::global() {
    static BackendRegistry registry;
    return registry;
}

void BackendRegistry::add(BackendInfo info) {
    if (find(info.name)) throw std::logic_error("backend '" + info.name + "' registered twice");
    if (!info.create) throw std::logic_error("backend '" + info.name + "' has no create function");
    infos_.push_back(std::move(info));
}

const BackendInfo* BackendRegistry::find(const std::string& name) const {
    for (const auto& info : infos_)
        if (info.name == name) return &info;
    return nullptr;
}

const BackendInfo& BackendRegistry::require(const std::string& name) const {
    if (const BackendInfo* info = find(name)) return *info;
    std::string known;
    for (const auto* info : all()) known += (known.empty() ? "" : ", ") + info->name;
    throw InputError("unknown backend '" + name + "' (known: " + known + ")");
}

std::vector<const BackendInfo*> BackendRegistry::all() const {
    std::vector<const BackendInfo*> out;
    for (const auto& info : infos_) out.push_back(&info);
    std::sort(out.begin(), out.end(), [](auto* a, auto* b) { return a->name < b->name; });
    return out;
}

}  // namespace vroc
