// Controller dynamics after interpolation (core/cycle/dynamics.h, issue 11):
// the closed forms against responses derived by hand, the drains, the
// in-position check, a touch during a linear filter's ramp, the makers'
// published overtravel formulas, and the keys' validation.
#include "core/cycle/dynamics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "core/common/units.h"
#include "core/cycle/cycle.h"
#include "core/cycle/scenario.h"

namespace probecycle {
namespace {

constexpr double kTol = 1e-12;

AxisDynamics dynamics(FilterKind filter, double t1, double t2, double servo_s,
                      double in_position_mm = 0.01) {
    return {filter, t1, t2, servo_s, in_position_mm};
}

MotionLimits no_plan() {
    MotionLimits limits;
    limits.model = AccelModel::none;
    return limits;
}

// The feed commanded at once at t = 0 and held (an open approach).
AxisMotion step_motion(const AxisDynamics& d, double v) {
    AxisCommand command;
    command.append(plan_accelerate(no_plan(), v, 100.0), 100.0);
    return {AxisKernel(d), command};
}

// A rest-to-rest move of `distance` at `v` commanded at once.
AxisMotion move(const AxisDynamics& d, double distance, double v,
                const MotionLimits& limits = no_plan()) {
    AxisCommand command;
    const SegmentPlan plan = plan_move(limits, distance, v);
    command.append(plan, plan.duration_s());
    command.close();
    return {AxisKernel(d), command};
}

// --- The kernel ---

TEST(AxisKernel, MomentsAreTheLagsAndTheMovingAveragesOnes) {
    // Moving average W: mu_1 = W/2, mu_2 = W^2/3! = W^2/6; a lag T: T, T^2.
    const AxisKernel linear(dynamics(FilterKind::linear, 0.1, 0.0, 0.0));
    EXPECT_NEAR(linear.moment(1), 0.05, kTol);
    EXPECT_NEAR(linear.moment(2), 0.01 / 6.0, kTol);
    const AxisKernel exponential(dynamics(FilterKind::exponential, 0.05, 0.0, 0.0));
    EXPECT_NEAR(exponential.moment(1), 0.05, kTol);
    EXPECT_NEAR(exponential.moment(2), 0.0025, kTol);
    // Moments of a cascade convolve: mu_1 adds, mu_2 = T1^2 + T1 T2 + T2^2.
    const AxisKernel two_lags(dynamics(FilterKind::exponential, 0.03, 0.0, 0.05));
    EXPECT_NEAR(two_lags.moment(1), 0.08, kTol);
    EXPECT_NEAR(two_lags.moment(2), 0.0009 + 0.0015 + 0.0025, kTol);
    const AxisDynamics bell = dynamics(FilterKind::bell, 0.06, 0.02, 0.01);
    EXPECT_NEAR(AxisKernel(bell).moment(1), 0.04 + 0.01, kTol);
    EXPECT_NEAR(bell.lag_s(), 0.05, kTol);
    EXPECT_FALSE(AxisKernel(dynamics(FilterKind::none, 0.1, 0.1, 0.0)).active());
    EXPECT_FALSE(dynamics(FilterKind::none, 0.1, 0.1, 0.0).active());
}

// --- Step responses: the feed v commanded at once ---

TEST(AxisMotion, LinearFilterTurnsAStepIntoARampOverItsWindow) {
    const double v = 10.0;
    const double w = 0.1;
    const AxisMotion m = step_motion(dynamics(FilterKind::linear, w, 0.0, 0.0), v);
    // In the window: speed v t/W, position v t^2/(2W); after it v (t - W/2).
    EXPECT_NEAR(m.state(0.05).speed_mm_s, 5.0, 1e-9);
    EXPECT_NEAR(m.state(0.05).position_mm, 10.0 * 0.0025 / 0.2, 1e-9);
    EXPECT_NEAR(m.state(0.3).speed_mm_s, v, 1e-9);
    EXPECT_NEAR(m.state(0.3).position_mm, v * (0.3 - 0.05), 1e-9);
    EXPECT_EQ(m.state(0.0).position_mm, 0.0);
}

TEST(AxisMotion, ExponentialFilterAndServoLagApproachTheFeedExponentially) {
    const double v = 10.0;
    const double t = 0.1;
    for (const AxisDynamics& d : {dynamics(FilterKind::exponential, 0.05, 0.0, 0.0),
                                  dynamics(FilterKind::none, 0.0, 0.0, 0.05)}) {
        // speed v (1 - e^(-t/T)), position v (t - T (1 - e^(-t/T))).
        const AxisMotion m = step_motion(d, v);
        const double e = std::exp(-t / 0.05);
        EXPECT_NEAR(m.state(t).speed_mm_s, v * (1.0 - e), 1e-9);
        EXPECT_NEAR(m.state(t).position_mm, v * (t - 0.05 * (1.0 - e)), 1e-9);
    }
}

TEST(AxisMotion, TwoLagsByPartialFractionsAndAsADoublePole) {
    const double v = 10.0;
    const double t = 0.07;
    {
        // T1 = 0.03 (filter), T2 = 0.05 (servo): speed v (1 - (T1 e1 - T2 e2)/(T1 - T2)),
        // position v (t - (T1 + T2) + (T1^2 e1 - T2^2 e2)/(T1 - T2)).
        const double t1 = 0.03;
        const double t2 = 0.05;
        const AxisMotion m = step_motion(dynamics(FilterKind::exponential, t1, 0.0, t2), v);
        const double e1 = std::exp(-t / t1);
        const double e2 = std::exp(-t / t2);
        EXPECT_NEAR(m.state(t).speed_mm_s, v * (1.0 - (t1 * e1 - t2 * e2) / (t1 - t2)), 1e-9);
        EXPECT_NEAR(m.state(t).position_mm,
                    v * (t - (t1 + t2) + (t1 * t1 * e1 - t2 * t2 * e2) / (t1 - t2)), 1e-9);
    }
    {
        // T1 = T2 = T: speed v (1 - (1 + t/T) e), position v (t - 2T + (2T + t) e).
        const double tc = 0.04;
        const AxisMotion m = step_motion(dynamics(FilterKind::exponential, tc, 0.0, tc), v);
        const double e = std::exp(-t / tc);
        EXPECT_NEAR(m.state(t).speed_mm_s, v * (1.0 - (1.0 + t / tc) * e), 1e-9);
        EXPECT_NEAR(m.state(t).position_mm, v * (t - 2.0 * tc + (2.0 * tc + t) * e), 1e-9);
    }
}

TEST(AxisMotion, BellFilterMakesAnSShapedRamp) {
    // Two moving averages W1 = 0.06, W2 = 0.02 of a step: speed
    // v t^2/(2 W1 W2) to W2, v (t - W2/2)/W1 to W1, v (1 - (W1+W2-t)^2/(2 W1 W2))
    // to W1 + W2; then v, and the position v (t - (W1 + W2)/2).
    const double v = 10.0;
    const double w1 = 0.06;
    const double w2 = 0.02;
    const AxisMotion m = step_motion(dynamics(FilterKind::bell, w1, w2, 0.0), v);
    EXPECT_NEAR(m.state(0.01).speed_mm_s, v * 0.0001 / (2.0 * w1 * w2), 1e-9);
    EXPECT_NEAR(m.state(0.04).speed_mm_s, v * (0.04 - 0.01) / w1, 1e-9);
    EXPECT_NEAR(m.state(0.07).speed_mm_s, v * (1.0 - 0.0001 / (2.0 * w1 * w2)), 1e-9);
    EXPECT_NEAR(m.state(0.5).speed_mm_s, v, 1e-9);
    EXPECT_NEAR(m.state(0.5).position_mm, v * (0.5 - 0.04), 1e-9);
}

TEST(AxisMotion, RampThroughALagMatchesItsAnalyticResponse) {
    // A time-constant plan accelerates at a = v/T; through a lag Tf the ramp
    // x = a t^2/2 becomes a (t^2/2 - Tf t + Tf^2 - Tf^2 e^(-t/Tf)).
    MotionLimits limits;
    limits.model = AccelModel::time_constant;
    limits.time_constant_s = 0.1;
    const double v = 10.0;
    const double a = v / 0.1;
    const double tf = 0.02;
    AxisCommand command;
    command.append(plan_accelerate(limits, v, 10.0), 10.0);
    const AxisMotion m(AxisKernel(dynamics(FilterKind::exponential, tf, 0.0, 0.0)), command);
    const double t = 0.05;
    const double e = std::exp(-t / tf);
    EXPECT_NEAR(m.state(t).position_mm, a * (t * t / 2.0 - tf * t + tf * tf - tf * tf * e), 1e-9);
    EXPECT_NEAR(m.state(t).speed_mm_s, a * (t - tf + tf * e), 1e-9);
}

// --- Drains and the in-position check ---

TEST(AxisMotion, AfterTheCommandStopsTheAxisDrainsItsLag) {
    // 10 mm at 10 mm/s commanded at once: the command ends at 1 s; the axis is
    // then v L behind it and comes to rest at 10 mm.
    const double v = 10.0;
    struct Case {
        AxisDynamics d;
        double drain_mm;
    };
    for (const Case& c : {Case{dynamics(FilterKind::linear, 0.1, 0.0, 0.0), v * 0.05},
                          Case{dynamics(FilterKind::exponential, 0.02, 0.0, 0.0), v * 0.02},
                          Case{dynamics(FilterKind::none, 0.0, 0.0, 0.02), v * 0.02},
                          Case{dynamics(FilterKind::bell, 0.06, 0.02, 0.0), v * 0.04}}) {
        SCOPED_TRACE(to_string(c.d.filter));
        const AxisMotion m = move(c.d, 10.0, v);
        EXPECT_NEAR(m.command().end_s(), 1.0, kTol);
        EXPECT_NEAR(m.state(1.0).position_mm, 10.0 - c.drain_mm, 1e-9);
        EXPECT_NEAR(m.state(3.0).position_mm, 10.0, 1e-9);
        EXPECT_NEAR(m.state(3.0).speed_mm_s, 0.0, 1e-9);
    }
}

TEST(AxisMotion, InPositionTimeEndsTheTails) {
    const double v = 10.0;
    const double w = 0.01;
    // Linear W: the error left at t is v (t_e + W - t)^2 / (2W).
    const AxisMotion linear = move(dynamics(FilterKind::linear, 0.1, 0.0, 0.0, w), 10.0, v);
    EXPECT_NEAR(linear.in_position_time(), 1.0 + 0.1 - std::sqrt(2.0 * 0.1 * w / v), 1e-9);
    // Exponential T: v T e^(-(t - t_e)/T) = w.
    const AxisMotion lag = move(dynamics(FilterKind::exponential, 0.05, 0.0, 0.0, w), 10.0, v);
    EXPECT_NEAR(lag.in_position_time(), 1.0 + 0.05 * std::log(v * 0.05 / w), 1e-9);
    // A width larger than the lag: in position when the command ends.
    const AxisMotion wide = move(dynamics(FilterKind::none, 0.0, 0.0, 0.01, 0.5), 10.0, v);
    EXPECT_NEAR(wide.in_position_time(), 1.0, kTol);
}

// --- Through evaluate() ---

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

double phase_time(const CycleResult& r, Phase phase) {
    return r.phase_time(phase);
}

TEST(DynamicsCycle, TouchDuringALinearFiltersRampGoesOnThroughTheWindow) {
    // Linear W = 0.1 s, 600 mm/min (10 mm/s), 0.1 mm from the surface, no
    // pretravel, 2 ms interface delay and nothing else. The axis follows
    // x = v t^2/(2W): it touches at sqrt(2 W D / v); the control reacts 2 ms
    // later and the command stops at v t_r. The axis goes on at v t_r / W to
    // t = W, then slows over a window; the error left is v (t_r+W-t)^2/(2W).
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
    const double t_touch = std::sqrt(2.0 * w * 0.1 / v);
    const double t_react = t_touch + 0.002;
    EXPECT_NEAR(phase_time(r, Phase::approach), t_touch, 1e-9);
    EXPECT_NEAR(r.first_touch().touch_speed_mm_s, v * t_touch / w, 1e-9);
    EXPECT_NEAR(r.first_touch().react_speed_mm_s, v * t_react / w, 1e-9);
    EXPECT_NEAR(r.overtravel_mm(), v * t_react - 0.1, 1e-9);
    const double settle = t_react + w - std::sqrt(2.0 * w * 0.01 / v);
    EXPECT_NEAR(phase_time(r, Phase::deceleration), settle - t_react, 1e-9);
    // Between the reaction and the end of the first window: the speed it had.
    const CycleState mid = r.state_at(0.07);
    EXPECT_NEAR(mid.velocity_mm_s, v * t_react / w, 1e-9);
    EXPECT_EQ(r.phases()[mid.phase_index].phase, Phase::deceleration);
    // The touch is while accelerating: reported, with the error against full feed.
    bool warned = false;
    for (const Warning& wn : r.warnings()) {
        warned = warned || wn.code == WarningCode::touch_while_accelerating;
    }
    EXPECT_TRUE(warned);
}

// Mitsubishi M700V, G31 without acc/dec: delta0 = F/60 (Tp + t1) +- F/60 t2
// (Tp position-loop time constant, t1 response delay, t2 = 1 ms scan; worked
// example Tp = 30 ms, t1 = 5 ms). The model's worst case (a full scan) is the
// upper end, its scan range the spread.
TEST(PublishedChecks, MitsubishiG31WithoutAccDec) {
    for (const double feed : {250.0, 500.0, 1000.0, 2000.0, 4000.0}) {
        SCOPED_TRACE(feed);
        Scenario s = single_touch(feed, 100.0);  // 100 mm: the lag's tail has died out
        s.machine.servo_time_constant_s = 0.030;
        s.probe.interface_delay_s = 0.002;
        s.machine.controller_latency_s = 0.003;  // t1 = 5 ms with the interface
        s.machine.scan_period_s = 0.001;
        ASSERT_TRUE(validate(s).empty());
        const CycleResult r = evaluate(s);
        const double v = feed / 60.0;
        EXPECT_NEAR(r.overtravel_mm() - s.probe.pretravel_mm, v * (0.030 + 0.005 + 0.001), 1e-9);
        EXPECT_NEAR(r.scan_range_mm(), v * 0.001, 1e-12);
    }
}

// Fanuc Power Mate i: Qmax = Fm/60 (20 + Tc + Ts) / 1000 mm, Tc the
// exponential cutting-feed acc/dec time constant after interpolation, Ts the
// servo time constant (ms), 20 ms the skip detection delay.
TEST(PublishedChecks, FanucQmaxWithExponentialAccDecAndServo) {
    for (const double ts : {0.033, 0.032}) {  // the second: Tc = Ts, a double pole
        for (const double feed : {250.0, 500.0, 1000.0, 2000.0, 4000.0}) {
            SCOPED_TRACE(std::to_string(feed) + " mm/min, Ts " + std::to_string(ts));
            Scenario s = single_touch(feed, 200.0);
            s.machine.filter = FilterKind::exponential;
            s.machine.filter_time_s = 0.032;
            s.machine.servo_time_constant_s = ts;
            s.probe.interface_delay_s = 0.002;
            s.machine.controller_latency_s = 0.014;
            s.machine.scan_period_s = 0.004;  // 20 ms in all
            ASSERT_TRUE(validate(s).empty());
            const double qmax = feed / 60.0 * (20.0 + 32.0 + ts * 1000.0) / 1000.0;
            EXPECT_NEAR(evaluate(s).overtravel_mm() - s.probe.pretravel_mm, qmax, 1e-9);
        }
    }
}

TEST(DynamicsCycle, TheKeysReadFromAFileGiveTheSameQmax) {
    // As the Fanuc-type preset file writes them.
    Scenario s = single_touch(2000.0, 200.0);
    s = merge_json(s, R"({"machine": {"accel_model": "none", "filter": "exponential",
        "filter_time_s": 0.032, "servo_time_constant_s": 0.033, "scan_period_s": 0.004,
        "controller_latency_s": 0.014}})");
    EXPECT_NEAR(evaluate(s).overtravel_mm() - s.probe.pretravel_mm,
                2000.0 / 60.0 * (20.0 + 32.0 + 33.0) / 1000.0, 1e-9);
}

