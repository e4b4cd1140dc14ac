// SPDX-License-Identifier: MIT
// The conformance suite can fail: each broken backend of broken_backends/broken_backends.h is
// rejected by the checks its entry names, and passes every other check (it breaks one thing, so
// the rejection is for that thing). The control, which keeps to the contract while refusing a
// shape kind, passes them all.
#include "broken_backends/broken_backends.h"

#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "checks/conformance_checks.h"

namespace vroc::conformance {

// gtest names a failing parameter by this (else it dumps the struct's bytes).
void PrintTo(const BrokenBackend& b, std::ostream* out) { *out << b.info().name; }

namespace {

class BrokenBackends : public ::testing::TestWithParam<BrokenBackend> {};

TEST_P(BrokenBackends, AreRejectedByTheirChecksOnly) {
    const BackendInfo info = GetParam().info();
    for (const ConformanceCheck& check : conformanceChecks()) {
        SCOPED_TRACE(check.name);
        const CheckResult r = check.run(info);
        if (GetParam().rejected_by.count(check.name))
            EXPECT_FALSE(r.passed()) << "check '" << check.name << "' should reject " << info.name;
        else
            EXPECT_TRUE(r.passed()) << "check '" << check.name << "' should pass " << info.name << ": " << r;
    }
}

// Every name in an entry is a check that exists (a misspelt name would make its EXPECT_FALSE
// vanish from the test above).
TEST(BrokenBackendList, NamesOnlyExistingChecks) {
    for (const BrokenBackend& b : brokenBackends())
        for (const std::string& name : b.rejected_by) {
            bool found = false;
            for (const ConformanceCheck& c : conformanceChecks()) found = found || c.name == name;
            EXPECT_TRUE(found) << b.info().name << " names an unknown check '" << name << "'";
        }
}

INSTANTIATE_TEST_SUITE_P(AllBroken, BrokenBackends, ::testing::ValuesIn(brokenBackends()),
                         [](const ::testing::TestParamInfo<BrokenBackend>& p) { return p.param.info().name; });

}  // namespace
}  // namespace vroc::conformance
