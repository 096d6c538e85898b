#pragma once

// Text forms of results, shared by the CLI and the window so both write the
// same bytes: evaluation JSON, sweep CSV, and the full CSV report.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/report_header.h"
#include "core/cycle/cycle.h"
#include "core/cycle/monte_carlo.h"
#include "core/cycle/scenario.h"
#include "core/cycle/sweep.h"

namespace probecycle {

// `probecycle-cli evaluate` output: cycle_time_s, overtravel_mm, ... phases,
// warnings; each warning with a one-click fix (fixes.h) carries `fix`, the
// scenario keys the fix sets and their values, as the window's button does.
std::string evaluation_to_json(const Scenario& scenario, const Analysis& analysis);

// `probecycle-cli move`: time_s (to the in-position check with dynamics
// after interpolation), the interpolator's command_time_s, peak_speed_mm_min
// (commanded), accel_model and filter of one rest-to-rest move of the
// scenario's axis (distance in mm, feed in mm/min).
std::string move_to_json(const Scenario& scenario, double distance_mm, double feed_mm_min);
// `probecycle-cli montecarlo`: the options and the histogram.
std::string monte_carlo_to_json(const MonteCarloOptions& options, const Histogram& histogram);

// Header: feed_mm_min,cycle_time_s,overtravel_mm,uncertainty_mm,<one column per phase>,
// valid,invalid_reasons; with `optimised` (the same feeds, two-touch with the
// recommended backoff at each) a last column cycle_time_recommended_backoff_s,
// the curve the knee is found on.
std::string sweep_to_csv(const SweepResult& sweep, const SweepResult* optimised = nullptr);
// One line: the knee as evaluate() and the window find it (find_knee on the
// optimised curve), searched over the sweep's feeds, and the fastest valid
// feed meeting the target.
std::string sweep_summary(const SweepResult& sweep, const Scenario& scenario);

// Feeds of the report's sweep table: round numbers from 10 to 10000 mm/min,
// plus the scenario's feed and its knee (exactly, so that row repeats the
// summary's knee_cycle_time).
std::vector<double> report_feeds(const Scenario& scenario, const Analysis& analysis);

// The report an engineer hands over: the header (report_header.h: title,
// date, version, the scenario's file name), then sections "# scenario" (the
// values as given), "# summary" (evaluate's keys, docs/cli.md), "# phases",
// "# warnings", "# sweep", each a CSV table, numbers to the digits the model
// supports (csv_writer.h). The sweep varies the probe feed over `feeds` with
// the rest as in the scenario (and, for two-touch, also with the recommended
// backoff: sweep_to_csv's last column).
std::string csv_report(const Scenario& scenario, const Analysis& analysis,
                       std::span<const double> feeds_mm_min, const ReportHeader& header);
// The same, analysed and swept over report_feeds(): what the window exports
// and `probecycle-cli report` writes.
std::string csv_report(const Scenario& scenario, const ReportHeader& header);

}  // namespace probecycle
