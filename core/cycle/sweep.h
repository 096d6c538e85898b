#pragma once

// Cycle time against feed (docs/model.md, "Cycle time against feed").

#include <array>
#include <optional>
#include <span>
#include <vector>

#include "core/cycle/cycle.h"
#include "core/cycle/scenario.h"

namespace probecycle {

struct SweepPoint {
    double feed_mm_min{0.0};
    double cycle_time_s{0.0};
    double overtravel_mm{0.0};  // the worst touch's
    // The worst touch's at up to the highest feed override, which
    // the limit is checked against (CycleResult::checked_overtravel_mm).
    double checked_overtravel_mm{0.0};
    // Of each touch, at up to the highest feed override: a fast first touch
    // can overtravel less than the second (two-touch with a fixed backoff).
    // second is 0 for single-touch.
    double first_overtravel_mm{0.0};
    double second_overtravel_mm{0.0};
    double uncertainty_mm{0.0};
    std::array<double, kPhaseCount> phase_time_s{};  // by Phase, summed over touches
    // CycleResult::invalid_codes() at this feed (0: a valid cycle).
    unsigned invalid_codes{0};
    // Whether the first touch meets the surface at this feed (reaches_feed());
    // a feed it never reaches does not count for the knee.
    bool feed_reached{true};
    bool valid() const { return invalid_codes == 0; }
    // Valid for the knee (valid_for_knee()) and at the feed it says.
    bool counts_for_knee() const { return valid_for_knee(invalid_codes) && feed_reached; }
};

struct SweepResult {
    std::vector<SweepPoint> points;
    // Lowest feed whose cycle time is within cycle.knee_tolerance of the
    // fastest, both among the valid feeds (CycleResult::valid(): overtravel
    // under the probe's limit, backoff enough) that the first touch reaches
    // (SweepPoint::counts_for_knee); none when no feed is.
    std::optional<double> knee_feed_mm_min;
    // Highest valid feed whose uncertainty meets the target (none without a
    // target or when no valid feed meets it).
    std::optional<double> max_feed_meeting_target_mm_min;
    // knee_at_range_end when the fastest valid cycle lies at the lowest or
    // the highest feed of the sweep: the knee then depends on the range.
    std::vector<Warning> warnings;
};

struct SweepOptions {
    // Two-touch: at each feed set the backoff to the recommended one (first
    // touch's overtravel + reseat) instead of the scenario's, i.e. the curve of
    // an optimised cycle (docs/model.md, "Strategies and features"). Costs a
    // second evaluation.
    bool recommended_backoff{false};
};

// Varies cycle.probe_feed_mm_min over the given feeds (the rest as in the scenario).
SweepResult sweep_feeds(const Scenario& scenario, std::span<const double> feeds_mm_min,
                        const SweepOptions& options = {});
// Same into a caller's buffer, reused across calls (the UI's slider path).
void sweep_feeds_into(const Scenario& scenario, std::span<const double> feeds_mm_min,
                      SweepResult& out, const SweepOptions& options = {});
// from, from+step, ... while <= to (to itself when it falls on the grid).
std::vector<double> linear_feeds(double from_mm_min, double to_mm_min, double step_mm_min);
// How many feeds linear_feeds() would make, without making them (0 for an
// empty range or a step that is not positive).
double linear_feed_count(double from_mm_min, double to_mm_min, double step_mm_min);
// n feeds spaced evenly on a log scale from..to inclusive (n >= 2).
std::vector<double> log_feeds(double from_mm_min, double to_mm_min, std::size_t n);

// The knee searched continuously between from and to: a log grid, golden
// section around the fastest cycle, bisection for the knee. Valid feeds only:
// the search stops at the feed where the cycle turns invalid (overtravel
// reaches the probe's limit, or a fixed backoff becomes too small; both grow
// with feed, so feeds beyond the first invalid one are not looked at), or
// where the first touch no longer reaches the feed from its start (that too
// only grows with the feed).
struct KneeSearch {
    std::optional<double> knee_feed_mm_min;  // none when even `from` is invalid
    std::optional<double> best_feed_mm_min;  // where the fastest valid cycle lies
    double best_cycle_time_s{0.0};
    // Highest valid feed searched: `to`, or where the cycle turns invalid or
    // the feed is no longer reached.
    double valid_to_mm_min{0.0};
    // knee_at_range_end when the fastest cycle lies at `from` or at `to`.
    std::optional<Warning> range_end_warning;
    // No knee because `from` is valid but the first touch does not reach it.
    bool none_reached{false};
};
KneeSearch find_knee(const Scenario& scenario, double from_mm_min, double to_mm_min,
                     const SweepOptions& options = {});

// Feed range in which analyse() looks for the knee: 10 to 10000 mm/min, or
// up to the scenario's probe feed when that is higher.
constexpr double kKneeSearchFrom_mm_min = 10.0;
constexpr double kKneeSearchTo_mm_min = 10000.0;

// evaluate() plus the warnings that need a sweep (feed_beyond_knee,
// knee_at_range_end). The knee
// of a two-touch cycle is that of the optimised cycle (recommended backoff at
// every feed): with a fixed backoff, fast first touches overtravel into it.
struct Analysis {
    CycleResult cycle;
    std::optional<double> knee_feed_mm_min;
    // Cycle time at the knee, on the curve it was found on.
    std::optional<double> knee_cycle_time_s;
};
Analysis analyse(const Scenario& scenario);

}  // namespace probecycle
