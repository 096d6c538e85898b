#include "core/cycle/sweep.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/common/units.h"

// domain.md, "Cycle time versus feed": the knee is the lowest feed whose cycle
// time is within a small tolerance (issue 2: 1 %) of the best over the range.

namespace probecycle {

namespace {

// The evaluation buffer the sweeps and knee searches reuse on this thread:
// its vectors are allocated once, not per evaluation.
CycleResult& scratch_result() {
    thread_local CycleResult scratch;
    return scratch;
}

// Evaluates `base` at a probe feed, into `scratch`; returns the cycle time.
double cycle_time_at(const Scenario& base, double feed_mm_min, const SweepOptions& options,
                     CycleResult& scratch) {
    Scenario s = base;
    s.cycle.probe_feed_mm_min = feed_mm_min;
    evaluate_into(s, scratch);
    if (options.recommended_backoff && s.cycle.strategy == Strategy::two_touch) {
        // The first touch does not depend on the backoff, so one pass tells it.
        s.cycle.backoff_mm = scratch.recommended_backoff_mm();
        evaluate_into(s, scratch);
    }
    return scratch.total();
}

}  // namespace

void sweep_feeds_into(const Scenario& scenario, std::span<const double> feeds_mm_min,
                      SweepResult& out, const SweepOptions& options) {
    CycleResult& scratch = scratch_result();
    out.points.resize(feeds_mm_min.size());
    double best_time = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < feeds_mm_min.size(); ++i) {
        SweepPoint& point = out.points[i];
        point.feed_mm_min = feeds_mm_min[i];
        point.cycle_time_s = cycle_time_at(scenario, feeds_mm_min[i], options, scratch);
        point.overtravel_mm = scratch.overtravel_mm();
        point.first_overtravel_mm = scratch.first_touch().overtravel_mm;
        point.second_overtravel_mm = scenario.cycle.strategy == Strategy::two_touch
                                         ? scratch.measuring_touch().overtravel_mm
                                         : 0.0;
        point.uncertainty_mm = scratch.uncertainty_mm();
        for (Phase phase : all_phases()) {
            point.phase_time_s[static_cast<std::size_t>(phase)] = scratch.phase_time(phase);
        }
        best_time = std::min(best_time, point.cycle_time_s);
    }

    out.knee_feed_mm_min.reset();
    out.max_feed_meeting_target_mm_min.reset();
    const double target = scenario.cycle.target_uncertainty_mm;
    for (const SweepPoint& point : out.points) {
        if (point.cycle_time_s <= best_time * (1.0 + kKneeTolerance) &&
            (!out.knee_feed_mm_min || point.feed_mm_min < *out.knee_feed_mm_min)) {
            out.knee_feed_mm_min = point.feed_mm_min;
        }
        if (target > 0.0 && point.uncertainty_mm <= target &&
            (!out.max_feed_meeting_target_mm_min ||
             point.feed_mm_min > *out.max_feed_meeting_target_mm_min)) {
            out.max_feed_meeting_target_mm_min = point.feed_mm_min;
        }
    }
}

SweepResult sweep_feeds(const Scenario& scenario, std::span<const double> feeds_mm_min,
                        const SweepOptions& options) {
    SweepResult out;
    sweep_feeds_into(scenario, feeds_mm_min, out, options);
    return out;
}

double linear_feed_count(double from_mm_min, double to_mm_min, double step_mm_min) {
    if (!(step_mm_min > 0.0) || to_mm_min < from_mm_min) return 0.0;
    return std::floor((to_mm_min - from_mm_min) / step_mm_min + 1e-9) + 1.0;
}

std::vector<double> linear_feeds(double from_mm_min, double to_mm_min, double step_mm_min) {
    std::vector<double> feeds;
    const auto count =
        static_cast<std::size_t>(linear_feed_count(from_mm_min, to_mm_min, step_mm_min));
    feeds.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        feeds.push_back(from_mm_min + static_cast<double>(i) * step_mm_min);
    }
    return feeds;
}

