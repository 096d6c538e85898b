#include "core/cycle/cycle.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/common/number_format.h"
#include "core/common/units.h"
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

namespace {

// Long enough for any touch: the approach plan is cut where the axis reacts.
constexpr double kOpenCruise_s = 1.0e9;

struct TouchPhases {
    Phase approach, pretravel, interface_delay, controller_delay, deceleration;
};
constexpr TouchPhases kFirstTouch{Phase::approach, Phase::pretravel, Phase::interface_delay,
                                  Phase::controller_delay, Phase::deceleration};
constexpr TouchPhases kSecondTouch{Phase::second_approach, Phase::second_pretravel,
                                   Phase::second_interface_delay, Phase::second_controller_delay,
                                   Phase::second_deceleration};

// The command of a touch's approach (the plan accelerating and cruising on,
// uncut), of a rest-to-rest move, and of a touch: its approach until the
// control reacts at `t_react_s`, then stopped (at once, or braking as its
// plan does). The actual motion of a touch's approach.
AxisCommand approach_command(const SegmentPlan& plan) {
    AxisCommand command;
    command.append(plan, plan.duration_s());
    return command;
}

AxisCommand move_command(const SegmentPlan& plan) {
    AxisCommand command = approach_command(plan);
    command.close();
    return command;
}

AxisCommand touch_command(const MotionLimits& limits, const SegmentPlan& plan, double feed_mm_s,
                          double t_react_s) {
    AxisCommand command;
    command.append(plan, t_react_s);
    const KinematicState at_react = command.end_state();
    const SegmentPlan stop =
        plan_stop(limits, feed_mm_s, at_react.speed_mm_s, at_react.accel_mm_s2);
    command.append(stop, stop.duration_s());
    command.close();
    return command;
}

AxisMotion approach_motion(const AxisKernel& kernel, const SegmentPlan& plan) {
    return {kernel, approach_command(plan)};
}

// Time from rest until a touch's approach covers `distance_mm`.
double approach_time_s(const MotionLimits& limits, const AxisKernel* kernel, double feed_mm_s,
                       double distance_mm) {
    const SegmentPlan plan = plan_accelerate(limits, feed_mm_s, kOpenCruise_s);
    const double planned = time_at_distance_s(plan, distance_mm);
    if (kernel == nullptr) return planned;
    return approach_motion(*kernel, plan)
        .time_at_position(distance_mm, planned + kernel->moment(1));
}

const AxisKernel* active_kernel(const AxisKernel& kernel) {
    return kernel.active() ? &kernel : nullptr;
}

// A rest-to-rest move's time to the in-position check and its command's end:
// the cache's, or solved on the actual motion `motion()` gives (built only
// then) and kept.
template <typename Motion>
MotionCache::Move filtered_move(MotionCache* cache, double distance_mm, double feed_mm_s,
                                Motion motion) {
    if (cache != nullptr) {
        if (const auto known = cache->move(distance_mm, feed_mm_s)) return *known;
    }
    const AxisMotion& solving = motion();
    const MotionCache::Move solved{solving.in_position_time(),
                                   solving.command().end_state().position_mm};
    if (cache != nullptr) cache->store_move(distance_mm, feed_mm_s, solved);
    return solved;
}

// block_time_s and approach_room_mm for a kernel already built (nullptr: the
// ideal axis).
double block_time(const MotionLimits& limits, const AxisKernel* kernel, double distance_mm,
                  double feed_mm_s, MotionCache* cache = nullptr) {
    if (kernel == nullptr) return move_time_s(limits, distance_mm, feed_mm_s);
    return filtered_move(cache, distance_mm, feed_mm_s,
                         [&] {
                             return AxisMotion(
                                 *kernel, move_command(plan_move(limits, distance_mm, feed_mm_s)));
                         })
        .time_s;
}

double approach_room(const Scenario& scenario, const MotionLimits& limits, const AxisKernel* kernel,
                     double feed_mm_s, MotionCache* cache = nullptr) {
    if (kernel == nullptr) return reach_distance_mm(limits, feed_mm_s);
    // The error of a touch at speed v - dv is at most dv * tau (the speed
    // still rises through the delay tau), so the feed counts as reached when
    // the deficit is under the tolerance / tau.
    const double tau = measurement_delay_s(scenario.machine, scenario.probe);
    if (tau <= 0.0) return 0.0;
    if (cache != nullptr) {
        if (const auto known = cache->approach_room_mm(feed_mm_s, tau)) return *known;
    }
    const SegmentPlan plan = plan_accelerate(limits, feed_mm_s, kOpenCruise_s);
    const AxisMotion motion = approach_motion(*kernel, plan);
    const double t = motion.time_at_speed_deficit(
        kAccelErrorTolerance_mm / tau,
        reach_time_s(limits, feed_mm_s) + kernel->window_s() + kernel->lag_time_s());
    const double room = motion.state(t).position_mm;
    if (cache != nullptr) cache->store_approach_room(feed_mm_s, tau, room);
    return room;
}

// Trigger to reaction after the mean scan wait, half a period: the timeline's.
double mean_reaction_s(const MotionCache::TouchKey& key) {
    return key.reaction_s - 0.5 * key.scan_s;
}

// Appends phases and motion to a result under construction.
class CycleBuilder {
  public:
    // `kernel`: the dynamics after interpolation, or nullptr for the ideal axis.
    CycleBuilder(std::vector<PhaseRecord>& phases, std::vector<TimedSegment>& segments,
                 std::vector<AxisMotion>& motions, std::array<double, kPhaseCount>& phase_time,
                 const AxisKernel* kernel, MotionCache& cache, Detail detail, double block_change_s)
        : phases_(phases),
          segments_(segments),
          motions_(motions),
          phase_time_(phase_time),
          kernel_(kernel),
          cache_(cache),
          full_(detail == Detail::full),
          block_change_s_(block_change_s) {}

