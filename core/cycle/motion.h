#pragma once

// Motion models of a single CNC axis (docs/model.md, "Motion").
//
// Every model is expressed as a sequence of constant-jerk segments, so one
// integrator serves all of them; the closed forms below are the fast path and
// the segment plans are what the cycle timeline and state_at() walk through.

#include <array>
#include <cstddef>

namespace probecycle {

// none: the interpolator commands the feed at once and stops at
// once, as on a skip block without acceleration (Mitsubishi G31 without
// acc/dec); what smooths the motion then is the filter after interpolation
// and the servo (dynamics.h).
enum class AccelModel { time_constant, constant_accel, jerk_limited, none };

// The time constant of a machine that sets none (machine.time_constant_s).
constexpr double kDefaultTimeConstant_s = 0.06;

struct MotionLimits {
    AccelModel model{AccelModel::time_constant};
    double time_constant_s{kDefaultTimeConstant_s};  // time_constant: a = v / T
    double max_accel_mm_s2{2000.0};                  // constant_accel, jerk_limited
    double max_jerk_mm_s3{40000.0};                  // jerk_limited

    bool operator==(const MotionLimits&) const = default;
};

struct KinematicState {
    double position_mm{0.0};
    double speed_mm_s{0.0};
    double accel_mm_s2{0.0};
};

// Constant-jerk motion for time t from s0 (ruckig utils.hpp `integrate`).
// Inline: every state of a motion and every segment of a command takes one.
inline KinematicState integrate(double t_s, const KinematicState& s0, double jerk_mm_s3) {
    if (jerk_mm_s3 == 0.0) {  // the same values without the division by 6
        return {s0.position_mm + t_s * (s0.speed_mm_s + t_s * (s0.accel_mm_s2 / 2.0)),
                s0.speed_mm_s + t_s * s0.accel_mm_s2, s0.accel_mm_s2};
    }
    return {
        s0.position_mm +
            t_s * (s0.speed_mm_s + t_s * (s0.accel_mm_s2 / 2.0 + t_s * jerk_mm_s3 / 6.0)),
        s0.speed_mm_s + t_s * (s0.accel_mm_s2 + t_s * jerk_mm_s3 / 2.0),
        s0.accel_mm_s2 + t_s * jerk_mm_s3,
    };
}

// A piece of a motion plan: constant jerk, starting with the given acceleration.
// Position and speed are continuous across segments; acceleration may jump
// (constant-acceleration profiles switch it instantly).
struct Segment {
    double duration_s{0.0};
    double accel_mm_s2{0.0};
    double jerk_mm_s3{0.0};
    // AccelModel::none: the speed steps to this value where the segment
    // starts (negative: continuous, the usual case).
    double step_speed_mm_s{-1.0};
};

// At most seven segments (the S-curve); fewer for the other models.
struct SegmentPlan {
    std::array<Segment, 7> segments{};
    std::size_t count{0};

    void push(double duration_s, double accel_mm_s2, double jerk_mm_s3);
    // A constant-speed segment entered with a step of the speed (model none).
    void push_step(double duration_s, double speed_mm_s);
    double duration_s() const;
    // End state after all segments, starting from `start`.
    KinematicState end_state(const KinematicState& start = {}) const;
    // State at time t (clamped to [0, duration]).
    KinematicState state_at(double t_s, const KinematicState& start = {}) const;
};

// --- Closed forms. All assume validated, positive limits and feed. ---
// The acceleration the model uses at a programmed feed (time_constant: v/T).
double effective_accel_mm_s2(const MotionLimits& limits, double feed_mm_s);

// Rest-to-rest move of `distance_mm` programmed at `feed_mm_s`.
double move_time_s(const MotionLimits& limits, double distance_mm, double feed_mm_s);
// Highest speed reached in that move (the feed, or less for short moves).
double move_peak_speed_mm_s(const MotionLimits& limits, double distance_mm, double feed_mm_s);
SegmentPlan plan_move(const MotionLimits& limits, double distance_mm, double feed_mm_s);

// From rest to the programmed feed.
double reach_time_s(const MotionLimits& limits, double feed_mm_s);
double reach_distance_mm(const MotionLimits& limits, double feed_mm_s);
// Accelerate from rest toward the feed, then cruise; the cruise segment is
// given `cruise_s` seconds (the caller cuts the plan where the axis reacts).
SegmentPlan plan_accelerate(const MotionLimits& limits, double feed_mm_s, double cruise_s);

// Speed reached after `distance_mm` when accelerating from rest toward the feed.
double speed_after_mm_s(const MotionLimits& limits, double feed_mm_s, double distance_mm);

// Braking to rest from `speed_mm_s` while the axis has acceleration
// `accel_mm_s2` (>= 0; 0 at cruise). `feed_mm_s` is the programmed feed, which
// sets the deceleration of the time-constant model.
SegmentPlan plan_stop(const MotionLimits& limits, double feed_mm_s, double speed_mm_s,
                      double accel_mm_s2 = 0.0);
double stop_time_s(const MotionLimits& limits, double feed_mm_s, double speed_mm_s);
double stop_distance_mm(const MotionLimits& limits, double feed_mm_s, double speed_mm_s);

// Time at which a plan started at rest first covers `distance_mm`
// (monotone plans only: speed >= 0 throughout). Returns the plan's duration
// when the distance is never reached.
double time_at_distance_s(const SegmentPlan& plan, double distance_mm);

const char* to_string(AccelModel model);

}  // namespace probecycle
