// Controller dynamics after interpolation (core/cycle/dynamics.h; docs/model.md).
//
// The command x_c passes an acc/dec filter (linear: a moving average of the
// speed over W; exponential: a first-order lag T; bell: two moving averages
// W1, W2) and the servo lag Tp before it is the actual position x_a. Every
// expectation below is derived by hand in the comment next to it, from the
// convolution of the command with those stages, not from the code's own sums:
//   - the kernel's moments, the lag and the windows;
//   - step and ramp responses of each stage and of the cascades;
//   - the drains after the command stops and the in-position time;
//   - a touch during a linear filter's ramp and touches at cruise, through
//     evaluate();
//   - the makers' published overtravel formulas (Mitsubishi, Fanuc);
//   - properties over random dynamics (fixed seed);
//   - the keys' validation, and that the defaults change nothing.
#include "core/cycle/dynamics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/common/units.h"
#include "core/cycle/cycle.h"
#include "core/cycle/motion.h"
#include "core/cycle/motion_cache.h"
#include "core/cycle/scenario.h"

namespace probecycle {
namespace {

// Sums of a few products: exact to rounding.
constexpr double kTol = 1e-12;
// Closed forms with exponentials, and roots solved to 1e-12.
constexpr double kClose = 1e-9;

AxisDynamics dynamics(FilterKind filter, double t1, double t2, double servo_s,
                      double in_position_mm = 0.01) {
    return {filter, t1, t2, servo_s, in_position_mm};
}

MotionLimits limits_of(AccelModel model) {
    MotionLimits limits;
    limits.model = model;
    return limits;
}

MotionLimits no_plan() {
    return limits_of(AccelModel::none);
}

// The feed commanded at once at t = 0 and held (an open approach).
AxisMotion step_motion(const AxisDynamics& d, double v) {
    AxisCommand command;
    command.append(plan_accelerate(no_plan(), v, 100.0), 100.0);
    return {AxisKernel(d), command};
}

// An open approach on a plan that accelerates, cruising on.
AxisMotion ramp_motion(const AxisDynamics& d, const MotionLimits& limits, double v) {
    AxisCommand command;
    command.append(plan_accelerate(limits, v, 100.0), 100.0);
    return {AxisKernel(d), command};
}

// A rest-to-rest move of `distance` at `v` (commanded at once by default).
AxisMotion move(const AxisDynamics& d, double distance, double v,
                const MotionLimits& limits = no_plan()) {
    AxisCommand command;
    const SegmentPlan plan = plan_move(limits, distance, v);
    command.append(plan, plan.duration_s());
    command.close();
    return {AxisKernel(d), command};
}

// --- Hand responses used by several tests ---

// Position of a first-order lag T fed the unit parabola t^2/2 from rest:
// y' = (t^2/2 - y)/T gives y = t^2/2 - T t + T^2 (1 - e^(-t/T)); 0 before 0.
double lag_of_parabola(double tc, double t) {
    if (t <= 0.0) return 0.0;
    return t * t / 2.0 - tc * t + tc * tc * (1.0 - std::exp(-t / tc));
}

// Its derivative, the lag's response to the unit ramp t: t - T (1 - e^(-t/T)).
double lag_of_ramp(double tc, double t) {
    if (t <= 0.0) return 0.0;
    return t - tc * (1.0 - std::exp(-t / tc));
}

// Position of a step of speed v at 0 through two lags T1 != T2 (partial
// fractions of 1/((1 + s T1)(1 + s T2)) applied to v/s^2):
// v (t - (T1 + T2) + (T1^2 e^(-t/T1) - T2^2 e^(-t/T2)) / (T1 - T2)).
double two_lags_step_position(double t1, double t2, double v, double t) {
    if (t <= 0.0) return 0.0;
    return v * (t - (t1 + t2) +
                (t1 * t1 * std::exp(-t / t1) - t2 * t2 * std::exp(-t / t2)) / (t1 - t2));
}

// Two equal lags T (1/(1 + s T)^2 on v/s^2): v (t - 2T + (2T + t) e^(-t/T)).
double double_pole_step_position(double tc, double v, double t) {
    if (t <= 0.0) return 0.0;
    return v * (t - 2.0 * tc + (2.0 * tc + t) * std::exp(-t / tc));
}

// A step of v through a moving average W (the position v t^2/(2W) for t < W,
// v (t - W/2) after: the parabola minus itself W later) and then a lag Tp.
double linear_servo_step_position(double w, double tp, double v, double t) {
    return v / w * (lag_of_parabola(tp, t) - lag_of_parabola(tp, t - w));
}
double linear_servo_step_speed(double w, double tp, double v, double t) {
    return v / w * (lag_of_ramp(tp, t) - lag_of_ramp(tp, t - w));
}

// --- The kernel ---

TEST(AxisKernel, LinearFilterMomentsAreThoseOfAMovingAverage) {
    // A moving average over W has M_k = W^k/(k+1), so mu_k = M_k/k! =
    // W^k/(k+1)!: W/2, W^2/6, W^3/24. No lag, one window.
    const double w = 0.1;
    const AxisKernel k(dynamics(FilterKind::linear, w, 0.7, 0.0));
    EXPECT_TRUE(k.active());
    EXPECT_NEAR(k.moment(0), 1.0, kTol);
    EXPECT_NEAR(k.moment(1), 0.05, kTol);
    EXPECT_NEAR(k.moment(2), 0.01 / 6.0, kTol);
    EXPECT_NEAR(k.moment(3), 0.001 / 24.0, kTol);
    EXPECT_NEAR(k.window_s(), w, kTol);
    EXPECT_EQ(k.lag_time_s(), 0.0);
    EXPECT_EQ(k.lag_count(), 0);
    EXPECT_NEAR(dynamics(FilterKind::linear, w, 0.7, 0.0).lag_s(), 0.05, kTol);
}

TEST(AxisKernel, ALagsMomentsArePowersOfItsTimeConstant) {
    // A lag T: M_k = k! T^k, mu_k = T^k. The exponential filter and the servo
    // are the same stage.
    const double tc = 0.05;
    for (const AxisDynamics& d : {dynamics(FilterKind::exponential, tc, 0.7, 0.0),
                                  dynamics(FilterKind::none, 0.3, 0.7, tc)}) {
        SCOPED_TRACE(to_string(d.filter));
        const AxisKernel k(d);
        EXPECT_NEAR(k.moment(1), 0.05, kTol);
        EXPECT_NEAR(k.moment(2), 0.0025, kTol);
        EXPECT_NEAR(k.moment(3), 0.000125, kTol);
        EXPECT_NEAR(k.lag_time_s(), tc, kTol);
        EXPECT_EQ(k.window_s(), 0.0);
        EXPECT_EQ(k.lag_count(), 1);
        EXPECT_NEAR(d.lag_s(), tc, kTol);
    }
}

TEST(AxisKernel, BellMomentsConvolveItsTwoWindows) {
    // Normalised moments of a cascade convolve as sequences:
    // mu_k = sum_i a_i b_(k-i) with a_i = W1^i/(i+1)!, b_i = W2^i/(i+1)!.
    // W1 = 0.06, W2 = 0.02:
    //   mu_1 = (W1 + W2)/2 = 0.04
    //   mu_2 = W1^2/6 + W1 W2/4 + W2^2/6 = 0.0006 + 0.0003 + 0.0000666...
    //   mu_3 = W1^3/24 + W1^2 W2/12 + W1 W2^2/12 + W2^3/24
    const double w1 = 0.06;
    const double w2 = 0.02;
    const AxisDynamics d = dynamics(FilterKind::bell, w1, w2, 0.0);
    const AxisKernel k(d);
    EXPECT_NEAR(k.moment(1), 0.04, kTol);
    EXPECT_NEAR(k.moment(2), 0.0006 + 0.0003 + 0.0004 / 6.0, kTol);
    EXPECT_NEAR(
        k.moment(3),
        w1 * w1 * w1 / 24.0 + w1 * w1 * w2 / 12.0 + w1 * w2 * w2 / 12.0 + w2 * w2 * w2 / 24.0,
        kTol);
    EXPECT_NEAR(k.window_s(), 0.08, kTol);
    EXPECT_NEAR(d.lag_s(), 0.04, kTol);
}

TEST(AxisKernel, TwoLagsMomentsAreCompleteHomogeneousSums) {
    // Two lags: mu_k = sum_i T1^i T2^(k-i). T1 = 0.03, T2 = 0.05:
    //   mu_1 = 0.08, mu_2 = 0.0009 + 0.0015 + 0.0025 = 0.0049,
    //   mu_3 = 2.7e-5 + 4.5e-5 + 7.5e-5 + 1.25e-4 = 2.72e-4.
    const AxisKernel two(dynamics(FilterKind::exponential, 0.03, 0.0, 0.05));
    EXPECT_NEAR(two.moment(1), 0.08, kTol);
    EXPECT_NEAR(two.moment(2), 0.0049, kTol);
    EXPECT_NEAR(two.moment(3), 2.72e-4, kTol);
    EXPECT_NEAR(two.lag_time_s(), 0.08, kTol);
    EXPECT_EQ(two.lag_count(), 2);
    // A double pole T = 0.04: (k + 1) T^k = 0.08, 0.0048, 0.000256.
    const AxisKernel pole(dynamics(FilterKind::exponential, 0.04, 0.0, 0.04));
    EXPECT_NEAR(pole.moment(1), 0.08, kTol);
    EXPECT_NEAR(pole.moment(2), 0.0048, kTol);
    EXPECT_NEAR(pole.moment(3), 0.000256, kTol);
}

TEST(AxisKernel, TheServoAddsItsTimeConstantToEveryFilter) {
    // lag_s = moment(1) = the filter's lag + Tp; Tp = 0.02.
    const double tp = 0.02;
    struct Case {
        AxisDynamics d;
        double lag_s;
    };
    for (const Case& c : {Case{dynamics(FilterKind::none, 0.1, 0.05, tp), 0.02},
                          Case{dynamics(FilterKind::linear, 0.1, 0.05, tp), 0.05 + 0.02},
                          Case{dynamics(FilterKind::exponential, 0.1, 0.05, tp), 0.1 + 0.02},
                          Case{dynamics(FilterKind::bell, 0.1, 0.05, tp), 0.075 + 0.02}}) {
        SCOPED_TRACE(to_string(c.d.filter));
        EXPECT_NEAR(c.d.lag_s(), c.lag_s, kTol);
        EXPECT_NEAR(AxisKernel(c.d).moment(1), c.lag_s, kTol);
    }
    // Linear W = 0.1 with Tp: mu_2 = W^2/6 + (W/2) Tp + Tp^2
    // = 0.0016666... + 0.001 + 0.0004.
    const AxisKernel k(dynamics(FilterKind::linear, 0.1, 0.05, tp));
    EXPECT_NEAR(k.moment(2), 0.01 / 6.0 + 0.001 + 0.0004, kTol);
    EXPECT_NEAR(k.window_s(), 0.1, kTol);
    EXPECT_NEAR(k.lag_time_s(), tp, kTol);
}

TEST(AxisKernel, TheIdealAxisIsTheIdentity) {
    // Filter none and no servo: no stage at all, whatever the unused times.
    const AxisDynamics ideal = dynamics(FilterKind::none, 0.1, 0.1, 0.0);
    EXPECT_FALSE(ideal.active());
    EXPECT_EQ(ideal.lag_s(), 0.0);
    const AxisKernel k(ideal);
    EXPECT_FALSE(k.active());
    EXPECT_EQ(k.moment(0), 1.0);
    EXPECT_EQ(k.moment(1), 0.0);
    EXPECT_EQ(k.moment(2), 0.0);
    EXPECT_EQ(k.moment(3), 0.0);
    EXPECT_FALSE(AxisKernel().active());
    // A servo alone makes the axis active.
    EXPECT_TRUE(dynamics(FilterKind::none, 0.1, 0.1, 0.001).active());
    EXPECT_TRUE(AxisKernel(dynamics(FilterKind::none, 0.1, 0.1, 0.001)).active());
}

// --- The command ---

TEST(DynamicsCommand, TheCommandIsItsBreaks) {
    // plan_move(none, 10 mm, 10 mm/s): +10 mm/s at 0, -10 mm/s at 1 s.
    AxisCommand command;
    const SegmentPlan plan = plan_move(no_plan(), 10.0, 10.0);
    command.append(plan, plan.duration_s());
    command.close();
    ASSERT_EQ(command.size(), 2u);
    EXPECT_EQ(command.at(0).t_s, 0.0);
    EXPECT_EQ(command.at(0).step[0], 10.0);
    EXPECT_EQ(command.at(0).step[1], 0.0);
    EXPECT_NEAR(command.at(1).t_s, 1.0, kTol);
    EXPECT_EQ(command.at(1).step[0], -10.0);
    EXPECT_NEAR(command.end_s(), 1.0, kTol);
    EXPECT_NEAR(command.end_state().position_mm, 10.0, kTol);
    EXPECT_EQ(command.end_state().speed_mm_s, 0.0);
    // Appending cuts a plan; closing stops the command where it is.
    // A step to 10 mm/s cut after 1.5 s of a 100 s cruise, then closed.
    AxisCommand cut;
    cut.append(plan_accelerate(no_plan(), 10.0, 100.0), 1.5);
    EXPECT_NEAR(cut.end_s(), 1.5, kTol);
    EXPECT_NEAR(cut.end_state().speed_mm_s, 10.0, kTol);
    cut.close();
    ASSERT_EQ(cut.size(), 2u);
    EXPECT_NEAR(cut.at(1).t_s, 1.5, kTol);
    EXPECT_NEAR(cut.at(1).step[0], -10.0, kTol);
    EXPECT_NEAR(cut.end_state().position_mm, 15.0, kTol);
    // Closing a command at rest adds nothing.
    cut.close();
    EXPECT_EQ(cut.size(), 2u);
    // A constant-acceleration stop (an acceleration step, no speed step):
    // 2000 mm/s^2 from 10 mm/s lasts 5 ms and covers 10^2/4000 = 0.025 mm.
    AxisCommand braking;
    braking.append(plan_accelerate(no_plan(), 10.0, 100.0), 1.0);
    const MotionLimits accel = limits_of(AccelModel::constant_accel);
    braking.append(plan_stop(accel, 10.0, 10.0), 1.0);
    braking.close();
    ASSERT_EQ(braking.size(), 3u);
    EXPECT_NEAR(braking.at(1).step[1], -2000.0, kTol);
    EXPECT_NEAR(braking.at(2).t_s, 1.005, kTol);
    EXPECT_NEAR(braking.end_state().position_mm, 10.025, kTol);
}

TEST(DynamicsCommand, ACopyHasTheSameBreaksAndEnd) {
    AxisCommand command;
    const SegmentPlan plan = plan_move(limits_of(AccelModel::jerk_limited), 10.0, 50.0);
    command.append(plan, plan.duration_s());
    command.close();
    AxisCommand copy;
    copy.append(plan_accelerate(no_plan(), 5.0, 1.0), 1.0);  // overwritten
    copy = command;
    const AxisCommand constructed(command);
    for (const AxisCommand* c : std::array<const AxisCommand*, 2>{&copy, &constructed}) {
        ASSERT_EQ(c->size(), command.size());
        for (std::size_t i = 0; i < command.size(); ++i) {
            EXPECT_EQ(c->at(i).t_s, command.at(i).t_s);
            EXPECT_EQ(c->at(i).step, command.at(i).step);
            EXPECT_EQ(c->at(i).after.position_mm, command.at(i).after.position_mm);
            EXPECT_EQ(c->at(i).jerk_after, command.at(i).jerk_after);
        }
        EXPECT_EQ(c->end_s(), command.end_s());
        EXPECT_EQ(c->end_state().position_mm, command.end_state().position_mm);
    }
}

// A motion reset to another command is the motion built on it, bit for bit,
// whichever breaks the two share (a touch: its approach cut and stopped).
TEST(AxisMotion, AResetMotionIsTheMotionOfItsNewCommand) {
    const std::array<AxisDynamics, 4> cases = {
        dynamics(FilterKind::exponential, 0.032, 0.0, 0.033),
        dynamics(FilterKind::exponential, 0.04, 0.0, 0.04),  // a double pole
        dynamics(FilterKind::none, 0.0, 0.0, 0.02),
        dynamics(FilterKind::linear, 0.05, 0.0, 0.01),
    };
    const MotionLimits limits = limits_of(AccelModel::jerk_limited);
    for (const AxisDynamics& d : cases) {
        const AxisKernel kernel(d);
        const SegmentPlan plan = plan_accelerate(limits, 40.0, 100.0);
        AxisCommand approach;
        approach.append(plan, plan.duration_s());
        for (double cut_s : {0.004, 0.05, 0.3}) {  // in the ramp and at cruise
            SCOPED_TRACE(cut_s);
            AxisCommand touch;
            touch.append(plan, cut_s);
            const KinematicState at_cut = touch.end_state();
            touch.append(plan_stop(limits, 40.0, at_cut.speed_mm_s, at_cut.accel_mm_s2), 1.0);
            touch.close();
            AxisMotion reset(kernel, approach);
            reset.reset(touch);
            const AxisMotion built(kernel, touch);
            for (double t = 0.0; t < 0.6; t += 0.0123) {
                EXPECT_EQ(reset.state(t).position_mm, built.state(t).position_mm) << t;
                EXPECT_EQ(reset.state(t).speed_mm_s, built.state(t).speed_mm_s) << t;
            }
            EXPECT_EQ(reset.in_position_time(), built.in_position_time());
            // And back to the approach it was built on.
            reset.reset(approach);
            const AxisMotion open(kernel, approach);
            EXPECT_EQ(reset.state(0.45).position_mm, open.state(0.45).position_mm);
        }
    }
}

// --- Step responses: the feed v commanded at once at t = 0 ---

TEST(AxisMotion, LinearFilterTurnsAStepIntoARampOverItsWindow) {
    // Moving average of a speed step over W = 0.1: speed v t/W, position
    // v t^2/(2W) in the window; after it v and v (t - W/2).
    const double v = 10.0;
    const double w = 0.1;
    const AxisMotion m = step_motion(dynamics(FilterKind::linear, w, 0.0, 0.0), v);
    EXPECT_EQ(m.state(0.0).position_mm, 0.0);
    EXPECT_EQ(m.state(-1.0).speed_mm_s, 0.0);
    EXPECT_NEAR(m.state(0.02).speed_mm_s, 2.0, kClose);
    EXPECT_NEAR(m.state(0.02).position_mm, 10.0 * 0.0004 / 0.2, kClose);  // 0.02 mm
    EXPECT_NEAR(m.state(0.05).speed_mm_s, 5.0, kClose);
    EXPECT_NEAR(m.state(0.05).position_mm, 10.0 * 0.0025 / 0.2, kClose);  // 0.125 mm
    EXPECT_NEAR(m.state(0.1).speed_mm_s, v, kClose);
    EXPECT_NEAR(m.state(0.1).position_mm, 0.5, kClose);  // v W/2
    EXPECT_NEAR(m.state(0.3).speed_mm_s, v, kClose);
    EXPECT_NEAR(m.state(0.3).position_mm, v * (0.3 - 0.05), kClose);
    EXPECT_NEAR(m.state(50.0).position_mm, v * (50.0 - 0.05), kClose);
}

TEST(AxisMotion, ExponentialFilterAndServoLagApproachTheFeedExponentially) {
    // A lag T = 0.05 on a step: speed v (1 - e^(-t/T)), position
    // v (t - T (1 - e^(-t/T))); at cruise v (t - T).
    const double v = 10.0;
    const double tc = 0.05;
    const AxisMotion m = step_motion(dynamics(FilterKind::exponential, tc, 0.0, 0.0), v);
    for (const double t : {0.01, 0.05, 0.2}) {
        SCOPED_TRACE(t);
        const double e = std::exp(-t / tc);
        EXPECT_NEAR(m.state(t).speed_mm_s, v * (1.0 - e), kClose);
        EXPECT_NEAR(m.state(t).position_mm, v * (t - tc * (1.0 - e)), kClose);
    }
    // At t = T: speed v (1 - 1/e) = 6.3212 mm/s.
    EXPECT_NEAR(m.state(tc).speed_mm_s, 6.321205588285577, kClose);
    EXPECT_NEAR(m.state(10.0).position_mm, v * (10.0 - tc), kClose);
    // The servo Tp is a first-order lag like the exponential filter: the same
    // formulas with Tp = 0.03.
    const double tp = 0.03;
    const AxisMotion servo = step_motion(dynamics(FilterKind::none, 0.0, 0.0, tp), v);
    const AxisMotion filter = step_motion(dynamics(FilterKind::exponential, tp, 0.0, 0.0), v);
    for (const double t : {0.001, 0.02, 0.03, 0.09, 1.0}) {
        SCOPED_TRACE(t);
        const double e = std::exp(-t / tp);
        EXPECT_NEAR(servo.state(t).speed_mm_s, v * (1.0 - e), kClose);
        EXPECT_NEAR(servo.state(t).position_mm, v * (t - tp * (1.0 - e)), kClose);
        EXPECT_NEAR(servo.state(t).position_mm, filter.state(t).position_mm, kTol);
    }
}

TEST(AxisMotion, ExponentialFilterAndServoByPartialFractions) {
    // T1 (filter) != T2 (servo): speed v (1 - (T1 e1 - T2 e2)/(T1 - T2)),
    // position v (t - (T1 + T2) + (T1^2 e1 - T2^2 e2)/(T1 - T2)),
    // e_i = e^(-t/T_i). Far apart (0.03, 0.05) and close (Fanuc-like 0.032,
    // 0.033, where the fractions nearly cancel).
    const double v = 10.0;
    for (const auto& [t1, t2] : {std::pair{0.03, 0.05}, std::pair{0.032, 0.033}}) {
        SCOPED_TRACE(std::to_string(t1) + " / " + std::to_string(t2));
        const AxisMotion m = step_motion(dynamics(FilterKind::exponential, t1, 0.0, t2), v);
        for (const double t : {0.005, 0.07, 0.2}) {
            SCOPED_TRACE(t);
            const double e1 = std::exp(-t / t1);
            const double e2 = std::exp(-t / t2);
            EXPECT_NEAR(m.state(t).speed_mm_s, v * (1.0 - (t1 * e1 - t2 * e2) / (t1 - t2)), kClose);
            EXPECT_NEAR(m.state(t).position_mm, two_lags_step_position(t1, t2, v, t), kClose);
        }
        // Cruise: v (t - T1 - T2).
        EXPECT_NEAR(m.state(5.0).position_mm, v * (5.0 - t1 - t2), kClose);
    }
}

TEST(AxisMotion, EqualLagsAreADoublePole) {
    // T1 = T2 = T = 0.04: speed v (1 - (1 + t/T) e^(-t/T)), position
    // v (t - 2T + (2T + t) e^(-t/T)). Lags equal to 1e-12 relative are the
    // same double pole (the partial fractions would divide by ~0).
    const double v = 10.0;
    const double tc = 0.04;
    for (const double t2 : {tc, tc * (1.0 + 1e-12)}) {
        const AxisMotion m = step_motion(dynamics(FilterKind::exponential, tc, 0.0, t2), v);
        for (const double t : {0.01, 0.04, 0.07, 0.3}) {
            SCOPED_TRACE(t);
            const double e = std::exp(-t / tc);
            EXPECT_NEAR(m.state(t).speed_mm_s, v * (1.0 - (1.0 + t / tc) * e), kClose);
            EXPECT_NEAR(m.state(t).position_mm, double_pole_step_position(tc, v, t), kClose);
        }
    }
}

TEST(AxisMotion, BellFilterMakesAnSShapedRamp) {
    // Two moving averages W1 = 0.06 >= W2 = 0.02 of a step: the speed is the
    // step convolved with two boxes, a trapezoid:
    //   t < W2:             v t^2/(2 W1 W2),        position v t^3/(6 W1 W2)
    //   W2 <= t < W1:       v (t - W2/2)/W1,        position v (t - W2/2)^2/(2W1) + v W2^2/(24 W1)
    //   W1 <= t < W1 + W2:  v (1 - (W1+W2-t)^2/(2 W1 W2)),
    //                       position v (t - (W1+W2)/2) + v (W1+W2-t)^3/(6 W1 W2)
    //   after:              v, position v (t - (W1 + W2)/2).
    // (The second form at t = W1 matches the third: v (W1-W2)/2 + v W2^2/(6 W1).)
    const double v = 10.0;
    const double w1 = 0.06;
    const double w2 = 0.02;
    const double k = 2.0 * w1 * w2;  // 0.0024
    const AxisMotion m = step_motion(dynamics(FilterKind::bell, w1, w2, 0.0), v);
    EXPECT_NEAR(m.state(0.01).speed_mm_s, v * 0.0001 / k, kClose);
    EXPECT_NEAR(m.state(0.01).position_mm, v * 1e-6 / (3.0 * k), kClose);
    EXPECT_NEAR(m.state(0.04).speed_mm_s, v * 0.03 / w1, kClose);
    EXPECT_NEAR(m.state(0.04).position_mm, v * 0.0009 / (2.0 * w1) + v * 0.0004 / (24.0 * w1),
                kClose);
    EXPECT_NEAR(m.state(0.07).speed_mm_s, v * (1.0 - 0.0001 / k), kClose);
    EXPECT_NEAR(m.state(0.07).position_mm, v * (0.07 - 0.04) + v * 1e-6 / (3.0 * k), kClose);
    EXPECT_NEAR(m.state(0.5).speed_mm_s, v, kClose);
    EXPECT_NEAR(m.state(0.5).position_mm, v * (0.5 - 0.04), kClose);
    // Convolution commutes: (W2, W1) is the same filter.
    const AxisMotion swapped = step_motion(dynamics(FilterKind::bell, w2, w1, 0.0), v);
    for (const double t : {0.005, 0.03, 0.065, 0.2}) {
        SCOPED_TRACE(t);
        EXPECT_NEAR(swapped.state(t).position_mm, m.state(t).position_mm, kTol);
        EXPECT_NEAR(swapped.state(t).speed_mm_s, m.state(t).speed_mm_s, kTol);
    }
    // W1 = W2 = W = 0.05: the step convolved with a triangle, v t^2/(2W^2) to
    // W, v (1 - (2W - t)^2/(2W^2)) to 2W; the position after 2W is v (t - W).
    const double w = 0.05;
    const AxisMotion c = step_motion(dynamics(FilterKind::bell, w, w, 0.0), v);
    EXPECT_NEAR(c.state(0.03).speed_mm_s, v * 0.0009 / 0.005, kClose);
    EXPECT_NEAR(c.state(0.05).speed_mm_s, v / 2.0, kClose);
    EXPECT_NEAR(c.state(0.08).speed_mm_s, v * (1.0 - 0.0004 / 0.005), kClose);
    EXPECT_NEAR(c.state(0.3).position_mm, v * (0.3 - w), kClose);
}

TEST(AxisMotion, LinearFilterThenServo) {
    // The filter's output (v t^2/(2W) less itself W later) through Tp: each
    // parabola becomes t^2/2 - Tp t + Tp^2 (1 - e^(-t/Tp)) (lag_of_parabola).
    // W = 0.05, Tp = 0.02; in the window and after it.
    const double v = 20.0;
    const double w = 0.05;
    const double tp = 0.02;
    const AxisMotion m = step_motion(dynamics(FilterKind::linear, w, 0.0, tp), v);
    for (const double t : {0.01, 0.05, 0.06, 0.12, 3.0}) {
        SCOPED_TRACE(t);
        EXPECT_NEAR(m.state(t).position_mm, linear_servo_step_position(w, tp, v, t), kClose);
        EXPECT_NEAR(m.state(t).speed_mm_s, linear_servo_step_speed(w, tp, v, t), kClose);
    }
    // At t = 0.01: (v/W)(0.00005 - 0.0002 + 0.0004 (1 - e^-0.5)) = 0.0029551 mm.
    EXPECT_NEAR(m.state(0.01).position_mm, 400.0 * (0.00005 - 0.0002 + 0.0004 * (1 - 0.60653066)),
                1e-8);
    // Cruise: v (t - W/2 - Tp) = 20 (3 - 0.045).
    EXPECT_NEAR(m.state(3.0).position_mm, 59.1, kClose);
}

// --- Ramps: a plan that accelerates before interpolation ---

TEST(AxisMotion, TimeConstantRampThroughAnExponentialLag) {
    // Time-constant plan, Tc = 0.1 s to v = 10: a = 100 mm/s^2 to t = 0.1,
    // then cruise. Through a lag T = 0.02 the parabola a t^2/2 becomes
    // a (t^2/2 - T t + T^2 - T^2 e^(-t/T)); the end of the ramp subtracts the
    // same started at 0.1. Far out: x_c - v T = (0.5 + 10 (t - 0.1)) - 0.2.
    const double a = 100.0;
    const double tf = 0.02;
    MotionLimits limits = limits_of(AccelModel::time_constant);
    limits.time_constant_s = 0.1;
    const AxisMotion m = ramp_motion(dynamics(FilterKind::exponential, tf, 0.0, 0.0), limits, 10.0);
    for (const double t : {0.05, 0.1, 0.15}) {
        SCOPED_TRACE(t);
        EXPECT_NEAR(m.state(t).position_mm,
                    a * (lag_of_parabola(tf, t) - lag_of_parabola(tf, t - 0.1)), kClose);
        EXPECT_NEAR(m.state(t).speed_mm_s, a * (lag_of_ramp(tf, t) - lag_of_ramp(tf, t - 0.1)),
                    kClose);
    }
    // t = 0.05: 100 (0.00125 - 0.001 + 0.0004 - 0.0004 e^-2.5) = 0.061716 mm.
    EXPECT_NEAR(m.state(0.05).position_mm, 100.0 * (0.00125 - 0.001 + 0.0004 * (1 - 0.0820850)),
                1e-8);
    EXPECT_NEAR(m.state(2.0).position_mm, 19.5 - 0.2, kClose);
}

TEST(AxisMotion, ConstantAccelRampThroughTheServo) {
    // Constant acceleration 2000 mm/s^2 to 50 mm/s: the ramp ends at 0.025 s.
    // Servo Tp = 0.01: a (g(t) - g(t - 0.025)), g = lag_of_parabola.
    const double a = 2000.0;
    const double tp = 0.01;
    const AxisMotion m = ramp_motion(dynamics(FilterKind::none, 0.0, 0.0, tp),
                                     limits_of(AccelModel::constant_accel), 50.0);
    for (const double t : {0.01, 0.025, 0.04}) {
        SCOPED_TRACE(t);
        EXPECT_NEAR(m.state(t).position_mm,
                    a * (lag_of_parabola(tp, t) - lag_of_parabola(tp, t - 0.025)), kClose);
        EXPECT_NEAR(m.state(t).speed_mm_s, a * (lag_of_ramp(tp, t) - lag_of_ramp(tp, t - 0.025)),
                    kClose);
    }
    // Far out: x_c - v Tp = (0.625 + 50 (1 - 0.025)) - 0.5.
    EXPECT_NEAR(m.state(1.0).position_mm, 0.625 + 48.75 - 0.5, kClose);
}

TEST(AxisMotion, RampThroughALinearFilterIsItsWindowAverage) {
    // Time-constant plan Tc = 0.2 s to v = 20: a = 100 to t = 0.2. A moving
    // average over W = 0.05 of x_c = a u^2/2 is (1/W) int_(t-W)^t x_c:
    //   t < W:     a t^3/(6W)                 (speed a t^2/(2W))
    //   W..0.2:    a (t^2/2 - W t/2 + W^2/6)   (the moment expansion; speed a (t - W/2))
    //   0.2..0.25: (a (0.2^3 - (t-W)^3)/6 + 2 (t - 0.2) + 10 (t - 0.2)^2) / W
    //   later:     x_c - v W/2 = 2 + 20 (t - 0.2) - 0.5.
    const double a = 100.0;
    const double w = 0.05;
    MotionLimits limits = limits_of(AccelModel::time_constant);
    limits.time_constant_s = 0.2;
    const AxisMotion m = ramp_motion(dynamics(FilterKind::linear, w, 0.0, 0.0), limits, 20.0);
    EXPECT_NEAR(m.state(0.03).position_mm, 0.009, kClose);  // 100 * 2.7e-5 / 0.3
    EXPECT_NEAR(m.state(0.03).speed_mm_s, 0.9, kClose);
    EXPECT_NEAR(m.state(0.1).position_mm, 100.0 * (0.005 - 0.0025 + 0.0025 / 6.0), kClose);
    EXPECT_NEAR(m.state(0.1).speed_mm_s, 7.5, kClose);
    const double t = 0.22;
    const double u = t - w;  // 0.17
    EXPECT_NEAR(m.state(t).position_mm,
                (a * (0.008 - u * u * u) / 6.0 + 2.0 * 0.02 + 10.0 * 0.0004) / w, kClose);
    EXPECT_NEAR(m.state(0.5).position_mm, 7.5, kClose);
    EXPECT_NEAR(m.state(0.5).speed_mm_s, 20.0, kClose);
}

TEST(AxisMotion, JerkLimitedRampThroughAnExponentialLag) {
    // Jerk-limited, a_max 2000, j 40000, to 200 mm/s: the jerk phase lasts
    // a/j = 0.05 s with x_c = j t^3/6. A lag T = 0.01 on the cubic:
    // j (t^3/6 - T t^2/2 + T^2 t - T^3 + T^3 e^(-t/T)). The S-curve reaches
    // the feed at 0.15 s after v * 0.15/2 = 15 mm; at t = 1 the command is at
    // 15 + 200 * 0.85 = 185 mm and the axis v T = 2 mm behind.
    const double j = 40000.0;
    const double tc = 0.01;
    const AxisMotion m = ramp_motion(dynamics(FilterKind::exponential, tc, 0.0, 0.0),
                                     limits_of(AccelModel::jerk_limited), 200.0);
    for (const double t : {0.005, 0.03, 0.05}) {
        SCOPED_TRACE(t);
        const double e = std::exp(-t / tc);
        EXPECT_NEAR(m.state(t).position_mm,
                    j * (t * t * t / 6.0 - tc * t * t / 2.0 + tc * tc * t - tc * tc * tc +
                         tc * tc * tc * e),
                    kClose);
        EXPECT_NEAR(m.state(t).speed_mm_s, j * (t * t / 2.0 - tc * t + tc * tc - tc * tc * e),
                    kClose);
    }
    EXPECT_NEAR(m.state(1.0).position_mm, 183.0, kClose);
    EXPECT_NEAR(m.state(1.0).speed_mm_s, 200.0, kClose);
}

// --- Drains: after the command stops ---

TEST(AxisMotion, AfterTheCommandStopsTheAxisDrainsItsLag) {
    // 10 mm at 10 mm/s commanded at once: the command ends at 1 s (50 of the
    // largest time constant, so e^(-t/T) < 2e-22). The axis is then v L
    // behind it (L = lag_s) and comes to rest at 10 mm.
    const double v = 10.0;
    struct Case {
        AxisDynamics d;
        double drain_mm;
    };
    for (const Case& c : {Case{dynamics(FilterKind::linear, 0.1, 0.0, 0.0), v * 0.05},
                          Case{dynamics(FilterKind::exponential, 0.02, 0.0, 0.0), v * 0.02},
                          Case{dynamics(FilterKind::none, 0.0, 0.0, 0.02), v * 0.02},
                          Case{dynamics(FilterKind::bell, 0.06, 0.02, 0.0), v * 0.04},
                          Case{dynamics(FilterKind::exponential, 0.02, 0.0, 0.015), v * 0.035},
                          Case{dynamics(FilterKind::exponential, 0.015, 0.0, 0.015), v * 0.03},
                          Case{dynamics(FilterKind::linear, 0.1, 0.0, 0.02), v * 0.07},
                          Case{dynamics(FilterKind::bell, 0.06, 0.02, 0.02), v * 0.06}}) {
        SCOPED_TRACE(std::string(to_string(c.d.filter)) + " servo " +
                     std::to_string(c.d.servo_time_constant_s));
        const AxisMotion m = move(c.d, 10.0, v);
        EXPECT_NEAR(m.command().end_s(), 1.0, kTol);
        EXPECT_NEAR(m.state(1.0).position_mm, 10.0 - c.drain_mm, kClose);
        EXPECT_NEAR(m.state(1.0).speed_mm_s, v, kClose);
        EXPECT_NEAR(m.state(3.0).position_mm, 10.0, kClose);
        EXPECT_NEAR(m.state(3.0).speed_mm_s, 0.0, kClose);
    }
}

TEST(AxisMotion, AStepThenCloseDrainsToWhereTheCommandStopped) {
    // The feed 10 mm/s stepped on at 0 and off at 1.5 s: the command ends at
    // 15 mm. Exponential T = 0.03: the actual is v T = 0.3 mm short when it
    // stops, then x_a = 15 - v T e^(-s/T) (1 - e^(-1.5/T)) at s after.
    const double v = 10.0;
    const double tc = 0.03;
    AxisCommand command;
    command.append(plan_accelerate(no_plan(), v, 100.0), 1.5);
    command.close();
    const AxisMotion m(AxisKernel(dynamics(FilterKind::exponential, tc, 0.0, 0.0)), command);
    EXPECT_NEAR(m.state(1.5).position_mm, 15.0 - 0.3, kClose);
    const double s = 0.05;
    EXPECT_NEAR(m.state(1.5 + s).position_mm, 15.0 - v * tc * std::exp(-s / tc), kClose);
    EXPECT_NEAR(m.state(1.5 + s).speed_mm_s, v * std::exp(-s / tc), kClose);
    EXPECT_NEAR(m.state(10.0).position_mm, 15.0, kClose);
}

TEST(AxisMotion, AShortPulseThroughALinearFilterIsATrapezoid) {
    // 0.4 mm at 160 mm/s: the command lasts t_e = 2.5 ms, less than W = 0.1.
    // The filtered speed rises to v t_e/W = 4 mm/s by t_e, holds to W, falls
    // to 0 at W + t_e. Position: v t^2/(2W) to t_e (0.005 mm at t_e), then
    // 0.005 + 4 (t - t_e), then 0.4 - v (t_e + W - t)^2/(2W).
    const double v = 160.0;
    const double w = 0.1;
    const AxisMotion m = move(dynamics(FilterKind::linear, w, 0.0, 0.0), 0.4, v);
    EXPECT_NEAR(m.command().end_s(), 0.0025, kTol);
    EXPECT_NEAR(m.state(0.0025).position_mm, 0.005, kClose);
    EXPECT_NEAR(m.state(0.05).speed_mm_s, 4.0, kClose);
    EXPECT_NEAR(m.state(0.05).position_mm, 0.005 + 4.0 * 0.0475, kClose);
    EXPECT_NEAR(m.state(0.101).speed_mm_s, v * 0.0015 / w, kClose);
    EXPECT_NEAR(m.state(0.101).position_mm, 0.4 - v * 0.0015 * 0.0015 / (2.0 * w), kClose);
    EXPECT_NEAR(m.state(0.2).position_mm, 0.4, kClose);
}

// --- The in-position check ---

TEST(AxisMotion, LinearFilterSettlesOnAParabolaInItsLastWindow) {
    // After the command stops at t_e (having cruised more than W), the
    // filtered speed is v (t_e + W - t)/W on [t_e, t_e + W], and the error
    // left is its integral v (t_e + W - t)^2/(2W) - a parabola over the whole
    // window, starting at v W/2. So error = w at t_e + W - sqrt(2 W w/v),
    // whenever w < v W/2; a wider width passes as the command ends.
    // v = 10, W = 0.1, t_e = 1: v W/2 = 0.5 mm.
    const double v = 10.0;
    const double w = 0.1;
    for (const double width : {0.01, 0.0001, 0.49}) {
        SCOPED_TRACE(width);
        const AxisMotion m = move(dynamics(FilterKind::linear, w, 0.0, 0.0, width), 10.0, v);
        const double expected = 1.0 + w - std::sqrt(2.0 * w * width / v);
        EXPECT_NEAR(m.in_position_time(), expected, kClose);
        EXPECT_NEAR(10.0 - m.state(expected).position_mm, width, kClose);
    }
    // 0.01 mm: 1.1 - sqrt(0.0002) = 1.0858579 s.
    EXPECT_NEAR(move(dynamics(FilterKind::linear, w, 0.0, 0.0, 0.01), 10.0, v).in_position_time(),
                1.0858578643762690, kClose);
    const AxisMotion wide = move(dynamics(FilterKind::linear, w, 0.0, 0.0, 0.5), 10.0, v);
    EXPECT_NEAR(wide.in_position_time(), 1.0, kTol);
}

TEST(AxisMotion, AShortPulseSettlesWhileTheFilterHoldsItsSpeed) {
    // The 2.5 ms pulse of 0.4 mm at 160 mm/s through W = 0.1 (the trapezoid
    // above): the error at the start of the hold is 0.4 - 0.005, and during
    // the hold 0.395 - 4 (t - t_e). Width 0.01 is reached there:
    //   t = t_e/2 + W (1 - w/d) = 0.00125 + 0.1 * 0.975 = 0.09875 s.
    // Width 0.002 is under the last parabola's start v t_e^2/(2W) = 0.005:
    //   t = t_e + W - sqrt(2 W w / v) = 0.1025 - 0.0015811 s.
    const double v = 160.0;
    EXPECT_NEAR(move(dynamics(FilterKind::linear, 0.1, 0.0, 0.0, 0.01), 0.4, v).in_position_time(),
                0.09875, kClose);
    EXPECT_NEAR(move(dynamics(FilterKind::linear, 0.1, 0.0, 0.0, 0.002), 0.4, v).in_position_time(),
                0.1025 - std::sqrt(2.0 * 0.1 * 0.002 / v), kClose);
}

TEST(AxisMotion, ALagSettlesLogarithmically) {
    // A lag T, a command of speed v lasting t_e: after it the error is
    // v T e^(-s/T) (1 - e^(-t_e/T)) (the step's and the stop's tails), so
    // s = T ln(v T (1 - e^(-t_e/T)) / w). Long moves: T ln(v T / w).
    const double v = 10.0;
    const double width = 0.01;
    for (const AxisDynamics& d : {dynamics(FilterKind::exponential, 0.05, 0.0, 0.0, width),
                                  dynamics(FilterKind::none, 0.0, 0.0, 0.05, width)}) {
        SCOPED_TRACE(to_string(d.filter));
        // 10 mm: t_e = 1 = 20 T; 1 - e^-20 = 1 - 2e-9 keeps the formula exact.
        const AxisMotion long_move = move(d, 10.0, v);
        EXPECT_NEAR(long_move.in_position_time(),
                    1.0 + 0.05 * std::log(v * 0.05 * (1.0 - std::exp(-20.0)) / width), kClose);
        // T ln(50) = 0.195601 s.
        EXPECT_NEAR(long_move.in_position_time(), 1.0 + 0.05 * std::log(50.0), 1e-9);
        // 0.5 mm: t_e = 0.05 = T, the tails far from negligible.
        const AxisMotion short_move = move(d, 0.5, v);
        EXPECT_NEAR(short_move.in_position_time(),
                    0.05 + 0.05 * std::log(v * 0.05 * (1.0 - std::exp(-1.0)) / width), kClose);
    }
    // A width over the whole lag v T = 0.1: in position as the command ends.
    const AxisMotion wide = move(dynamics(FilterKind::none, 0.0, 0.0, 0.01, 0.5), 10.0, v);
    EXPECT_NEAR(wide.in_position_time(), 1.0, kTol);
}

TEST(AxisMotion, TwoLagsSettleWhereTheirTailMeetsTheWidth) {
    // No closed form for the time: the error is v t_e - (P(t) - P(t - t_e)),
    // P the two lags' step response (two_lags_step_position,
    // double_pole_step_position). The time returned makes it the width, and a
    // microsecond earlier it is still over.
    const double v = 10.0;
    const double width = 0.01;
    for (const double distance : {10.0, 0.4}) {
        SCOPED_TRACE(distance);
        const double t_e = distance / v;
        {
            const double t1 = 0.03;
            const double t2 = 0.05;
            const AxisMotion m =
                move(dynamics(FilterKind::exponential, t1, 0.0, t2, width), distance, v);
            const auto error = [&](double t) {
                return distance - (two_lags_step_position(t1, t2, v, t) -
                                   two_lags_step_position(t1, t2, v, t - t_e));
            };
            const double t = m.in_position_time();
            EXPECT_NEAR(error(t), width, 1e-11);
            EXPECT_GT(error(t - 1e-6), width);
            EXPECT_GT(t, t_e);
        }
        {
            const double tc = 0.04;
            const AxisMotion m =
                move(dynamics(FilterKind::exponential, tc, 0.0, tc, width), distance, v);
            const auto error = [&](double t) {
                return distance - (double_pole_step_position(tc, v, t) -
                                   double_pole_step_position(tc, v, t - t_e));
            };
            const double t = m.in_position_time();
            EXPECT_NEAR(error(t), width, 1e-11);
            EXPECT_GT(error(t - 1e-6), width);
        }
    }
    // Long move, T1 = 0.03, T2 = 0.05: the error v (T1^2 e1 - T2^2 e2)/(T1 - T2)
    // at s after the stop; width 0.01 at s = 0.233 s (checked by the error).
    const AxisMotion m = move(dynamics(FilterKind::exponential, 0.03, 0.0, 0.05, width), 10.0, v);
    // (The start's tails, e^(-1/T2) = 2e-9 of it, are left out here.)
    const double s = m.in_position_time() - 1.0;
    EXPECT_NEAR(v * (0.0009 * std::exp(-s / 0.03) - 0.0025 * std::exp(-s / 0.05)) / (0.03 - 0.05),
                width, 1e-9);
}

TEST(AxisMotion, LinearFilterAndServoSettle) {
    // W = 0.05, Tp = 0.02: the error after a rest-to-rest command is
    // v t_e - (P(t) - P(t - t_e)), P = linear_servo_step_position.
    const double v = 20.0;
    const double w = 0.05;
    const double tp = 0.02;
    const double width = 0.005;
    for (const double distance : {10.0, 0.5, 0.02}) {  // t_e = 0.5, 0.025, 0.001
        SCOPED_TRACE(distance);
        const double t_e = distance / v;
        const AxisMotion m = move(dynamics(FilterKind::linear, w, 0.0, tp, width), distance, v);
        const auto error = [&](double t) {
            return distance - (linear_servo_step_position(w, tp, v, t) -
                               linear_servo_step_position(w, tp, v, t - t_e));
        };
        const double t = m.in_position_time();
        EXPECT_NEAR(error(t), width, 1e-11);
        EXPECT_GT(error(t - 1e-6), width);
    }
}

TEST(DynamicsCycle, BlockTimeIsTheInPositionTime) {
    // block_time_s: the plan's time on the ideal axis; with a linear filter
    // W = 0.1 and in-position 0.01 mm, d/v + W - sqrt(2 W w / v):
    // 10 mm at 10 mm/s -> 1.0858579 s.
    Scenario s;
    s.machine.accel_model = AccelModel::none;
    EXPECT_NEAR(block_time_s(s, 10.0, 10.0), 1.0, kTol);
    s.machine.filter = FilterKind::linear;
    s.machine.filter_time_s = 0.1;
    s.machine.in_position_mm = 0.01;
    EXPECT_NEAR(block_time_s(s, 10.0, 10.0), 1.1 - std::sqrt(0.0002), kClose);
    // The time-constant plan alone: d/v + T = 1.06 s (ramps of T each way).
    Scenario plan;
    EXPECT_NEAR(block_time_s(plan, 10.0, 10.0), 1.06, kTol);
}

TEST(DynamicsCycle, ApproachRoomIsWhereTheSpeedDeficitMeetsTheTolerance) {
    // A touch at v - dv errs at most dv tau (tau = t_i + t_c + t_s/2 =
    // 0.002 + 0.002 + 0.002 = 0.006 s by default); the feed counts as reached
    // when dv = 1e-4/0.006 = 0.0166667 mm/s. v = 2000 mm/min = 33.333 mm/s.
    Scenario s;
    s.machine.accel_model = AccelModel::none;
    const double v = 2000.0 / 60.0;
    const double tau = 0.006;
    ASSERT_NEAR(measurement_delay_s(s.machine, s.probe), tau, kTol);
    const double dv = kAccelErrorTolerance_mm / tau;
    // Ideal axis, no acc/dec: the feed at once.
    EXPECT_EQ(approach_room_mm(s, v), 0.0);
    // Exponential T = 0.03: v e^(-t/T) = dv at t = T ln(v/dv) = 0.03 ln 2000;
    // the travel v (t - T (1 - e^(-t/T))) = v (t - T) + T dv.
    s.machine.filter = FilterKind::exponential;
    s.machine.filter_time_s = 0.03;
    const double t_exp = 0.03 * std::log(v / dv);
    EXPECT_NEAR(approach_room_mm(s, v), v * (t_exp - 0.03) + 0.03 * dv, kClose);
    // Linear W = 0.1: v (1 - t/W) = dv at t = W (1 - dv/v); travel v t^2/(2W).
    s.machine.filter = FilterKind::linear;
    s.machine.filter_time_s = 0.1;
    const double t_lin = 0.1 * (1.0 - dv / v);
    EXPECT_NEAR(approach_room_mm(s, v), v * t_lin * t_lin / 0.2, kClose);
    // Without dynamics the plan's ramp: a time-constant plan covers v T/2.
    Scenario plan;
    EXPECT_NEAR(approach_room_mm(plan, v), v * 0.06 / 2.0, kTol);
}

// --- Touches through evaluate() ---

Scenario single_touch(double feed_mm_min, double approach_mm) {
    Scenario s;
    s.cycle.strategy = Strategy::single_touch;
    s.cycle.feature = Feature::surface;
    s.cycle.probe_feed_mm_min = feed_mm_min;
    s.cycle.approach_mm = approach_mm;
    s.probe.overtravel_limit_mm = 100.0;
    s.machine.accel_model = AccelModel::none;
    return s;
}

bool has_warning(const CycleResult& r, WarningCode code, Warning* found = nullptr) {
    for (const Warning& w : r.warnings()) {
        if (w.code != code) continue;
        if (found != nullptr) *found = w;
        return true;
    }
    return false;
}

TEST(DynamicsCycle, TouchDuringALinearFiltersRampGoesOnThroughTheWindow) {
    // Linear W = 0.1 s, 600 mm/min (v = 10 mm/s), D = 0.1 mm to the surface,
    // no pretravel, 2 ms interface delay and nothing else; in-position 0.01.
    // The axis follows x_a = v t^2/(2W): it touches at
    //   t_t = sqrt(2 W D / v) = sqrt(0.002) = 0.0447214 s, at v t_t/W = 4.47214 mm/s;
    // the control reacts at t_r = t_t + 0.002 = 0.0467214 s and the command
    // stops at v t_r = 0.467214 mm: overtravel v t_r - D = 0.367214 mm. The
    // window still covers the whole command until W, so the axis goes on at
    // v t_r/W = 4.67214 mm/s to W, then slows linearly to 0 at t_r + W, the
    // error v (t_r + W - t)^2/(2W): in position at t_r + W - sqrt(2 W w/v)
    // = 0.1467214 - 0.0141421 = 0.1325793 s.
    Scenario s = single_touch(600.0, 0.1);
    s.machine.filter = FilterKind::linear;
    s.machine.filter_time_s = 0.1;
    s.machine.servo_time_constant_s = 0.0;
    s.machine.scan_period_s = 0.0;
    s.machine.controller_latency_s = 0.0;
    s.probe.pretravel_mm = 0.0;
    s.probe.interface_delay_s = 0.002;
    s.machine.in_position_mm = 0.01;
    ASSERT_TRUE(validate(s).empty());
    const CycleResult r = evaluate(s);
    const double v = 10.0;
    const double w = 0.1;
    const double d = 0.1;
    const double t_touch = std::sqrt(2.0 * w * d / v);
    const double t_react = t_touch + 0.002;
    const double rest = v * t_react;
    const double settle = t_react + w - std::sqrt(2.0 * w * 0.01 / v);
    const TouchResult& touch = r.first_touch();
    EXPECT_NEAR(touch.touch_speed_mm_s, 4.47213595499958, kClose);
    EXPECT_NEAR(touch.trigger_speed_mm_s, v * t_touch / w, kClose);
    EXPECT_NEAR(touch.react_speed_mm_s, v * t_react / w, kClose);
    EXPECT_NEAR(touch.overtravel_mm, rest - d, kClose);
    EXPECT_NEAR(r.overtravel_mm(), 0.36721359549996, kClose);
    // Recorded at t_r too (no scan): x_a(t_r) - D = v t_r^2/(2W) - D.
    EXPECT_NEAR(touch.recorded_mm, v * t_react * t_react / (2.0 * w) - d, kClose);
    EXPECT_NEAR(touch.delay_travel_mm, v * t_react * t_react / (2.0 * w) - d, kClose);
    // Phases: approach to the touch, no pretravel, the interface delay, no
    // controller delay, deceleration to the in-position time.
    EXPECT_NEAR(r.phase_time(Phase::approach), t_touch, kClose);
    EXPECT_NEAR(r.phase_time(Phase::pretravel), 0.0, kClose);
    EXPECT_NEAR(r.phase_time(Phase::interface_delay), 0.002, kTol);
    EXPECT_NEAR(r.phase_time(Phase::controller_delay), 0.0, kClose);
    EXPECT_NEAR(r.phase_time(Phase::deceleration), settle - t_react, kClose);
    EXPECT_NEAR(r.phase_time(Phase::deceleration), 0.0858579, 1e-7);
    // The chart: on the parabola during the approach, then the held speed
    // between t_r and W, then 0.01 short of the rest when in position.
    EXPECT_NEAR(r.state_at(0.03).position_mm, v * 0.0009 / (2.0 * w), kClose);
    const CycleState mid = r.state_at(0.07);
    EXPECT_NEAR(mid.velocity_mm_s, v * t_react / w, kClose);
    EXPECT_NEAR(mid.position_mm,
                v * t_react * t_react / (2.0 * w) + v * t_react / w * (0.07 - t_react), kClose);
    EXPECT_EQ(r.phases()[mid.phase_index].phase, Phase::deceleration);
    const CycleState late = r.state_at(0.12);
    EXPECT_NEAR(late.velocity_mm_s, v * (t_react + w - 0.12) / w, kClose);
    // (The chart starts the return there; the touch's own motion shows the residue.)
    ASSERT_EQ(r.motions().size(), 2u);
    EXPECT_NEAR(r.motions()[0].state(settle).position_mm, rest - 0.01, kClose);
    // The return move, 0.467214 mm at 10000 mm/min: a pulse of t_e = rest/v_r
    // = 2.80 ms through W; its last parabola starts at rest t_e/(2W) =
    // 0.00655 < 0.01, so it settles in the hold: t_e/2 + W (1 - w/rest).
    const double v_r = 10000.0 / 60.0;
    const double t_e = rest / v_r;
    const double back = t_e / 2.0 + w * (1.0 - 0.01 / rest);
    EXPECT_NEAR(r.phase_time(Phase::return_move), back, kClose);
    EXPECT_NEAR(r.total(), settle + back, kClose);
    // A touch while accelerating: the error against full feed is
    // v tau - delay travel = 0.02 - 0.0091534 mm.
    Warning warning;
    ASSERT_TRUE(has_warning(r, WarningCode::touch_while_accelerating, &warning));
    EXPECT_NEAR(std::get<warning::TouchWhileAccelerating>(warning.figures).speed_mm_s,
                v * t_touch / w, kClose);
    EXPECT_NEAR(std::get<warning::TouchWhileAccelerating>(warning.figures).error_mm,
                v * 0.002 - (v * t_react * t_react / (2.0 * w) - d), kClose);
}

TEST(DynamicsCycle, ATouchAtCruiseThroughALinearFilterIsHandComputable) {
    // 2000 mm/min (v = 33.333 mm/s), D = 20 mm, W = 0.1, defaults otherwise:
    // pretravel 0.005, t_i 0.002, t_c 0.002, t_s 0.004 (tau_r = 0.008 s),
    // in-position 0.01. At cruise x_a = v (t - W/2), so
    //   approach   D/v + W/2 = 0.65 s
    //   pretravel  p/v = 0.00015 s
    //   delays     t_i, then t_c + t_s/2 (the mean scan wait)
    //   overtravel p + v (tau_r + W/2) = 0.005 + 33.333 * 0.058 = 1.938333 mm
    //              (the worst case, a full scan), on average v t_s/2 less
    //   recorded   p + v (t_i + t_s) = 0.205 mm
    //   settling   W - sqrt(2 W w / v) after the reaction.
    // The return, D + the mean overtravel at 10000 mm/min, lasts t_e = 0.1312 s
    // > W, so it settles at t_e + W - sqrt(2 W w / v_r).
    const double v = 2000.0 / 60.0;
    const double w = 0.1;
    Scenario s = single_touch(2000.0, 20.0);
    s.machine.filter = FilterKind::linear;
    s.machine.filter_time_s = w;
    ASSERT_TRUE(validate(s).empty());
    const CycleResult r = evaluate(s);
    const double overtravel = 0.005 + v * (0.008 + 0.05);
    EXPECT_NEAR(r.overtravel_mm(), overtravel, kClose);
    EXPECT_NEAR(r.overtravel_mm(), 1.9383333333333, 1e-12);
    EXPECT_NEAR(r.first_touch().recorded_mm, 0.005 + v * 0.006, kClose);
    EXPECT_NEAR(r.first_touch().touch_speed_mm_s, v, kClose);
    EXPECT_NEAR(r.trigger_speed_mm_s(), v, kClose);
    EXPECT_NEAR(r.scan_range_mm(), v * 0.004, kClose);
    EXPECT_NEAR(r.phase_time(Phase::approach), 20.0 / v + 0.05, kClose);
    EXPECT_NEAR(r.phase_time(Phase::pretravel), 0.005 / v, kClose);
    EXPECT_NEAR(r.phase_time(Phase::interface_delay), 0.002, kClose);
    EXPECT_NEAR(r.phase_time(Phase::controller_delay), 0.004, kClose);
    EXPECT_NEAR(r.phase_time(Phase::deceleration), w - std::sqrt(2.0 * w * 0.01 / v), kClose);
    const double mean_overtravel = overtravel - v * 0.002;
    EXPECT_NEAR(r.first_touch().mean_overtravel_mm, mean_overtravel, kClose);
    EXPECT_NEAR(r.first_touch().mean_recorded_mm, 0.005 + v * 0.004, kClose);
    const double v_r = 10000.0 / 60.0;
    const double back = (20.0 + mean_overtravel) / v_r + w - std::sqrt(2.0 * w * 0.01 / v_r);
    EXPECT_NEAR(r.phase_time(Phase::return_move), back, kClose);
    EXPECT_NEAR(r.total(),
                20.0 / v + 0.05 + 0.005 / v + 0.006 + w - std::sqrt(2.0 * w * 0.01 / v) + back,
                kClose);
    EXPECT_FALSE(has_warning(r, WarningCode::touch_while_accelerating));
}

TEST(DynamicsCycle, ATouchAtCruiseThroughAnExponentialFilter) {
    // Exponential T = 0.03, 2000 mm/min, D = 50 mm (1.5 s = 50 T of cruise).
    //   approach   D/v + T = 1.53 s
    //   overtravel p + v (tau_r + T) = 0.005 + 33.333 * 0.038 = 1.271667 mm
    //   settling   v T e^(-s/T) = w: s = T ln(v T / w) = 0.03 ln 100
    //   return     d = D + the mean overtravel (v t_s/2 less) at v_r =
    //              166.667 mm/s: t_e = d/v_r and s = T ln(v_r T (1 -
    //              e^(-t_e/T)) / w) after it.
    const double v = 2000.0 / 60.0;
    const double tc = 0.03;
    Scenario s = single_touch(2000.0, 50.0);
    s.machine.filter = FilterKind::exponential;
    s.machine.filter_time_s = tc;
    ASSERT_TRUE(validate(s).empty());
    const CycleResult r = evaluate(s);
    const double overtravel = 0.005 + v * (0.008 + tc);
    EXPECT_NEAR(r.overtravel_mm(), overtravel, kClose);
    EXPECT_NEAR(r.phase_time(Phase::approach), 50.0 / v + tc, kClose);
    EXPECT_NEAR(r.phase_time(Phase::deceleration), tc * std::log(100.0), kClose);
    const double v_r = 10000.0 / 60.0;
    const double t_e = (50.0 + overtravel - v * 0.002) / v_r;
    EXPECT_NEAR(r.phase_time(Phase::return_move),
                t_e + tc * std::log(v_r * tc * (1.0 - std::exp(-t_e / tc)) / 0.01), kClose);
}

// A measuring touch whose approach has settled before it touches (61 time
// constants of the slower lag after the feed was commanded) is solved once, at
// the distance where the approach settles, and shifted (MotionCache): at any
// backoff it is the hand-computed touch at cruise.
//   Exponential 0.03 + servo 0.02: the actual lags the command by L = 0.05 s.
//   approach    d2 / v + L, d2 = b - overtravel_1
//   overtravel  p + v (tau_r + L) = 0.005 + 0.5 * (0.008 + 0.05) = 0.034 mm
//   settling    v (T1^2 e^(-s/T1) - T2^2 e^(-s/T2)) / (T1 - T2) = w, by bisection
TEST(DynamicsCycle, ASettledMeasuringTouchIsTheSameTouchAtEveryBackoff) {
    const double v = 30.0 / 60.0;
    const double t1 = 0.03;
    const double t2 = 0.02;
    const double w = 0.01;
    const auto error = [&](double s) {
        return v * (t1 * t1 * std::exp(-s / t1) - t2 * t2 * std::exp(-s / t2)) / (t1 - t2);
    };
    double lo = 0.0;
    double hi = 1.0;
    for (int i = 0; i < 200; ++i) (error(0.5 * (lo + hi)) > w ? lo : hi) = 0.5 * (lo + hi);
    const double settling = 0.5 * (lo + hi);

    MotionCache cache;
    std::optional<CycleResult> first;
    for (const double backoff : {3.0, 4.0, 6.0, 3.5}) {
        SCOPED_TRACE(backoff);
        Scenario s = single_touch(2000.0, 5.0);
        s.cycle.strategy = Strategy::two_touch;
        s.cycle.measure_feed_mm_min = 30.0;
        s.cycle.backoff_mm = backoff;
        s.machine.filter = FilterKind::exponential;
        s.machine.filter_time_s = t1;
        s.machine.servo_time_constant_s = t2;
        s.machine.in_position_mm = w;
        ASSERT_TRUE(validate(s).empty());
        CycleResult r;
        evaluate_into(s, r, cache);
        const CycleResult fresh = evaluate(s);  // shifted the same way without a cache
        EXPECT_EQ(r.total(), fresh.total());
        EXPECT_EQ(r.phase_time(Phase::second_approach), fresh.phase_time(Phase::second_approach));
        const double d2 = backoff - r.first_touch().mean_overtravel_mm;
        ASSERT_GT(d2 / v, 61.0 * t1);  // settled
        EXPECT_NEAR(r.phase_time(Phase::second_approach), d2 / v + t1 + t2, kClose);
        EXPECT_NEAR(r.measuring_touch().overtravel_mm, 0.034, kClose);
        EXPECT_EQ(r.measuring_touch().trigger_speed_mm_s, v);
        EXPECT_NEAR(r.phase_time(Phase::second_deceleration), settling, kClose);
        // The timeline's motion touches the surface where the phases say.
        const PhaseRecord* pretravel = nullptr;
        for (const PhaseRecord& phase : r.phases()) {
            if (phase.phase == Phase::second_pretravel) pretravel = &phase;
        }
        ASSERT_NE(pretravel, nullptr);
        EXPECT_NEAR(r.state_at(pretravel->start_s).position_mm, 5.0, kClose);
        if (!first) {
            first = r;
            continue;
        }
        for (const Phase phase : {Phase::second_pretravel, Phase::second_interface_delay,
                                  Phase::second_controller_delay, Phase::second_deceleration}) {
            EXPECT_NEAR(r.phase_time(phase), first->phase_time(phase), 1e-12) << to_string(phase);
        }
        EXPECT_NEAR(r.measuring_touch().recorded_mm, first->measuring_touch().recorded_mm, 1e-12);
    }
}

TEST(DynamicsCycle, TheBellFilterAndTheServoAddTheirLagsToTheOvertravel) {
    // At cruise the drain adds v L: bell (W1 + W2)/2 + Tp.
    // W1 = 0.032, W2 = 0.016, Tp = 0.02: L = 0.044; 3000 mm/min = 50 mm/s;
    // overtravel p + v (tau_r + L) = 0.005 + 50 * 0.052 = 2.605 mm.
    Scenario s = single_touch(3000.0, 60.0);
    s.machine.filter = FilterKind::bell;
    s.machine.filter_time_s = 0.032;
    s.machine.filter2_time_s = 0.016;
    s.machine.servo_time_constant_s = 0.02;
    ASSERT_TRUE(validate(s).empty());
    const CycleResult r = evaluate(s);
    EXPECT_NEAR(r.overtravel_mm(), 2.605, kClose);
    EXPECT_NEAR(r.phase_time(Phase::approach), 60.0 / 50.0 + 0.044, kClose);
}

TEST(DynamicsCycle, TheKeysReadFromAFileGiveTheSameQmax) {
    // As the Fanuc-type preset file writes them: 2000 mm/min,
    // Qmax = 33.333 * (20 + 32 + 33) / 1000 = 2.833333 mm.
    Scenario s = single_touch(2000.0, 200.0);
    s = merge_json(s, R"({"machine": {"accel_model": "none", "filter": "exponential",
        "filter_time_s": 0.032, "servo_time_constant_s": 0.033, "scan_period_s": 0.004,
        "controller_latency_s": 0.014}})");
    EXPECT_NEAR(evaluate(s).overtravel_mm() - s.probe.pretravel_mm,
                2000.0 / 60.0 * (20.0 + 32.0 + 33.0) / 1000.0, kClose);
}

