// SPDX-License-Identifier: MIT
// vroc/core/csv.h against the C library in the C locale: numbers are written as printf("%.17g")
// and printf("%.6f") write them, read back bit for bit, and bad fields are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>

#include "vroc/core/csv.h"

namespace vroc {
namespace {

std::string printf17(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::vector<double> awkwardDoubles() {
    std::vector<double> values = {0.0, -0.0, 1.0, -1.0, 0.1, 1.0 / 3.0, 1e-300, 4.9e-324, 2.2250738585072014e-308,
                                  std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(), 1e16,
                                  123456789012345678.0, 1e-5, 0.0001, 1e17, 9.999999999999999e22};
    std::mt19937_64 rng(13);
    for (int i = 0; i < 20000; ++i) {
        std::uint64_t bits = rng();
        double v = 0;
        std::memcpy(&v, &bits, sizeof v);
        if (std::isfinite(v)) values.push_back(v);
    }
    std::uniform_real_distribution<double> u(-100.0, 100.0);
    for (int i = 0; i < 20000; ++i) values.push_back(u(rng));
    return values;
}

TEST(Csv, NumbersAreWrittenAsPrintf17gAndReadBackExactly) {
    for (double v : awkwardDoubles()) {
        std::string text;
        csv::appendNumber(text, v);
        ASSERT_EQ(text, printf17(v));
        double back = 0;
        ASSERT_TRUE(csv::parseNumber(text, back)) << text;
        ASSERT_EQ(std::memcmp(&back, &v, sizeof v), 0) << text;
    }
}

TEST(Csv, FixedNumbersAreWrittenAsPrintf) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 5000.0);
    for (int i = 0; i < 20000; ++i) {
        const double v = u(rng);
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.6f", v);
        std::string text;
        csv::appendFixed(text, v, 6);
        ASSERT_EQ(text, buf);
    }
}

TEST(Csv, IntegersRoundTripAndOutOfRangeOrSignedTextIsRefused) {
    std::string text;
    csv::appendInteger(text, std::numeric_limits<std::int64_t>::min());
    EXPECT_EQ(text, "-9223372036854775808");
    std::int64_t i = 0;
    EXPECT_TRUE(csv::parseInteger(text, i));
    EXPECT_EQ(i, std::numeric_limits<std::int64_t>::min());
    std::uint32_t u = 0;
    EXPECT_TRUE(csv::parseInteger("4294967295", u));
    EXPECT_EQ(u, 4294967295u);
    EXPECT_FALSE(csv::parseInteger("4294967296", u));
    EXPECT_FALSE(csv::parseInteger("-1", u));
    EXPECT_FALSE(csv::parseInteger("", u));
    EXPECT_FALSE(csv::parseInteger("12a", u));
    EXPECT_FALSE(csv::parseInteger("1.0", u));
}

TEST(Csv, NumberFieldsMustBeWholeNumbers) {
    double v = 0;
    for (const char* bad : {"", "1.5x", " 1", "1 ", "+1", "0x10", "1,5", "e5"}) EXPECT_FALSE(csv::parseNumber(bad, v)) << bad;
    EXPECT_TRUE(csv::parseNumber("-2.5e-3", v));
    EXPECT_EQ(v, -2.5e-3);
    EXPECT_TRUE(csv::parseNumber("7", v));
    EXPECT_EQ(v, 7.0);
}

TEST(Csv, FieldsAreQuotedOnlyWhenTheyMustBe) {
    EXPECT_EQ(csv::field("ball"), "ball");
    EXPECT_EQ(csv::field("a,b"), "\"a,b\"");
    EXPECT_EQ(csv::field("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(csv::field("two\nlines"), "\"two\nlines\"");
}

TEST(Csv, SplitLineKeepsEmptyFieldsAndDropsACarriageReturn) {
    const auto f = csv::splitLine("a,,b,\r");
    ASSERT_EQ(f.size(), 4u);
    EXPECT_EQ(f[0], "a");
    EXPECT_EQ(f[1], "");
    EXPECT_EQ(f[2], "b");
    EXPECT_EQ(f[3], "");
    EXPECT_EQ(csv::splitLine("").size(), 1u);
}

}  // namespace
}  // namespace vroc
