#pragma once

// The delay fit's report, as CSV text: the Latency tab's export
// and `latency fit --report`, the same bytes. The header and the number
// formats of every report (report_header.h, csv_writer.h).

#include <span>
#include <string>

#include "core/common/report_header.h"
#include "core/common/report_summary.h"
#include "core/lab/delay_fit.h"

namespace probecycle {

// The header (subject "touches": the touches' file name, or "pasted"), then
// sections "# fit" (the interpolation period), "# groups" (per axis and
// direction: the delay, p0, the lag in cycles, the residual), "# feeds" (the
// delay's stability: each feed's mean deviation from p0 and its range),
// "# touches" (each touch's residual from its line) and "# warnings". A
// summary (report_summary.h) of more than kReportFullRows feeds or touches
// gives, in place of the table, its statistics ("# feeds summary": the mean's
// distance from the line; "# touches summary": the residual per group) and
// its 10 rows farthest from the line.
std::string delay_fit_report_csv(std::span<const DelayTouch> touches,
                                 const DelayFitOptions& options, const DelayFit& fit,
                                 const ReportHeader& header, ReportRows rows = ReportRows::all);

}  // namespace probecycle