    double now() const { return t_; }
    double axis_mm() const { return axis_mm_; }
    void set_touch(int touch) { touch_ = touch; }

    void add_phase(Phase phase, double time_s, double distance_mm) {
        phases_.push_back({phase, touch_, t_, time_s, full_ ? distance_mm : 0.0});
        phase_time_[static_cast<std::size_t>(phase)] += time_s;
        t_ += time_s;
    }

    // Motion from the current axis position, `direction` +1/-1 along the
    // probing axis or 0 across it, starting at `start_speed_mm_s`; returns
    // the path length covered.
    double add_motion(const SegmentPlan& plan, double direction, double duration_s,
                      double start_speed_mm_s = 0.0) {
        KinematicState state;
        state.speed_mm_s = start_speed_mm_s;
        double remaining = duration_s;
        double seg_t = motion_t_;
        for (std::size_t i = 0; i < plan.count && remaining > 0.0; ++i) {
            const Segment& seg = plan.segments[i];
            const double dt = std::min(seg.duration_s, remaining);
            state.accel_mm_s2 = seg.accel_mm_s2;
            if (seg.step_speed_mm_s >= 0.0) state.speed_mm_s = seg.step_speed_mm_s;
            if (full_) {
                KinematicState start = state;
                start.position_mm = 0.0;
                segments_.push_back({seg_t, dt, axis_mm_ + direction * state.position_mm, direction,
                                     start, seg.jerk_mm_s3, touch_});
            }
            state = integrate(dt, state, seg.jerk_mm_s3);
            seg_t += dt;
            remaining -= dt;
        }
        motion_t_ = seg_t;
        axis_mm_ += direction * state.position_mm;
        return state.position_mm;
    }

    // The actual motion of `command`, kept in motions_ (built in place: a
    // motion is a kilobyte); its index there.
    int keep_motion(const AxisCommand& command) {
        motions_.emplace_back(*kernel_, command);
        return static_cast<int>(motions_.size() - 1);
    }
    // A block with dynamics, `duration_s` of it (to the in-position check):
    // kept motion `index` (-1 in a summary, which has no timeline); the next block
    // starts where the command ended, `end_mm` along the path.
    void add_filtered_motion(int index, double direction, double duration_s, double end_mm) {
        if (full_) push_segment(duration_s, direction, index);
        motion_t_ += duration_s;
        axis_mm_ += direction * end_mm;
    }

    // A timeline segment from now, where the axis stands: kept motion
    // `motion`, or at rest (-1, with no jerk or speed).
    void push_segment(double duration_s, double direction, int motion) {
        TimedSegment segment;
        segment.start_s = motion_t_;
        segment.duration_s = duration_s;
        segment.axis_start_mm = axis_mm_;
        segment.direction = direction;
        segment.touch = touch_;
        segment.motion = motion;
        segments_.push_back(segment);
    }

    // The control's block change after a move (machine.block_change_s): the
    // axis stands where the move left it, or with dynamics goes on settling
    // inside the in-position width.
    void add_block_change() {
        if (block_change_s_ <= 0.0) return;
        if (full_) {
            TimedSegment* last = segments_.empty() ? nullptr : &segments_.back();
            if (last != nullptr && last->motion >= 0 &&
                last->start_s + last->duration_s == motion_t_) {
                last->duration_s += block_change_s_;
            } else {
                push_segment(block_change_s_, 0.0, -1);
            }
        }
        motion_t_ += block_change_s_;
        add_phase(Phase::block_change, block_change_s_, 0.0);
    }

    std::size_t phase_count() const { return phases_.size(); }
    double phase_time(std::size_t index) const { return phases_[index].time_s; }
    std::size_t segment_count() const { return segments_.size(); }

    // Repeats `phase_count` phases from `first_phase` and `segment_count`
    // segments from `first_segment` (a touch sequence that starts and ends at
    // the touch's start position) as touch `touch_`, from now.
    void replay_sequence(std::size_t first_phase, std::size_t phase_count,
                         std::size_t first_segment, std::size_t segment_count) {
        const double origin = phases_[first_phase].start_s;
        const double shift = t_ - origin;
        for (std::size_t i = first_phase; i < first_phase + phase_count; ++i) {
            PhaseRecord record = phases_[i];
            record.start_s += shift;
            record.touch = touch_;
            phase_time_[static_cast<std::size_t>(record.phase)] += record.time_s;
            phases_.push_back(record);
        }
        for (std::size_t i = first_segment; i < first_segment + segment_count; ++i) {
            TimedSegment segment = segments_[i];
            segment.start_s += shift;
            segment.touch = touch_;
            segments_.push_back(segment);
        }
        const PhaseRecord& last = phases_[first_phase + phase_count - 1];
        const double sequence_s = last.start_s + last.time_s - origin;
        t_ += sequence_s;
        motion_t_ += sequence_s;
    }

