#include "core/cycle/cycle_warnings.h"

#include <algorithm>

#include "core/common/units.h"

// Each check finds its problem and keeps its figures; beside it, its figures
// type words the message (the texts are the window's too, translated through
// ui::translate; each exists here only). Arguments are in the units their
// names say; docs/model.md explains each check to users.

namespace probecycle {

namespace {

// What every check reads: the scenario, the evaluated cycle and its timeline.
struct Checked {
    const Scenario& scenario;
    const CycleTimeline& timeline;
    const CycleResult& result;
    MotionCache& cache;
    bool full;
    bool two_touch() const { return scenario.cycle.strategy == Strategy::two_touch; }
    const AxisKernel* dynamics() const { return active_kernel(cache.kernel()); }
};

// A touch that triggers below its feed misses the delay travel calibrated at
// full feed, v * tau. The axis keeps accelerating while the signal travels, so
// the travel it makes is that of its real speed through tau, not v_t * tau.
// Only a touch that measures errs so: the first touch of two-touch only finds
// the surface (its speed only sets its overtravel, which the model follows).
void check_touch_while_accelerating(const Checked& in, std::vector<Warning>& out) {
    if (!in.full) return;
    const TouchResult& touch = in.result.measuring_touch();
    const double v = touch.programmed_feed_mm_s;
    if (touch.trigger_speed_mm_s >= v) return;
    const double error =
        v * measurement_delay_s(in.scenario.machine, in.scenario.probe) - touch.delay_travel_mm;
    if (error > kAccelErrorTolerance_mm) {
        out.emplace_back(Severity::warning,
                         warning::TouchWhileAccelerating{touch.trigger_speed_mm_s, v, error,
                                                         in.two_touch() ? 2 : 1});
    }
}

// The overtravel every check takes, at up to the highest feed override.
// Touches of one cycle differ only in direction, so the first point's speak
// for all.
void check_overtravel(const Checked& in, std::vector<Warning>& out) {
    const double overtravel = in.result.checked_overtravel_mm();
    const double limit = in.scenario.probe.overtravel_limit_mm;
    const warning::OvertravelLimit figures{
        overtravel, limit, feed_override_factor(in.scenario.cycle), in.result.overtravel_touch()};
    if (overtravel >= limit) {
        out.emplace_back(Severity::error, figures);
    } else if (overtravel >= kOvertravelWarningFraction * limit) {
        out.emplace_back(Severity::warning, figures);
    }
}

// A two-touch backoff against the recommended one: too small is an error;
// an excess beyond 10 % (at least 0.05 mm) of it is reported with the time
// it wastes.
void check_backoff(const Checked& in, std::vector<Warning>& out) {
    if (!in.two_touch()) return;
    const Cycle& c = in.scenario.cycle;
    const double recommended = in.result.recommended_backoff_mm();
    // Within 1 nm of the recommendation counts as following it: the value
    // shown and typed back may differ from it in its last bits.
    constexpr double kBackoffTolerance_mm = 1e-6;
    if (c.backoff_mm < recommended - kBackoffTolerance_mm) {
        out.emplace_back(Severity::error,
                         warning::BackoffTooSmall{c.backoff_mm, recommended, c.backoff_from});
        return;
    }
    if (!in.full || c.backoff_mm - recommended <= std::max(0.1 * recommended, 0.05)) return;
    // Every backoff wastes: the first touch's, and each repeat's from the
    // measuring touch. The costs at the scenario's backoff are the cycle's
    // own phases.
    const MotionLimits limits = in.scenario.motion_limits();
    const auto excess = [&](double cost_s, const TouchResult& from) {
        return cost_s -
               backoff_cost_s(in.scenario, limits, in.dynamics(), recommended, from, in.cache);
    };
    const int repeats = repeat_count(c);
    double wasted = excess(in.timeline.first_backoff_cost_s, in.result.first_touch());
    if (repeats > 1) {
        wasted +=
            (repeats - 1) * excess(in.timeline.repeat_backoff_cost_s, in.result.measuring_touch());
    }
    wasted *= touch_count(c.feature);
    out.emplace_back(Severity::info, warning::BackoffExcess{c.backoff_mm, recommended, wasted});
}

void check_uncertainty(const Checked& in, std::vector<Warning>& out) {
    const double target = in.scenario.cycle.target_uncertainty_mm;
    if (target > 0.0 && in.result.uncertainty_mm() > target) {
        out.emplace_back(Severity::warning,
                         warning::UncertaintyOverTarget{in.result.uncertainty_mm(), target});
    }
}

// The probe maker's rated maximum probing speed: beyond it the probe may not
// trigger reliably, so the cycle is not one to run.
void check_probe_feed(const Checked& in, std::vector<Warning>& out) {
    const double max_probe_v = mm_min_to_mm_s(in.scenario.probe.max_feed_mm_min);
    if (max_probe_v <= 0.0) return;
    const Cycle& c = in.scenario.cycle;
    const double probe_v = mm_min_to_mm_s(c.probe_feed_mm_min);
    const double measure_v = mm_min_to_mm_s(c.measure_feed_mm_min);
    const double fastest = in.two_touch() ? std::max(probe_v, measure_v) : probe_v;
    if (fastest > max_probe_v) {
        out.emplace_back(Severity::error,
                         warning::FeedOverProbeLimit{fastest, max_probe_v,
                                                     in.two_touch() && measure_v > probe_v});
    }
}

// Wherever the part lies within its position uncertainty, the touch must
// start outside it and at full feed. Two-touch: the first touch only finds
// the surface, so only a start inside the uncertainty itself (the probe may
// start in contact) is reported.
void check_start(const Checked& in, std::vector<Warning>& out) {
    const Cycle& c = in.scenario.cycle;
    const double part_u = c.part_position_uncertainty_mm;
    if (part_u <= 0.0) return;
    const double s = c.approach_mm;
    const double room = approach_room(in.scenario, in.scenario.motion_limits(), in.dynamics(),
                                      mm_min_to_mm_s(c.probe_feed_mm_min), &in.cache);
    if (s <= part_u || (!in.two_touch() && s < part_u + room - 1e-9)) {
        out.emplace_back(Severity::warning,
                         warning::StartInsideUncertainty{s, part_u, room, s <= part_u});
    }
}

// A search must reach past its touch's stop (search_beyond_mm in cycle.h).
// The automatic value always does; a value set by hand is checked against the
// touch that stops farthest past its surface.
void check_search(const Checked& in, std::vector<Warning>& out) {
    const double set = in.scenario.cycle.search_beyond_mm;
    if (set <= 0.0) return;
    const bool second_worse = in.result.overtravel_touch() == 2;
    const double stop = second_worse ? in.result.measuring_touch().override_overtravel_mm
                                     : in.result.first_touch().override_overtravel_mm;
    if (set < stop) {
        out.emplace_back(Severity::error,
                         warning::SearchEndsTooSoon{set, stop, second_worse ? 2 : 1});
    }
}

// A feature's protected moves: an obstruction met at the positioning feed is
// a touch at that feed, and the stylus must survive it too.
void check_protected_moves(const Checked& in, std::vector<Warning>& out) {
    const Cycle& c = in.scenario.cycle;
    if (touch_count(c.feature) <= 1) return;
    const double position_v = mm_min_to_mm_s(c.position_feed_mm_min);
    const double guard = protected_move_overtravel_mm(in.scenario, position_v);
    const double limit = in.scenario.probe.overtravel_limit_mm;
    if (guard >= kOvertravelWarningFraction * limit) {
        out.emplace_back(
            guard >= limit ? Severity::error : Severity::warning,
            warning::ProtectedMoveOvertravel{guard, limit, position_v, feed_override_factor(c)});
    }
}

// The delay travel calibrated at one speed is wrong at another by
// (v - v_cal) * tau (speed_error_mm in cycle.h).
void check_calibration_feed(const Checked& in, std::vector<Warning>& out) {
    const Machine& m = in.scenario.machine;
    const Probe& p = in.scenario.probe;
    const double calibration_v = mm_min_to_mm_s(p.calibration_feed_mm_min);
    const double v = in.result.measuring_touch().programmed_feed_mm_s;
    if (calibration_v > 0.0 && calibration_v != v) {
        out.emplace_back(Severity::warning,
                         warning::CalibrationFeedMismatch{v, calibration_v,
                                                          speed_error_mm(m, p, v, calibration_v)});
    }
}

}  // namespace

void collect_warnings(const Scenario& scenario, const CycleTimeline& timeline,
                      const CycleResult& result, MotionCache& cache, Detail detail,
                      std::vector<Warning>& warnings) {
    const Checked in{scenario, timeline, result, cache, detail == Detail::full};
    check_touch_while_accelerating(in, warnings);
    check_overtravel(in, warnings);
    check_backoff(in, warnings);
    check_uncertainty(in, warnings);
    check_probe_feed(in, warnings);
    check_start(in, warnings);
    check_search(in, warnings);
    check_protected_moves(in, warnings);
    check_calibration_feed(in, warnings);
    order_by_severity(warnings);
}

// --- The messages, one per figures type. ---

namespace warning {

Message OvertravelLimit::message(Severity severity) const {
    const bool overridden = feed_override > 1.0;
    const char* text = nullptr;
    if (severity == Severity::error) {
        text = overridden ? QT_TRANSLATE_NOOP("Warning",
                                              "Overtravel %1 at %5 % feed override is %2 % of "
                                              "the probe's %3 limit: the probe or stylus will "
                                              "be damaged; lower the feed or the delays")
                          : QT_TRANSLATE_NOOP("Warning",
                                              "Overtravel %1 is %2 % of the probe's %3 limit: "
                                              "the probe or stylus will be damaged; lower the "
                                              "feed or the delays");
    } else {
        text = overridden ? QT_TRANSLATE_NOOP("Warning",
                                              "Overtravel %1 at %5 % feed override is %2 % of "
                                              "the probe's %3 limit: little margin left for "
                                              "the stylus")
                          : QT_TRANSLATE_NOOP("Warning",
                                              "Overtravel %1 is %2 % of the probe's %3 limit: "
                                              "little margin left for the stylus");
    }
    return warning_message(
        code, text,
        {arg("overtravel_mm", ArgKind::length_mm, overtravel_mm, 3),
         arg("percent_of_limit", ArgKind::number, 100.0 * overtravel_mm / limit_mm, 0),
         arg("limit_mm", ArgKind::length_mm, limit_mm, 3), arg("touch", ArgKind::integer, touch),
         arg("feed_override_pct", ArgKind::number, 100.0 * std::max(feed_override, 1.0), 0)});
}

Message BackoffTooSmall::message(Severity /*severity*/) const {
    const char* text =
        from == BackoffFrom::trigger
            ? QT_TRANSLATE_NOOP("Warning",
                                "Backoff %1 from the recorded trigger position is less than "
                                "the recommended %2 (that position's distance past the "
                                "surface plus room to reseat and to reach the measuring feed): "
                                "the probe may not reseat before the second touch")
            : QT_TRANSLATE_NOOP("Warning",
                                "Backoff %1 from where the probe stopped is less than the "
                                "recommended %2 (the first touch's overtravel plus room to "
                                "reseat and to reach the measuring feed): the probe may not "
                                "reseat before the second touch");
    return warning_message(code, text,
                           {arg("backoff_mm", ArgKind::length_mm, backoff_mm, 3),
                            arg("recommended_backoff_mm", ArgKind::length_mm, recommended_mm, 3)});
}

Message BackoffExcess::message(Severity /*severity*/) const {
    return warning_message(
        code,
        QT_TRANSLATE_NOOP("Warning",
                          "Backoff %1 is more than the recommended %2 and wastes %3 per cycle"),
        {arg("backoff_mm", ArgKind::length_mm, backoff_mm, 3),
         arg("recommended_backoff_mm", ArgKind::length_mm, recommended_mm, 3),
         arg("time_wasted_s", ArgKind::time_s, wasted_s, 2)});
}

Message TouchWhileAccelerating::message(Severity /*severity*/) const {
    const char* text = touch == 2 ? QT_TRANSLATE_NOOP("Warning",
                                                      "Second touch starts closer than the "
                                                      "distance needed to reach its feed: it "
                                                      "triggers at %1 instead of %2, an error "
                                                      "of %3 against a calibration at full feed")
                                  : QT_TRANSLATE_NOOP("Warning",
                                                      "First touch starts closer than the "
                                                      "distance needed to reach its feed: it "
                                                      "triggers at %1 instead of %2, an error "
                                                      "of %3 against a calibration at full feed");
    return warning_message(
        code, text,
        {arg("speed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(speed_mm_s), 1),
         arg("feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(feed_mm_s), 1),
         arg("error_mm", ArgKind::length_mm, error_mm, 4), arg("touch", ArgKind::integer, touch)});
}

Message UncertaintyOverTarget::message(Severity /*severity*/) const {
    return warning_message(code,
                           QT_TRANSLATE_NOOP("Warning", "Uncertainty %1 exceeds the target %2"),
                           {arg("uncertainty_mm", ArgKind::length_mm, uncertainty_mm, 4),
                            arg("target_mm", ArgKind::length_mm, target_mm, 4)});
}

Message CalibrationFeedMismatch::message(Severity /*severity*/) const {
    return warning_message(
        code,
        QT_TRANSLATE_NOOP("Warning",
                          "Measuring at %1 but calibrated at %2: the delay travel shifts the "
                          "measured value by %3; calibrate at the measuring feed"),
        {arg("speed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(speed_mm_s), 1),
         arg("calibration_speed_mm_min", ArgKind::feed_mm_min,
             mm_s_to_mm_min(calibration_speed_mm_s), 1),
         arg("error_mm", ArgKind::length_mm, error_mm, 4)});
}

Message FeedOverProbeLimit::message(Severity /*severity*/) const {
    const char* text = measuring ? QT_TRANSLATE_NOOP("Warning",
                                                     "Measuring feed %1 is over the probe's rated "
                                                     "maximum %2: it may not trigger reliably or "
                                                     "may be damaged; measure at %2 or slower")
                                 : QT_TRANSLATE_NOOP("Warning",
                                                     "Probing feed %1 is over the probe's rated "
                                                     "maximum %2: it may not trigger reliably or "
                                                     "may be damaged; probe at %2 or slower");
    return warning_message(
        code, text,
        {arg("feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(feed_mm_s), 0),
         arg("max_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(max_feed_mm_s), 0)});
}

Message StartInsideUncertainty::message(Severity /*severity*/) const {
    const char* text =
        inside ? QT_TRANSLATE_NOOP("Warning",
                                   "Start distance %1 is inside the part's position uncertainty "
                                   "%2: where the part lies nearer, the probe starts in contact "
                                   "with it; start at least %3 out (the uncertainty plus the "
                                   "distance to reach the probing feed)")
               : QT_TRANSLATE_NOOP("Warning",
                                   "Start distance %1 covers the part's position uncertainty %2 "
                                   "but not the distance to reach the probing feed after it: "
                                   "where the part lies nearer, the touch is made while "
                                   "accelerating; start at least %3 out");
    return warning_message(
        code, text,
        {arg("approach_mm", ArgKind::length_mm, approach_mm, 3),
         arg("part_position_uncertainty_mm", ArgKind::length_mm, part_uncertainty_mm, 3),
         arg("needed_mm", ArgKind::length_mm, part_uncertainty_mm + reach_mm, 3)});
}

Message SearchEndsTooSoon::message(Severity /*severity*/) const {
    const char* text =
        touch == 2
            ? QT_TRANSLATE_NOOP("Warning",
                                "The second touch's search ends %1 past where the first touch "
                                "stopped, before its own stop %2 past the surface: it is braking "
                                "when it touches, triggers below the measuring feed and stops at "
                                "the search end; search at least %2 past the surface")
            : QT_TRANSLATE_NOOP("Warning",
                                "The search ends %1 past the farthest place the surface can be, "
                                "before the first touch's stop %2 past it: the axis is braking "
                                "when it touches, triggers below the feed and stops at the search "
                                "end; search at least %2 past the surface");
    return warning_message(code, text,
                           {arg("search_beyond_mm", ArgKind::length_mm, search_beyond_mm, 3),
                            significant_arg("stop_mm", ArgKind::length_mm, stop_mm, 4),
                            arg("touch", ArgKind::integer, touch)});
}

Message ProtectedMoveOvertravel::message(Severity severity) const {
    const bool error = severity == Severity::error;
    const char* text = nullptr;
    if (feed_override > 1.0) {
        text = error ? QT_TRANSLATE_NOOP("Warning",
                                         "A protected move at the positioning feed %1 and %5 % "
                                         "feed override that meets an obstruction stops %2 past "
                                         "it, %3 % of the probe's %4 limit: the stylus would be "
                                         "overrun; lower the positioning feed")
                     : QT_TRANSLATE_NOOP("Warning",
                                         "A protected move at the positioning feed %1 and %5 % "
                                         "feed override that meets an obstruction stops %2 past "
                                         "it, %3 % of the probe's %4 limit: little margin left "
                                         "for the stylus");
    } else {
        text = error ? QT_TRANSLATE_NOOP("Warning",
                                         "A protected move at the positioning feed %1 that meets "
                                         "an obstruction stops %2 past it, %3 % of the probe's %4 "
                                         "limit: the stylus would be overrun; lower the "
                                         "positioning feed")
                     : QT_TRANSLATE_NOOP("Warning",
                                         "A protected move at the positioning feed %1 that meets "
                                         "an obstruction stops %2 past it, %3 % of the probe's %4 "
                                         "limit: little margin left for the stylus");
    }
    return warning_message(
        code, text,
        {arg("position_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(position_feed_mm_s), 0),
         arg("overtravel_mm", ArgKind::length_mm, overtravel_mm, 3),
         arg("percent_of_limit", ArgKind::number, 100.0 * overtravel_mm / limit_mm, 0),
         arg("limit_mm", ArgKind::length_mm, limit_mm, 3),
         arg("feed_override_pct", ArgKind::number, 100.0 * std::max(feed_override, 1.0), 0)});
}

}  // namespace warning

}  // namespace probecycle
