// The calibration report as text (core/calibration_report.h); the Calibration
// tab's test checks the report of a ring fit through export_report().

#include "core/lab/calibration_report.h"

#include <gtest/gtest.h>

#include <string>

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

}  // namespace
}  // namespace probecycle