TEST(DynamicsCycle, PhasesSumToTheTotalAndFollowTheActualMotion) {
    Scenario s;
    s.cycle.feature = Feature::bore;
    s.cycle.feature_size_mm = 40.0;
    s.cycle.backoff_mm = 3.5;
    s.machine.accel_model = AccelModel::none;
    s.machine.filter = FilterKind::bell;
    s.machine.filter_time_s = 0.032;
    s.machine.filter2_time_s = 0.016;
    s.machine.servo_time_constant_s = 0.033;
    ASSERT_TRUE(validate(s).empty());
    const CycleResult r = evaluate(s);
    EXPECT_TRUE(r.valid());
    double sum = 0.0;
    for (const PhaseRecord& p : r.phases()) sum += p.time_s;
    EXPECT_NEAR(sum, r.total(), kClose);
    // The chart's position is continuous but for the in-position residue
    // (the next block starts 0.01 mm before the last has come to rest).
    double last = r.state_at(0.0).position_mm;
    for (double t = 0.001; t < r.total(); t += 0.001) {
        const double x = r.state_at(t).position_mm;
        EXPECT_LE(std::abs(x - last), 0.001 * 200.0 + s.machine.in_position_mm) << t;
        last = x;
    }
}

// --- Published checks: the makers' overtravel formulas at cruise ---