    // A rest-to-rest move as one phase, then the block change.
    void add_move(Phase phase, const MotionLimits& limits, double distance_mm, double feed_mm_s,
                  double direction) {
        add_move_only(phase, limits, distance_mm, feed_mm_s, direction);
        add_block_change();
    }

    // A touch, then the block change.
    TouchResult add_touch(const Scenario& scenario, const MotionLimits& limits, double feed_mm_s,
                          double distance_mm, const TouchPhases& names) {
        const TouchResult touch = add_touch_only(scenario, limits, feed_mm_s, distance_mm, names);
        add_block_change();
        return touch;
    }

    // A touch solved for its figures only (issue 28: the stop at the feed
    // override): nothing of it stays in the result.
    TouchResult solve_touch(const Scenario& scenario, const MotionLimits& limits, double feed_mm_s,
                            double distance_mm, const TouchPhases& names) {
        const std::size_t phase_count = phases_.size();
        const std::size_t segment_count = segments_.size();
        const std::size_t motion_count = motions_.size();
        const std::array<double, kPhaseCount> phase_time = phase_time_;
        const double t = t_;
        const double motion_t = motion_t_;
        const double axis_mm = axis_mm_;
        const TouchResult touch = add_touch_only(scenario, limits, feed_mm_s, distance_mm, names);
        phases_.resize(phase_count);
        segments_.resize(segment_count);
        motions_.erase(motions_.begin() + static_cast<std::ptrdiff_t>(motion_count),
                       motions_.end());
        phase_time_ = phase_time;
        t_ = t;
        motion_t_ = motion_t;
        axis_mm_ = axis_mm;
        return touch;
    }

  private:
    // A touch's phases and motion, without the block change after it.
    TouchResult add_touch_only(const Scenario& scenario, const MotionLimits& limits,
                               double feed_mm_s, double distance_mm, const TouchPhases& names) {
        return kernel_ != nullptr
                   ? add_filtered_touch(scenario, limits, feed_mm_s, distance_mm, names)
                   : add_ideal_touch(scenario, limits, feed_mm_s, distance_mm, names);
    }

    void add_move_only(Phase phase, const MotionLimits& limits, double distance_mm,
                       double feed_mm_s, double direction) {
        if (kernel_ != nullptr) {
            // A feature repeats its moves (to and from the centre, across it):
            // one motion serves every repeat.
            for (const MoveMemo& memo : memo_) {
                if (memo.distance_mm == distance_mm && memo.feed_mm_s == feed_mm_s) {
                    add_filtered_motion(memo.motion, direction, memo.duration_s, memo.end_mm);
                    add_phase(phase, memo.duration_s, distance_mm);
                    return;
                }
            }
            const auto command = [&] {
                return move_command(plan_move(limits, distance_mm, feed_mm_s));
            };
            int index = -1;
            MotionCache::Move solved;
            if (full_) {
                index = keep_motion(command());
                solved = filtered_move(&cache_, distance_mm, feed_mm_s, [&]() -> const AxisMotion& {
                    return motions_[static_cast<std::size_t>(index)];
                });
            } else {  // the command and the motion only for a solve the cache does not hold
                solved = filtered_move(&cache_, distance_mm, feed_mm_s,
                                       [&] { return AxisMotion(*kernel_, command()); });
            }
            add_filtered_motion(index, direction, solved.time_s, solved.end_mm);
            if (memo_.size() < memo_.capacity()) {
                memo_.push_back({distance_mm, feed_mm_s, index, solved.time_s, solved.end_mm});
            }
            add_phase(phase, solved.time_s, distance_mm);
            return;
        }
        const SegmentPlan plan = plan_move(limits, distance_mm, feed_mm_s);
        const double duration = plan.duration_s();
        add_motion(plan, direction, duration);
        add_phase(phase, duration, distance_mm);
    }

