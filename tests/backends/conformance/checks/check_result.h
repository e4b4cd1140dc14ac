// SPDX-License-Identifier: MIT
// What one conformance check found on one backend. A check collects its failures instead of
// calling EXPECT itself, so the same check is asserted to pass on a real backend and asserted to
// fail on a deliberately broken one (broken_backends/) without failing the test that asks.
#pragma once

#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "vroc/core/math.h"

namespace vroc::conformance {

/// One part of a failure line as it is streamed: a vector as "(x, y, z)", anything else as is.
template <class T>
const T& failureText(const T& part) {
    return part;
}
inline std::string failureText(const Vec3& v) {
    std::ostringstream out;
    out.precision(9);
    out << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
    return out.str();
}

struct CheckResult {
    std::string backend;                ///< name of the backend checked
    std::vector<std::string> failures;  ///< one line each: scene, body, numbers; empty = passed

    bool passed() const { return failures.empty(); }

    /// Adds a failure from its parts, streamed ("scene ", path, ": rose ", rise, " m"); a vector
    /// part prints as "(x, y, z)".
    template <class... Parts>
    void fail(const Parts&... parts) {
        std::ostringstream line;
        line.precision(9);
        ((line << failureText(parts)), ...);
        failures.push_back(line.str());
    }
};

inline std::ostream& operator<<(std::ostream& out, const CheckResult& r) {
    out << r.backend << ": " << (r.passed() ? "passed" : std::to_string(r.failures.size()) + " failure(s)");
    for (const std::string& f : r.failures) out << "\n  " << f;
    return out;
}

}  // namespace vroc::conformance
