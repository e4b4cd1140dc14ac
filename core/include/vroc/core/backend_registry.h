// SPDX-License-Identifier: MIT
// Registry of backends by name. Backends add themselves through an explicit register function
// that the program calls at start (static initialisers in static libraries get dropped).
#pragma once

#include <string>
#include <vector>

#include "vroc/core/backend.h"

namespace vroc {

class BackendRegistry {
public:
    /// Process-wide registry.
    static BackendRegistry& global();

    /// Adds a backend; throws std::logic_error if the name is taken.
    void add(BackendInfo info);
    /// nullptr if unknown.
    const BackendInfo* find(const std::string& name) const;
    /// Throws InputError "unknown backend 'x' (known: a, b)".
    const BackendInfo& require(const std::string& name) const;
    /// In name order.
    std::vector<const BackendInfo*> all() const;

private:
    std::vector<BackendInfo> infos_;
};

}  // namespace vroc
