// The delay fit's report as text (core/lab/delay_fit_report.h); the golden
// files hold the whole report of the lab's example.

#include "core/lab/delay_fit_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace probecycle {
namespace {

// X+ with an 8.5 ms delay from 10 mm: `count` touches over `feeds` feeds,
// a micrometre of scatter, one touch 30 um out.
std::vector<DelayTouch> touches_of(std::size_t count, std::size_t feeds) {
    std::vector<DelayTouch> touches;
    for (std::size_t i = 0; i < count; ++i) {
        const double feed = 100.0 + 10.0 * static_cast<double>(i % feeds);
        const double scatter = (i % 3 == 0 ? 0.001 : -0.0005) + (i == 4321 ? 0.03 : 0.0);
        touches.push_back({"X", 1, feed, 10.0 + feed / 60.0 * 0.0085 + scatter, i + 2});
    }
    return touches;
}

std::size_t lines(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(DelayFitReport, ASummaryOfManyTouchesAndFeedsHasTheirStatisticsAndTheLargest) {
    const std::vector<DelayTouch> touches = touches_of(10000, 200);
    const DelayFit fit = fit_delay(touches);
    const std::string summary =
        delay_fit_report_csv(touches, {}, fit, ReportHeader{}, ReportRows::summary);
    EXPECT_LT(lines(summary), 60u) << summary;
    EXPECT_NE(summary.find("\n# touches summary\nquantity,count,min_mm,max_mm,mean_mm,std_mm\n"
                           "residual X+,10000,"),
              std::string::npos)
        << summary;
    EXPECT_NE(summary.find("\n# touches: the 10 largest |residual_mm| of 10000\n"
                           "line,group,feed_mm_min,measured_mm,residual_mm\n4323,X+,"),
              std::string::npos)
        << summary;
    EXPECT_NE(summary.find("\n# feeds summary\n"), std::string::npos) << summary;
    EXPECT_NE(summary.find("\n# feeds: the 10 largest |mean_deviation_mm - fitted_deviation_mm| "
                           "of 200\n"),
              std::string::npos)
        << summary;

    // The CSV export keeps every touch and every feed.
    const std::string all = delay_fit_report_csv(touches, {}, fit, ReportHeader{});
    EXPECT_GT(lines(all), 10200u);
    EXPECT_NE(all.find("\n# touches\n"), std::string::npos);
    EXPECT_NE(all.find("\n# feeds\n"), std::string::npos);
}

TEST(DelayFitReport, AFewTouchesStayWholeInASummary) {
    const std::vector<DelayTouch> touches = touches_of(kReportFullRows, 5);
    const DelayFit fit = fit_delay(touches);
    EXPECT_EQ(delay_fit_report_csv(touches, {}, fit, ReportHeader{}, ReportRows::summary),
              delay_fit_report_csv(touches, {}, fit, ReportHeader{}));
}

}  // namespace
}  // namespace probecycle
