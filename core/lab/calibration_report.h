#pragma once

// The calibration report, as CSV text: the sections an engineer files with the
// probe's calibration record, each a CSV table, in the style of csv_report
// (cycle_report.h). The Calibration tab exports it; `calibrate ring --report` writes it.

#include <optional>
#include <span>
#include <string>

#include "core/common/report_header.h"
#include "core/common/report_summary.h"
#include "core/lab/calibration.h"

namespace probecycle {

struct RingReportInput {
    std::span<const RingPoint> points;
    RingCalibrationOptions options;
    RingCalibration result;
};

struct LengthReportInput {
    LengthCalibrationInput input;
    LengthCalibration result;
};

// The header (report_header.h; subject "points": the ring points' file name,
// or "pasted"), then sections "# ring", "# fits", "# points", "# length",
// "# warnings"; the ring sections without a ring result and "# length"
// without a length result are left out. Results to 0.1 um, inputs as given
// (csv_writer.h); unknowns empty. A summary (report_summary.h) of more than
// kReportFullRows points has "# points summary" (the effective radius's and
// the residual's statistics) and "# points: the 10 largest |residual_mm| of N"
// in place of "# points".
std::string calibration_report_csv(const std::optional<RingReportInput>& ring,
                                   const std::optional<LengthReportInput>& length,
                                   const ReportHeader& header, ReportRows rows = ReportRows::all);

}  // namespace probecycle