TEST(DynamicsCycle, DefaultsAndUnusedKeysChangeNothing) {
    Scenario defaults;
    EXPECT_EQ(defaults.machine.filter, FilterKind::none);
    EXPECT_EQ(defaults.machine.servo_time_constant_s, 0.0);
    Scenario other = defaults;
    other.machine.filter_time_s = 0.5;
    other.machine.filter2_time_s = 0.2;
    other.machine.in_position_mm = 0.5;
    const CycleResult a = evaluate(defaults);
    const CycleResult b = evaluate(other);
    EXPECT_EQ(a.total(), b.total());
    EXPECT_EQ(a.overtravel_mm(), b.overtravel_mm());
    EXPECT_TRUE(a.motions().empty());
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
    const CycleResult r = evaluate(s);
    EXPECT_TRUE(r.valid());
    double sum = 0.0;
    for (const PhaseRecord& p : r.phases()) sum += p.time_s;
    EXPECT_NEAR(sum, r.total(), 1e-9);
    // The chart's position is continuous but for the in-position residue.
    double last = r.state_at(0.0).position_mm;
    for (double t = 0.001; t < r.total(); t += 0.001) {
        const double x = r.state_at(t).position_mm;
        EXPECT_LE(std::abs(x - last), 0.001 * 200.0 + s.machine.in_position_mm) << t;
        last = x;
    }
}