// Approach long enough that every exponential tail is below e^-50 of its lag
// when the probe touches.
double cruise_approach_mm(double feed_mm_min, double largest_time_constant_s) {
    return std::max(1.0, 50.0 * largest_time_constant_s * feed_mm_min / 60.0);
}

// Mitsubishi M700V, G31 without acc/dec: delta0 = F/60 (Tp + t1) +- F/60 t2
// (Tp the position-loop time constant, t1 the response delay, t2 = 1 ms the
// scan; worked example Tp = 30 ms, t1 = 5 ms). The model's worst case (a full
// scan) is the upper end F/60 (Tp + t1 + t2); its scan range is F/60 t2, so
// the upper end less that range is the best case F/60 (Tp + t1). (The
// formula's +- spans 2 t2 around F/60 (Tp + t1); the model's scan wait lies
// in [0, t2], the upper half of it.)
TEST(PublishedChecks, MitsubishiG31WithoutAccDec) {
    for (const double feed : {250.0, 500.0, 1000.0, 2000.0, 4000.0}) {
        SCOPED_TRACE(feed);
        Scenario s = single_touch(feed, cruise_approach_mm(feed, 0.030));
        s.machine.servo_time_constant_s = 0.030;
        s.probe.interface_delay_s = 0.002;
        s.machine.controller_latency_s = 0.003;  // t1 = 5 ms with the interface
        s.machine.scan_period_s = 0.001;
        s.machine.latched_input = false;
        ASSERT_TRUE(validate(s).empty());
        const CycleResult r = evaluate(s);
        const double v = feed / 60.0;
        const double beyond_trigger = r.overtravel_mm() - s.probe.pretravel_mm;
        EXPECT_NEAR(beyond_trigger, v * (0.030 + 0.005 + 0.001), kClose);
        EXPECT_NEAR(r.scan_range_mm(), v * 0.001, kClose);
        EXPECT_NEAR(beyond_trigger - r.scan_range_mm(), v * (0.030 + 0.005), kClose);
        EXPECT_NEAR(r.trigger_speed_mm_s(), v, kClose);
    }
    // At 1000 mm/min: 16.667 * 0.036 = 0.6 mm beyond the trigger.
    Scenario s = single_touch(1000.0, cruise_approach_mm(1000.0, 0.030));
    s.machine.servo_time_constant_s = 0.030;
    s.machine.controller_latency_s = 0.003;
    s.machine.scan_period_s = 0.001;
    EXPECT_NEAR(evaluate(s).overtravel_mm() - s.probe.pretravel_mm, 0.6, kClose);
}

