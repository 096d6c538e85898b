#include "core/cycle/cycle.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/cycle/cycle_builder.h"
#include "core/cycle/cycle_warnings.h"
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

unsigned CycleResult::invalid_codes() const {
    unsigned codes = 0;
    for (const Warning& w : warnings_) {
        if (w.severity == Severity::error) codes |= invalid_code_bit(w.code);
    }
    return codes;
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

// docs/model.md, "One touch": interface response t_i, controller latency t_c and,
// worst case, a full scan period t_s pass between trigger and reaction.
double reaction_time_s(const Machine& machine, const Probe& probe) {
    return probe.interface_delay_s + machine.controller_latency_s + machine.scan_period_s;
}

// docs/model.md, "One touch": the wait for the next scan is anywhere in
// [0, t_s], a range of v_t * t_s; a latched input removes it from the value.
double scan_range_mm(const Machine& machine, double trigger_speed_mm_s) {
    return machine.latched_input ? 0.0 : trigger_speed_mm_s * machine.scan_period_s;
}

// A uniform range R has sigma R/sqrt(12); repeatability is given as 2 sigma.
// Expanded (k = 2): 2 * sqrt(R^2/12 + (rep/2)^2) = sqrt(R^2/3 + rep^2).
double expanded_uncertainty_mm(double range_mm, double repeatability_2sigma_mm) {
    return std::sqrt(range_mm * range_mm / 3.0 + repeatability_2sigma_mm * repeatability_2sigma_mm);
}

// docs/model.md, "One touch" (calibration feed): the delay travel calibrated at
// one speed is wrong at another by (v - v_cal) * tau, tau = t_i + t_c + t_s/2
// with a scanned input. A latched input captures the position when the signal
// reaches the control, before the controller's latency and scan, so there
// tau = t_i alone.
double measurement_delay_s(const Machine& machine, const Probe& probe) {
    if (machine.latched_input) return probe.interface_delay_s;
    return probe.interface_delay_s + machine.controller_latency_s + 0.5 * machine.scan_period_s;
}

double speed_error_mm(const Machine& machine, const Probe& probe, double speed_mm_s,
                      double calibrated_speed_mm_s) {
    return (speed_mm_s - calibrated_speed_mm_s) * measurement_delay_s(machine, probe);
}

// The moves of a feature as real cycles make them (cycle.h; docs/model.md,
// "Strategies and features").
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

void evaluate_into(const Scenario& scenario, CycleResult& r) {
    MotionCache cache;
    evaluate_into(scenario, r, cache);
}

// Build the timeline, work out the figures, collect the warnings.
void evaluate_into(const Scenario& scenario, CycleResult& r, MotionCache& cache, Detail detail) {
    const CycleTimeline timeline = build_timeline(
        scenario, {r.phases_, r.segments_, r.motions_, r.phase_time_s_}, cache, detail);
    const Probe& p = scenario.probe;
    const Cycle& c = scenario.cycle;
    const bool two_touch = c.strategy == Strategy::two_touch;
    const TouchResult& first = timeline.first;
    const TouchResult& measuring = timeline.measuring;
    r.first_ = first;
    r.measuring_ = measuring;
    r.total_s_ = timeline.total_s;

    // Overtravel: the stop at 100 % feed override, and the one the checks
    // take, at up to the highest override. Two-touch: a faster first touch
    // may overtravel less than the slow second one when a fixed backoff
    // leaves the second approach too short to brake from; the user must see
    // which touch sets the worst.
    const double first_worst = first.override_overtravel_mm;
    const double measuring_worst = two_touch ? measuring.override_overtravel_mm : first_worst;
    r.overtravel_mm_ = std::max(first.overtravel_mm, measuring.overtravel_mm);
    r.checked_overtravel_mm_ = std::max(first_worst, measuring_worst);
    r.overtravel_touch_ = two_touch && measuring_worst > first_worst ? 2 : 1;

    // Uncertainty: the scan phase and the repeatability are random from touch
    // to touch, so the mean of N touches has 1/sqrt(N) of their uncertainty;
    // the budget's fixed terms (uncertainty.h) join it as the GUM combines
    // independent terms (docs/model.md, "One touch").
    r.trigger_speed_mm_s_ = measuring.trigger_speed_mm_s;
    r.scan_range_mm_ = scan_range_mm(scenario.machine, r.trigger_speed_mm_s_);
    r.trigger_uncertainty_mm_ =
        expanded_uncertainty_mm(r.scan_range_mm_, p.repeatability_2sigma_mm) /
        std::sqrt(static_cast<double>(repeat_count(c)));
    r.uncertainty_mm_ = combined_expanded_uncertainty_mm(fixed_expanded_uncertainty_mm(scenario),
                                                         r.trigger_uncertainty_mm_, 1);

    // The recommended backoff: the first touch's distance past the surface
    // from the backoff's reference (its stop or its recorded trigger), plus
    // room to reseat and to reach the measuring feed before the second touch;
    // at the highest feed override the probe must still reseat (the
    // measuring feed's room is for the measurement, at 100 %). Rounded up to
    // the editors' digits, so the value shown is the value that clears
    // backoff_too_small.
    const double room =
        approach_room(scenario, scenario.motion_limits(), active_kernel(cache.kernel()),
                      mm_min_to_mm_s(c.measure_feed_mm_min), &cache);
    const double needed =
        std::max(backoff_reference_mm(c, first, TouchCase::worst) + std::max(p.reseat_mm, room),
                 backoff_reference_mm(c, timeline.first_fast, TouchCase::worst) + p.reseat_mm);
    r.recommended_backoff_mm_ = round_up_to(needed, kBackoffStep_mm);

    r.warnings_.clear();
    collect_warnings(scenario, timeline, r, cache, detail, r.warnings_);
    // A summary's touches kept their motions only while they were solved.
    if (detail != Detail::full) r.motions_.clear();
}

}  // namespace probecycle
