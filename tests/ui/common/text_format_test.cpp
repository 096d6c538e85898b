// Times in one column: one unit for all, each number to at least two
// significant digits (English: this test loads no translation).

#include "ui/common/text_format.h"

#include <gtest/gtest.h>

#include <vector>

#include "ui/common/parameter_info.h"

namespace probecycle::ui {
namespace {

TEST(SecondsColumn, ACyclesPhasesReadInMillisecondsWholeFromTenUp) {
    // The default two-touch cycle's phases (cycle 2.08 s).
    const SecondsColumn column =
        format_seconds_column({0.18, 1.62, 0.00015, 0.010, 0.002, 0.004, 0.0537, 0.085});
    EXPECT_EQ(column.unit, unit_ms());
    EXPECT_EQ(column.numbers,
              (QStringList{QStringLiteral("180"), QStringLiteral("1620"), QStringLiteral("0.15"),
                           QStringLiteral("10"), QStringLiteral("2.0"), QStringLiteral("4.0"),
                           QStringLiteral("54"), QStringLiteral("85")}));
}

TEST(SecondsColumn, LongPhasesReadInSecondsAndTinyOnesToFourDecimalsAtMost) {
    const SecondsColumn column = format_seconds_column({12.5, 3.26, 0.2, 0.00002, 0.0});
    EXPECT_EQ(column.unit, unit_s());
    EXPECT_EQ(column.numbers,
              (QStringList{QStringLiteral("12.5"), QStringLiteral("3.3"), QStringLiteral("0.20"),
                           QStringLiteral("0.0000"), QStringLiteral("0.0")}));
}

TEST(SecondsColumn, OnlyMicrosecondsReadInMicroseconds) {
    const SecondsColumn column = format_seconds_column({0.00004, 0.0000025});
    EXPECT_EQ(column.unit, QStringLiteral("µs"));
    EXPECT_EQ(column.numbers, (QStringList{QStringLiteral("40"), QStringLiteral("2.5")}));
    EXPECT_TRUE(format_seconds_column({}).numbers.isEmpty());
}

}  // namespace
}  // namespace probecycle::ui