    // domain.md, "One touch, phase by phase": approach from rest `distance_mm`
    // in front of the surface, pretravel, interface and controller response
    // (after the mean scan wait; the overtravel after a full one), then braking. The axis follows
    // its planned acceleration until it reacts, so a touch while still accelerating triggers at the
    // real, lower speed.
    TouchResult add_ideal_touch(const Scenario& scenario, const MotionLimits& limits,
                                double feed_mm_s, double distance_mm, const TouchPhases& names) {
        const Machine& m = scenario.machine;
        const Probe& p = scenario.probe;
        const SegmentPlan plan = plan_accelerate(limits, feed_mm_s, kOpenCruise_s);
        const double t_touch = time_at_distance_s(plan, distance_mm);
        const double t_trigger = time_at_distance_s(plan, distance_mm + p.pretravel_mm);
        const double t_interface = t_trigger + p.interface_delay_s;
        // The timeline waits the mean scan; the overtravel and the recorded
        // position take the worst case, a full scan.
        const double t_react_worst = t_trigger + reaction_time_s(m, p);
        const double t_react = t_react_worst - 0.5 * m.scan_period_s;
        const double record_scan_s = m.latched_input ? 0.0 : m.scan_period_s;
        const double t_record = t_interface + record_scan_s;

        const KinematicState at_touch = plan.state_at(t_touch);
        const KinematicState at_trigger = plan.state_at(t_trigger);
        const KinematicState at_interface = plan.state_at(t_interface);
        const KinematicState at_react = plan.state_at(t_react);
        const SegmentPlan stop =
            plan_stop(limits, feed_mm_s, at_react.speed_mm_s, at_react.accel_mm_s2);
        const double stop_time = stop.duration_s();
        // Past the plan's ramp the worst case reacts the rest of the scan
        // later at the same speed and brakes the same way; on the ramp it is
        // a stop of its own.
        const double ramp_end_s = reach_time_s(limits, feed_mm_s);
        const bool cruising = t_react >= ramp_end_s;
        double worst_stop_extra_mm = 0.5 * m.scan_period_s * at_react.speed_mm_s;
        if (!cruising) {
            const KinematicState at_worst = plan.state_at(t_react_worst);
            worst_stop_extra_mm =
                at_worst.position_mm - at_react.position_mm +
                plan_stop(limits, feed_mm_s, at_worst.speed_mm_s, at_worst.accel_mm_s2)
                    .end_state({0.0, at_worst.speed_mm_s, at_worst.accel_mm_s2})
                    .position_mm;
        }

        add_motion(plan, +1.0, t_react);
        const double stop_distance = add_motion(stop, +1.0, stop_time, at_react.speed_mm_s);

        add_phase(names.approach, t_touch, at_touch.position_mm);
        add_phase(names.pretravel, t_trigger - t_touch,
                  at_trigger.position_mm - at_touch.position_mm);
        add_phase(names.interface_delay, p.interface_delay_s,
                  at_interface.position_mm - at_trigger.position_mm);
        add_phase(names.controller_delay, t_react - t_interface,
                  at_react.position_mm - at_interface.position_mm);
        add_phase(names.deceleration, stop_time, stop_distance);

        TouchResult touch;
        touch.programmed_feed_mm_s = feed_mm_s;
        touch.touch_speed_mm_s = at_touch.speed_mm_s;
        touch.trigger_speed_mm_s = at_trigger.speed_mm_s;
        // Overtravel: pretravel + delay travel + stopping distance, past the surface.
        touch.mean_overtravel_mm = at_react.position_mm + stop_distance - at_touch.position_mm;
        touch.overtravel_mm =
            cruising ? touch.mean_overtravel_mm + worst_stop_extra_mm
                     : at_react.position_mm + worst_stop_extra_mm - at_touch.position_mm;
        touch.recorded_mm = plan.state_at(t_record).position_mm - at_touch.position_mm;
        touch.mean_recorded_mm =
            t_interface >= ramp_end_s
                ? touch.recorded_mm - 0.5 * record_scan_s * at_interface.speed_mm_s
                : plan.state_at(t_interface + 0.5 * record_scan_s).position_mm -
                      at_touch.position_mm;
        if (full_) {  // as the touch with dynamics (Detail::summary)
            touch.react_speed_mm_s = at_react.speed_mm_s;
            touch.delay_travel_mm =
                plan.state_at(t_trigger + measurement_delay_s(m, p)).position_mm -
                at_trigger.position_mm;
        }
        return touch;
    }

