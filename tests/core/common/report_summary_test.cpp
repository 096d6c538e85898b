// Per-point tables summarised for reading (core/common/report_summary.h).

#include "core/common/report_summary.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace probecycle {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(ReportSummary, ATableIsSummarisedOnlyPastTheLimitAndOnlyInASummary) {
    EXPECT_FALSE(summarised(ReportRows::summary, kReportFullRows));
    EXPECT_TRUE(summarised(ReportRows::summary, kReportFullRows + 1));
    EXPECT_FALSE(summarised(ReportRows::all, 1000000));
}

TEST(ReportSummary, StatisticsLeaveOutMissingValues) {
    const std::vector<double> values = {1.0, kNaN, 3.0, -2.0, 6.0};
    const ValueStats s = value_stats(values);
    EXPECT_EQ(s.count, 4u);
    EXPECT_EQ(s.min, -2.0);
    EXPECT_EQ(s.max, 6.0);
    EXPECT_DOUBLE_EQ(s.mean, 2.0);
    // Sample standard deviation: squares 1 + 1 + 16 + 16 over 3.
    EXPECT_DOUBLE_EQ(s.std, std::sqrt(34.0 / 3.0));
    EXPECT_EQ(value_stats(std::vector<double>{kNaN}).count, 0u);
    EXPECT_EQ(value_stats(std::vector<double>{4.0}).std, 0.0);
}

TEST(ReportSummary, SmallResidualsOnLargeOffsetsKeepTheirSpread) {
    // A micrometre of spread on 100 000 values near 500 mm.
    std::vector<double> values;
    for (int i = 0; i < 100000; ++i) values.push_back(500.0 + (i % 2 == 0 ? 0.001 : -0.001));
    EXPECT_NEAR(value_stats(values).std, 0.001 * std::sqrt(100000.0 / 99999.0), 1e-12);
}

TEST(ReportSummary, LargestMagnitudesComeFirstTiesInOrder) {
    const std::vector<double> values = {0.1, -0.5, kNaN, 0.5, 0.2, -0.05};
    EXPECT_EQ(largest_magnitudes(values, 3), (std::vector<std::size_t>{1, 3, 4}));
    EXPECT_EQ(largest_magnitudes(values, 10).size(), 5u);  // the NaN is no value
    EXPECT_TRUE(largest_magnitudes(values, 0).empty());
}

TEST(ReportSummary, TheTablesRead) {
    EXPECT_EQ(csv_stats_header(), "quantity,count,min_mm,max_mm,mean_mm,std_mm\n");
    EXPECT_EQ(csv_stats_row("residual", value_stats(std::vector<double>{-0.001, 0.003})),
              "residual,2,-0.001,0.003,0.001,0.0028\n");
    EXPECT_EQ(csv_stats_row("residual", ValueStats{}), "residual,0,,,,\n");
    EXPECT_EQ(csv_largest_heading("points", "residual_mm", 10, 290000),
              "# points: the 10 largest |residual_mm| of 290000\n");
}

}  // namespace
}  // namespace probecycle
