#include "core/cycle/sweep.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/cycle/motion_cache.h"

// docs/model.md, "Cycle time against feed": the knee is the lowest feed whose
// cycle time is within a small tolerance (cycle.knee_tolerance, 1 % by default)
// of the best over the range, among the valid feeds only (CycleResult::valid():
// overtravel under the probe's limit, backoff enough), and a fastest cycle at
// an end of the range is said (knee_at_range_end), since the knee then depends
// on the range.

namespace probecycle {

namespace {

// The evaluation buffer the sweeps and knee searches reuse on this thread:
// its vectors are allocated once, not per evaluation; with it, the solves
// that do not change with the feed (MotionCache).
CycleResult& scratch_result() {
    thread_local CycleResult scratch;
    return scratch;
}
MotionCache& scratch_cache() {
    thread_local MotionCache cache;
    return cache;
}

// Whether the evaluation in `scratch` counts for the knee: valid for it, and at
// the feed it says (a cycle whose first touch never reaches its feed can look
// faster only because of that).
bool counts_for_knee(const CycleResult& scratch) {
    return valid_for_knee(scratch.invalid_codes()) && reaches_feed(scratch.first_touch());
}

// Evaluates `base` at a probe feed, into `scratch`; returns the cycle time.
double cycle_time_at(const Scenario& base, double feed_mm_min, const SweepOptions& options,
                     CycleResult& scratch) {
    Scenario s = base;
    s.cycle.probe_feed_mm_min = feed_mm_min;
    evaluate_into(s, scratch, scratch_cache(), Detail::summary);
    if (options.recommended_backoff && s.cycle.strategy == Strategy::two_touch) {
        // The first touch does not depend on the backoff, so one pass tells it.
        s.cycle.backoff_mm = scratch.recommended_backoff_mm();
        evaluate_into(s, scratch, scratch_cache(), Detail::summary);
    }
    return scratch.total();
}

Warning range_end_warning(double end_feed_mm_min, double knee_feed_mm_min, bool highest) {
    return {Severity::info, warning::KneeAtRangeEnd{mm_min_to_mm_s(end_feed_mm_min),
                                                    mm_min_to_mm_s(knee_feed_mm_min), highest}};
}

}  // namespace

void sweep_feeds_into(const Scenario& scenario, std::span<const double> feeds_mm_min,
                      SweepResult& out, const SweepOptions& options) {
    CycleResult& scratch = scratch_result();
    out.points.resize(feeds_mm_min.size());
    double best_time = std::numeric_limits<double>::infinity();
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < feeds_mm_min.size(); ++i) {
        SweepPoint& point = out.points[i];
        point.feed_mm_min = feeds_mm_min[i];
        point.cycle_time_s = cycle_time_at(scenario, feeds_mm_min[i], options, scratch);
        point.overtravel_mm = scratch.overtravel_mm();
        point.checked_overtravel_mm = scratch.checked_overtravel_mm();
        point.first_overtravel_mm = scratch.first_touch().override_overtravel_mm;
        point.second_overtravel_mm = scenario.cycle.strategy == Strategy::two_touch
                                         ? scratch.measuring_touch().override_overtravel_mm
                                         : 0.0;
        point.uncertainty_mm = scratch.uncertainty_mm();
        for (Phase phase : all_phases()) {
            point.phase_time_s[static_cast<std::size_t>(phase)] = scratch.phase_time(phase);
        }
        point.invalid_codes = scratch.invalid_codes();
        point.feed_reached = reaches_feed(scratch.first_touch());
        if (point.counts_for_knee() && point.cycle_time_s < best_time) {
            best_time = point.cycle_time_s;
            best = i;
        }
    }