    // The touch with dynamics after interpolation (issue 11): the actual
    // position touches and triggers; the control reacts after the trigger
    // chain, the interpolator then stops its command (at once, or braking as
    // its plan does), and the axis drains the filters and the servo lag. The
    // overtravel is where it comes to rest, the command's end; the next block
    // starts when the in-position check passes.
    TouchResult add_filtered_touch(const Scenario& scenario, const MotionLimits& limits,
                                   double feed_mm_s, double distance_mm, const TouchPhases& names) {
        const Machine& m = scenario.machine;
        const Probe& p = scenario.probe;
        const SegmentPlan plan = plan_accelerate(limits, feed_mm_s, kOpenCruise_s);
        const MotionCache::TouchKey key{
            feed_mm_s,           p.pretravel_mm,
            p.interface_delay_s, reaction_time_s(m, p),
            m.scan_period_s,     m.latched_input ? 0.0 : m.scan_period_s};
        // The timeline reacts after the mean scan wait (TouchResult).
        const double reaction_s = mean_reaction_s(key);
        // Past the distance where the approach settles it cruises as its
        // moment expansion: the touch is the one there, shifted
        // (MotionCache::SolvedTouch).
        std::optional<MotionCache::SolvedTouch> solved = cache_.touch(key, distance_mm);
        int index = -1;  // the touch's kept motion (the timeline's; a summary's until it ends)
        if (!solved) {
            const AxisCommand approach = approach_command(plan);
            const AxisCommand::Break& last = approach.at(approach.size() - 1);
            const double settled_mm =
                moment_expansion(*kernel_, last, last.t_s + kernel_->settled_age_s()).position_mm;
            const bool settled = distance_mm > settled_mm;
            index = keep_motion(approach);
            solved = solve_filtered_touch(limits, plan, key, settled ? settled_mm : distance_mm,
                                          motions_[static_cast<std::size_t>(index)]);
            solved->reference = settled;
            cache_.store_touch(key, *solved);
        }
        MotionCache::SolvedTouch& t = *solved;
        bool stopped_here = index >= 0;  // the solved motion stops where this touch reacts
        if (t.reference && distance_mm != t.distance_mm) {
            // Shifted by the phases' lengths, so none turns negative by rounding.
            const double pretravel_s = t.trigger_s - t.touch_s;
            const double settling_s = t.settle_s - (t.trigger_s + reaction_s);
            t.touch_s += (distance_mm - t.distance_mm) / t.touch_speed_mm_s;
            t.trigger_s = t.touch_s + pretravel_s;
            t.settle_s = t.trigger_s + reaction_s + settling_s;
            t.rest_mm += distance_mm - t.distance_mm;
            t.worst_rest_mm += distance_mm - t.distance_mm;
            t.distance_mm = distance_mm;
            stopped_here = false;
        }
        const double t_interface = t.trigger_s + p.interface_delay_s;
        const double t_react = t.trigger_s + reaction_s;
        if (full_ && !stopped_here) {  // the timeline's motion, stopped where this touch reacts
            const AxisCommand command = touch_command(limits, plan, feed_mm_s, t_react);
            if (index < 0) {
                index = keep_motion(command);
            } else {
                motions_[static_cast<std::size_t>(index)].reset(command);
            }
        }

        // The states only the full result shows (the phases' distances, the
        // react speed, the delay travel) are not solved for a summary.
        KinematicState at_trigger;
        KinematicState at_interface;
        KinematicState at_react;
        double delay_travel_mm = 0.0;
        if (full_) {
            const AxisMotion& motion = motions_[static_cast<std::size_t>(index)];
            at_trigger = motion.state(t.trigger_s);
            at_interface = motion.state(t_interface);
            at_react = motion.state(t_react);
            delay_travel_mm = motion.state(t.trigger_s + measurement_delay_s(m, p)).position_mm -
                              at_trigger.position_mm;
        }
        add_filtered_motion(index, +1.0, t.settle_s, t.rest_mm);

        add_phase(names.approach, t.touch_s, distance_mm);
        add_phase(names.pretravel, t.trigger_s - t.touch_s, p.pretravel_mm);
        add_phase(names.interface_delay, p.interface_delay_s,
                  at_interface.position_mm - at_trigger.position_mm);
        add_phase(names.controller_delay, t_react - t_interface,
                  at_react.position_mm - at_interface.position_mm);
        add_phase(names.deceleration, t.settle_s - t_react, t.rest_mm - at_react.position_mm);

        TouchResult touch;
        touch.programmed_feed_mm_s = feed_mm_s;
        touch.touch_speed_mm_s = t.touch_speed_mm_s;
        touch.trigger_speed_mm_s = t.trigger_speed_mm_s;
        touch.react_speed_mm_s = at_react.speed_mm_s;  // 0 in a summary
        touch.overtravel_mm = t.worst_rest_mm - distance_mm;
        touch.recorded_mm = t.recorded_mm;
        touch.mean_overtravel_mm = t.rest_mm - distance_mm;
        touch.mean_recorded_mm = t.mean_recorded_mm;
        touch.delay_travel_mm = delay_travel_mm;  // 0 in a summary
        return touch;
    }

    // Solves a touch `distance_mm` in front of the surface on `motion`, the
    // approach's actual motion, which it leaves stopped where the axis reacts
    // (AxisMotion::reset).
    MotionCache::SolvedTouch solve_filtered_touch(const MotionLimits& limits,
                                                  const SegmentPlan& plan,
                                                  const MotionCache::TouchKey& key,
                                                  double distance_mm, AxisMotion& motion) const {
        const AxisMotion& approach = motion;
        const double lag = kernel_->moment(1);
        const auto reach = [&](double position_mm, KinematicState& at) {
            return approach.time_at_position(position_mm,
                                             time_at_distance_s(plan, position_mm) + lag, at);
        };
        MotionCache::SolvedTouch t;
        t.distance_mm = distance_mm;
        KinematicState at_touch;
        t.touch_s = reach(distance_mm, at_touch);
        t.touch_speed_mm_s = at_touch.speed_mm_s;
        // The trigger a pretravel later, near the touch at its speed.
        const double pretravel_mm = key.pretravel_mm;
        KinematicState at_trigger = at_touch;
        if (pretravel_mm > 0.0) {
            t.trigger_s = at_touch.speed_mm_s > 0.0
                              ? approach.time_at_position(
                                    distance_mm + pretravel_mm,
                                    t.touch_s + pretravel_mm / at_touch.speed_mm_s, at_trigger)
                              : reach(distance_mm + pretravel_mm, at_trigger);
        } else {
            t.trigger_s = t.touch_s;
        }
        t.trigger_speed_mm_s = at_trigger.speed_mm_s;
        const double t_interface = t.trigger_s + key.interface_delay_s;
        const double t_react = t.trigger_s + mean_reaction_s(key);
        const double t_react_worst = t.trigger_s + key.reaction_s;
        // Both records come before the worst reaction, where the approach is
        // still the touch's motion.
        t.recorded_mm = approach.state(t_interface + key.record_delay_s).position_mm - distance_mm;
        t.mean_recorded_mm =
            approach.state(t_interface + 0.5 * key.record_delay_s).position_mm - distance_mm;
        t.worst_rest_mm =
            touch_command(limits, plan, key.feed_mm_s, t_react_worst).end_state().position_mm;

        // (Before the reaction the command is the approach's.)
        const AxisCommand command = touch_command(limits, plan, key.feed_mm_s, t_react);
        motion.reset(command);
        t.settle_s = std::max(motion.in_position_time(), t_react);
        t.rest_mm = command.end_state().position_mm;
        return t;
    }

