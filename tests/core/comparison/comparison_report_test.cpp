// The comparison's report as text (core/comparison/comparison_report.h); the
// golden files hold the whole report of the simulated example.

#include "core/comparison/comparison_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace probecycle {
namespace {

std::size_t lines(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(ComparisonReport, ASummaryOfManyPointsHasTheLargestDeviationsFirst) {
    const ComparisonDataSet data = simulate_comparison({});
    const ComparisonResult result = run_comparison(data.input);
    const std::size_t count = result.points.size();
    ASSERT_GT(count, kReportFullRows);
    const std::string summary =
        comparison_report_csv(data.input, result, ReportHeader{}, ReportRows::summary);
    EXPECT_LT(lines(summary), 50u) << summary;
    EXPECT_EQ(summary.find("\n# points\n"), std::string::npos);
    EXPECT_NE(summary.find("\n# summary\n"), std::string::npos);
    // The point that deviates most leads the table.
    const auto worst = std::max_element(
        result.points.begin(), result.points.end(), [](const auto& a, const auto& b) {
            return std::abs(a.deviation_mm) < std::abs(b.deviation_mm);
        });
    const std::string heading =
        "\n# points: the 10 largest |deviation_mm| of " + std::to_string(count) + "\npoint,x_mm,";
    const std::size_t at = summary.find(heading);
    ASSERT_NE(at, std::string::npos) << summary;
    const std::size_t first_row = summary.find('\n', at + heading.size()) + 1;
    EXPECT_EQ(summary.substr(first_row, summary.find(',', first_row) - first_row),
              std::to_string(worst - result.points.begin() + 1));

    // The CSV export keeps every point.
    const std::string all = comparison_report_csv(data.input, result, ReportHeader{});
    EXPECT_GT(lines(all), count);
    EXPECT_NE(all.find("\n# points\n"), std::string::npos);
}

}  // namespace
}  // namespace probecycle
