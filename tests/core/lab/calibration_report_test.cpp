// The calibration report as text (core/calibration_report.h); the Calibration
// tab's test checks the report of a ring fit through export_report().

#include "core/lab/calibration_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace probecycle {
namespace {

TEST(CalibrationReport, LengthOnlyHasNoRingSections) {
    LengthReportInput length;
    length.input.surface_z_mm = 10.0;
    length.input.trigger_z_mm = {110.0};
    length.result = calibrate_length(length.input);
    const std::string csv =
        calibration_report_csv(std::nullopt, length, {.date = "2026-11-26", .subject = "pasted"});
    EXPECT_EQ(csv.find("# ring"), std::string::npos);
    EXPECT_EQ(csv.find("# points\n"), std::string::npos);
    // The header of every report (report_header.h), then the length.
    EXPECT_EQ(csv.rfind("# ProbeCycle calibration report\n# date,2026-11-26\n# version,", 0), 0u)
        << csv;
    EXPECT_NE(csv.find("\n# points,pasted\n\n# length\nquantity,value,unit\nsurface_z,10,mm\n"),
              std::string::npos)
        << csv;
    EXPECT_NE(csv.find("effective_length,100,mm\nwear,,mm\n"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\n# warnings\ncode,severity,message\n"), std::string::npos) << csv;
}

TEST(CalibrationReport, WarningsAreQuotedWithTheirCode) {
    LengthReportInput length;
    length.input.surface_z_mm = 10.0;
    length.input.trigger_z_mm = {110.0};
    length.input.nominal_length_mm = 90.0;  // 10 mm of "wear": a wrong nominal
    length.result = calibrate_length(length.input);
    ASSERT_FALSE(length.result.warnings.empty());
    const std::string csv = calibration_report_csv(std::nullopt, length, ReportHeader{});
    EXPECT_NE(csv.find("\nlength_wear,warning,\"the effective length"), std::string::npos) << csv;
}

// 10 000 points on a 50 mm ring, a micrometre out of round, and one 20 um
// out (a chip on the gauge).
RingReportInput ring_of(std::size_t count, std::vector<RingPoint>& points) {
    points.clear();
    for (std::size_t i = 0; i < count; ++i) {
        const double angle =
            2.0 * std::numbers::pi * static_cast<double>(i / 2) / static_cast<double>(count / 2);
        const double r = 23.5 + 0.001 * std::sin(3.0 * angle) + (i == 777 ? 0.02 : 0.0);
        points.push_back(
            {i % 2 == 0 ? 0.0 : 180.0, r * std::cos(angle), r * std::sin(angle), i + 2});
    }
    RingReportInput ring;
    ring.points = points;
    ring.options.gauge_diameter_mm = 50.0;
    ring.result = calibrate_ring(points, ring.options);
    return ring;
}

TEST(CalibrationReport, ASummaryOfManyPointsHasTheirStatisticsAndTheLargestResiduals) {
    std::vector<RingPoint> points;
    const RingReportInput ring = ring_of(10000, points);
    const std::string summary =
        calibration_report_csv(ring, std::nullopt, ReportHeader{}, ReportRows::summary);
    EXPECT_LT(std::count(summary.begin(), summary.end(), '\n'), 60) << summary;
    EXPECT_EQ(summary.find("\n# points\n"), std::string::npos);
    EXPECT_NE(summary.find("\n# points summary\nquantity,count,min_mm,max_mm,mean_mm,std_mm\n"
                           "effective_radius,10000,"),
              std::string::npos)
        << summary;
    EXPECT_NE(summary.find("\nresidual,10000,"), std::string::npos) << summary;
    // The chip comes first: line 779, 20 um out.
    EXPECT_NE(summary.find("\n# points: the 10 largest |residual_mm| of 10000\n"
                           "line,orientation_deg,x_mm,y_mm,direction,effective_radius_mm,"
                           "residual_mm\n779,180,"),
              std::string::npos)
        << summary;

    // The CSV export keeps every point, and a few points stay whole in a summary.
    const std::string all = calibration_report_csv(ring, std::nullopt, ReportHeader{});
    EXPECT_GT(std::count(all.begin(), all.end(), '\n'), 10000);
    const std::string few = calibration_report_csv(ring_of(kReportFullRows, points), std::nullopt,
                                                   ReportHeader{}, ReportRows::summary);
    EXPECT_EQ(few, calibration_report_csv(ring_of(kReportFullRows, points), std::nullopt,
                                          ReportHeader{}));
}

}  // namespace
}  // namespace probecycle
