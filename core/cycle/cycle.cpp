#include "core/cycle/cycle.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/cycle/cycle_builder.h"
#include "core/cycle/motion_cache.h"
#include "core/cycle/uncertainty.h"

namespace probecycle {

const char* to_string(Phase phase) {
    switch (phase) {
        case Phase::approach:
            return "approach";
        case Phase::pretravel:
            return "pretravel";
        case Phase::interface_delay:
            return "interface_delay";
        case Phase::controller_delay:
            return "controller_delay";
        case Phase::deceleration:
            return "deceleration";
        case Phase::backoff:
            return "backoff";
        case Phase::second_approach:
            return "second_approach";
        case Phase::second_pretravel:
            return "second_pretravel";
        case Phase::second_interface_delay:
            return "second_interface_delay";
        case Phase::second_controller_delay:
            return "second_controller_delay";
        case Phase::second_deceleration:
            return "second_deceleration";
        case Phase::return_move:
            return "return";
        case Phase::position:
            return "position";
        case Phase::lift:
            return "lift";
        case Phase::lower:
            return "lower";
        case Phase::block_change:
            return "block_change";
    }
    return "?";
}

const std::array<Phase, kPhaseCount>& all_phases() {
    static constexpr std::array<Phase, kPhaseCount> phases = {
        Phase::approach,
        Phase::pretravel,
        Phase::interface_delay,
        Phase::controller_delay,
        Phase::deceleration,
        Phase::backoff,
        Phase::second_approach,
        Phase::second_pretravel,
        Phase::second_interface_delay,
        Phase::second_controller_delay,
        Phase::second_deceleration,
        Phase::return_move,
        Phase::position,
        Phase::lift,
        Phase::lower,
        Phase::block_change,
    };
    return phases;
}

const char* to_string(WarningCode code) {
    switch (code) {
        case WarningCode::overtravel_limit:
            return "overtravel_limit";
        case WarningCode::backoff_too_small:
            return "backoff_too_small";
        case WarningCode::backoff_excess:
            return "backoff_excess";
        case WarningCode::touch_while_accelerating:
            return "touch_while_accelerating";
        case WarningCode::feed_beyond_knee:
            return "feed_beyond_knee";
        case WarningCode::knee_at_range_end:
            return "knee_at_range_end";
        case WarningCode::uncertainty_over_target:
            return "uncertainty_over_target";
        case WarningCode::calibration_feed_mismatch:
            return "calibration_feed_mismatch";
        case WarningCode::no_valid_feed:
            return "no_valid_feed";
        case WarningCode::feed_over_probe_limit:
            return "feed_over_probe_limit";
        case WarningCode::start_inside_uncertainty:
            return "start_inside_uncertainty";
        case WarningCode::search_ends_too_soon:
            return "search_ends_too_soon";
        case WarningCode::protected_move_overtravel:
            return "protected_move_overtravel";
    }
    return "?";
}

void order_by_severity(std::vector<Warning>& warnings) {
    // An insertion sort, stable and without the buffer std::stable_sort
    // allocates: it runs in every evaluation, on a handful of warnings.
    const auto before = [](const Warning& x, const Warning& y) {
        return static_cast<int>(x.severity) > static_cast<int>(y.severity);
    };
    for (auto it = warnings.begin(); it != warnings.end(); ++it) {
        std::rotate(std::upper_bound(warnings.begin(), it, *it, before), it, it + 1);
    }
}

unsigned CycleResult::invalid_codes() const {
    unsigned codes = 0;
    for (const Warning& w : warnings_) {
        if (w.severity == Severity::error) codes |= invalid_code_bit(w.code);
    }
    return codes;
}

std::string invalid_codes_text(unsigned codes, const char* separator) {
    std::string text;
    for (unsigned k = 0; k < 32; ++k) {
        if ((codes & (1u << k)) == 0) continue;
        if (!text.empty()) text += separator;
        text += to_string(static_cast<WarningCode>(k));
    }
    return text;
}

// The texts are the window's too (ui::translate); each exists here only.
// Arguments in the units their names say.
Message Warning::to_message() const {
    Message m;
    m.code = to_string(code);
    m.context = "Warning";
    switch (code) {
        case WarningCode::overtravel_limit: {
            // c: the feed override the overtravel is at (issue 28).
            const bool overridden = c > 1.0;
            if (severity == Severity::error) {
                m.text = overridden
                             ? QT_TRANSLATE_NOOP("Warning",
                                                 "Overtravel %1 at %5 % feed override is %2 % of "
                                                 "the probe's %3 limit: the probe or stylus will "
                                                 "be damaged; lower the feed or the delays")
                             : QT_TRANSLATE_NOOP("Warning",
                                                 "Overtravel %1 is %2 % of the probe's %3 limit: "
                                                 "the probe or stylus will be damaged; lower the "
                                                 "feed or the delays");
            } else {
                m.text = overridden
                             ? QT_TRANSLATE_NOOP("Warning",
                                                 "Overtravel %1 at %5 % feed override is %2 % of "
                                                 "the probe's %3 limit: little margin left for "
                                                 "the stylus")
                             : QT_TRANSLATE_NOOP("Warning",
                                                 "Overtravel %1 is %2 % of the probe's %3 limit: "
                                                 "little margin left for the stylus");
            }
            m.args = {arg("overtravel_mm", ArgKind::length_mm, a, 3),
                      arg("percent_of_limit", ArgKind::number, 100.0 * a / b, 0),
                      arg("limit_mm", ArgKind::length_mm, b, 3),
                      arg("touch", ArgKind::integer, d > 1.5 ? 2.0 : 1.0),
                      arg("feed_override_pct", ArgKind::number, 100.0 * std::max(c, 1.0), 0)};
            break;
        }
        case WarningCode::backoff_too_small:
            // d: the backoff's reference (0 where the probe stopped, 1 the recorded trigger).
            m.text = d > 0.5 ? QT_TRANSLATE_NOOP(
                                   "Warning",
                                   "Backoff %1 from the recorded trigger position is less than "
                                   "the recommended %2 (that position's distance past the "
                                   "surface plus room to reseat and to reach the measuring feed): "
                                   "the probe may not reseat before the second touch")
                             : QT_TRANSLATE_NOOP(
                                   "Warning",
                                   "Backoff %1 from where the probe stopped is less than the "
                                   "recommended %2 (the first touch's overtravel plus room to "
                                   "reseat and to reach the measuring feed): the probe may not "
                                   "reseat before the second touch");
            m.args = {arg("backoff_mm", ArgKind::length_mm, a, 3),
                      arg("recommended_backoff_mm", ArgKind::length_mm, b, 3)};
            break;
        case WarningCode::backoff_excess:
            m.text = QT_TRANSLATE_NOOP(
                "Warning", "Backoff %1 is more than the recommended %2 and wastes %3 per cycle");
            m.args = {arg("backoff_mm", ArgKind::length_mm, a, 3),
                      arg("recommended_backoff_mm", ArgKind::length_mm, b, 3),
                      arg("time_wasted_s", ArgKind::time_s, c, 2)};
            break;
        case WarningCode::touch_while_accelerating:
            m.text = d > 0.5 ? QT_TRANSLATE_NOOP("Warning",
                                                 "Second touch starts closer than the distance "
                                                 "needed to reach its feed: it triggers at %1 "
                                                 "instead of %2, an error of %3 against a "
                                                 "calibration at full feed")
                             : QT_TRANSLATE_NOOP("Warning",
                                                 "First touch starts closer than the distance "
                                                 "needed to reach its feed: it triggers at %1 "
                                                 "instead of %2, an error of %3 against a "
                                                 "calibration at full feed");
            m.args = {arg("speed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(a), 1),
                      arg("feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(b), 1),
                      arg("error_mm", ArgKind::length_mm, c, 4),
                      arg("touch", ArgKind::integer, d > 0.5 ? 2.0 : 1.0)};
            break;
        case WarningCode::feed_beyond_knee:
            if (c <= 0.0) {
                m.text = QT_TRANSLATE_NOOP(
                    "Warning",
                    "Probing feed %1 is beyond the knee at %2 and no faster: the cycle takes %3 "
                    "longer, with more overtravel and uncertainty");
                m.args = {arg("feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(a), 0),
                          arg("knee_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(b), 0),
                          arg("time_lost_s", ArgKind::time_s, -c, 3)};
            } else {
                m.text = QT_TRANSLATE_NOOP(
                    "Warning",
                    "Probing feed %1 is beyond the knee at %2: the extra feed saves only %3 "
                    "(under %4) while overtravel and uncertainty grow");
                m.args = {arg("feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(a), 0),
                          arg("knee_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(b), 0),
                          arg("time_saved_s", ArgKind::time_s, c, 3),
                          arg("knee_tolerance_percent", ArgKind::percent, 100.0 * d)};
            }
            break;
        case WarningCode::knee_at_range_end:
            m.text = d > 0.5 ? QT_TRANSLATE_NOOP("Warning",
                                                 "The fastest cycle lies at the highest feed "
                                                 "searched, %1: the knee at %2 depends on that "
                                                 "range; search faster feeds too")
                             : QT_TRANSLATE_NOOP("Warning",
                                                 "The fastest cycle lies at the lowest feed "
                                                 "searched, %1: the knee at %2 depends on that "
                                                 "range; search slower feeds too");
            m.args = {arg("range_end_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(a), 0),
                      arg("knee_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(b), 0),
                      text_arg("range_end", d > 0.5 ? "highest" : "lowest")};
            break;
        case WarningCode::uncertainty_over_target:
            m.text = QT_TRANSLATE_NOOP("Warning", "Uncertainty %1 exceeds the target %2");
            m.args = {arg("uncertainty_mm", ArgKind::length_mm, a, 4),
                      arg("target_mm", ArgKind::length_mm, b, 4)};
            break;
        case WarningCode::calibration_feed_mismatch:
            m.text = QT_TRANSLATE_NOOP(
                "Warning",
                "Measuring at %1 but calibrated at %2: the delay travel shifts the measured value "
                "by %3; calibrate at the measuring feed");
            m.args = {arg("speed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(a), 1),
                      arg("calibration_speed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(b), 1),
                      arg("error_mm", ArgKind::length_mm, c, 4)};
            break;
        case WarningCode::no_valid_feed:
            // d = 1: valid, but the first touch reaches none of the feeds (issue 28).
            m.text = d > 0.5 ? QT_TRANSLATE_NOOP(
                                   "Warning",
                                   "No probing feed from %1 to %2 is reached: the first touch "
                                   "meets the surface before it reaches even %1, so there is no "
                                   "knee; start the touch farther out")
                             : QT_TRANSLATE_NOOP(
                                   "Warning",
                                   "No probing feed from %1 to %2 gives a valid cycle: the "
                                   "overtravel reaches the probe's limit even at %1, so there is "
                                   "no knee; shorten the delays or use a probe with more "
                                   "overtravel");
            m.args = {arg("from_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(a), 0),
                      arg("to_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(b), 0)};
            break;
        case WarningCode::feed_over_probe_limit:
            m.text = d > 0.5 ? QT_TRANSLATE_NOOP("Warning",
                                                 "Measuring feed %1 is over the probe's rated "
                                                 "maximum %2: it may not trigger reliably or may "
                                                 "be damaged; measure at %2 or slower")
                             : QT_TRANSLATE_NOOP("Warning",
                                                 "Probing feed %1 is over the probe's rated "
                                                 "maximum %2: it may not trigger reliably or may "
                                                 "be damaged; probe at %2 or slower");
            m.args = {arg("feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(a), 0),
                      arg("max_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(b), 0)};
            break;
        case WarningCode::start_inside_uncertainty:
            m.text = d > 0.5
                         ? QT_TRANSLATE_NOOP(
                               "Warning",
                               "Start distance %1 is inside the part's position uncertainty %2: "
                               "where the part lies nearer, the probe starts in contact with it; "
                               "start at least %3 out (the uncertainty plus the distance to "
                               "reach the probing feed)")
                         : QT_TRANSLATE_NOOP(
                               "Warning",
                               "Start distance %1 covers the part's position uncertainty %2 but "
                               "not the distance to reach the probing feed after it: where the "
                               "part lies nearer, the touch is made while accelerating; start at "
                               "least %3 out");
            m.args = {arg("approach_mm", ArgKind::length_mm, a, 3),
                      arg("part_position_uncertainty_mm", ArgKind::length_mm, b, 3),
                      arg("needed_mm", ArgKind::length_mm, b + c, 3)};
            break;
        case WarningCode::search_ends_too_soon:
            m.text = d > 1.5
                         ? QT_TRANSLATE_NOOP(
                               "Warning",
                               "The second touch's search ends %1 past where the first touch "
                               "stopped, before its own stop %2 past the surface: it is braking "
                               "when it touches, triggers below the measuring feed and stops at "
                               "the search end; search at least %2 past the surface")
                         : QT_TRANSLATE_NOOP(
                               "Warning",
                               "The search ends %1 past the farthest place the surface can be, "
                               "before the first touch's stop %2 past it: the axis is braking "
                               "when it touches, triggers below the feed and stops at the search "
                               "end; search at least %2 past the surface");
            m.args = {arg("search_beyond_mm", ArgKind::length_mm, a, 3),
                      significant_arg("stop_mm", ArgKind::length_mm, b, 4),
                      arg("touch", ArgKind::integer, d > 1.5 ? 2.0 : 1.0)};
            break;
        case WarningCode::protected_move_overtravel:
            // d: the feed override it is at (issue 28).
            if (d > 1.0) {
                m.text = severity == Severity::error
                             ? QT_TRANSLATE_NOOP(
                                   "Warning",
                                   "A protected move at the positioning feed %1 and %5 % feed "
                                   "override that meets an obstruction stops %2 past it, %3 % of "
                                   "the probe's %4 limit: the stylus would be overrun; lower the "
                                   "positioning feed")
                             : QT_TRANSLATE_NOOP(
                                   "Warning",
                                   "A protected move at the positioning feed %1 and %5 % feed "
                                   "override that meets an obstruction stops %2 past it, %3 % of "
                                   "the probe's %4 limit: little margin left for the stylus");
            } else {
                m.text = severity == Severity::error
                             ? QT_TRANSLATE_NOOP(
                                   "Warning",
                                   "A protected move at the positioning feed %1 that meets an "
                                   "obstruction stops %2 past it, %3 % of the probe's %4 limit: "
                                   "the stylus would be overrun; lower the positioning feed")
                             : QT_TRANSLATE_NOOP(
                                   "Warning",
                                   "A protected move at the positioning feed %1 that meets an "
                                   "obstruction stops %2 past it, %3 % of the probe's %4 limit: "
                                   "little margin left for the stylus");
            }
            m.args = {arg("position_feed_mm_min", ArgKind::feed_mm_min, mm_s_to_mm_min(c), 0),
                      arg("overtravel_mm", ArgKind::length_mm, a, 3),
                      arg("percent_of_limit", ArgKind::number, 100.0 * a / b, 0),
                      arg("limit_mm", ArgKind::length_mm, b, 3),
                      arg("feed_override_pct", ArgKind::number, 100.0 * std::max(d, 1.0), 0)};
            break;
    }
    return m;
}

std::string Warning::message() const {
    return render(to_message());
}

double search_beyond_mm(const Scenario& scenario, double overtravel_mm) {
    const double set = scenario.cycle.search_beyond_mm;
    if (set > 0.0) return set;
    return std::max(overtravel_mm, 0.5 * (overtravel_mm + scenario.probe.overtravel_limit_mm));
}

double feed_override_factor(const Cycle& cycle) {
    return std::max(1.0, cycle.feed_override_max_pct / 100.0);
}

int repeat_count(const Cycle& cycle) {
    return std::max(1, static_cast<int>(cycle.repeats));
}

double protected_move_overtravel_mm(const Scenario& scenario, double feed_mm_s) {
    const double v = feed_override_factor(scenario.cycle) * feed_mm_s;
    return scenario.probe.pretravel_mm +
           v * (reaction_time_s(scenario.machine, scenario.probe) +
                scenario.axis_dynamics().lag_s()) +
           stop_distance_mm(scenario.motion_limits(), v, v);
}

std::optional<double> highest_position_feed_mm_min(const Scenario& scenario, double upper_mm_min,
                                                   double fraction) {
    const double limit = fraction * scenario.probe.overtravel_limit_mm;
    return highest_feed_where(1.0, upper_mm_min, [&](double feed) {
        return protected_move_overtravel_mm(scenario, mm_min_to_mm_s(feed)) < limit;
    });
}

// domain.md, "One touch": interface response t_i, controller latency t_c and,
// worst case, a full scan period t_s pass between trigger and reaction.
double reaction_time_s(const Machine& machine, const Probe& probe) {
    return probe.interface_delay_s + machine.controller_latency_s + machine.scan_period_s;
}

// domain.md, "Controller response": the wait for the next scan is anywhere in
// [0, t_s], a range of v_t * t_s; a latched input removes it from the value.
double scan_range_mm(const Machine& machine, double trigger_speed_mm_s) {
    return machine.latched_input ? 0.0 : trigger_speed_mm_s * machine.scan_period_s;
}

// A uniform range R has sigma R/sqrt(12); repeatability is given as 2 sigma.
// Expanded (k = 2): 2 * sqrt(R^2/12 + (rep/2)^2) = sqrt(R^2/3 + rep^2).
double expanded_uncertainty_mm(double range_mm, double repeatability_2sigma_mm) {
    return std::sqrt(range_mm * range_mm / 3.0 + repeatability_2sigma_mm * repeatability_2sigma_mm);
}

// Issue 4, "Calibration feed versus measuring feed": the delay travel
// calibrated at one speed is wrong at another by (v - v_cal) * tau, tau =
// t_i + t_c + t_s/2 with a scanned input. Issue 11: a latched input captures
// the position when the signal reaches the control, before the controller's
// latency and scan, so there tau = t_i alone.
double measurement_delay_s(const Machine& machine, const Probe& probe) {
    if (machine.latched_input) return probe.interface_delay_s;
    return probe.interface_delay_s + machine.controller_latency_s + 0.5 * machine.scan_period_s;
}

double speed_error_mm(const Machine& machine, const Probe& probe, double speed_mm_s,
                      double calibrated_speed_mm_s) {
    return (speed_mm_s - calibrated_speed_mm_s) * measurement_delay_s(machine, probe);
}

int touch_count(Feature feature) {
    switch (feature) {
        case Feature::surface:
            return 1;
        case Feature::web:
        case Feature::pocket:
            return 2;
        case Feature::bore:
        case Feature::boss:
            return 4;
    }
    return 1;
}

// Issue 11, loose end 6: the moves of a feature as real cycles make them
// (cycle.h).
double start_radius_mm(const Cycle& cycle) {
    const double half = 0.5 * cycle.feature_size_mm;
    return lifts_over(cycle.feature) ? half + cycle.approach_mm : half - cycle.approach_mm;
}

bool lifts_over(Feature feature) {
    return feature == Feature::boss || feature == Feature::web;
}

CycleState CycleResult::state_at(double t_s) const {
    CycleState state;
    if (phases_.empty()) return state;
    const double t = std::clamp(t_s, 0.0, total_s_);

    auto phase_it = std::upper_bound(phases_.begin(), phases_.end(), t,
                                     [](double v, const PhaseRecord& p) { return v < p.start_s; });
    std::size_t phase_index =
        phase_it == phases_.begin() ? 0 : static_cast<std::size_t>(phase_it - phases_.begin()) - 1;
    while (phase_index > 0 && phases_[phase_index].time_s <= 0.0) --phase_index;
    state.phase_index = phase_index;
    state.touch = phases_[phase_index].touch;

    if (segments_.empty()) return state;
    auto seg_it = std::upper_bound(segments_.begin(), segments_.end(), t,
                                   [](double v, const TimedSegment& s) { return v < s.start_s; });
    const TimedSegment& seg = seg_it == segments_.begin() ? segments_.front() : *(seg_it - 1);
    if (seg.motion >= 0) {
        const KinematicState k = motions_[static_cast<std::size_t>(seg.motion)].state(
            std::min(t - seg.start_s, seg.duration_s));
        state.position_mm = seg.axis_start_mm + seg.direction * k.position_mm;
        state.velocity_mm_s = seg.direction * k.speed_mm_s;
        state.path_speed_mm_s = k.speed_mm_s;
        return state;
    }
    const KinematicState k =
        integrate(std::min(t - seg.start_s, seg.duration_s), seg.start, seg.jerk_mm_s3);
    state.position_mm = seg.axis_start_mm + seg.direction * k.position_mm;
    state.velocity_mm_s = seg.direction * k.speed_mm_s;
    state.path_speed_mm_s = k.speed_mm_s;
    return state;
}

CycleResult evaluate(const Scenario& scenario) {
    CycleResult result;
    evaluate_into(scenario, result);
    return result;
}

namespace {

void add_touch_warnings(const Scenario& scenario, const TouchResult& touch, int which,
                        std::vector<Warning>& warnings) {
    const double v = touch.programmed_feed_mm_s;
    if (touch.trigger_speed_mm_s >= v) return;
    // domain.md, "Acceleration models": a slower touch misses the delay
    // travel calibrated at full feed, v * tau. Issue 11: the axis keeps
    // accelerating while the signal travels, so the travel it makes is
    // that of its real speed through tau, not v_t * tau.
    const double error =
        v * measurement_delay_s(scenario.machine, scenario.probe) - touch.delay_travel_mm;
    if (error > kAccelErrorTolerance_mm) {
        warnings.push_back({WarningCode::touch_while_accelerating, Severity::warning,
                            touch.trigger_speed_mm_s, v, error, static_cast<double>(which)});
    }
}

}  // namespace

void evaluate_into(const Scenario& scenario, CycleResult& r) {
    MotionCache cache;
    evaluate_into(scenario, r, cache);
}

void evaluate_into(const Scenario& scenario, CycleResult& r, MotionCache& cache, Detail detail) {
    const bool full = detail == Detail::full;
    r.warnings_.clear();
    const CycleTimeline timeline = build_timeline(
        scenario, {r.phases_, r.segments_, r.motions_, r.phase_time_s_}, cache, detail);

    const Machine& m = scenario.machine;
    const Probe& p = scenario.probe;
    const Cycle& c = scenario.cycle;
    const MotionLimits limits = scenario.motion_limits();
    const double s = c.approach_mm;
    const double probe_v = mm_min_to_mm_s(c.probe_feed_mm_min);
    const double measure_v = mm_min_to_mm_s(c.measure_feed_mm_min);
    const double position_v = mm_min_to_mm_s(c.position_feed_mm_min);
    const bool two_touch = c.strategy == Strategy::two_touch;
    const int touches = touch_count(c.feature);
    const int repeats = repeat_count(c);
    const double override_k = feed_override_factor(c);
    const AxisKernel* dynamics = active_kernel(cache.kernel());
    const TouchResult& first = timeline.first;
    const TouchResult& first_fast = timeline.first_fast;
    const TouchResult& measuring = timeline.measuring;
    const double first_backoff_cost_s = timeline.first_backoff_cost_s;
    const double repeat_backoff_cost_s = timeline.repeat_backoff_cost_s;
    // Only a touch that measures errs by touching while accelerating: the
    // first touch of two-touch only finds the surface (its speed only sets
    // its overtravel, which the model follows).
    if (full) add_touch_warnings(scenario, measuring, two_touch ? 1 : 0, r.warnings_);
    r.first_ = first;
    r.measuring_ = measuring;

    const double first_worst = first.override_overtravel_mm;
    const double measuring_worst = two_touch ? measuring.override_overtravel_mm : first_worst;
    const double worst_overtravel = std::max(first_worst, measuring_worst);
    // Two-touch: a faster first touch may overtravel less than the slow second
    // one when a fixed backoff leaves the second approach too short to brake
    // from; the user must see which touch sets the worst.
    r.overtravel_touch_ = two_touch && measuring_worst > first_worst ? 2 : 1;

    r.total_s_ = timeline.total_s;
    r.overtravel_mm_ = std::max(first.overtravel_mm, measuring.overtravel_mm);
    r.checked_overtravel_mm_ = worst_overtravel;
    r.trigger_speed_mm_s_ = r.measuring_.trigger_speed_mm_s;
    r.scan_range_mm_ = scan_range_mm(m, r.trigger_speed_mm_s_);
    // Issue 14: the scan phase and the repeatability are random from touch to
    // touch, so the mean of N touches has 1/sqrt(N) of their uncertainty.
    r.trigger_uncertainty_mm_ =
        expanded_uncertainty_mm(r.scan_range_mm_, p.repeatability_2sigma_mm) /
        std::sqrt(static_cast<double>(repeats));
    // Issue 28: the budget's fixed terms (uncertainty.h) join it as the GUM
    // combines independent terms; its figures are the budget's.
    r.uncertainty_mm_ = combined_expanded_uncertainty_mm(fixed_expanded_uncertainty_mm(scenario),
                                                         r.trigger_uncertainty_mm_, 1);
    // domain.md, "Strategies": recommended backoff = overtravel at the fast feed + reseat.
    // Issue 11: measured from the backoff's reference, and the second touch
    // also needs room to reach the measuring feed before it touches.
    // Issue 12: rounded up to the editors' digits, so the value shown is the
    // value that clears backoff_too_small.
    // Issue 28: at the highest feed override the probe must still reseat
    // before the second touch starts (the measuring feed's room is for the
    // measurement, at 100 %).
    const double needed = std::max(
        backoff_reference_mm(c, r.first_, TouchCase::worst) +
            std::max(p.reseat_mm, approach_room(scenario, limits, dynamics, measure_v, &cache)),
        backoff_reference_mm(c, first_fast, TouchCase::worst) + p.reseat_mm);
    r.recommended_backoff_mm_ = round_up_to(needed, kBackoffStep_mm);

    // Touches of one cycle differ only in direction, so touch 0 speaks for all.
    std::vector<Warning>& w = r.warnings_;
    if (worst_overtravel >= p.overtravel_limit_mm) {
        w.push_back({WarningCode::overtravel_limit, Severity::error, worst_overtravel,
                     p.overtravel_limit_mm, override_k, static_cast<double>(r.overtravel_touch_)});
    } else if (worst_overtravel >= kOvertravelWarningFraction * p.overtravel_limit_mm) {
        w.push_back({WarningCode::overtravel_limit, Severity::warning, worst_overtravel,
                     p.overtravel_limit_mm, override_k, static_cast<double>(r.overtravel_touch_)});
    }
    if (two_touch) {
        const double recommended = r.recommended_backoff_mm_;
        // Within 1 nm of the recommendation counts as following it: the value
        // shown and typed back may differ from it in its last bits.
        constexpr double kBackoffTolerance_mm = 1e-6;
        if (c.backoff_mm < recommended - kBackoffTolerance_mm) {
            w.push_back({WarningCode::backoff_too_small, Severity::error, c.backoff_mm, recommended,
                         0.0, c.backoff_from == BackoffFrom::trigger ? 1.0 : 0.0});
        } else if (full && c.backoff_mm - recommended > std::max(0.1 * recommended, 0.05)) {
            // Excess beyond 10 % (at least 0.05 mm) of the recommendation is reported.
            // Every backoff wastes: the first touch's, and each repeat's from
            // the measuring touch.
            // The costs at the scenario's backoff are the cycle's own phases.
            const auto excess = [&](double cost_s, const TouchResult& from) {
                return cost_s -
                       backoff_cost_s(scenario, limits, dynamics, recommended, from, cache);
            };
            double wasted = excess(first_backoff_cost_s, r.first_);
            if (repeats > 1) wasted += (repeats - 1) * excess(repeat_backoff_cost_s, r.measuring_);
            wasted *= touches;
            w.push_back(
                {WarningCode::backoff_excess, Severity::info, c.backoff_mm, recommended, wasted});
        }
    }
    if (c.target_uncertainty_mm > 0.0 && r.uncertainty_mm_ > c.target_uncertainty_mm) {
        w.push_back({WarningCode::uncertainty_over_target, Severity::warning, r.uncertainty_mm_,
                     c.target_uncertainty_mm});
    }
    // Issue 14: the probe maker's rated maximum probing speed; beyond it the
    // probe may not trigger reliably, so the cycle is not one to run.
    const double max_probe_v = mm_min_to_mm_s(p.max_feed_mm_min);
    if (max_probe_v > 0.0) {
        const double fastest = two_touch ? std::max(probe_v, measure_v) : probe_v;
        if (fastest > max_probe_v) {
            w.push_back({WarningCode::feed_over_probe_limit, Severity::error, fastest, max_probe_v,
                         0.0, two_touch && measure_v > probe_v ? 1.0 : 0.0});
        }
    }
    // Issue 14: wherever the part lies within its position uncertainty, the
    // touch must start outside it and at full feed. Two-touch: the first
    // touch only finds the surface, so only a start inside the uncertainty
    // itself (the probe may start in contact) is reported.
    const double part_u = c.part_position_uncertainty_mm;
    if (part_u > 0.0) {
        const double room = approach_room(scenario, limits, dynamics, probe_v, &cache);
        if (s <= part_u || (!two_touch && s < part_u + room - 1e-9)) {
            w.push_back({WarningCode::start_inside_uncertainty, Severity::warning, s, part_u, room,
                         s <= part_u ? 1.0 : 0.0});
        }
    }
    // A search must reach past its touch's stop (search_beyond_mm). The
    // automatic value always does; a value set by hand is checked against
    // the touch that stops farthest past its surface.
    if (c.search_beyond_mm > 0.0) {
        const bool second_worse = r.overtravel_touch_ == 2;
        const double stop = second_worse ? measuring_worst : first_worst;
        if (c.search_beyond_mm < stop) {
            w.push_back({WarningCode::search_ends_too_soon, Severity::error, c.search_beyond_mm,
                         stop, 0.0, second_worse ? 2.0 : 1.0});
        }
    }
    // A feature's protected moves: an obstruction met at the positioning feed
    // is a touch at that feed, and the stylus must survive it too.
    if (touches > 1) {
        const double guard = protected_move_overtravel_mm(scenario, position_v);
        const double limit = p.overtravel_limit_mm;
        if (guard >= kOvertravelWarningFraction * limit) {
            w.push_back({WarningCode::protected_move_overtravel,
                         guard >= limit ? Severity::error : Severity::warning, guard, limit,
                         position_v, override_k});
        }
    }
    const double calibration_v = mm_min_to_mm_s(p.calibration_feed_mm_min);
    const double measuring_programmed_v = r.measuring_.programmed_feed_mm_s;
    if (calibration_v > 0.0 && calibration_v != measuring_programmed_v) {
        w.push_back({WarningCode::calibration_feed_mismatch, Severity::warning,
                     measuring_programmed_v, calibration_v,
                     speed_error_mm(m, p, measuring_programmed_v, calibration_v)});
    }
    order_by_severity(w);
    // A summary's touches kept their motions only while they were solved.
    if (!full) r.motions_.clear();
}

}  // namespace probecycle
