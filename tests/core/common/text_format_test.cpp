// Numbers in messages: formatFixed is printf "%.*f", formatSignificant is what std::ostream prints
// with that precision (both replaced per-file helpers, so their output must not change).
#include "core/common/text_format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace tt::core {
namespace {

TEST(TextFormat, FixedDecimals) {
    EXPECT_EQ(formatFixed(27.0, 3), "27.000");
    EXPECT_EQ(formatFixed(0.12345, 3), "0.123");
    EXPECT_EQ(formatFixed(162.5, 1), "162.5");
    EXPECT_EQ(formatFixed(-0.25, 0), "-0");  // round half to even, sign kept (C printf)
    EXPECT_EQ(formatFixed(1e30, 1).size(), 33u) << "long values are not cut off";
    EXPECT_EQ(formatFixed(std::numeric_limits<double>::infinity(), 3), "inf");
}

TEST(TextFormat, SignificantDigitsAreWhatAStreamPrints) {
    EXPECT_EQ(formatSignificant(0.000123456, 3), "0.000123");
    EXPECT_EQ(formatSignificant(1e7, 6), "1e+07");
    EXPECT_EQ(formatSignificant(325.0, 6), "325");
    EXPECT_EQ(formatSignificant(std::nan(""), 4), "nan");
    for (const double v : {0.0, -0.0013, 1.0 / 3.0, 210000.0, 6.02e23, -1e-300, 12345.678})
        for (const int digits : {3, 4, 6, 10}) {
            std::ostringstream out;
            out.precision(digits);
            out << v;
            EXPECT_EQ(formatSignificant(v, digits), out.str()) << v << " with " << digits << " digits";
        }
}

}  // namespace
}  // namespace tt::core