    out.knee_feed_mm_min.reset();
    out.max_feed_meeting_target_mm_min.reset();
    out.warnings.clear();
    const double target = scenario.cycle.target_uncertainty_mm;
    const double knee_limit = best_time * (1.0 + scenario.cycle.knee_tolerance);
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -std::numeric_limits<double>::infinity();
    for (const SweepPoint& point : out.points) {
        lowest = std::min(lowest, point.feed_mm_min);
        highest = std::max(highest, point.feed_mm_min);
        if (point.counts_for_knee() && point.cycle_time_s <= knee_limit &&
            (!out.knee_feed_mm_min || point.feed_mm_min < *out.knee_feed_mm_min)) {
            out.knee_feed_mm_min = point.feed_mm_min;
        }
        if (target > 0.0 && valid_for_knee(point.invalid_codes) && point.uncertainty_mm <= target &&
            (!out.max_feed_meeting_target_mm_min ||
             point.feed_mm_min > *out.max_feed_meeting_target_mm_min)) {
            out.max_feed_meeting_target_mm_min = point.feed_mm_min;
        }
    }
    if (best && out.knee_feed_mm_min && highest > lowest) {
        const double best_feed = out.points[*best].feed_mm_min;
        if (best_feed == highest || best_feed == lowest) {
            out.warnings.push_back(
                range_end_warning(best_feed, *out.knee_feed_mm_min, best_feed == highest));
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

KneeSearch find_knee(const Scenario& scenario, double from_mm_min, double to_mm_min,
                     const SweepOptions& options) {
    KneeSearch out;
    if (!(from_mm_min > 0.0) || !(to_mm_min >= from_mm_min)) return out;
    CycleResult& scratch = scratch_result();
    const auto time_at = [&](double feed) {
        return cycle_time_at(scenario, feed, options, scratch);
    };
    if (to_mm_min == from_mm_min) {
        // One feed (a sweep from a feed to itself): the knee of a single valid
        // feed is that feed; there is no range whose end it could be.
        const double t = time_at(from_mm_min);
        if (!counts_for_knee(scratch)) {
            out.none_reached = valid_for_knee(scratch.invalid_codes());
            return out;
        }
        out.valid_to_mm_min = from_mm_min;
        out.best_feed_mm_min = from_mm_min;
        out.best_cycle_time_s = t;
        out.knee_feed_mm_min = from_mm_min;
        return out;
    }
    // A log grid of the valid feeds: it ends at the first invalid one, where a
    // bisection finds the last valid feed, which closes the grid.
    constexpr std::size_t kGrid = 48;
    const std::vector<double> grid = log_feeds(from_mm_min, to_mm_min, kGrid);
    std::array<double, kGrid + 1> feeds{};
    std::array<double, kGrid + 1> times{};
    std::size_t n = 0;
    bool cut = false;
    for (std::size_t i = 0; i < kGrid; ++i) {
        const double t = time_at(grid[i]);
        if (!counts_for_knee(scratch)) {
            out.none_reached = i == 0 && valid_for_knee(scratch.invalid_codes());
            cut = true;
            break;
        }
        feeds[n] = grid[i];
        times[n] = t;
        ++n;
    }
    if (n == 0) return out;
    out.valid_to_mm_min = to_mm_min;
    if (cut) {
        double lo = feeds[n - 1];
        double hi = grid[n];
        for (int iter = 0; iter < 60 && hi - lo > 1e-7 * hi; ++iter) {
            const double mid = 0.5 * (lo + hi);
            time_at(mid);
            (counts_for_knee(scratch) ? lo : hi) = mid;
        }
        out.valid_to_mm_min = lo;
        if (lo > feeds[n - 1]) {
            feeds[n] = lo;
            times[n] = time_at(lo);
            ++n;
        }
    }
    std::size_t best = 0;
    for (std::size_t i = 1; i < n; ++i) {
        if (times[i] < times[best]) best = i;
    }
    // Refine the minimum between the grid neighbours: golden section, one new
    // cycle per step.
    double best_time = times[best];
    double best_feed = feeds[best];
    {
        double a = feeds[best == 0 ? 0 : best - 1];
        double b = feeds[std::min(best + 1, n - 1)];
        constexpr double kInvPhi = 0.6180339887498949;
        double x1 = b - kInvPhi * (b - a);
        double x2 = a + kInvPhi * (b - a);
        double f1 = time_at(x1);
        double f2 = time_at(x2);
        const auto consider = [&](double feed, double time) {
            if (time < best_time) {
                best_time = time;
                best_feed = feed;
            }
        };
        consider(x1, f1);
        consider(x2, f2);
        for (int iter = 0; iter < 80 && b - a > 1e-9 * b; ++iter) {
            if (f1 < f2) {
                b = x2;
                x2 = x1;
                f2 = f1;
                x1 = b - kInvPhi * (b - a);
                f1 = time_at(x1);
                consider(x1, f1);
            } else {
                a = x1;
                x1 = x2;
                f1 = f2;
                x2 = a + kInvPhi * (b - a);
                f2 = time_at(x2);
                consider(x2, f2);
            }
        }
    }
    out.best_feed_mm_min = best_feed;
    out.best_cycle_time_s = best_time;
    const double limit = best_time * (1.0 + scenario.cycle.knee_tolerance);
    std::size_t first = 0;
    while (first < n && times[first] > limit) ++first;
    if (first == 0) {
        out.knee_feed_mm_min = feeds[0];
    } else if (first == n) {
        out.knee_feed_mm_min = best_feed;  // only the refined minimum itself qualifies
    } else {
        // Bisection for the crossing between the last grid feed above the limit
        // and the first within.
        double lo = feeds[first - 1];
        double hi = feeds[first];
        for (int iter = 0; iter < 50 && hi - lo > 1e-6; ++iter) {
            const double mid = 0.5 * (lo + hi);
            (time_at(mid) <= limit ? hi : lo) = mid;
        }
        out.knee_feed_mm_min = hi;
    }
    // A feed of the editors' digits, so that the readout, the one-click fix,
    // the report and the CLI name the same feed: rounded up, so that its cycle
    // stays within the tolerance (the curve falls towards the fastest cycle),
    // unless that would pass the last valid feed.
    {
        const double knee = *out.knee_feed_mm_min;
        const double up = round_feed_up(knee);
        out.knee_feed_mm_min = up <= out.valid_to_mm_min ? up : round_feed_down(knee);
    }
    // At an end of the searched range the fastest cycle may lie beyond it. Not
    // when invalid cycles end the range: that end does not move.
    const bool at_low = best_feed == from_mm_min;
    const bool at_high = best_feed == to_mm_min && !cut;
    if (at_low || at_high) {
        out.range_end_warning = range_end_warning(best_feed, *out.knee_feed_mm_min, at_high);
    }
    return out;
}

Analysis analyse(const Scenario& scenario) {
    const SweepOptions optimised{.recommended_backoff = true};
    Analysis analysis{evaluate(scenario), std::nullopt, std::nullopt};
    // Up to the scenario's own feed at least, so a feed beyond 10000 mm/min is
    // judged against a curve that reaches it.
    const double search_to = std::max(kKneeSearchTo_mm_min, scenario.cycle.probe_feed_mm_min);
    const KneeSearch knee = find_knee(scenario, kKneeSearchFrom_mm_min, search_to, optimised);
    analysis.knee_feed_mm_min = knee.knee_feed_mm_min;
    std::vector<Warning>& warnings = analysis.cycle.mutable_warnings();
    if (!analysis.knee_feed_mm_min) {
        // No feed of the range counts: say why there is no knee.
        warnings.emplace_back(Severity::warning,
                              warning::NoValidFeed{mm_min_to_mm_s(kKneeSearchFrom_mm_min),
                                                   mm_min_to_mm_s(search_to), knee.none_reached});
        order_by_severity(warnings);
        return analysis;
    }
    if (knee.range_end_warning) warnings.push_back(*knee.range_end_warning);
    CycleResult& scratch = scratch_result();
    const double knee_feed = *analysis.knee_feed_mm_min;
    analysis.knee_cycle_time_s = cycle_time_at(scenario, knee_feed, optimised, scratch);
    const double feed = scenario.cycle.probe_feed_mm_min;
    if (feed > knee_feed * (1.0 + 1e-6)) {
        // Both times on the same (optimised) curve the knee was found on. A
        // feed the first touch does not reach may be faster than the knee
        // only because of that: then not "no faster".
        const double feed_time = cycle_time_at(scenario, feed, optimised, scratch);
        if (!reaches_feed(scratch.first_touch()) && feed_time < *analysis.knee_cycle_time_s) {
            order_by_severity(warnings);
            return analysis;
        }
        warnings.emplace_back(
            Severity::info, warning::FeedBeyondKnee{mm_min_to_mm_s(feed), mm_min_to_mm_s(knee_feed),
                                                    *analysis.knee_cycle_time_s - feed_time,
                                                    scenario.cycle.knee_tolerance});
    }
    order_by_severity(warnings);
    return analysis;
}

// --- The knee's messages (warning.h). ---

namespace warning {

Message FeedBeyondKnee::message(Severity /*severity*/) const {
    if (time_saved_s <= 0.0) {
        return warning_message(
            code,
            QT_TRANSLATE_NOOP("Warning",
                              "Probing feed %1 is beyond the knee at %2 and no faster: the cycle "
                              "takes %3 longer, with more overtravel and uncertainty"),
            {arg("feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(feed_mm_s), 0),
             arg("knee_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(knee_feed_mm_s), 0),
             arg("time_lost_s", ArgKind::time_s, -time_saved_s, 3)});
    }
    return warning_message(
        code,
        QT_TRANSLATE_NOOP("Warning",
                          "Probing feed %1 is beyond the knee at %2: the extra feed saves only %3 "
                          "(under %4) while overtravel and uncertainty grow"),
        {arg("feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(feed_mm_s), 0),
         arg("knee_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(knee_feed_mm_s), 0),
         arg("time_saved_s", ArgKind::time_s, time_saved_s, 3),
         arg("knee_tolerance_percent", ArgKind::percent, 100.0 * knee_tolerance)});
}

Message KneeAtRangeEnd::message(Severity /*severity*/) const {
    const char* text = highest ? QT_TRANSLATE_NOOP("Warning",
                                                   "The fastest cycle lies at the highest feed "
                                                   "searched, %1: the knee at %2 depends on that "
                                                   "range; search faster feeds too")
                               : QT_TRANSLATE_NOOP("Warning",
                                                   "The fastest cycle lies at the lowest feed "
                                                   "searched, %1: the knee at %2 depends on that "
                                                   "range; search slower feeds too");
    return warning_message(
        code, text,
        {arg("range_end_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(end_feed_mm_s), 0),
         arg("knee_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(knee_feed_mm_s), 0),
         text_arg("range_end", highest ? "highest" : "lowest")});
}

Message NoValidFeed::message(Severity /*severity*/) const {
    const char* text =
        unreached ? QT_TRANSLATE_NOOP("Warning",
                                      "No probing feed from %1 to %2 is reached: the first touch "
                                      "meets the surface before it reaches even %1, so there is "
                                      "no knee; start the touch farther out")
                  : QT_TRANSLATE_NOOP("Warning",
                                      "No probing feed from %1 to %2 gives a valid cycle: the "
                                      "overtravel reaches the probe's limit even at %1, so there "
                                      "is no knee; shorten the delays or use a probe with more "
                                      "overtravel");
    return warning_message(
        code, text,
        {arg("from_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(from_feed_mm_s), 0),
         arg("to_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(to_feed_mm_s), 0)});
}

}  // namespace warning

}  // namespace probecycle
