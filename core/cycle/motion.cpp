#include "core/cycle/motion.h"

#include <algorithm>
#include <cmath>
#include <limits>

// Formulas: docs/model.md, "Motion". The jerk-limited rest-to-rest
// profile is the time-optimal one for symmetric limits: the acceleration phase
// is a (possibly reduced) trapezoid in acceleration, the braking phase its
// mirror image, and the distance of either is v * t / 2 by symmetry.

namespace probecycle {

void SegmentPlan::push(double duration_s, double accel_mm_s2, double jerk_mm_s3) {
    if (duration_s <= 0.0 || count == segments.size()) return;
    segments[count++] = {duration_s, accel_mm_s2, jerk_mm_s3};
}

void SegmentPlan::push_step(double duration_s, double speed_mm_s) {
    if (duration_s <= 0.0 || count == segments.size()) return;
    segments[count++] = {duration_s, 0.0, 0.0, speed_mm_s};
}

namespace {
// The state where segment `seg` starts, from the state where the last ended.
KinematicState enter(KinematicState state, const Segment& seg) {
    state.accel_mm_s2 = seg.accel_mm_s2;
    if (seg.step_speed_mm_s >= 0.0) state.speed_mm_s = seg.step_speed_mm_s;
    return state;
}
}  // namespace

double SegmentPlan::duration_s() const {
    double total = 0.0;
    for (std::size_t i = 0; i < count; ++i) total += segments[i].duration_s;
    return total;
}

KinematicState SegmentPlan::end_state(const KinematicState& start) const {
    KinematicState state = start;
    for (std::size_t i = 0; i < count; ++i) {
        state =
            integrate(segments[i].duration_s, enter(state, segments[i]), segments[i].jerk_mm_s3);
    }
    return state;
}

KinematicState SegmentPlan::state_at(double t_s, const KinematicState& start) const {
    KinematicState state = start;
    double remaining = std::max(t_s, 0.0);
    for (std::size_t i = 0; i < count; ++i) {
        state = enter(state, segments[i]);
        if (remaining <= segments[i].duration_s) {
            return integrate(remaining, state, segments[i].jerk_mm_s3);
        }
        state = integrate(segments[i].duration_s, state, segments[i].jerk_mm_s3);
        remaining -= segments[i].duration_s;
    }
    state.accel_mm_s2 = 0.0;  // at rest or cruising after the plan
    return state;
}

double effective_accel_mm_s2(const MotionLimits& limits, double feed_mm_s) {
    // Time constant: "the control chooses the acceleration so that the
    // programmed feed is reached in T seconds whatever the feed: a = v/T".
    if (limits.model == AccelModel::time_constant) return feed_mm_s / limits.time_constant_s;
    if (limits.model == AccelModel::none) return std::numeric_limits<double>::infinity();
    return limits.max_accel_mm_s2;
}

namespace {

// Jerk-limited: time to reach speed v from rest, acceleration limit reached
// when v >= a^2 / j (then a trapezoid, else a triangle in acceleration).
double jerk_reach_time_s(double v, double a, double j) {
    if (v * j >= a * a) return v / a + a / j;
    return 2.0 * std::sqrt(v / j);
}

// Jerk-limited: the peak speed of a rest-to-rest move too short to reach the
// feed: solves 2 * (vp * t_reach(vp) / 2) = d for vp.
double jerk_short_move_peak_mm_s(double d, double a, double j) {
    const double a2_j = a * a / j;
    // With the acceleration limit reached: vp^2 / a + vp * a / j = d.
    // Positive root, written without cancellation.
    const double vp = 2.0 * a * d / (a2_j + std::sqrt(a2_j * a2_j + 4.0 * a * d));
    if (vp >= a2_j) return vp;
    // Otherwise: d = 2 vp sqrt(vp / j)  =>  vp = (d^2 j / 4)^(1/3).
    return std::cbrt(d * d * j / 4.0);
}

void push_jerk_ramp(SegmentPlan& plan, double v, double a, double j, double sign) {
    // Acceleration (sign +1) or braking (sign -1) between rest and speed v.
    if (v * j >= a * a) {
        const double tj = a / j;
        plan.push(tj, 0.0, sign * j);
        plan.push(v / a - a / j, sign * a, 0.0);
        plan.push(tj, sign * a, -sign * j);
    } else {
        const double tj = std::sqrt(v / j);
        plan.push(tj, 0.0, sign * j);
        plan.push(tj, sign * j * tj, -sign * j);
    }
}

}  // namespace

double reach_time_s(const MotionLimits& limits, double feed_mm_s) {
    if (limits.model == AccelModel::none) return 0.0;
    if (limits.model == AccelModel::jerk_limited) {
        return jerk_reach_time_s(feed_mm_s, limits.max_accel_mm_s2, limits.max_jerk_mm_s3);
    }
    return feed_mm_s / effective_accel_mm_s2(limits, feed_mm_s);
}

double reach_distance_mm(const MotionLimits& limits, double feed_mm_s) {
    // Symmetric ramps: mean speed v/2 (time constant: F*T/60/2).
    return 0.5 * feed_mm_s * reach_time_s(limits, feed_mm_s);
}

namespace {

// A rest-to-rest move: the peak speed, the time of each (symmetric) ramp to
// and from it, and the time at it. Trapezoid when the move is long enough to
// reach the feed (time constant: d >= v*T), else a triangle (or the reduced
// S-curve) peaking lower with the same limits.
struct MoveShape {
    double peak_mm_s{0.0};
    double ramp_s{0.0};
    double cruise_s{0.0};
};

MoveShape move_shape(const MotionLimits& limits, double distance_mm, double feed_mm_s) {
    if (distance_mm <= 0.0) return {};
    const double v = feed_mm_s;
    if (limits.model == AccelModel::none) return {v, 0.0, distance_mm / v};
    if (limits.model == AccelModel::jerk_limited) {
        const double a = limits.max_accel_mm_s2;
        const double j = limits.max_jerk_mm_s3;
        const double t_reach = jerk_reach_time_s(v, a, j);
        const double d_ramps = v * t_reach;  // both ramps
        if (distance_mm >= d_ramps) return {v, t_reach, (distance_mm - d_ramps) / v};
        const double vp = jerk_short_move_peak_mm_s(distance_mm, a, j);
        return {vp, jerk_reach_time_s(vp, a, j), 0.0};
    }
    const double a = effective_accel_mm_s2(limits, v);
    if (distance_mm * a >= v * v) return {v, v / a, (distance_mm - v * v / a) / v};
    const double vp = std::sqrt(a * distance_mm);  // 2 sqrt(d/a) in all (2 sqrt(d T / v))
    return {vp, vp / a, 0.0};
}

}  // namespace

double move_time_s(const MotionLimits& limits, double distance_mm, double feed_mm_s) {
    const MoveShape shape = move_shape(limits, distance_mm, feed_mm_s);
    return 2.0 * shape.ramp_s + shape.cruise_s;
}

double move_peak_speed_mm_s(const MotionLimits& limits, double distance_mm, double feed_mm_s) {
    return move_shape(limits, distance_mm, feed_mm_s).peak_mm_s;
}

SegmentPlan plan_move(const MotionLimits& limits, double distance_mm, double feed_mm_s) {
    SegmentPlan plan;
    const MoveShape shape = move_shape(limits, distance_mm, feed_mm_s);
    if (shape.peak_mm_s <= 0.0) return plan;
    if (limits.model == AccelModel::none) {
        plan.push_step(shape.cruise_s, shape.peak_mm_s);
    } else if (limits.model == AccelModel::jerk_limited) {
        push_jerk_ramp(plan, shape.peak_mm_s, limits.max_accel_mm_s2, limits.max_jerk_mm_s3, +1.0);
        plan.push(shape.cruise_s, 0.0, 0.0);
        push_jerk_ramp(plan, shape.peak_mm_s, limits.max_accel_mm_s2, limits.max_jerk_mm_s3, -1.0);
    } else {
        const double a = effective_accel_mm_s2(limits, feed_mm_s);
        plan.push(shape.ramp_s, a, 0.0);
        plan.push(shape.cruise_s, 0.0, 0.0);
        plan.push(shape.ramp_s, -a, 0.0);
    }
    return plan;
}

SegmentPlan plan_accelerate(const MotionLimits& limits, double feed_mm_s, double cruise_s) {
    SegmentPlan plan;
    if (limits.model == AccelModel::none) {
        plan.push_step(cruise_s, feed_mm_s);
        return plan;
    }
    if (limits.model == AccelModel::jerk_limited) {
        push_jerk_ramp(plan, feed_mm_s, limits.max_accel_mm_s2, limits.max_jerk_mm_s3, +1.0);
    } else {
        plan.push(reach_time_s(limits, feed_mm_s), effective_accel_mm_s2(limits, feed_mm_s), 0.0);
    }
    plan.push(cruise_s, 0.0, 0.0);
    return plan;
}

double speed_after_mm_s(const MotionLimits& limits, double feed_mm_s, double distance_mm) {
    if (distance_mm <= 0.0) return 0.0;
    if (distance_mm >= reach_distance_mm(limits, feed_mm_s)) return feed_mm_s;
    if (limits.model != AccelModel::jerk_limited) {
        return std::sqrt(2.0 * effective_accel_mm_s2(limits, feed_mm_s) * distance_mm);
    }
    const SegmentPlan plan = plan_accelerate(limits, feed_mm_s, 0.0);
    return plan.state_at(time_at_distance_s(plan, distance_mm)).speed_mm_s;
}

SegmentPlan plan_stop(const MotionLimits& limits, double feed_mm_s, double speed_mm_s,
                      double accel_mm_s2) {
    SegmentPlan plan;
    // none: the command stops at once (an empty plan; the speed steps to 0).
    if (limits.model == AccelModel::none) return plan;
    if (speed_mm_s <= 0.0 && accel_mm_s2 <= 0.0) return plan;
    if (limits.model != AccelModel::jerk_limited) {
        // The acceleration switches at once to the braking value.
        const double a = effective_accel_mm_s2(limits, feed_mm_s);
        plan.push(speed_mm_s / a, -a, 0.0);
        return plan;
    }
    // Jerk-limited from (v0, a0 >= 0): ramp a0 down to -ap, hold, ramp to 0.
    // Speed balance: ap^2 / j + ap * t_hold = v0 + a0^2 / (2 j).
    const double a_max = limits.max_accel_mm_s2;
    const double j = limits.max_jerk_mm_s3;
    const double a0 = std::max(accel_mm_s2, 0.0);
    const double v_eff = speed_mm_s + a0 * a0 / (2.0 * j);
    double ap = a_max;
    double t_hold = (v_eff - a_max * a_max / j) / a_max;
    if (t_hold < 0.0) {
        ap = std::sqrt(j * v_eff);
        t_hold = 0.0;
    }
    plan.push((a0 + ap) / j, a0, -j);
    plan.push(t_hold, -ap, 0.0);
    plan.push(ap / j, -ap, j);
    return plan;
}

double stop_time_s(const MotionLimits& limits, double feed_mm_s, double speed_mm_s) {
    if (speed_mm_s <= 0.0 || limits.model == AccelModel::none) return 0.0;
    if (limits.model == AccelModel::jerk_limited) {
        return jerk_reach_time_s(speed_mm_s, limits.max_accel_mm_s2, limits.max_jerk_mm_s3);
    }
    // Time constant, braking from the programmed feed: T ("braking from v takes T").
    return speed_mm_s / effective_accel_mm_s2(limits, feed_mm_s);
}

double stop_distance_mm(const MotionLimits& limits, double feed_mm_s, double speed_mm_s) {
    // Braking from cruise mirrors the ramp up: mean speed v/2 (time constant: v*T/2).
    return 0.5 * speed_mm_s * stop_time_s(limits, feed_mm_s, speed_mm_s);
}

double time_at_distance_s(const SegmentPlan& plan, double distance_mm) {
    if (distance_mm <= 0.0) return 0.0;
    KinematicState state;
    double t0 = 0.0;
    for (std::size_t i = 0; i < plan.count; ++i) {
        const Segment& seg = plan.segments[i];
        state = enter(state, seg);
        const KinematicState end = integrate(seg.duration_s, state, seg.jerk_mm_s3);
        if (end.position_mm >= distance_mm) {
            const double rest = distance_mm - state.position_mm;
            if (seg.jerk_mm_s3 == 0.0) {
                // a0/2 t^2 + v0 t - rest = 0, in the cancellation-free form.
                const double v0 = state.speed_mm_s;
                const double disc = std::max(0.0, v0 * v0 + 2.0 * state.accel_mm_s2 * rest);
                const double denom = v0 + std::sqrt(disc);
                return t0 + (denom > 0.0 ? 2.0 * rest / denom : 0.0);
            }
            // Cubic: safeguarded Newton on [0, duration]; position is monotone.
            double lo = 0.0;
            double hi = seg.duration_s;
            double t = 0.5 * (lo + hi);
            for (int iter = 0; iter < 100; ++iter) {
                const KinematicState s = integrate(t, state, seg.jerk_mm_s3);
                const double f = s.position_mm - distance_mm;
                if (f > 0.0) {
                    hi = t;
                } else {
                    lo = t;
                }
                double next = s.speed_mm_s > 0.0 ? t - f / s.speed_mm_s : 0.5 * (lo + hi);
                if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
                if (std::abs(next - t) <= 1e-15 * std::max(1.0, t) || hi - lo <= 1e-16) {
                    t = next;
                    break;
                }
                t = next;
            }
            return t0 + t;
        }
        state = end;
        t0 += seg.duration_s;
    }
    return t0;
}

const char* to_string(AccelModel model) {
    switch (model) {
        case AccelModel::time_constant:
            return "time_constant";
        case AccelModel::constant_accel:
            return "constant_accel";
        case AccelModel::jerk_limited:
            return "jerk_limited";
        case AccelModel::none:
            return "none";
    }
    return "?";
}

}  // namespace probecycle