// Fanuc Power Mate i: Qmax = Fm/60 (20 + Tc + Ts) / 1000 mm, Tc the
// exponential cutting-feed acc/dec time constant after interpolation, Ts the
// servo time constant (ms), 20 ms the skip detection delay (here t_i + t_c +
// t_s = 2 + 14 + 4 ms).
void expect_fanuc_qmax(double tc_s, double ts_s) {
    for (const double feed : {250.0, 500.0, 1000.0, 2000.0, 4000.0}) {
        SCOPED_TRACE(std::to_string(feed) + " mm/min, Tc " + std::to_string(tc_s) + ", Ts " +
                     std::to_string(ts_s));
        Scenario s = single_touch(feed, cruise_approach_mm(feed, std::max(tc_s, ts_s)));
        s.machine.filter = FilterKind::exponential;
        s.machine.filter_time_s = tc_s;
        s.machine.servo_time_constant_s = ts_s;
        s.probe.interface_delay_s = 0.002;
        s.machine.controller_latency_s = 0.014;
        s.machine.scan_period_s = 0.004;
        ASSERT_TRUE(validate(s).empty());
        const double qmax = feed / 60.0 * (20.0 + tc_s * 1000.0 + ts_s * 1000.0) / 1000.0;
        const CycleResult r = evaluate(s);
        EXPECT_NEAR(r.overtravel_mm() - s.probe.pretravel_mm, qmax, kClose);
        EXPECT_NEAR(r.trigger_speed_mm_s(), feed / 60.0, kClose);
    }
}

