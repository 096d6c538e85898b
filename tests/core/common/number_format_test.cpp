#include "core/common/number_format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace probecycle {
namespace {

TEST(ParseDecimal, ReadsDecimalNumbersOnly) {
    EXPECT_EQ(parse_decimal("1500"), 1500.0);
    EXPECT_EQ(parse_decimal(" 1500"), 1500.0);
    EXPECT_EQ(parse_decimal("1500 "), 1500.0);  // white space one way: ignored on both sides
    EXPECT_EQ(parse_decimal("-2.5e-3"), -2.5e-3);
    EXPECT_EQ(parse_decimal(".5"), 0.5);
    for (const char* bad :
         {"", " ", "0x10", "0X1p3", "inf", "-inf", "nan", "1e400", "10 mm", "1,5", "+-1", "--1"}) {
        EXPECT_FALSE(parse_decimal(bad).has_value()) << bad;
    }
}

TEST(FormatNumber, ShortestTextToTheDigitsAsked) {
    EXPECT_EQ(format_number(0.004), "0.004");
    EXPECT_EQ(format_number(1e9), "1e+09");
    EXPECT_EQ(format_number(2.0 / 3.0, 3), "0.667");
    EXPECT_EQ(format_number(std::nan("")), "NaN");
    EXPECT_EQ(format_number(-INFINITY), "-inf");
}

TEST(FormatFixed, RoundedToTheDecimalsWithoutTrailingZeros) {
    EXPECT_EQ(format_fixed(13.11179578, 6), "13.111796");
    EXPECT_EQ(format_fixed(0.36, 6), "0.36");
    EXPECT_EQ(format_fixed(15.0, 4), "15");
    EXPECT_EQ(format_fixed(3986.09153, 1), "3986.1");
    EXPECT_EQ(format_fixed(0.00152752523, 4), "0.0015");
    EXPECT_EQ(format_fixed(-1e-9, 4), "0");  // no "-0"
    EXPECT_EQ(format_fixed(-2.5, 0), "-2");  // round half to even, as printf
    EXPECT_EQ(format_fixed(std::nan(""), 3), "NaN");
}

TEST(FormatDecimals, ExactlyTheDecimalsNeverMinusZero) {
    EXPECT_EQ(format_decimals(26.01666666, 4), "26.0167");
    EXPECT_EQ(format_decimals(0.4, 4), "0.4000");
    EXPECT_EQ(format_decimals(-12.5, 1), "-12.5");
    EXPECT_EQ(format_decimals(-1e-9, 4), "0.0000");
    EXPECT_EQ(format_decimals(-0.0, 3), "0.000");
    EXPECT_EQ(format_decimals(3000.0, 0), "3000");
    EXPECT_EQ(format_decimals(-std::numeric_limits<double>::infinity(), 2), "-inf");
    EXPECT_EQ(format_decimals(std::numeric_limits<double>::max(), 1).size(), 311u);
}

TEST(FormatExact, ShortestTextThatReadsBackAsTheValue) {
    EXPECT_EQ(format_exact(0.06), "0.06");
    EXPECT_EQ(format_exact(40000.0), "40000");
    EXPECT_EQ(format_exact(2.1050000000000004), "2.1050000000000004");
    for (const double v : {0.1, 1.0 / 3.0, 1e-6, 123456.789, -0.004}) {
        EXPECT_EQ(parse_decimal(format_exact(v)), v) << v;
    }
}

TEST(RoundTo, UpAndDownToTheStepWithoutMovingAValueOnIt) {
    EXPECT_DOUBLE_EQ(round_up_to(1.4716667, 0.001), 1.472);
    EXPECT_DOUBLE_EQ(round_down_to(3580.9, 1.0), 3580.0);
    // A sum's last bits do not move a value on the step a whole step.
    EXPECT_DOUBLE_EQ(round_up_to(2.1050000000000004, 0.001), 2.105);
    EXPECT_DOUBLE_EQ(round_down_to(0.30000000000000004 - 1e-16, 0.1), 0.3);
    EXPECT_DOUBLE_EQ(round_up_to(2.105, 0.001), 2.105);
    EXPECT_DOUBLE_EQ(round_down_to(99.95, 0.1), 99.9);
}

}  // namespace
}  // namespace probecycle
