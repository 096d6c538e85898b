#include "core/cycle/motion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <string>

#include "core/common/units.h"

namespace probecycle {
namespace {

constexpr double kRel = 1e-12;  // closed forms against hand values and the reference solver

MotionLimits time_constant(double time_constant_s) {
    MotionLimits limits;
    limits.model = AccelModel::time_constant;
    limits.time_constant_s = time_constant_s;
    return limits;
}

MotionLimits constant_accel(double max_accel_mm_s2) {
    MotionLimits limits;
    limits.model = AccelModel::constant_accel;
    limits.max_accel_mm_s2 = max_accel_mm_s2;
    return limits;
}

MotionLimits jerk_limited(double max_accel_mm_s2, double max_jerk_mm_s3) {
    MotionLimits limits;
    limits.model = AccelModel::jerk_limited;
    limits.max_accel_mm_s2 = max_accel_mm_s2;
    limits.max_jerk_mm_s3 = max_jerk_mm_s3;
    return limits;
}

// Names parameterized cases after their `name` field.
struct CaseName {
    template <typename T>
    std::string operator()(const testing::TestParamInfo<T>& case_info) const {
        return case_info.param.name;
    }
};

double rel_tol(double expected, double rel = kRel) {
    return rel * std::abs(expected);
}

// ---------------------------------------------------------------------------
// An independent reference for the jerk-limited (seven-segment) profile, built
// only from its definition: from rest, jerk +j until the peak acceleration
// ap = min(a, sqrt(vp * j)), hold ap, jerk -j down to zero at the peak speed vp;
// cruise; then the mirror image. Positions come from integrating the
// polynomials directly, and short moves are solved by bisection on vp.

struct Ramp {
    double t_jerk_s;     // each of the two jerk segments
    double t_hold_s;     // at the peak acceleration
    double accel_mm_s2;  // peak acceleration
    double jerk_mm_s3;
};

Ramp ramp_to(double peak_speed_mm_s, double a, double j) {
    const double ap = std::min(a, std::sqrt(peak_speed_mm_s * j));
    const double t_jerk = ap / j;
    // The two jerk segments together gain ap * t_jerk of speed.
    const double t_hold = std::max(0.0, (peak_speed_mm_s - ap * t_jerk) / ap);
    return {t_jerk, t_hold, ap, j};
}

double ramp_time_s(const Ramp& r) {
    return 2.0 * r.t_jerk_s + r.t_hold_s;
}

struct RefState {
    double x;
    double v;
};

// Position and speed at time t in the ramp (t within [0, ramp_time]).
RefState ramp_state_at(const Ramp& r, double t) {
    const double j = r.jerk_mm_s3;
    const double ap = r.accel_mm_s2;
    const double t1 = std::min(t, r.t_jerk_s);
    RefState s{j * t1 * t1 * t1 / 6.0, j * t1 * t1 / 2.0};
    if (t <= r.t_jerk_s) return s;
    const double t2 = std::min(t - r.t_jerk_s, r.t_hold_s);
    s = {s.x + s.v * t2 + ap * t2 * t2 / 2.0, s.v + ap * t2};
    if (t <= r.t_jerk_s + r.t_hold_s) return s;
    const double t3 = std::min(t - r.t_jerk_s - r.t_hold_s, r.t_jerk_s);
    return {s.x + s.v * t3 + ap * t3 * t3 / 2.0 - j * t3 * t3 * t3 / 6.0,
            s.v + ap * t3 - j * t3 * t3 / 2.0};
}

double ramp_distance_mm(const Ramp& r) {
    return ramp_state_at(r, ramp_time_s(r)).x;
}

// Bisection until the interval cannot shrink any more.
template <typename F>
double bisect_increasing(F f, double lo, double hi, double target) {
    for (int i = 0; i < 2000; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        if (f(mid) < target) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return 0.5 * (lo + hi);
}

struct RefMove {
    double time_s;
    double peak_speed_mm_s;
};

RefMove reference_jerk_move(double d, double v, double a, double j) {
    const Ramp full = ramp_to(v, a, j);
    const double d_ramps = 2.0 * ramp_distance_mm(full);
    if (d >= d_ramps) return {2.0 * ramp_time_s(full) + (d - d_ramps) / v, v};
    const double vp = bisect_increasing(
        [&](double peak) { return 2.0 * ramp_distance_mm(ramp_to(peak, a, j)); }, 0.0, v, d);
    return {2.0 * ramp_time_s(ramp_to(vp, a, j)), vp};
}

// Speed after `d` when accelerating from rest toward v (d within the ramp).
double reference_jerk_speed_after(double d, double v, double a, double j) {
    const Ramp r = ramp_to(v, a, j);
    const double t = bisect_increasing([&](double time) { return ramp_state_at(r, time).x; }, 0.0,
                                       ramp_time_s(r), d);
    return ramp_state_at(r, t).v;
}

double max_speed_in(const SegmentPlan& plan) {
    double peak = 0.0;
    double t0 = 0.0;
    for (std::size_t i = 0; i < plan.count; ++i) {
        const double dt = plan.segments[i].duration_s;
        for (int k = 0; k <= 8; ++k) {
            peak = std::max(peak, plan.state_at(t0 + dt * k / 8.0).speed_mm_s);
        }
        t0 += dt;
    }
    return peak;
}

// ---------------------------------------------------------------------------
// Named cases, computed by hand (docs/model.md, "Motion").

TEST(Integrate, ConstantJerkClosedForm) {
    // x = 1 + 3*2 + 4*2^2/2 + 6*2^3/6 = 23; v = 3 + 4*2 + 6*2^2/2 = 23; a = 4 + 6*2 = 16.
    const KinematicState s = integrate(2.0, {1.0, 3.0, 4.0}, 6.0);
    EXPECT_DOUBLE_EQ(s.position_mm, 23.0);
    EXPECT_DOUBLE_EQ(s.speed_mm_s, 23.0);
    EXPECT_DOUBLE_EQ(s.accel_mm_s2, 16.0);
}

TEST(Integrate, ZeroTimeIsTheStart) {
    const KinematicState s = integrate(0.0, {1.5, -2.0, 3.0}, 100.0);
    EXPECT_EQ(s.position_mm, 1.5);
    EXPECT_EQ(s.speed_mm_s, -2.0);
    EXPECT_EQ(s.accel_mm_s2, 3.0);
}

TEST(SegmentPlan, DurationEndStateAndClampedStateAt) {
    SegmentPlan plan;
    plan.push(0.5, 4.0, 0.0);   // to 2 mm/s over 0.5 mm
    plan.push(1.0, 0.0, 0.0);   // cruise 2 mm
    plan.push(0.5, -4.0, 0.0);  // back to rest over 0.5 mm
    ASSERT_EQ(plan.count, 3u);
    EXPECT_DOUBLE_EQ(plan.duration_s(), 2.0);
    const KinematicState end = plan.end_state();
    EXPECT_DOUBLE_EQ(end.position_mm, 3.0);
    EXPECT_NEAR(end.speed_mm_s, 0.0, 1e-15);
    EXPECT_DOUBLE_EQ(plan.state_at(0.5).speed_mm_s, 2.0);
    EXPECT_DOUBLE_EQ(plan.state_at(1.0).position_mm, 1.5);
    EXPECT_EQ(plan.state_at(-1.0).position_mm, 0.0);
    EXPECT_DOUBLE_EQ(plan.state_at(10.0).position_mm, 3.0);
    const KinematicState shifted = plan.state_at(1.0, {10.0, 0.0, 0.0});
    EXPECT_DOUBLE_EQ(shifted.position_mm, 11.5);
}

TEST(SegmentPlan, ZeroDurationSegmentsAreDropped) {
    SegmentPlan plan;
    plan.push(0.0, 1.0, 0.0);
    plan.push(1.0, 1.0, 0.0);
    EXPECT_EQ(plan.count, 1u);
}

TEST(EffectiveAccel, TimeConstantIsFeedOverT) {
    // a = v / T: 6000 mm/min = 100 mm/s in 0.06 s.
    EXPECT_NEAR(effective_accel_mm_s2(time_constant(0.06), 100.0), 100.0 / 0.06, 1e-9);
    EXPECT_EQ(effective_accel_mm_s2(constant_accel(2500.0), 100.0), 2500.0);
    EXPECT_EQ(effective_accel_mm_s2(jerk_limited(2500.0, 1e5), 100.0), 2500.0);
}

TEST(AccelModelNames, Exact) {
    EXPECT_STREQ(to_string(AccelModel::time_constant), "time_constant");
    EXPECT_STREQ(to_string(AccelModel::constant_accel), "constant_accel");
    EXPECT_STREQ(to_string(AccelModel::jerk_limited), "jerk_limited");
}

struct MoveCase {
    const char* name;
    MotionLimits limits;
    double distance_mm;
    double feed_mm_min;
    double time_s;
    double peak_mm_min;
};

// clang-format off
const MoveCase kMoveCases[] = {
    // name                 limits                         d [mm]   F [mm/min]  t [s]  peak [mm/min]
    // Time constant 0.06 s: d >= v*T -> d/v + T; shorter -> 2*sqrt(d*T/v) at a = v/T.
    {"tc_cruise",           time_constant(0.06),           10.0,    6000.0,     0.16,  6000.0},
    {"tc_triangle",         time_constant(0.06),           1.5,     6000.0,     0.06,  3000.0},
    {"tc_just_full_50",     time_constant(0.06),           0.05,    50.0,       0.12,  50.0},
    {"tc_just_full_5000",   time_constant(0.06),           5.0,     5000.0,     0.12,  5000.0},
    {"tc_2mm_at_30",        time_constant(0.06),           2.0,     30.0,       4.06,  30.0},
    // Constant acceleration 2000 mm/s^2: v^2/a = 5 mm at 100 mm/s.
    {"ca_trapezoid",        constant_accel(2000.0),        20.0,    6000.0,     0.25,  6000.0},
    {"ca_triangle",         constant_accel(2000.0),        1.25,    6000.0,     0.05,  3000.0},
    // Jerk-limited a = 2000, j = 40000: a^2/j = 100 mm/s; ramp to 100 mm/s takes 0.1 s, 5 mm.
    {"jl_cruise",           jerk_limited(2000.0, 40000.0), 20.0,    6000.0,     0.30,  6000.0},
    {"jl_just_full",        jerk_limited(2000.0, 40000.0), 10.0,    6000.0,     0.20,  6000.0},
    // vp = 25: ramp 2*sqrt(25/40000) = 0.05 s over 0.625 mm (a never reached).
    {"jl_no_accel_limit",   jerk_limited(2000.0, 40000.0), 1.25,    6000.0,     0.10,  1500.0},
    // vp = 150: ramp 150/2000 + 0.05 = 0.125 s over 9.375 mm (a reached, v not).
    {"jl_accel_limit_only", jerk_limited(2000.0, 40000.0), 18.75,   12000.0,    0.25,  9000.0},
    // 200 mm/s: ramp 0.15 s over 15 mm; 70 mm cruise 0.35 s.
    {"jl_long",             jerk_limited(2000.0, 40000.0), 100.0,   12000.0,    0.65,  12000.0},
};
// clang-format on

class MoveTimeCase : public testing::TestWithParam<MoveCase> {};

TEST_P(MoveTimeCase, MatchesHandComputed) {
    const MoveCase& c = GetParam();
    const double v = mm_min_to_mm_s(c.feed_mm_min);
    EXPECT_NEAR(move_time_s(c.limits, c.distance_mm, v), c.time_s, rel_tol(c.time_s));
    EXPECT_NEAR(mm_s_to_mm_min(move_peak_speed_mm_s(c.limits, c.distance_mm, v)), c.peak_mm_min,
                rel_tol(c.peak_mm_min));
}

TEST_P(MoveTimeCase, PlanCoversTheDistanceInTheMoveTime) {
    const MoveCase& c = GetParam();
    const double v = mm_min_to_mm_s(c.feed_mm_min);
    const SegmentPlan plan = plan_move(c.limits, c.distance_mm, v);
    EXPECT_NEAR(plan.duration_s(), c.time_s, rel_tol(c.time_s));
    const KinematicState end = plan.end_state();
    EXPECT_NEAR(end.position_mm, c.distance_mm, rel_tol(c.distance_mm, 1e-10));
    EXPECT_NEAR(end.speed_mm_s, 0.0, 1e-9 * v);
    EXPECT_NEAR(max_speed_in(plan), mm_min_to_mm_s(c.peak_mm_min), 1e-9 * v);
}

INSTANTIATE_TEST_SUITE_P(HandComputed, MoveTimeCase, testing::ValuesIn(kMoveCases), CaseName());

struct ReachCase {
    const char* name;
    MotionLimits limits;
    double feed_mm_min;
    double time_s;
    double distance_mm;
};

// clang-format off
const ReachCase kReachCases[] = {
    // name            limits                         F [mm/min]  t [s]   d [mm]
    // v T / 2 with T = 0.06 s: 50 mm/min needs 0.025 mm, 5000 mm/min needs 2.5 mm.
    {"tc_50",          time_constant(0.06),           50.0,       0.06,   0.025},
    {"tc_5000",        time_constant(0.06),           5000.0,     0.06,   2.5},
    {"ca_6000",        constant_accel(2000.0),        6000.0,     0.05,   2.5},
    {"jl_6000",        jerk_limited(2000.0, 40000.0), 6000.0,     0.10,   5.0},
    {"jl_1500",        jerk_limited(2000.0, 40000.0), 1500.0,     0.05,   0.625},
    {"jl_12000",       jerk_limited(2000.0, 40000.0), 12000.0,    0.15,   15.0},
};
// clang-format on

class ReachCaseTest : public testing::TestWithParam<ReachCase> {};

TEST_P(ReachCaseTest, TimeAndDistanceToReachTheFeed) {
    const ReachCase& c = GetParam();
    const double v = mm_min_to_mm_s(c.feed_mm_min);
    EXPECT_NEAR(reach_time_s(c.limits, v), c.time_s, rel_tol(c.time_s));
    EXPECT_NEAR(reach_distance_mm(c.limits, v), c.distance_mm, rel_tol(c.distance_mm));
    const SegmentPlan plan = plan_accelerate(c.limits, v, 0.0);
    EXPECT_NEAR(plan.duration_s(), c.time_s, rel_tol(c.time_s));
    const KinematicState end = plan.end_state();
    EXPECT_NEAR(end.position_mm, c.distance_mm, rel_tol(c.distance_mm, 1e-10));
    EXPECT_NEAR(end.speed_mm_s, v, rel_tol(v, 1e-10));
}

TEST_P(ReachCaseTest, BrakingFromTheFeedMirrorsTheRamp) {
    // "Braking from v takes T and v*T/2" (time constant), likewise for the others.
    const ReachCase& c = GetParam();
    const double v = mm_min_to_mm_s(c.feed_mm_min);
    EXPECT_NEAR(stop_time_s(c.limits, v, v), c.time_s, rel_tol(c.time_s));
    EXPECT_NEAR(stop_distance_mm(c.limits, v, v), c.distance_mm, rel_tol(c.distance_mm));
}

INSTANTIATE_TEST_SUITE_P(HandComputed, ReachCaseTest, testing::ValuesIn(kReachCases), CaseName());

TEST(StopTime, TimeConstantBrakesAtTheProgrammedFeedsDeceleration) {
    // Programmed 3000 mm/min (a = 50/0.06), braking from 25 mm/s: 0.03 s over 0.375 mm.
    const MotionLimits limits = time_constant(0.06);
    EXPECT_NEAR(stop_time_s(limits, 50.0, 25.0), 0.03, rel_tol(0.03));
    EXPECT_NEAR(stop_distance_mm(limits, 50.0, 25.0), 0.375, rel_tol(0.375));
    EXPECT_EQ(stop_time_s(limits, 50.0, 0.0), 0.0);
    EXPECT_EQ(stop_distance_mm(limits, 50.0, 0.0), 0.0);
}

struct SpeedAfterCase {
    const char* name;
    MotionLimits limits;
    double feed_mm_min;
    double distance_mm;
    double speed_mm_s;
};

// clang-format off
const SpeedAfterCase kSpeedAfterCases[] = {
    // name               limits                         F [mm/min]  d [mm]      v [mm/s]
    // Time constant, 6000 mm/min: a = 100/0.06, sqrt(2 a d) = 50 at 0.75 mm; full at 3 mm.
    {"tc_quarter",        time_constant(0.06),           6000.0,     0.75,       50.0},
    {"tc_at_reach",       time_constant(0.06),           6000.0,     3.0,        100.0},
    {"tc_beyond",         time_constant(0.06),           6000.0,     10.0,       100.0},
    {"tc_zero",           time_constant(0.06),           6000.0,     0.0,        0.0},
    {"ca_quarter",        constant_accel(2000.0),        6000.0,     0.625,      50.0},
    // Jerk-limited: end of the jerk-up segment, t = 0.05 s: v = j t^2/2 = 50, x = j t^3/6.
    {"jl_end_of_jerk_up", jerk_limited(2000.0, 40000.0), 6000.0,     5.0 / 6.0,  50.0},
    {"jl_beyond",         jerk_limited(2000.0, 40000.0), 6000.0,     7.0,        100.0},
};
// clang-format on

class SpeedAfterCaseTest : public testing::TestWithParam<SpeedAfterCase> {};

TEST_P(SpeedAfterCaseTest, MatchesHandComputed) {
    const SpeedAfterCase& c = GetParam();
    const double v = mm_min_to_mm_s(c.feed_mm_min);
    EXPECT_NEAR(speed_after_mm_s(c.limits, v, c.distance_mm), c.speed_mm_s,
                1e-9 * c.speed_mm_s + 1e-12);
}

INSTANTIATE_TEST_SUITE_P(HandComputed, SpeedAfterCaseTest, testing::ValuesIn(kSpeedAfterCases),
                         CaseName());

TEST(MoveTime, ZeroDistanceTakesNoTime) {
    for (const MotionLimits& limits :
         {time_constant(0.06), constant_accel(2000.0), jerk_limited(2000.0, 40000.0)}) {
        EXPECT_EQ(move_time_s(limits, 0.0, 100.0), 0.0);
        EXPECT_EQ(plan_move(limits, 0.0, 100.0).duration_s(), 0.0);
    }
}

TEST(TimeAtDistance, InvertsAConstantAccelerationPlan) {
    // a = 2000 from rest: x = 1000 t^2, so 0.25 mm at t = 1/sqrt(4000).
    const SegmentPlan plan = plan_accelerate(constant_accel(2000.0), 100.0, 1.0);
    EXPECT_NEAR(time_at_distance_s(plan, 0.25), 1.0 / std::sqrt(4000.0), 1e-15);
    // In the cruise: 2.5 mm ramp in 0.05 s, then 100 mm/s.
    EXPECT_NEAR(time_at_distance_s(plan, 12.5), 0.15, 1e-14);
    EXPECT_EQ(time_at_distance_s(plan, 0.0), 0.0);
    // Never reached: the plan's duration.
    EXPECT_NEAR(time_at_distance_s(plan, 1000.0), plan.duration_s(), 1e-15);
}

// ---------------------------------------------------------------------------
// Fixed-seed randomized properties (ruckig test_target.cpp style).

constexpr int kRandomCases = 20000;

class RandomMoves {
  public:
    double log_uniform(double lo, double hi) {
        std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
        return std::exp(u(rng_));
    }
    MotionLimits limits(AccelModel model) {
        MotionLimits limits;
        limits.model = model;
        limits.time_constant_s = log_uniform(0.005, 0.5);
        limits.max_accel_mm_s2 = log_uniform(50.0, 30000.0);
        limits.max_jerk_mm_s3 = log_uniform(500.0, 5e6);
        return limits;
    }
    double feed_mm_s() { return mm_min_to_mm_s(log_uniform(1.0, 60000.0)); }
    double distance_mm() { return log_uniform(1e-5, 2000.0); }

  private:
    std::mt19937_64 rng_{42};
};

class MotionProperty : public testing::TestWithParam<AccelModel> {};

TEST_P(MotionProperty, NeverFasterThanDistanceOverFeed) {
    RandomMoves random;
    for (int i = 0; i < kRandomCases; ++i) {
        const MotionLimits limits = random.limits(GetParam());
        const double v = random.feed_mm_s();
        const double d = random.distance_mm();
        ASSERT_GE(move_time_s(limits, d, v), d / v) << "case " << i << " d=" << d << " v=" << v;
        ASSERT_LE(move_peak_speed_mm_s(limits, d, v), v * (1.0 + 1e-15)) << "case " << i;
    }
}

TEST_P(MotionProperty, PlanMoveMatchesMoveTimeAndEndsAtRestAtTheDistance) {
    RandomMoves random;
    for (int i = 0; i < kRandomCases; ++i) {
        const MotionLimits limits = random.limits(GetParam());
        const double v = random.feed_mm_s();
        const double d = random.distance_mm();
        const double t = move_time_s(limits, d, v);
        const SegmentPlan plan = plan_move(limits, d, v);
        ASSERT_NEAR(plan.duration_s(), t, rel_tol(t)) << "case " << i << " d=" << d << " v=" << v;
        const KinematicState end = plan.end_state();
        ASSERT_NEAR(end.position_mm, d, rel_tol(d, 1e-9)) << "case " << i;
        const double vp = move_peak_speed_mm_s(limits, d, v);
        ASSERT_NEAR(end.speed_mm_s, 0.0, 1e-9 * vp) << "case " << i;
        ASSERT_NEAR(max_speed_in(plan), vp, 1e-9 * vp) << "case " << i;
    }
}

TEST_P(MotionProperty, FasterFeedIsNeverSlowerAndLongerMoveNeverQuicker) {
    RandomMoves random;
    for (int i = 0; i < kRandomCases; ++i) {
        const MotionLimits limits = random.limits(GetParam());
        const double v = random.feed_mm_s();
        const double d = random.distance_mm();
        const double t = move_time_s(limits, d, v);
        ASSERT_LE(move_time_s(limits, d, 1.5 * v), t * (1.0 + 1e-14)) << "case " << i;
        ASSERT_GE(move_time_s(limits, 1.5 * d, v), t) << "case " << i;
    }
}

TEST_P(MotionProperty, StopPlanMatchesStopTimeAndDistance) {
    RandomMoves random;
    for (int i = 0; i < kRandomCases; ++i) {
        const MotionLimits limits = random.limits(GetParam());
        const double v = random.feed_mm_s();
        // Braking from the feed or from a lower speed (a touch during acceleration).
        const double speed = (i % 2 == 0) ? v : v * (0.05 + 0.9 * (i % 17) / 17.0);
        const SegmentPlan plan = plan_stop(limits, v, speed);
        const double t = stop_time_s(limits, v, speed);
        const double d = stop_distance_mm(limits, v, speed);
        ASSERT_NEAR(plan.duration_s(), t, rel_tol(t)) << "case " << i;
        const KinematicState end = plan.end_state({0.0, speed, 0.0});
        ASSERT_NEAR(end.position_mm, d, rel_tol(d, 1e-10)) << "case " << i;
        ASSERT_NEAR(end.speed_mm_s, 0.0, 1e-9 * speed) << "case " << i;
        // Stopping from the feed is the acceleration ramp in reverse.
        if (speed == v) {
            ASSERT_NEAR(t, reach_time_s(limits, v), rel_tol(t)) << "case " << i;
            ASSERT_NEAR(d, reach_distance_mm(limits, v), rel_tol(d)) << "case " << i;
        }
    }
}

TEST_P(MotionProperty, AccelerationPlanReachesTheFeedAtTheReachDistance) {
    RandomMoves random;
    for (int i = 0; i < kRandomCases; ++i) {
        const MotionLimits limits = random.limits(GetParam());
        const double v = random.feed_mm_s();
        const double cruise_s = 0.01 * (i % 7);
        const SegmentPlan plan = plan_accelerate(limits, v, cruise_s);
        const double t_reach = reach_time_s(limits, v);
        const double d_reach = reach_distance_mm(limits, v);
        ASSERT_NEAR(plan.duration_s(), t_reach + cruise_s, rel_tol(t_reach + cruise_s))
            << "case " << i;
        const KinematicState end = plan.end_state();
        ASSERT_NEAR(end.speed_mm_s, v, rel_tol(v, 1e-10)) << "case " << i;
        ASSERT_NEAR(end.position_mm, d_reach + v * cruise_s, rel_tol(d_reach + v * cruise_s, 1e-10))
            << "case " << i;
    }
}

TEST_P(MotionProperty, SpeedAfterAgreesWithTheAccelerationPlan) {
    RandomMoves random;
    for (int i = 0; i < kRandomCases; ++i) {
        const MotionLimits limits = random.limits(GetParam());
        const double v = random.feed_mm_s();
        const double d_reach = reach_distance_mm(limits, v);
        const double d = d_reach * (0.001 + 1.5 * (i % 101) / 100.0);
        const double speed = speed_after_mm_s(limits, v, d);
        if (d >= d_reach) {
            ASSERT_EQ(speed, v) << "case " << i;
            continue;
        }
        const SegmentPlan plan = plan_accelerate(limits, v, 0.0);
        const double t = time_at_distance_s(plan, d);
        const KinematicState at = plan.state_at(t);
        ASSERT_NEAR(at.position_mm, d, rel_tol(d, 1e-9)) << "case " << i;
        ASSERT_NEAR(at.speed_mm_s, speed, rel_tol(speed, 1e-9)) << "case " << i;
        // Independently: sqrt(2 a d) or the reference S-curve ramp.
        const double expected =
            GetParam() == AccelModel::jerk_limited
                ? reference_jerk_speed_after(d, v, limits.max_accel_mm_s2, limits.max_jerk_mm_s3)
                : std::sqrt(2.0 * effective_accel_mm_s2(limits, v) * d);
        ASSERT_NEAR(speed, expected, rel_tol(expected, 1e-9)) << "case " << i;
    }
}

TEST_P(MotionProperty, TimeAtDistanceInvertsTheMovePlan) {
    RandomMoves random;
    for (int i = 0; i < kRandomCases; ++i) {
        const MotionLimits limits = random.limits(GetParam());
        const double v = random.feed_mm_s();
        const double total = random.distance_mm();
        const double d = total * (i % 97 + 1) / 98.0;
        const SegmentPlan plan = plan_move(limits, total, v);
        const double t = time_at_distance_s(plan, d);
        ASSERT_GE(t, 0.0);
        ASSERT_LE(t, plan.duration_s());
        ASSERT_NEAR(plan.state_at(t).position_mm, d, rel_tol(total, 1e-9)) << "case " << i;
    }
}

INSTANTIATE_TEST_SUITE_P(AllModels, MotionProperty,
                         testing::Values(AccelModel::time_constant, AccelModel::constant_accel,
                                         AccelModel::jerk_limited),
                         [](const testing::TestParamInfo<AccelModel>& model) {
                             return std::string(to_string(model.param));
                         });

TEST(MotionEquivalence, TimeConstantIsConstantAccelWithAccelFeedOverT) {
    RandomMoves random;
    for (int i = 0; i < kRandomCases; ++i) {
        const MotionLimits tc = random.limits(AccelModel::time_constant);
        const double v = random.feed_mm_s();
        const double d = random.distance_mm();
        const MotionLimits ca = constant_accel(v / tc.time_constant_s);
        const double speed = v * (i % 10 + 1) / 10.0;
        const double d_part = d * (i % 13) / 12.0;
        ASSERT_NEAR(move_time_s(tc, d, v), move_time_s(ca, d, v), rel_tol(move_time_s(ca, d, v)))
            << "case " << i;
        ASSERT_NEAR(move_peak_speed_mm_s(tc, d, v), move_peak_speed_mm_s(ca, d, v),
                    rel_tol(move_peak_speed_mm_s(ca, d, v)));
        ASSERT_NEAR(reach_time_s(tc, v), reach_time_s(ca, v), rel_tol(reach_time_s(ca, v)));
        ASSERT_NEAR(reach_distance_mm(tc, v), reach_distance_mm(ca, v),
                    rel_tol(reach_distance_mm(ca, v)));
        ASSERT_NEAR(stop_time_s(tc, v, speed), stop_time_s(ca, v, speed),
                    rel_tol(stop_time_s(ca, v, speed)));
        ASSERT_NEAR(stop_distance_mm(tc, v, speed), stop_distance_mm(ca, v, speed),
                    rel_tol(stop_distance_mm(ca, v, speed)));
        ASSERT_NEAR(speed_after_mm_s(tc, v, d_part), speed_after_mm_s(ca, v, d_part),
                    rel_tol(speed_after_mm_s(ca, v, d_part), 1e-12));
        // Time constant T: d >= v*T -> d/v + T, else 2*sqrt(d*T/v).
        const double T = tc.time_constant_s;
        const double expected = d >= v * T ? d / v + T : 2.0 * std::sqrt(d * T / v);
        ASSERT_NEAR(move_time_s(tc, d, v), expected, rel_tol(expected)) << "case " << i;
    }
}

TEST(JerkLimited, MoveTimeEqualsTheTimeOptimalReference) {
    RandomMoves random;
    int cruising = 0;
    int accel_limited = 0;
    int jerk_only = 0;
    for (int i = 0; i < kRandomCases; ++i) {
        const MotionLimits limits = random.limits(AccelModel::jerk_limited);
        const double a = limits.max_accel_mm_s2;
        const double j = limits.max_jerk_mm_s3;
        const double v = random.feed_mm_s();
        const double d = random.distance_mm();
        const RefMove ref = reference_jerk_move(d, v, a, j);
        if (ref.peak_speed_mm_s >= v) {
            ++cruising;
        } else if (ref.peak_speed_mm_s * j >= a * a) {
            ++accel_limited;
        } else {
            ++jerk_only;
        }
        ASSERT_NEAR(move_time_s(limits, d, v), ref.time_s, rel_tol(ref.time_s))
            << "case " << i << " d=" << d << " v=" << v << " a=" << a << " j=" << j;
        ASSERT_NEAR(move_peak_speed_mm_s(limits, d, v), ref.peak_speed_mm_s,
                    rel_tol(ref.peak_speed_mm_s, 1e-11))
            << "case " << i;
    }
    // Every branch of the profile was exercised, not just one.
    EXPECT_GT(cruising, 1000);
    EXPECT_GT(accel_limited, 1000);
    EXPECT_GT(jerk_only, 1000);
}

TEST(JerkLimited, NeverFasterThanConstantAccelAndTendsToItAsJerkGrows) {
    RandomMoves random;
    for (int i = 0; i < kRandomCases / 10; ++i) {
        const MotionLimits base = random.limits(AccelModel::jerk_limited);
        const double a = base.max_accel_mm_s2;
        const double v = random.feed_mm_s();
        const double d = random.distance_mm();
        const double t_ca = move_time_s(constant_accel(a), d, v);
        double previous_gap = 1e300;
        for (double j = 1e2; j <= 1e14; j *= 10.0) {
            const double t_j = move_time_s(jerk_limited(a, j), d, v);
            const double gap = t_j - t_ca;
            // 0 <= t_j - t_ca <= 4 a / j (2 a / j once a is reached).
            ASSERT_GE(gap, -rel_tol(t_ca)) << "case " << i << " j=" << j;
            ASSERT_LE(gap, 4.0 * a / j + rel_tol(t_ca)) << "case " << i << " j=" << j;
            ASSERT_LE(gap, previous_gap + rel_tol(t_ca)) << "case " << i << " j=" << j;
            previous_gap = gap;
        }
        EXPECT_NEAR(move_time_s(jerk_limited(a, 1e14), d, v), t_ca, 4.0 * a / 1e14 + rel_tol(t_ca));
    }
}

TEST(JerkLimited, StopWithResidualAccelerationEndsAtRestWithoutReversing) {
    RandomMoves random;
    for (int i = 0; i < kRandomCases / 4; ++i) {
        const MotionLimits limits = random.limits(AccelModel::jerk_limited);
        const double v = random.feed_mm_s();
        const double speed = v * (i % 9 + 1) / 10.0;
        const double a0 = limits.max_accel_mm_s2 * (i % 5) / 4.0;
        const SegmentPlan plan = plan_stop(limits, v, speed, a0);
        const KinematicState end = plan.end_state({0.0, speed, a0});
        ASSERT_NEAR(end.speed_mm_s, 0.0, 1e-9 * (speed + a0 * a0 / limits.max_jerk_mm_s3))
            << "case " << i;
        ASSERT_NEAR(end.accel_mm_s2, 0.0, 1e-9 * limits.max_accel_mm_s2) << "case " << i;
        // Within the limits and never moving backwards.
        const double dt = plan.duration_s() / 64.0;
        for (int k = 0; k <= 64; ++k) {
            const KinematicState s = plan.state_at(dt * k, {0.0, speed, a0});
            ASSERT_GE(s.speed_mm_s, -1e-9 * (speed + 1.0)) << "case " << i << " k=" << k;
            ASSERT_LE(std::abs(s.accel_mm_s2), limits.max_accel_mm_s2 * (1.0 + 1e-12));
        }
        if (a0 > 0.0) {
            // Still accelerating when braking starts: longer than from cruise.
            ASSERT_GT(plan.duration_s(), stop_time_s(limits, v, speed)) << "case " << i;
        }
    }
}

}  // namespace
}  // namespace probecycle