TEST(PublishedChecks, FanucQmaxWithExponentialAccDecAndServo) {
    expect_fanuc_qmax(0.032, 0.033);
    // At 4000 mm/min: 66.667 * 0.085 = 5.6667 mm.
    Scenario s = single_touch(4000.0, cruise_approach_mm(4000.0, 0.033));
    s.machine.filter = FilterKind::exponential;
    s.machine.filter_time_s = 0.032;
    s.machine.servo_time_constant_s = 0.033;
    s.machine.controller_latency_s = 0.014;
    EXPECT_NEAR(evaluate(s).overtravel_mm() - s.probe.pretravel_mm, 4000.0 / 60.0 * 0.085, kClose);
}

TEST(PublishedChecks, FanucQmaxWithEqualTimeConstants) {
    // Tc = Ts: the double pole.
    expect_fanuc_qmax(0.032, 0.032);
}

// --- Properties (fixed seed) ---

struct RandomDynamics {
    std::mt19937_64 rng{112501};
    std::uniform_real_distribution<double> unit{0.0, 1.0};

    double between(double lo, double hi) { return lo + (hi - lo) * unit(rng); }
    int pick(int n) { return static_cast<int>(unit(rng) * n) % n; }

    // Random acc/dec model, filter, times and servo on a single-touch scenario.
    Scenario scenario(double feed_mm_min, double approach_mm) {
        Scenario s = single_touch(feed_mm_min, approach_mm);
        s.machine.accel_model = static_cast<AccelModel>(pick(4));
        s.machine.time_constant_s = between(0.01, 0.1);
        s.machine.max_accel_mm_s2 = between(500.0, 5000.0);
        s.machine.max_jerk_mm_s3 = between(1e4, 1e5);
        s.machine.filter = static_cast<FilterKind>(pick(4));
        s.machine.filter_time_s = between(0.005, 0.06);
        s.machine.filter2_time_s = between(0.005, 0.06);
        s.machine.servo_time_constant_s = unit(rng) < 0.25 ? 0.0 : between(0.002, 0.04);
        s.machine.in_position_mm = between(0.001, 0.05);
        s.machine.scan_period_s = between(0.0, 0.008);
        s.machine.controller_latency_s = between(0.0, 0.01);
        s.probe.interface_delay_s = between(0.0, 0.005);
        s.probe.pretravel_mm = between(0.0, 0.02);
        return s;
    }
};