// --- Properties (fixed seed) ---

TEST(DynamicsProperties, DrainOnlyAddsAndOvertravelRisesWithFeedAtCruise) {
    std::mt19937_64 rng(112501);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int checked = 0;
    for (int i = 0; i < 300; ++i) {
        Scenario s = single_touch(100.0 + 3900.0 * unit(rng), 1000.0);
        s.machine.accel_model = static_cast<AccelModel>(i % 4);
        s.machine.filter = static_cast<FilterKind>((i / 4) % 4);
        s.machine.filter_time_s = 0.005 + 0.05 * unit(rng);
        s.machine.filter2_time_s = 0.005 + 0.05 * unit(rng);
        s.machine.servo_time_constant_s = 0.04 * unit(rng);
        s.probe.overtravel_limit_mm = 100.0;
        if (!validate(s).empty()) continue;
        ++checked;
        Scenario ideal = s;
        ideal.machine.filter = FilterKind::none;
        ideal.machine.servo_time_constant_s = 0.0;
        const CycleResult r = evaluate(s);
        const double v = mm_min_to_mm_s(s.cycle.probe_feed_mm_min);
        // At cruise the lag adds exactly v L to the ideal axis's overtravel.
        EXPECT_NEAR(r.overtravel_mm(),
                    evaluate(ideal).overtravel_mm() + v * s.axis_dynamics().lag_s(), 1e-8)
            << scenario_to_json(s);
        Scenario faster = s;
        faster.cycle.probe_feed_mm_min *= 1.1;
        EXPECT_GE(evaluate(faster).overtravel_mm(), r.overtravel_mm()) << scenario_to_json(s);
        // A filter never shortens a move.
        EXPECT_GE(block_time_s(s, 7.0, v), block_time_s(ideal, 7.0, v) - 1e-12);
    }
    EXPECT_GT(checked, 250);
}