    struct MoveMemo {
        double distance_mm;
        double feed_mm_s;
        int motion;
        double duration_s;
        double end_mm;
    };
    // A handful of distinct moves per cycle; fixed capacity, no allocation.
    // Only items[0, count) are set (MoveMemo has no initialisers: the list
    // is not 320 bytes of zeros to write per evaluation).
    struct MemoList {
        std::array<MoveMemo, 8> items;
        std::size_t count{0};
        const MoveMemo* begin() const { return items.data(); }
        const MoveMemo* end() const { return items.data() + count; }
        std::size_t size() const { return count; }
        std::size_t capacity() const { return items.size(); }
        void push_back(const MoveMemo& m) { items[count++] = m; }
    };
    MemoList memo_;

    std::vector<PhaseRecord>& phases_;
    std::vector<TimedSegment>& segments_;
    std::vector<AxisMotion>& motions_;
    std::array<double, kPhaseCount>& phase_time_;
    const AxisKernel* kernel_;
    MotionCache& cache_;
    bool full_{true};  // Detail::full: the timeline and every distance
    double block_change_s_{0.0};
    double t_{0.0};
    double motion_t_{0.0};
    double axis_mm_{0.0};
    int touch_{0};
};

// Which of a touch's figures: the worst case, which the checks, the
// recommended backoff and the programs take, or after the mean scan wait,
// which the timeline takes (TouchResult).
enum class TouchCase { worst, mean };

// Where the backoff is measured from, beyond the surface (issue 11): where the
// first touch stopped, or where the control recorded it.
double backoff_reference_mm(const Cycle& cycle, const TouchResult& first, TouchCase which) {
    const bool mean = which == TouchCase::mean;
    if (cycle.backoff_from == BackoffFrom::stop) {
        return mean ? first.mean_overtravel_mm : first.overtravel_mm;
    }
    return mean ? first.mean_recorded_mm : first.recorded_mm;
}

// The backoff move's length: from the stop to `backoff_mm` in front of the
// reference (exactly the backoff from the stop: the same move at every feed).
double backoff_move_mm(const Cycle& cycle, double backoff_mm, const TouchResult& first,
                       TouchCase which) {
    if (cycle.backoff_from == BackoffFrom::stop) return backoff_mm;
    return which == TouchCase::mean ? backoff_mm + first.mean_overtravel_mm - first.mean_recorded_mm
                                    : backoff_mm + first.overtravel_mm - first.recorded_mm;
}

// Time for the backoff move and the second approach, the part of a two-touch
// cycle that the backoff changes (domain.md, "Strategies"). The move runs from
// the stop to `backoff_mm` in front of the reference; the second touch starts
// `backoff_mm - reference` in front of the surface.
double backoff_cost_s(const Scenario& scenario, const MotionLimits& limits,
                      const AxisKernel* kernel, double backoff_mm, const TouchResult& first,
                      MotionCache& cache) {
    const Cycle& c = scenario.cycle;
    const double reference = backoff_reference_mm(c, first, TouchCase::mean);
    const double measure_v = mm_min_to_mm_s(c.measure_feed_mm_min);
    return block_time(limits, kernel, backoff_move_mm(c, backoff_mm, first, TouchCase::mean),
                      mm_min_to_mm_s(c.return_feed_mm_min), &cache) +
           approach_time_s(limits, kernel, measure_v, std::max(0.0, backoff_mm - reference));
}

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

double block_time_s(const Scenario& scenario, double distance_mm, double feed_mm_s) {
    const AxisKernel kernel(scenario.axis_dynamics());
    return block_time(scenario.motion_limits(), active_kernel(kernel), distance_mm, feed_mm_s);
}

double approach_room_mm(const Scenario& scenario, double feed_mm_s) {
    const AxisKernel kernel(scenario.axis_dynamics());
    return approach_room(scenario, scenario.motion_limits(), active_kernel(kernel), feed_mm_s);
}

CycleResult evaluate(const Scenario& scenario) {
    CycleResult result;
    evaluate_into(scenario, result);
    return result;
}

void MotionCache::bind(const MotionLimits& limits, const AxisDynamics& dynamics) {
    if (limits_ && *limits_ == limits && dynamics_ == dynamics) return;
    limits_ = limits;
    dynamics_ = dynamics;
    kernel_ = AxisKernel(dynamics);
    moves_ = {};
    rooms_ = {};
    touch_count_ = 0;
}

std::optional<MotionCache::Move> MotionCache::move(double distance_mm, double feed_mm_s) const {
    return moves_.find(distance_mm, feed_mm_s);
}

void MotionCache::store_move(double distance_mm, double feed_mm_s, const Move& move) {
    moves_.store(distance_mm, feed_mm_s, move);
}

std::optional<double> MotionCache::approach_room_mm(double feed_mm_s, double delay_s) const {
    return rooms_.find(feed_mm_s, delay_s);
}

void MotionCache::store_approach_room(double feed_mm_s, double delay_s, double room_mm) {
    rooms_.store(feed_mm_s, delay_s, room_mm);
}

std::optional<MotionCache::SolvedTouch> MotionCache::touch(const TouchKey& key,
                                                           double distance_mm) {
    for (std::size_t i = 0; i < touch_count_; ++i) {
        const std::uint8_t slot = touch_order_[i];
        const KeptTouch& kept = touches_[slot];
        if (!(kept.key == key)) continue;
        const SolvedTouch& t = kept.touch;
        if (distance_mm == t.distance_mm || (t.reference && distance_mm > t.distance_mm)) {
            std::copy_backward(touch_order_.begin(),
                               touch_order_.begin() + static_cast<std::ptrdiff_t>(i),
                               touch_order_.begin() + static_cast<std::ptrdiff_t>(i) + 1);
            touch_order_[0] = slot;
            return t;
        }
    }
    return std::nullopt;
}

void MotionCache::store_touch(const TouchKey& key, const SolvedTouch& touch) {
    // A free slot while there is one, else the least recently used.
    const std::uint8_t slot = touch_count_ < touches_.size()
                                  ? static_cast<std::uint8_t>(touch_count_)
                                  : touch_order_[touches_.size() - 1];
    touch_count_ = std::min(touch_count_ + 1, touches_.size());
    std::copy_backward(touch_order_.begin(),
                       touch_order_.begin() + static_cast<std::ptrdiff_t>(touch_count_) - 1,
                       touch_order_.begin() + static_cast<std::ptrdiff_t>(touch_count_));
    touch_order_[0] = slot;
    touches_[slot] = {key, touch};
}

template <typename Value>
std::optional<Value> MotionCache::Table<Value>::find(double key1, double key2) const {
    for (std::size_t i = 0; i < count; ++i) {
        if (entries[i].key1 == key1 && entries[i].key2 == key2) return entries[i].value;
    }
    return std::nullopt;
}

template <typename Value>
void MotionCache::Table<Value>::store(double key1, double key2, const Value& value) {
    entries[next] = {key1, key2, value};
    next = (next + 1) % entries.size();
    count = std::max(count, next == 0 ? entries.size() : next);
}

void evaluate_into(const Scenario& scenario, CycleResult& r) {
    MotionCache cache;
    evaluate_into(scenario, r, cache);
}

void evaluate_into(const Scenario& scenario, CycleResult& r, MotionCache& cache, Detail detail) {
    const bool full = detail == Detail::full;
    r.phases_.clear();
    r.segments_.clear();
    r.motions_.clear();
    r.warnings_.clear();
    r.phase_time_s_.fill(0.0);

    const Machine& m = scenario.machine;
    const Probe& p = scenario.probe;
    const Cycle& c = scenario.cycle;
    const MotionLimits limits = scenario.motion_limits();
    const double s = c.approach_mm;
    const double probe_v = mm_min_to_mm_s(c.probe_feed_mm_min);
    const double measure_v = mm_min_to_mm_s(c.measure_feed_mm_min);
    const double return_v = mm_min_to_mm_s(c.return_feed_mm_min);
    const double rapid_v = mm_min_to_mm_s(m.rapid_feed_mm_min);
    const bool two_touch = c.strategy == Strategy::two_touch;
    const int touches = touch_count(c.feature);

    cache.bind(limits, scenario.axis_dynamics());
    const AxisKernel* dynamics = active_kernel(cache.kernel());
    CycleBuilder b(r.phases_, r.segments_, r.motions_, r.phase_time_s_, dynamics, cache, detail,
                   m.block_change_s);
    // Issue 11, loose end 6: a feature's moves are protected, at the positioning
    // feed, from the centre (above it for a boss or web, which lifts over the
    // wall at the rapid feed, away from the part).
    const double position_v = mm_min_to_mm_s(c.position_feed_mm_min);
    const bool lift = lifts_over(c.feature);
    // Out from the centre to a touch's start (over it, then down to the
    // measuring depth), and back (up over the wall, then over the centre).
    const double radius = start_radius_mm(c);
    const auto out_to_start = [&] {
        if (radius > 0.0) b.add_move(Phase::position, limits, radius, position_v, 0.0);
        if (lift) b.add_move(Phase::lower, limits, c.clearance_mm, position_v, 0.0);
    };
    const auto back_to_centre = [&] {
        if (lift) b.add_move(Phase::lift, limits, c.clearance_mm, rapid_v, 0.0);
        if (radius > 0.0) b.add_move(Phase::position, limits, radius, position_v, 0.0);
    };
    if (touches > 1) out_to_start();
    const std::size_t sequence_first_phase = b.phase_count();
    const std::size_t sequence_first_segment = b.segment_count();
    // One touch sequence: first touch, (backoff, second touch,) return to start.
    TouchResult first = b.add_touch(scenario, limits, probe_v, s, kFirstTouch);
    // Issue 28: the operator may turn the feed override up to its highest:
    // the same touch at that feed stops farther, and every overtravel check
    // (the limit, the searches, the backoff) holds at it. The timeline stays
    // at 100 %.
    const double override_k = feed_override_factor(c);
    const bool overridden = override_k > 1.0;
    const TouchResult first_fast =
        overridden ? b.solve_touch(scenario, limits, override_k * probe_v, s, kFirstTouch) : first;
    first.override_overtravel_mm = std::max(first.overtravel_mm, first_fast.overtravel_mm);
    first.search_mm = s + c.part_position_uncertainty_mm +
                      search_beyond_mm(scenario, first.override_overtravel_mm);
    TouchResult measuring = first;
    // domain.md, "Strategies": the second touch starts b - overtravel_1 in
    // front of the surface (none left if the backoff is too short). From the
    // recorded trigger position (issue 11), b - recorded_1, and the backoff
    // move also covers the travel from there to the stop.
    // `cost_s`: the time the backoff sets, the backoff move and the second
    // approach (backoff_cost_s, here taken from the phases as they are made).
    const auto back_off_and_measure = [&](const TouchResult& from, double& cost_s) {
        const double reference = backoff_reference_mm(c, from, TouchCase::mean);
        const std::size_t backoff_phase = b.phase_count();
        b.add_move(Phase::backoff, limits, backoff_move_mm(c, c.backoff_mm, from, TouchCase::mean),
                   return_v, -1.0);
        // (The move itself: its block change does not change with the backoff.)
        const double backoff_s = b.phase_time(backoff_phase);
        const double distance = std::max(0.0, c.backoff_mm - reference);
        const std::size_t approach_phase = b.phase_count();
        const TouchResult touch = b.add_touch(scenario, limits, measure_v, distance, kSecondTouch);
        cost_s = backoff_s + b.phase_time(approach_phase);
        return touch;
    };
    double first_backoff_cost_s = 0.0;
    double repeat_backoff_cost_s = 0.0;
    if (two_touch) {
        measuring = back_off_and_measure(first, first_backoff_cost_s);
        measuring.override_overtravel_mm = measuring.overtravel_mm;
        if (overridden) {  // after the first touch at the override, as the timeline's
            const double distance =
                std::max(0.0, c.backoff_mm - backoff_reference_mm(c, first_fast, TouchCase::mean));
            measuring.override_overtravel_mm = std::max(
                measuring.overtravel_mm,
                b.solve_touch(scenario, limits, override_k * measure_v, distance, kSecondTouch)
                    .overtravel_mm);
        }
        // The backoff as the programs move it, from the worst-case figures
        // (from the recorded trigger, the stop at the override is farther).
        measuring.search_mm =
            std::max(backoff_move_mm(c, c.backoff_mm, first, TouchCase::worst),
                     backoff_move_mm(c, c.backoff_mm, first_fast, TouchCase::worst)) +
            search_beyond_mm(scenario, measuring.override_overtravel_mm);
        if (full) add_touch_warnings(scenario, measuring, 1, r.warnings_);
    }
    // Issue 14: the measuring touch made `repeats` times and averaged. Two-touch
    // backs off from the measuring touch and touches again at the measuring
    // feed; single-touch returns to the start and touches again. Each repeat
    // after the first is the first one again (it starts and ends where the
    // measuring touch stopped), so it is replayed.
    const int repeats = repeat_count(c);
    if (repeats > 1) {
        const std::size_t repeat_first_phase = b.phase_count();
        const std::size_t repeat_first_segment = b.segment_count();
        if (two_touch) {
            back_off_and_measure(measuring, repeat_backoff_cost_s);
        } else {
            b.add_move(Phase::return_move, limits, b.axis_mm(), return_v, -1.0);
            b.add_touch(scenario, limits, probe_v, s, kFirstTouch);
        }
        const std::size_t repeat_phases = b.phase_count() - repeat_first_phase;
        const std::size_t repeat_segments = b.segment_count() - repeat_first_segment;
        for (int k = 2; k < repeats; ++k) {
            b.replay_sequence(repeat_first_phase, repeat_phases, repeat_first_segment,
                              repeat_segments);
        }
    }
    // domain.md, "Return": back to the start position, s + overtravel.
    b.add_move(Phase::return_move, limits, b.axis_mm(), return_v, -1.0);
    // Only a touch that measures errs by touching while accelerating: the
    // first touch of two-touch only finds the surface (its speed only sets
    // its overtravel, which the model follows).
    if (full && !two_touch) add_touch_warnings(scenario, first, 0, r.warnings_);
    r.first_ = first;
    r.measuring_ = measuring;

    // The other touches of a feature differ only in direction: each is reached
    // from the centre by protected moves, then the same sequence again, then
    // back to the centre.
    if (touches > 1) {
        const std::size_t sequence_phases = b.phase_count() - sequence_first_phase;
        const std::size_t sequence_segments = b.segment_count() - sequence_first_segment;
        back_to_centre();
        for (int k = 1; k < touches; ++k) {
            b.set_touch(k);
            out_to_start();
            b.replay_sequence(sequence_first_phase, sequence_phases, sequence_first_segment,
                              sequence_segments);
            back_to_centre();
        }
    }
    const double first_worst = first.override_overtravel_mm;
    const double measuring_worst = two_touch ? measuring.override_overtravel_mm : first_worst;
    const double worst_overtravel = std::max(first_worst, measuring_worst);
    // Two-touch: a faster first touch may overtravel less than the slow second
    // one when a fixed backoff leaves the second approach too short to brake
    // from; the user must see which touch sets the worst.
    r.overtravel_touch_ = two_touch && measuring_worst > first_worst ? 2 : 1;

    r.total_s_ = b.now();
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