Scenario without_dynamics(Scenario s) {
    s.machine.filter = FilterKind::none;
    s.machine.servo_time_constant_s = 0.0;
    return s;
}

// Room to reach the feed on the plan and to let every tail die out (e^-50).
double cruise_room_mm(const Scenario& s, double v) {
    const AxisKernel k(s.axis_dynamics());
    return reach_distance_mm(s.motion_limits(), v) + 50.0 * (k.window_s() + k.lag_time_s()) * v +
           1.0;
}

TEST(DynamicsProperties, OvertravelAtCruiseRisesWithFeed) {
    RandomDynamics random;
    int checked = 0;
    for (int i = 0; i < 120; ++i) {
        Scenario s = random.scenario(250.0, 1.0);
        double last = 0.0;
        for (const double feed : {250.0, 500.0, 1000.0, 2000.0, 4000.0, 8000.0}) {
            s.cycle.probe_feed_mm_min = feed;
            s.cycle.approach_mm = std::min(1000.0, cruise_room_mm(s, feed / 60.0));
            ASSERT_TRUE(validate(s).empty()) << scenario_to_json(s);
            const double overtravel = evaluate(s).overtravel_mm();
            EXPECT_GE(overtravel, last) << scenario_to_json(s);
            last = overtravel;
            ++checked;
        }
    }
    EXPECT_EQ(checked, 720);
}