// --- The keys ---

TEST(DynamicsKeys, BadValuesNameTheKeyAndTheRange) {
    Scenario s;
    const auto message = [&](const char* assignment) {
        // --set changes the value; validation (as every command does) refuses it.
        Scenario t = s;
        try {
            apply_setting(t, assignment);
            validate_or_throw(t);
            s = t;
        } catch (const ScenarioError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    const std::string word = message("machine.filter=gaussian");
    EXPECT_NE(word.find("machine.filter"), std::string::npos) << word;
    EXPECT_NE(word.find("none, linear, exponential, bell"), std::string::npos) << word;
    const std::string servo = message("machine.servo_time_constant_s=-0.01");
    EXPECT_NE(servo.find("machine.servo_time_constant_s"), std::string::npos) << servo;
    EXPECT_NE(servo.find("from 0 to 0.5 s"), std::string::npos) << servo;
    const std::string width = message("machine.in_position_mm=0");
    EXPECT_NE(width.find("from 0.0001 to 1 mm"), std::string::npos) << width;
    const std::string time = message("machine.filter_time_s=5");
    EXPECT_NE(time.find("from 0.0005 to 1 s"), std::string::npos) << time;
    EXPECT_EQ(message("machine.accel_model=none"), "accepted");
    EXPECT_EQ(s.machine.accel_model, AccelModel::none);

    Scenario nan = Scenario{};
    nan.machine.filter2_time_s = std::nan("");
    const std::vector<FieldError> errors = validate(nan);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_NE(errors[0].message().find("machine.filter2_time_s"), std::string::npos);
}

}  // namespace
}  // namespace probecycle
