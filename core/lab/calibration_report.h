#pragma once

// The calibration report, as CSV text: the sections an engineer files with the
// probe's calibration record, each a CSV table, in the style of csv_report
// (report.h). The Calibration tab exports it; `calibrate ring --report` writes it.

#include <optional>
#include <span>
#include <string>

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

// Sections "# ring", "# fits", "# points", "# length", "# warnings"; the ring
// sections without a ring result and "# length" without a length result are
// left out. Numbers in C locale, 9 significant digits; unknowns empty.
std::string calibration_report_csv(const std::optional<RingReportInput>& ring,
                                   const std::optional<LengthReportInput>& length);

}  // namespace probecycle