TEST(DynamicsProperties, PhaseTimesSumToTheTotal) {
    RandomDynamics random;
    int checked = 0;
    for (int i = 0; i < 200; ++i) {
        Scenario s = random.scenario(random.between(100.0, 4000.0), random.between(0.2, 10.0));
        s.cycle.strategy = random.pick(2) == 0 ? Strategy::single_touch : Strategy::two_touch;
        s.cycle.feature = static_cast<Feature>(random.pick(5));
        s.cycle.feature_size_mm = random.between(25.0, 80.0);
        s.cycle.backoff_mm = random.between(0.5, 5.0);
        s.cycle.measure_feed_mm_min = random.between(20.0, 200.0);
        if (!validate(s).empty()) continue;
        ++checked;
        const CycleResult r = evaluate(s);
        double sum = 0.0;
        for (const PhaseRecord& p : r.phases()) {
            EXPECT_GE(p.time_s, 0.0);
            sum += p.time_s;
        }
        EXPECT_NEAR(sum, r.total(), kClose * std::max(1.0, r.total())) << scenario_to_json(s);
        double by_kind = 0.0;
        for (const Phase phase : all_phases()) by_kind += r.phase_time(phase);
        EXPECT_NEAR(by_kind, r.total(), kClose * std::max(1.0, r.total()));
    }
    EXPECT_GT(checked, 150);
}