std::vector<double> log_feeds(double from_mm_min, double to_mm_min, std::size_t n) {
    std::vector<double> feeds;
    if (n < 2 || !(from_mm_min > 0.0) || to_mm_min < from_mm_min) return feeds;
    feeds.reserve(n);
    const double ratio = std::log(to_mm_min / from_mm_min);
    for (std::size_t i = 0; i < n; ++i) {
        feeds.push_back(from_mm_min *
                        std::exp(ratio * static_cast<double>(i) / static_cast<double>(n - 1)));
    }
    feeds.back() = to_mm_min;
    return feeds;
}

std::optional<double> find_knee_mm_min(const Scenario& scenario, double from_mm_min,
                                       double to_mm_min, const SweepOptions& options) {
    if (!(from_mm_min > 0.0) || !(to_mm_min > from_mm_min)) return std::nullopt;
    CycleResult& scratch = scratch_result();
    constexpr std::size_t kGrid = 48;
    const std::vector<double> grid = log_feeds(from_mm_min, to_mm_min, kGrid);
    std::array<double, kGrid> times{};
    std::size_t best = 0;
    for (std::size_t i = 0; i < kGrid; ++i) {
        times[i] = cycle_time_at(scenario, grid[i], options, scratch);
        if (times[i] < times[best]) best = i;
    }
    // Refine the minimum between the grid neighbours (golden section).
    double lo = grid[best == 0 ? 0 : best - 1];
    double hi = grid[std::min(best + 1, kGrid - 1)];
    double best_time = times[best];
    double best_feed = grid[best];
    constexpr double kInvPhi = 0.6180339887498949;
    for (int iter = 0; iter < 40 && hi - lo > 1e-9 * hi; ++iter) {
        const double x1 = hi - kInvPhi * (hi - lo);
        const double x2 = lo + kInvPhi * (hi - lo);
        const double t1 = cycle_time_at(scenario, x1, options, scratch);
        const double t2 = cycle_time_at(scenario, x2, options, scratch);
        for (const auto& [feed, time] : {std::pair{x1, t1}, std::pair{x2, t2}}) {
            if (time < best_time) {
                best_time = time;
                best_feed = feed;
            }
        }
        if (t1 < t2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    const double limit = best_time * (1.0 + kKneeTolerance);
    std::size_t first = 0;
    while (first < kGrid && times[first] > limit) ++first;
    if (first == 0) return grid[0];
    if (first == kGrid) return best_feed;  // only the refined minimum itself qualifies
    // Bisection for the crossing between the last grid feed above the limit and the first within.
    lo = grid[first - 1];
    hi = grid[first];
    for (int iter = 0; iter < 50 && hi - lo > 1e-6; ++iter) {
        const double mid = 0.5 * (lo + hi);
        if (cycle_time_at(scenario, mid, options, scratch) <= limit) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    return hi;
}

Analysis analyse(const Scenario& scenario) {
    const SweepOptions optimised{.recommended_backoff = true};
    Analysis analysis{evaluate(scenario), std::nullopt, std::nullopt};
    // Up to the scenario's own feed at least, so a feed beyond 10000 mm/min is
    // judged against a curve that reaches it.
    const double search_to = std::max(kKneeSearchTo_mm_min, scenario.cycle.probe_feed_mm_min);
    analysis.knee_feed_mm_min =
        find_knee_mm_min(scenario, kKneeSearchFrom_mm_min, search_to, optimised);
    if (!analysis.knee_feed_mm_min) return analysis;
    CycleResult& scratch = scratch_result();
    const double knee_feed = *analysis.knee_feed_mm_min;
    analysis.knee_cycle_time_s = cycle_time_at(scenario, knee_feed, optimised, scratch);
    const double feed = scenario.cycle.probe_feed_mm_min;
    if (feed > knee_feed * (1.0 + 1e-6)) {
        // Both times on the same (optimised) curve the knee was found on.
        const double feed_time = cycle_time_at(scenario, feed, optimised, scratch);
        analysis.cycle.mutable_warnings().push_back(
            {WarningCode::feed_beyond_knee, Severity::info, mm_min_to_mm_s(feed),
             mm_min_to_mm_s(knee_feed), *analysis.knee_cycle_time_s - feed_time});
    }
    return analysis;
}

}  // namespace probecycle
