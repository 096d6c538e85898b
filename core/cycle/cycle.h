#pragma once

// The probing cycle, phase by phase (docs/model.md, "One touch", "Strategies
// and features").

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/message.h"
#include "core/common/number_format.h"
#include "core/common/severity.h"
#include "core/cycle/dynamics.h"
#include "core/cycle/motion.h"
#include "core/cycle/scenario.h"
#include "core/cycle/warning.h"

namespace probecycle {

class MotionCache;

// How much of a CycleResult an evaluation fills in.
enum class Detail {
    full,
    // What a sweep, the knee search, the optimiser and the overtravel fix
    // read of each candidate: the total and phase times, the touches'
    // overtravel, recorded position and trigger speed, the uncertainty, the
    // recommended backoff and every error (valid(), invalid_codes()), bit for
    // bit as `full`. Left out: the timeline (segments() and motions();
    // state_at() is not available), the phases' distances, the touches'
    // react_speed_mm_s and delay_travel_mm (all 0), and the notes and
    // warnings that take solves of their own (backoff_excess,
    // touch_while_accelerating).
    summary,
};

enum class Phase {
    approach,
    pretravel,
    interface_delay,
    controller_delay,
    deceleration,
    backoff,
    second_approach,
    second_pretravel,
    second_interface_delay,
    second_controller_delay,
    second_deceleration,
    return_move,  // "return"
    position,     // protected move at the positioning feed (between touches, from/to the centre)
    lift,         // boss/web: up to the clearance height, at the rapid feed (away from the part)
    lower,        // boss/web: down to the measuring depth, protected, at the positioning feed
    // After each move, the control's block change (machine.block_change_s):
    // the axis at rest.
    block_change,
};
constexpr std::size_t kPhaseCount = 16;
const char* to_string(Phase phase);  // the exact file/CSV names ("return" for return_move)
// Every phase in its canonical order.
const std::array<Phase, kPhaseCount>& all_phases();

struct PhaseRecord {
    Phase phase{Phase::approach};
    int touch{0};  // 0-based index of the touch point (bore: X+, X-, Y+, Y-)
    double start_s{0.0};
    double time_s{0.0};
    double distance_mm{0.0};
};

// Where the probe is at a time in the cycle.
struct CycleState {
    std::size_t phase_index{0};  // into CycleResult::phases()
    int touch{0};
    // Along the probing direction of the current touch: 0 at its start
    // position, positive toward the surface (the surface is at approach_mm).
    // Constant during positioning moves, which run across that direction.
    double position_mm{0.0};
    double velocity_mm_s{0.0};    // signed, along the probing direction
    double path_speed_mm_s{0.0};  // magnitude along the path, positioning moves too
};

// A constant-jerk piece of the cycle's motion, in path coordinates.
struct TimedSegment {
    double start_s{0.0};
    double duration_s{0.0};
    double axis_start_mm{0.0};  // position along the probing direction at start
    double direction{0.0};      // +1 toward the surface, -1 away, 0 positioning
    KinematicState start{};     // path state at start (position 0)
    double jerk_mm_s3{0.0};
    int touch{0};
    // With dynamics after interpolation (dynamics.h): the block's actual motion
    // is CycleResult::motions()[motion] at (t - start_s); start and jerk are
    // then unused. -1: the constant-jerk piece above.
    int motion{-1};
};

struct TouchResult {
    double programmed_feed_mm_s{0.0};
    double touch_speed_mm_s{0.0};    // when the stylus meets the surface
    double trigger_speed_mm_s{0.0};  // when the probe triggers (after pretravel)
    double react_speed_mm_s{0.0};    // when the controller reacts and braking starts
    // Beyond the surface, where the axis stops: worst case, after a full
    // scan period (the stylus must survive it; the searches and the
    // recommended backoff must clear it).
    double overtravel_mm{0.0};
    // Beyond the surface, where the control records the touch (the skip
    // position): the trigger plus the interface delay's travel plus, with a
    // scanned input, a full scan period's (worst case, as the overtravel).
    double recorded_mm{0.0};
    // The same two after the mean scan wait, half a period: where the touch
    // stops and is recorded on average. The cycle's timeline (its phases and
    // total, the moves that follow the touch) takes these, so the cycle time
    // is the one a control averages to; a fixed backoff leaves the second
    // touch the backoff less this stop to approach.
    double mean_overtravel_mm{0.0};
    double mean_recorded_mm{0.0};
    // Where the touch stops, worst case, with its feed at up to
    // the highest feed override (cycle.feed_override_max_pct) from the same
    // start: the farther of the stops at 100 % and at that override (a touch
    // that does not reach its feed at the override may stop nearer). The
    // overtravel checks, the searches and the recommended backoff take it;
    // overtravel_mm is at 100 %.
    double override_overtravel_mm{0.0};
    // Travel from the trigger through the measurement delay (see
    // measurement_delay_s) at the axis's real speed: what calibration takes
    // as v * tau when the touch is at full feed.
    double delay_travel_mm{0.0};
    // The probing move's length from the touch's start: to the farthest place
    // the surface can be, plus search_beyond_mm(). The first touch's farthest
    // surface is the nominal one plus the part position uncertainty; a
    // second touch's is where the first stopped (its search covers the whole
    // backoff move, whatever the first touch's real overtravel was).
    double search_mm{0.0};
};

class CycleResult {
  public:
    const std::vector<PhaseRecord>& phases() const { return phases_; }
    double total() const { return total_s_; }
    CycleState state_at(double t_s) const;