TEST(DynamicsProperties, AFilterNeverShortensAMove) {
    // block_time_s with dynamics >= the plan alone; with moving averages only
    // (no lag) the axis is exactly at the end W_total after the command, so
    // it is also <= plan + window.
    RandomDynamics random;
    for (int i = 0; i < 300; ++i) {
        const Scenario s = random.scenario(1000.0, 1.0);
        const Scenario ideal = without_dynamics(s);
        const double distance = random.between(0.01, 50.0);
        const double v = random.between(1.0, 500.0);
        const double with = block_time_s(s, distance, v);
        const double plan = block_time_s(ideal, distance, v);
        EXPECT_NEAR(plan, move_time_s(s.motion_limits(), distance, v), kTol);
        // Within 1e-12 s: the last bits of exp() and pow() differ between C
        // libraries (the Windows build's among them).
        EXPECT_GE(with, plan - 1e-12) << scenario_to_json(s) << distance << " at " << v;
        const AxisKernel k(s.axis_dynamics());
        if (k.lag_count() == 0) {
            EXPECT_LE(with, plan + k.window_s() + 1e-12);
        }
    }
}

TEST(DynamicsProperties, TheDrainOnlyAddsToTheOvertravel) {
    // At cruise the drain adds exactly v L to the ideal axis's overtravel
    // (the trigger comes L later on the command, the stop is the same). From
    // short approaches too (touches while accelerating, plans before
    // interpolation of every model) the overtravel with dynamics is at least
    // the ideal axis's: the actual lags the command, so the trigger and the
    // reaction come no earlier, and stopping later never stops shorter.
    RandomDynamics random;
    int at_cruise = 0;
    int short_approach = 0;
    for (int i = 0; i < 400; ++i) {
        const double feed = random.between(100.0, 4000.0);
        const double v = feed / 60.0;
        Scenario s = random.scenario(feed, 1.0);
        const bool cruise = i % 2 == 0;
        s.cycle.approach_mm =
            cruise ? std::min(1000.0, cruise_room_mm(s, v)) : random.between(0.0, 2.0);
        ASSERT_TRUE(validate(s).empty());
        const Scenario ideal = without_dynamics(s);
        const double with = evaluate(s).overtravel_mm();
        const double without = evaluate(ideal).overtravel_mm();
        if (cruise) {
            ++at_cruise;
            EXPECT_NEAR(with, without + v * s.axis_dynamics().lag_s(), 1e-9) << scenario_to_json(s);
        } else {
            ++short_approach;
            EXPECT_GE(with, without - 1e-12) << scenario_to_json(s);
        }
    }
    EXPECT_EQ(at_cruise, 200);
    EXPECT_EQ(short_approach, 200);
}

TEST(DynamicsProperties, TheActualFollowsTheCommandAndDrainsToItsEnd) {
    // A non-negative kernel of unit area on a command that never moves back:
    // the actual is non-decreasing, never ahead of the command, never past
    // the end, at rest on the end once every stage has drained.
    RandomDynamics random;
    for (int i = 0; i < 100; ++i) {
        const Scenario s = random.scenario(1000.0, 1.0);
        const AxisDynamics d = s.axis_dynamics();
        if (!d.active()) continue;
        const MotionLimits limits = s.motion_limits();
        const double distance = random.between(0.05, 20.0);
        const double v = random.between(5.0, 200.0);
        const SegmentPlan plan = plan_move(limits, distance, v);
        const AxisMotion m = move(d, distance, v, limits);
        const AxisKernel k(d);
        const double end = m.command().end_s();
        const double horizon = end + k.window_s() + 60.0 * k.lag_time_s();
        double last = 0.0;
        for (int step = 0; step <= 400; ++step) {
            const double t = horizon * step / 400.0;
            const KinematicState a = m.state(t);
            const double commanded = plan.state_at(t).position_mm;
            EXPECT_GE(a.position_mm, last - 1e-12) << t;
            EXPECT_LE(a.position_mm, commanded + 1e-9) << t;
            EXPECT_LE(a.position_mm, distance + 1e-9) << t;
            EXPECT_GE(a.speed_mm_s, 0.0);
            last = a.position_mm;
        }
        EXPECT_NEAR(m.state(horizon).position_mm, distance, 1e-9) << scenario_to_json(s);
        EXPECT_GE(m.in_position_time(), end);
        EXPECT_LE(distance - m.state(m.in_position_time()).position_mm, d.in_position_mm + 1e-9);
    }
}

// --- The keys ---

template <typename F>
std::string error_text(F&& action) {
    try {
        action();
    } catch (const ScenarioError& e) {
        return e.what();
    }
    return "accepted";
}

TEST(DynamicsKeys, AnUnknownFilterWordNamesTheKeyAndTheWords) {
    // Refused by --set itself, the scenario left as it was.
    Scenario s;
    const std::string what = error_text([&] { apply_setting(s, "machine.filter=gaussian"); });
    EXPECT_NE(what.find("machine.filter"), std::string::npos) << what;
    EXPECT_NE(what.find("gaussian"), std::string::npos) << what;
    EXPECT_NE(what.find("none, linear, exponential, bell"), std::string::npos) << what;
    EXPECT_EQ(s.machine.filter, FilterKind::none);
    const KeyInfo* key = find_any_key("machine.filter");
    ASSERT_NE(key, nullptr);
    EXPECT_EQ(allowed_words(*key),
              (std::vector<std::string>{"none", "linear", "exponential", "bell"}));
    // Every word is accepted and read back.
    for (const char* word : {"none", "linear", "exponential", "bell"}) {
        apply_setting(s, std::string("machine.filter=") + word);
        EXPECT_STREQ(to_string(s.machine.filter), word);
    }
    apply_setting(s, "machine.accel_model=none");
    EXPECT_EQ(s.machine.accel_model, AccelModel::none);
}

TEST(DynamicsKeys, OutOfRangeAndNaNValuesNameTheKeyAndTheRange) {
    // --set stores the number; validation (as every command does) refuses it.
    struct Case {
        const char* assignment;
        const char* key;
        const char* range;
    };
    for (const Case& c :
         {Case{"machine.servo_time_constant_s=-0.01", "machine.servo_time_constant_s",
               "from 0 to 0.5 s"},
          Case{"machine.in_position_mm=0", "machine.in_position_mm", "from 0.0001 to 1 mm"},
          Case{"machine.filter_time_s=5", "machine.filter_time_s", "from 0.0005 to 1 s"},
          Case{"machine.filter2_time_s=0", "machine.filter2_time_s", "from 0.0005 to 1 s"}}) {
        SCOPED_TRACE(c.assignment);
        Scenario s;
        const std::string what = error_text([&] {
            apply_setting(s, c.assignment);
            validate_or_throw(s);
        });
        EXPECT_NE(what.find(c.key), std::string::npos) << what;
        EXPECT_NE(what.find(c.range), std::string::npos) << what;
        const std::vector<FieldError> errors = validate(s);
        ASSERT_EQ(errors.size(), 1u);
        EXPECT_EQ(errors[0].key, c.key);
    }
    // The ends of the ranges are allowed.
    Scenario edge;
    apply_setting(edge, "machine.servo_time_constant_s=0.5");
    apply_setting(edge, "machine.in_position_mm=0.0001");
    apply_setting(edge, "machine.filter_time_s=1");
    EXPECT_TRUE(validate(edge).empty());
    // NaN is refused by name.
    Scenario with_nan;
    with_nan.machine.filter2_time_s = std::numeric_limits<double>::quiet_NaN();
    const std::vector<FieldError> errors = validate(with_nan);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].key, "machine.filter2_time_s");
    EXPECT_NE(errors[0].message().find("machine.filter2_time_s"), std::string::npos);
    const std::string what = error_text([&] { validate_or_throw(with_nan); });
    EXPECT_NE(what.find("machine.filter2_time_s"), std::string::npos) << what;
}

TEST(DynamicsKeys, TheFileCarriesTheDynamics) {
    Scenario s;
    s.machine.accel_model = AccelModel::none;
    s.machine.filter = FilterKind::bell;
    s.machine.filter_time_s = 0.04;
    s.machine.filter2_time_s = 0.012;
    s.machine.servo_time_constant_s = 0.025;
    s.machine.in_position_mm = 0.005;
    const Scenario back = scenario_from_json(scenario_to_json(s));
    EXPECT_EQ(back.machine.accel_model, AccelModel::none);
    EXPECT_EQ(back.machine.filter, FilterKind::bell);
    EXPECT_EQ(back.machine.filter_time_s, 0.04);
    EXPECT_EQ(back.machine.filter2_time_s, 0.012);
    EXPECT_EQ(back.machine.servo_time_constant_s, 0.025);
    EXPECT_EQ(back.machine.in_position_mm, 0.005);
    const std::string what =
        error_text([] { merge_json(Scenario{}, R"({"machine": {"filter": "gaussian"}})"); });
    EXPECT_NE(what.find("machine.filter"), std::string::npos) << what;
}

// --- The defaults change nothing ---

TEST(DynamicsDefaults, TheDefaultIsTheIdealAxisAndUnusedKeysChangeNothing) {
    const Scenario defaults;
    EXPECT_EQ(defaults.machine.filter, FilterKind::none);
    EXPECT_EQ(defaults.machine.servo_time_constant_s, 0.0);
    EXPECT_FALSE(defaults.axis_dynamics().active());
    const CycleResult r = evaluate(defaults);
    EXPECT_TRUE(r.motions().empty());
    for (const TimedSegment& segment : r.segments()) EXPECT_EQ(segment.motion, -1);
    // Filter none and servo 0: the filter times and the in-position width are
    // unused, phase for phase, for every feature and strategy.
    for (const Feature feature :
         {Feature::surface, Feature::web, Feature::pocket, Feature::bore, Feature::boss}) {
        for (const Strategy strategy : {Strategy::single_touch, Strategy::two_touch}) {
            SCOPED_TRACE(std::string(to_string(feature)) + " " + to_string(strategy));
            Scenario a;
            a.cycle.feature = feature;
            a.cycle.strategy = strategy;
            Scenario b = a;
            b.machine.filter_time_s = 0.5;
            b.machine.filter2_time_s = 0.2;
            b.machine.in_position_mm = 0.5;
            ASSERT_TRUE(validate(b).empty());
            const CycleResult ra = evaluate(a);
            const CycleResult rb = evaluate(b);
            EXPECT_EQ(ra.total(), rb.total());
            EXPECT_EQ(ra.overtravel_mm(), rb.overtravel_mm());
            EXPECT_EQ(ra.recommended_backoff_mm(), rb.recommended_backoff_mm());
            ASSERT_EQ(ra.phases().size(), rb.phases().size());
            for (std::size_t i = 0; i < ra.phases().size(); ++i) {
                EXPECT_EQ(ra.phases()[i].phase, rb.phases()[i].phase);
                EXPECT_EQ(ra.phases()[i].start_s, rb.phases()[i].start_s);
                EXPECT_EQ(ra.phases()[i].time_s, rb.phases()[i].time_s);
                EXPECT_EQ(ra.phases()[i].distance_mm, rb.phases()[i].distance_mm);
            }
            EXPECT_EQ(ra.warnings().size(), rb.warnings().size());
        }
    }
}

}  // namespace
}  // namespace probecycle
