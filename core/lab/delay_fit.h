#pragma once

// The total trigger delay from touches at several feeds: the delay-stability
// test of ISO 230-10 (docs/cli.md, "Delay fit").

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/message.h"
#include "core/common/severity.h"
#include "core/cycle/scenario.h"  // the delay is applied to a scenario

namespace probecycle {

// One touch of the test.
struct DelayTouch {
    std::string axis;  // "X", "Y", "Z", ... (upper case)
    int direction{1};  // +1 or -1, the direction of travel
    double feed_mm_min{0.0};
    double measured_mm{0.0};  // the position the control recorded
    std::size_t line{0};      // line in the input file, for messages; 0 when typed in
};

enum class LatencyWarningCode {
    few_feeds,          // fewer than 3 feeds: linearity unchecked
    unstable_delay,     // scatter at one feed much larger than the others predict
    curved_residuals,   // the delay changes with speed
    negative_delay,     // the position moves against the travel: direction column?
    single_touch_feed,  // a feed touched once: no scatter there
};
const char* to_string(LatencyWarningCode code);

struct LatencyWarning {
    LatencyWarningCode code{};
    Severity severity{};
    // Code, template (context "DelayFit") and the numbers as named arguments,
    // the group ("X+") first; the window translates it, the CLI renders it.
    Message message;
    std::string text() const;  // in English: render(message)
};

struct FeedScatter {
    double feed_mm_min{0.0};
    double mean_mm{0.0};
    double range_mm{0.0};  // max - min at this feed
    std::size_t n{0};
};

struct DelayGroup {
    std::string axis;
    int direction{1};
    // measured = p0 + direction * v * tau, v = feed / 60 (docs/cli.md, "Delay
    // fit").
    double delay_s{0.0};                 // tau
    double zero_speed_position_mm{0.0};  // p0
    std::optional<double> lag_cycles;    // tau / T_ipo, when the period is given
    // 2 x the residual standard deviation of the line; nullopt with no
    // degrees of freedom (two touches).
    std::optional<double> residual_2sigma_mm;
    std::vector<FeedScatter> feeds;  // ascending feed
    std::vector<std::size_t> lines;  // lines of its touches
    std::vector<LatencyWarning> warnings;

    // "X+" / "Z-".
    std::string name() const;
    // The fitted line at a feed.
    double predicted_mm(double feed_mm_min) const;
};

struct DelayFitOptions {
    std::optional<double> interpolation_period_s;
    // unstable_delay: a feed's range above `unstable_ratio` times what the
    // other feeds predict at its speed, and above `scatter_floor_mm`.
    double unstable_ratio{3.0};
    double scatter_floor_mm{0.002};
    // curved_residuals: the quadratic departs from the line by more than this
    // at some feed, and its curvature term is significant (|t| > 3).
    double curvature_floor_mm{0.002};
};

// Groups in the order their first touch appears.
struct DelayFit {
    std::vector<DelayGroup> groups;
};

// Parses `axis,direction,feed_mm_min,measured_mm`. Throws CsvError naming the
// line and column.
std::vector<DelayTouch> parse_delay_csv(std::string_view text);

// Least-squares line per (axis, direction) over all touches. Throws CsvError
// naming the lines of a group whose touches are all at one feed.
DelayFit fit_delay(std::span<const DelayTouch> touches, const DelayFitOptions& options = {});

// Putting a fitted delay into a scenario. The fitted tau is the whole delay
// from trigger to recorded position: the interface, the controller, and on
// average half a scan period (docs/model.md, "One touch": phases 3 and 4; the
// calibration's measurement delay tau counts the same three). The scenario
// keeps the interface delay and the scan period as keys of their own, so the
// controller latency is what remains: tau - t_i - t_s/2. With a latched input
// the position is captured in hardware when the signal reaches the control, so
// tau is the interface delay alone: it goes into probe.interface_delay_s, and
// the controller latency (which still lengthens the overtravel) is left alone.
struct AppliedDelay {
    std::string group;  // "X+", the group whose delay was used
    Message rule;       // why that group
    double total_delay_s{0.0};
    double interface_delay_s{0.0};
    double half_scan_s{0.0};
    bool latched{false};
    // The key written: machine.controller_latency_s, or probe.interface_delay_s
    // with a latched input; its value before and after.
    std::string key;
    double previous_s{0.0};
    double value_s{0.0};
};
// The group whose delay goes into the scenario: the named one
// (case-insensitive), the only one, or else the one with the longest delay.
// Throws InputError (a std::invalid_argument) for an unknown name or a fit with
// no groups.
struct ChosenGroup {
    const DelayGroup* group{nullptr};
    Message rule;  // why that group: "the only group", ...
};
ChosenGroup choose_group(const DelayFit& fit, const std::optional<std::string>& name);

// Uses the named group (case-insensitive), the only group, or else the
// longest delay: the scenario has one delay for every axis, and the longest
// gives the longest overtravel (the safe side for the stylus). Throws
// InputError (a std::invalid_argument) naming the problem: an unknown group, a
// fit with no groups, or a delay shorter than t_i + t_s/2 (a negative latency).
AppliedDelay delay_to_apply(const DelayFit& fit, const Scenario& scenario,
                            const std::optional<std::string>& group = std::nullopt);
// The scenario with the applied delay (validated; throws ScenarioError).
Scenario apply_delay(const Scenario& scenario, const AppliedDelay& applied);

// The straight-line fit alone: y = p0 + slope * x, least squares.
struct LineFit {
    double intercept{0.0};
    double slope{0.0};
};
// Needs two distinct x; nullopt otherwise.
std::optional<LineFit> fit_line(std::span<const double> x, std::span<const double> y);

}  // namespace probecycle
