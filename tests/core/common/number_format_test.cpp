#include "core/common/number_format.h"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace probecycle
