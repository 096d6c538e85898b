#include "core/cycle/cycle_builder.h"

#include <algorithm>
#include <cstddef>
#include <optional>

#include "core/common/number_format.h"
#include "core/common/units.h"

namespace probecycle {

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

    // A touch solved for its figures only (such as its stop at the highest feed
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

    // docs/model.md, "One touch": approach from rest `distance_mm`
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

    // The touch with dynamics after interpolation (docs/model.md, "Controller
    // dynamics after interpolation"): the actual position touches and triggers;
    // the control reacts after the trigger chain, the interpolator then stops
    // its command (at once, or braking as its plan does), and the axis drains
    // the filters and the servo lag. The overtravel is where it comes to rest,
    // the command's end; the next block starts when the in-position check
    // passes.
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

// The backoff move's length: from the stop to `backoff_mm` in front of the
// reference (exactly the backoff from the stop: the same move at every feed).
double backoff_move_mm(const Cycle& cycle, double backoff_mm, const TouchResult& first,
                       TouchCase which) {
    if (cycle.backoff_from == BackoffFrom::stop) return backoff_mm;
    return which == TouchCase::mean ? backoff_mm + first.mean_overtravel_mm - first.mean_recorded_mm
                                    : backoff_mm + first.overtravel_mm - first.recorded_mm;
}

}  // namespace

const AxisKernel* active_kernel(const AxisKernel& kernel) {
    return kernel.active() ? &kernel : nullptr;
}

// Where the backoff is measured from, beyond the surface (cycle.backoff_from):
// where the first touch stopped, or where the control recorded it.
double backoff_reference_mm(const Cycle& cycle, const TouchResult& first, TouchCase which) {
    const bool mean = which == TouchCase::mean;
    if (cycle.backoff_from == BackoffFrom::stop) {
        return mean ? first.mean_overtravel_mm : first.overtravel_mm;
    }
    return mean ? first.mean_recorded_mm : first.recorded_mm;
}

double approach_room(const Scenario& scenario, const MotionLimits& limits, const AxisKernel* kernel,
                     double feed_mm_s, MotionCache* cache) {
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

CycleTimeline build_timeline(const Scenario& scenario, const TimelineBuffers& buffers,
                             MotionCache& cache, Detail detail) {
    buffers.phases.clear();
    buffers.segments.clear();
    buffers.motions.clear();
    buffers.phase_time_s.fill(0.0);

    const Machine& m = scenario.machine;
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
    CycleBuilder b(buffers.phases, buffers.segments, buffers.motions, buffers.phase_time_s,
                   active_kernel(cache.kernel()), cache, detail, m.block_change_s);
    // A feature's moves are protected, at the positioning feed, from the
    // centre (above it for a boss or web, which lifts over the wall at the
    // rapid feed, away from the part): docs/model.md, "Strategies and
    // features".
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
    CycleTimeline timeline;
    // One touch sequence: first touch, (backoff, second touch,) return to start.
    TouchResult& first = timeline.first;
    first = b.add_touch(scenario, limits, probe_v, s, kFirstTouch);
    // The operator may turn the feed override up to its highest: the same
    // touch at that feed stops farther, and every overtravel check (the
    // limit, the searches, the backoff) holds at it. The timeline stays at
    // 100 %.
    const double override_k = feed_override_factor(c);
    const bool overridden = override_k > 1.0;
    const TouchResult& first_fast = timeline.first_fast =
        overridden ? b.solve_touch(scenario, limits, override_k * probe_v, s, kFirstTouch) : first;
    first.override_overtravel_mm = std::max(first.overtravel_mm, first_fast.overtravel_mm);
    first.search_mm = s + c.part_position_uncertainty_mm +
                      search_beyond_mm(scenario, first.override_overtravel_mm);
    TouchResult& measuring = timeline.measuring;
    measuring = first;
    // The second touch starts b - overtravel_1 in front of the surface (none
    // left if the backoff is too short); from the recorded trigger position,
    // b - recorded_1, and the backoff move also covers the travel from there
    // to the stop (docs/model.md, "Strategies and features").
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
    if (two_touch) {
        measuring = back_off_and_measure(first, timeline.first_backoff_cost_s);
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
    }
    // The measuring touch made cycle.repeats times and averaged. Two-touch
    // backs off from the measuring touch and touches again at the measuring
    // feed; single-touch returns to the start and touches again. Each repeat
    // after the first is the first one again (it starts and ends where the
    // measuring touch stopped), so it is replayed.
    const int repeats = repeat_count(c);
    if (repeats > 1) {
        const std::size_t repeat_first_phase = b.phase_count();
        const std::size_t repeat_first_segment = b.segment_count();
        if (two_touch) {
            back_off_and_measure(measuring, timeline.repeat_backoff_cost_s);
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
    // Back to the start position, s + overtravel.
    b.add_move(Phase::return_move, limits, b.axis_mm(), return_v, -1.0);

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
    timeline.total_s = b.now();
    return timeline;
}

double block_time_s(const Scenario& scenario, double distance_mm, double feed_mm_s) {
    const AxisKernel kernel(scenario.axis_dynamics());
    return block_time(scenario.motion_limits(), active_kernel(kernel), distance_mm, feed_mm_s);
}

double approach_room_mm(const Scenario& scenario, double feed_mm_s) {
    const AxisKernel kernel(scenario.axis_dynamics());
    return approach_room(scenario, scenario.motion_limits(), active_kernel(kernel), feed_mm_s);
}

}  // namespace probecycle
