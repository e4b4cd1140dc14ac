// SPDX-License-Identifier: MIT
#include "checks/capability_notes_check.h"

#include <string>
#include <utility>
#include <vector>

namespace vroc::conformance {

CheckResult checkCapabilityNotes(const BackendInfo& backend) {
    CheckResult r{backend.name, {}};
    const BackendCapabilities& c = backend.capabilities;
    const std::vector<std::pair<std::string, Support>> features{
        {"sphere", c.sphere},           {"box", c.box},        {"hull", c.hull}, {"compound", c.compound},
        {"restitution", c.restitution}, {"tracked", c.tracked}};
    for (const auto& [feature, support] : features) {
        const auto note = c.notes.find(feature);
        if (support == Support::Approximated && (note == c.notes.end() || note->second.empty()))
            r.fail(feature, " is declared approximated without a note saying how");
        if (support == Support::Exact && note != c.notes.end())
            r.fail(feature, " is declared exact, yet has a note: ", note->second);
    }
    if (backend.version.empty()) r.fail("no version");
    if (c.precision.empty()) r.fail("no precision");
    for (const std::string& d : backend.deviations)
        if (d.find(':') == std::string::npos) r.fail("a deviation without its reason (\"what: why\"): ", d);
    return r;
}

}  // namespace vroc::conformance