    // Sum of the time spent in one kind of phase over all touches.
    double phase_time(Phase phase) const { return phase_time_s_[static_cast<std::size_t>(phase)]; }

    double overtravel_mm() const { return overtravel_mm_; }  // worst over all touches
    // The overtravel the stylus must survive, which every check
    // takes: the worst over all touches at up to the highest feed override
    // (TouchResult::override_overtravel_mm).
    double checked_overtravel_mm() const { return checked_overtravel_mm_; }
    // Which touch overtravels most (at the override): 1 = the first, 2 = the
    // second of two-touch.
    int overtravel_touch() const { return overtravel_touch_; }
    double trigger_speed_mm_s() const { return trigger_speed_mm_s_; }  // of the measuring touch
    double scan_range_mm() const { return scan_range_mm_; }
    // Expanded (k = 2) uncertainty of the measured point, the whole budget
    // (uncertainty.h): the trigger's part below, combined with the
    // terms no feed changes (lobing, calibration artefact, machine
    // repeatability, thermal drift). The target, the optimiser and the
    // reports take this figure.
    double uncertainty_mm() const { return uncertainty_mm_; }
    // The trigger's part: uniform scan phase combined with the probe's
    // repeatability, over sqrt(cycle.repeats) for the mean of the repeated
    // touches.
    double trigger_uncertainty_mm() const { return trigger_uncertainty_mm_; }
    // The backoff the cycle needs, rounded up to kBackoffStep_mm: the value
    // shown is the value that clears backoff_too_small.
    double recommended_backoff_mm() const { return recommended_backoff_mm_; }
    const TouchResult& first_touch() const { return first_; }
    // The measuring touch (the second touch of two-touch, else the first).
    const TouchResult& measuring_touch() const { return measuring_; }
    const std::vector<Warning>& warnings() const { return warnings_; }
    const std::vector<TimedSegment>& segments() const { return segments_; }
    const std::vector<AxisMotion>& motions() const { return motions_; }
    // False when the cycle as set cannot run as modelled, which an
    // error says: backoff_too_small (the second touch would start with the
    // stylus still deflected) or overtravel_limit at or over the limit (the
    // stylus is overrun). Its time is then no cycle time to compare or to
    // optimise for; invalid_codes() names why. A time or an overtravel that is
    // not a finite number is never valid either (the scenario's
    // checks keep it from happening; this keeps a NaN from being shown as a
    // valid cycle should a value slip through).
    bool valid() const {
        return invalid_codes() == 0 && std::isfinite(total_s_) && std::isfinite(overtravel_mm_);
    }
    // The error codes as bits, 1 << WarningCode (0 when valid).
    unsigned invalid_codes() const;

    std::vector<Warning>& mutable_warnings() { return warnings_; }

  private:
    friend void evaluate_into(const Scenario&, CycleResult&, MotionCache&, Detail);
    std::vector<PhaseRecord> phases_;
    std::vector<TimedSegment> segments_;
    std::vector<AxisMotion> motions_;
    std::vector<Warning> warnings_;
    std::array<double, kPhaseCount> phase_time_s_{};
    double total_s_{0.0};
    double overtravel_mm_{0.0};
    double checked_overtravel_mm_{0.0};
    int overtravel_touch_{1};
    double trigger_speed_mm_s_{0.0};
    double scan_range_mm_{0.0};
    double uncertainty_mm_{0.0};
    double trigger_uncertainty_mm_{0.0};
    double recommended_backoff_mm_{0.0};
    TouchResult first_{};
    TouchResult measuring_{};
};

// How far a touch's search goes past the farthest place its surface can be:
// cycle.search_beyond_mm, or when that is 0, halfway from the touch's stop
// (`overtravel_mm` past the surface) to the probe's overtravel limit (never
// short of the stop). A control plans a probing move to stop at its end, so a
// search that ends before the touch's stop is already braking when it
// touches: the trigger comes below the feed and the axis stops at the search
// end, not where the model puts it. Halfway to the limit leaves a margin past
// the stop and keeps a probe that fails to trigger at that surface inside
// its stylus's range.
double search_beyond_mm(const Scenario& scenario, double overtravel_mm);

// The highest feed override the checks hold at, as a factor (1.5 for 150 %).
double feed_override_factor(const Cycle& cycle);

// How many times the measuring touch is made and averaged: cycle.repeats, a
// whole number stored as a number, at least 1.
int repeat_count(const Cycle& cycle);

// How far past an obstruction a protected positioning move programmed at
// `feed_mm_s` stops (a feature's moves to and from its touches run with the
// probe armed), at the highest feed override: the probe triggers on it as on
// a surface, at the move's full feed v = override * feed_mm_s (the worst
// case: no protected move is faster), so pretravel + v * (t_i + t_c + t_s) +
// v * the dynamics' lag + the plan's braking from v.
double protected_move_overtravel_mm(const Scenario& scenario, double feed_mm_s);
// The highest positioning feed, rounded down to the editors' digits, at most
// `upper_mm_min`, at which an obstruction's overtravel (above, which grows
// with the feed) is under `fraction` of the probe's limit; nullopt when even
// 1 mm/min is not.
std::optional<double> highest_position_feed_mm_min(const Scenario& scenario, double upper_mm_min,
                                                   double fraction);

// --- Small closed forms (docs/model.md, "One touch"), each testable alone. ---
// Travel between trigger and the controller's reaction, worst case (full scan).
double reaction_time_s(const Machine& machine, const Probe& probe);
// Range of the scan-phase error at a trigger speed; 0 with a latched input.
double scan_range_mm(const Machine& machine, double trigger_speed_mm_s);
// k = 2 combination of a uniform range and a 2-sigma repeatability.
double expanded_uncertainty_mm(double scan_range_mm, double repeatability_2sigma_mm);
// The delay between trigger and recorded position that calibration absorbs:
// t_i + t_c + t_s/2 with a scanned input, t_i alone with a latched one (the
// position is captured when the signal arrives).
double measurement_delay_s(const Machine& machine, const Probe& probe);
// Error in the measured value from a speed other than the calibrated one:
// (v - v_cal) * measurement_delay_s.
double speed_error_mm(const Machine& machine, const Probe& probe, double speed_mm_s,
                      double calibrated_speed_mm_s);

// A touch while accelerating is reported when its error is over this (0.1 µm):
// below it the axis counts as at its feed (filters and a servo lag approach
// the feed only exponentially).
constexpr double kAccelErrorTolerance_mm = 1e-4;
// The recommended backoff is rounded up to this (1 µm), the editors' digits.
constexpr double kBackoffStep_mm = 0.001;
// Feeds are shown, set and programmed to 1 mm/min from 100 mm/min up and to
// 0.1 mm/min below: the knee is a feed of these digits, so that the readout, the
// one-click fix and the report name one feed (they once showed 4449, 4448 and 4448.7).
inline double feed_step_mm_min(double feed_mm_min) {
    return feed_mm_min >= 100.0 ? 1.0 : 0.1;
}
// A feed rounded down or up to those digits (round_down_to, round_up_to).
inline double round_feed_down(double feed_mm_min) {
    return round_down_to(feed_mm_min, feed_step_mm_min(feed_mm_min));
}
inline double round_feed_up(double feed_mm_min) {
    return round_up_to(feed_mm_min, feed_step_mm_min(feed_mm_min));
}
// The highest feed from `lo_mm_min` up to `hi_mm_min`, rounded down to the
// editors' digits, at which `under` holds, for a test that holds up to some
// feed and not beyond (an overtravel under a limit: it grows with the feed);
// nullopt when it does not hold at `lo_mm_min` or at the rounded feed. A
// bisection to 0.05 mm/min, under the 0.1 mm/min the editors show.
template <typename Under>
std::optional<double> highest_feed_where(double lo_mm_min, double hi_mm_min, Under under) {
    double lo = lo_mm_min;
    if (!under(lo)) return std::nullopt;
    double hi = hi_mm_min;
    while (hi - lo > 0.05) {
        const double mid = 0.5 * (lo + hi);
        (under(mid) ? lo : hi) = mid;
    }
    const double feed = round_feed_down(lo);
    if (feed <= 0.0 || !under(feed)) return std::nullopt;
    return feed;
}
// Whether a touch meets its surface at its programmed feed (to
// within kFeedReachedFraction): a probing feed the first touch never reaches
// from its start is not the programmed feed. The knee looks past such feeds,
// and the curves show them as such: their cycle times fall again only
// because the touch does not reach the feed.
constexpr double kFeedReachedFraction = 0.999;
inline bool reaches_feed(const TouchResult& touch) {
    return touch.touch_speed_mm_s >= kFeedReachedFraction * touch.programmed_feed_mm_s;
}

// Overtravel at this fraction of the probe's limit is a warning (at the
// limit, an error).
constexpr double kOvertravelWarningFraction = 0.8;

// The scenario's axis: the interpolator's plans (motion.h) and, when the
// machine has them, its dynamics after interpolation (dynamics.h).
// Time of a rest-to-rest move: the plan's, or until the in-position check
// passes.
double block_time_s(const Scenario& scenario, double distance_mm, double feed_mm_s);
// Distance a touch from rest needs to reach `feed_mm_s`: the plan's ramp
// (reach_distance_mm), or with dynamics the actual travel until the speed is
// close enough to the feed that a touch there errs less than
// kAccelErrorTolerance_mm.
double approach_room_mm(const Scenario& scenario, double feed_mm_s);

// Evaluates the cycle: phases, overtravel, uncertainty, warnings that need no
// sweep (all but feed_beyond_knee; see analyse() in sweep.h). Assumes a valid
// scenario (validate() first). evaluate_into reuses the result's buffers; with
// a MotionCache, the solves of earlier evaluations of the same machine.
CycleResult evaluate(const Scenario& scenario);
void evaluate_into(const Scenario& scenario, CycleResult& result);
void evaluate_into(const Scenario& scenario, CycleResult& result, MotionCache& cache,
                   Detail detail = Detail::full);

// The moves of a feature as real cycles and our programs make them. A pocket
// or bore starts and ends at the feature centre; each touch starts `approach`
// inside the wall, reached from the centre and left back to it. A boss or web
// starts above its centre at the clearance height; each touch starts outside:
// out over it, down by the clearance, the touch, up by the clearance (over the
// wall) and back over the centre. Every move runs along one axis and stops
// at its end. Touches go X+, X-, Y+, Y- (pocket and web X+, X-).
// The distance from the centre to a touch's start position: D/2 - approach
// inside a pocket or bore, D/2 + approach outside a boss or web.
double start_radius_mm(const Cycle& cycle);
// A boss or web: the probe lifts over the wall between touches.
bool lifts_over(Feature feature);

}  // namespace probecycle
