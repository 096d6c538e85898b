#include "core/lab/compensation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/units.h"

namespace probecycle {
namespace {

struct CompensationCaseName {
    template <typename T>
    std::string operator()(const testing::TestParamInfo<T>& case_info) const {
        return case_info.param.name;
    }
};

constexpr std::uint64_t kMax32 = 0xFFFFFFFFu;
constexpr std::uint64_t kMax64 = std::numeric_limits<std::uint64_t>::max();

// ---------------------------------------------------------------------------
// Timestamp interpolation

TEST(TimestampInterpolation, LinearInsideTheCycle) {
    // Domain.md: P3 = P1 + (P2 - P1) * dt / T_ipo.
    EXPECT_DOUBLE_EQ(interpolate_trigger_mm(10.0, 10.04, 0.0, 0.002), 10.0);
    EXPECT_DOUBLE_EQ(interpolate_trigger_mm(10.0, 10.04, 0.002, 0.002), 10.04);
    EXPECT_NEAR(interpolate_trigger_mm(10.0, 10.04, 0.0005, 0.002), 10.01, 1e-12);
    EXPECT_NEAR(interpolate_trigger_mm(-3.0, -3.1, 0.00075, 0.001), -3.075, 1e-12);
}

// ---------------------------------------------------------------------------
// Counter roll-over

struct IncrementCase {
    const char* name;
    int bits;
    std::uint64_t previous;
    std::uint64_t current;
    std::int64_t expected;
};
// Test names in ctest show the case name, not the bytes.
void PrintTo(const IncrementCase& c, std::ostream* os) {
    *os << c.name;
}

class CounterIncrement : public testing::TestWithParam<IncrementCase> {};

TEST_P(CounterIncrement, ShortestWayRound) {
    const auto& c = GetParam();
    EXPECT_EQ(counter_increment(c.previous, c.current, c.bits), c.expected);
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(
    Counters, CounterIncrement,
    testing::Values(
        IncrementCase{"Zero",              32, 0,           0,          0},
        IncrementCase{"Forward",           32, 100,         150,        50},
        IncrementCase{"Backward",          32, 150,         100,        -50},
        IncrementCase{"WrapUp32",          32, kMax32 - 2,  5,          8},
        IncrementCase{"WrapDown32",        32, 3,           kMax32 - 1, -5},
        IncrementCase{"LimitToZero32",     32, kMax32,      0,          1},
        IncrementCase{"ZeroToLimit32",     32, 0,           kMax32,     -1},
        IncrementCase{"SignBit32",         32, 0x7FFFFFFF,  0x80000000, 1},
        IncrementCase{"LargestForward32",  32, 0,           0x7FFFFFFF, 0x7FFFFFFF},
        IncrementCase{"WrapUp16",          16, 65530,       4,          10},
        IncrementCase{"WrapDown16",        16, 4,           65530,      -10},
        IncrementCase{"HighBitsIgnored16", 16, 0x10000 + 5, 7,          2},
        IncrementCase{"WrapUp24",          24, 0xFFFFFF,    0x000010,   17},
        IncrementCase{"WrapUp64",          64, kMax64 - 1,  3,          5},
        IncrementCase{"WrapDown64",        64, 3,           kMax64 - 1, -5}),
    CompensationCaseName{});
// clang-format on

TEST(IncrementRing, KeepsTheLastFiftyAcrossTheRollOver) {
    IncrementRing ring(16);
    EXPECT_EQ(ring.size(), 0u);
    std::uint64_t raw = 65536 - 100;  // wraps after 15 steps of 7
    ring.push_counter(raw);
    EXPECT_EQ(ring.size(), 0u);  // the first read is only the reference
    for (int i = 1; i <= 60; ++i) {
        raw = (raw + static_cast<std::uint64_t>(i)) & 0xFFFF;  // increments 1, 2, ..., 60
        ring.push_counter(raw);
    }
    EXPECT_EQ(ring.size(), IncrementRing::kCapacity);
    EXPECT_EQ(ring.increment(0), 60);
    EXPECT_EQ(ring.increment(49), 11);
    EXPECT_EQ(ring.sum_latest(0), 0);
    EXPECT_EQ(ring.sum_latest(3), 60 + 59 + 58);
    EXPECT_EQ(ring.sum_latest(50), (11 + 60) * 50 / 2);
    EXPECT_THROW(ring.sum_latest(51), std::out_of_range);
}

TEST(IncrementRing, NegativeIncrementsThroughZero) {
    IncrementRing ring(32);
    ring.push_counter(2);
    ring.push_counter(kMax32 - 2);   // -5 through zero
    ring.push_counter(kMax32 - 10);  // -8
    EXPECT_EQ(ring.sum_latest(2), -13);
    EXPECT_DOUBLE_EQ(compensate_cycle_lag_mm(-0.0013, ring, 2, 10000.0), 0.0);
}

TEST(NaiveCorrection, SubtractsSpeedTimesDelayAlongTheTravel) {
    EXPECT_DOUBLE_EQ(compensate_naive_mm(10.5, 1, 50.0, 0.01), 10.0);
    EXPECT_DOUBLE_EQ(compensate_naive_mm(-10.5, -1, 50.0, 0.01), -10.0);
}

// ---------------------------------------------------------------------------
// Simulator

MotionLimits limits_of(AccelModel model) {
    MotionLimits limits;
    limits.model = model;
    limits.time_constant_s = 0.06;
    limits.max_accel_mm_s2 = 1500.0;
    limits.max_jerk_mm_s3 = 30000.0;
    return limits;
}

struct ConstantSpeedCase {
    const char* name;
    AccelModel model;
    double feed_mm_min;
    int direction;
    int lag_cycles;
    double phase;
    int counter_bits;
};
// Test names in ctest show the case name, not the bytes.
void PrintTo(const ConstantSpeedCase& c, std::ostream* os) {
    *os << c.name;
}

class SimulatedConstantSpeed : public testing::TestWithParam<ConstantSpeedCase> {};

TEST_P(SimulatedConstantSpeed, EveryMethodAsPredicted) {
    const auto& c = GetParam();
    CompensationSetup setup;
    setup.limits = limits_of(c.model);
    setup.feed_mm_min = c.feed_mm_min;
    setup.direction = c.direction;
    setup.lag_cycles = c.lag_cycles;
    setup.trigger_phase = c.phase;
    setup.counter_bits = c.counter_bits;
    ASSERT_TRUE(validate(setup).empty());
    const auto out = simulate_compensation(setup);

    const double v = mm_min_to_mm_s(c.feed_mm_min);
    const double period = setup.interpolation_period_s;
    const double quantum = 1.0 / setup.counts_per_mm;  // the encoder's resolution
    const double d = c.direction;
    EXPECT_NEAR(out.trigger_speed_mm_s, v, 1e-9);
    EXPECT_NEAR(out.recorded_speed_mm_s, v, 1e-9);
    // Recorded (lag + 1 - phase) cycles after the trigger.
    EXPECT_NEAR(out.result(CompensationMethod::uncompensated).error_mm,
                d * v * (c.lag_cycles + 1 - c.phase) * period, quantum);
    // The naive delay is the mean, (lag + 0.5) T: off by v T (0.5 - phase).
    EXPECT_NEAR(out.result(CompensationMethod::naive_v_tau).error_mm,
                d * v * period * (0.5 - c.phase), quantum);
    // The ring buffer takes the axis back to the end of the trigger's cycle, P2.
    EXPECT_NEAR(out.result(CompensationMethod::cycle_lag).error_mm,
                d * v * period * (1.0 - c.phase), quantum);
    EXPECT_DOUBLE_EQ(out.result(CompensationMethod::cycle_lag).position_mm, out.p2_mm);
    // Interpolating with the timestamp is exact at constant speed.
    EXPECT_NEAR(out.result(CompensationMethod::timestamp).error_mm, 0.0, quantum);
    // The default counter start makes the counter wrap once during the lag.
    EXPECT_EQ(out.counter_wraps, 1);
    ASSERT_EQ(out.trace.size(), IncrementRing::kCapacity + 1);
    EXPECT_EQ(out.trace.back().cycle, 1 + c.lag_cycles);
    EXPECT_NEAR(out.trace[static_cast<std::size_t>(out.trace.size() - 1 - c.lag_cycles - 1)].time_s,
                -setup.trigger_phase * period, 1e-12);
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(
    Models, SimulatedConstantSpeed,
    testing::Values(
        ConstantSpeedCase{"TimeConstant",      AccelModel::time_constant,  2000.0, 1,  8,  0.4,  32},
        ConstantSpeedCase{"TimeConstantMinus", AccelModel::time_constant,  2000.0, -1, 8,  0.4,  32},
        ConstantSpeedCase{"ConstantAccel",     AccelModel::constant_accel, 3000.0, 1,  10, 0.0,  32},
        ConstantSpeedCase{"JerkLimited",       AccelModel::jerk_limited,   1000.0, -1, 7,  0.9,  32},
        ConstantSpeedCase{"Counter16Bit",      AccelModel::time_constant,  5000.0, 1,  9,  0.25, 16},
        ConstantSpeedCase{"Counter64Bit",      AccelModel::time_constant,  500.0,  -1, 1,  0.75, 64},
        ConstantSpeedCase{"NoLag",             AccelModel::time_constant,  2000.0, 1,  0,  0.5,  32}),
    CompensationCaseName{});
// clang-format on

// The machine lags N = 10 cycles, the compensation subtracts N_c. At constant
// speed the cycle-lag result is the position at the end of cycle 1 + N - N_c:
// an error of v ((1 + N - N_c) T - dt).
TEST(SimulatedWrongLag, EachCycleTooFewLeavesVTMoreError) {
    CompensationSetup setup;
    setup.lag_cycles = 10;
    setup.trigger_phase = 0.4;
    const double v = 2000.0 / 60.0;
    const double period = setup.interpolation_period_s;
    const double quantum = 1.0 / setup.counts_per_mm;
    for (int compensated : {7, 8, 9, 10, 11}) {
        SCOPED_TRACE(compensated);
        setup.compensated_lag_cycles = compensated;
        ASSERT_TRUE(validate(setup).empty());
        const auto out = simulate_compensation(setup);
        EXPECT_NEAR(out.result(CompensationMethod::cycle_lag).error_mm,
                    v * ((1 + 10 - compensated) * period - 0.4 * period), quantum);
        // The other methods do not use it.
        EXPECT_NEAR(out.result(CompensationMethod::timestamp).error_mm, 0.0, quantum);
    }
    // 7 to 9 cycles on a 10-cycle machine: 0.12 to 0.053 mm at 2000 mm/min.
    setup.compensated_lag_cycles.reset();
    const std::vector<LagRow> rows = sweep_compensated_lag(setup);
    ASSERT_EQ(rows.size(), IncrementRing::kCapacity);
    // Up to N_c = 11: further back the simulated axis was still accelerating
    // (it triggers one cycle into its cruise).
    for (const LagRow& row : rows) {
        if (row.compensated_lag_cycles > 11) break;
        EXPECT_NEAR(row.error_mm, v * ((11 - row.compensated_lag_cycles) * period - 0.4 * period),
                    quantum)
            << row.compensated_lag_cycles;
    }
    // Default: the true lag.
    EXPECT_NEAR(rows[10].error_mm,
                simulate_compensation(setup).result(CompensationMethod::cycle_lag).error_mm, 1e-15);
    // Outside the ring: refused, naming the option.
    setup.compensated_lag_cycles = 50;
    const auto errors = validate(setup);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].key, "compensated-lag-cycles");
}

TEST(SimulatedRollOver, SameResultWithAndWithoutTheWrap) {
    CompensationSetup setup;
    setup.lag_cycles = 9;
    const auto wrapped = simulate_compensation(setup);
    ASSERT_EQ(wrapped.counter_wraps, 1);
    setup.counter_at_zero = std::uint64_t{1} << 31;  // far from both ends
    const auto plain = simulate_compensation(setup);
    EXPECT_EQ(plain.counter_wraps, 0);
    for (std::size_t m = 0; m < kCompensationMethodCount; ++m) {
        EXPECT_DOUBLE_EQ(wrapped.methods[m].position_mm, plain.methods[m].position_mm);
    }
    // Start exactly at the limit: the first increment crosses it.
    setup.counter_at_zero = kMax32;
    EXPECT_DOUBLE_EQ(simulate_compensation(setup).result(CompensationMethod::cycle_lag).position_mm,
                     plain.result(CompensationMethod::cycle_lag).position_mm);
}

struct BrakingCase {
    const char* name;
    AccelModel model;
    double feed_mm_min;
    double fraction;
    int lag_cycles;
};
// Test names in ctest show the case name, not the bytes.
void PrintTo(const BrakingCase& c, std::ostream* os) {
    *os << c.name;
}

class SimulatedBraking : public testing::TestWithParam<BrakingCase> {};

TEST_P(SimulatedBraking, OnlyRealIncrementsAreRight) {
    // Domain.md, "Cycle-lag compensation": "Because real increments are used,
    // this also holds when the touch happens while decelerating, which a plain
    // v * tau correction gets wrong."
    const auto& c = GetParam();
    CompensationSetup setup;
    setup.limits = limits_of(c.model);
    setup.feed_mm_min = c.feed_mm_min;
    setup.touch = TouchMotion::braking;
    setup.braking_speed_fraction = c.fraction;
    setup.lag_cycles = c.lag_cycles;
    setup.trigger_phase = 0.3;
    ASSERT_TRUE(validate(setup).empty());
    const auto out = simulate_compensation(setup);

    const double v = mm_min_to_mm_s(c.feed_mm_min);
    const double period = setup.interpolation_period_s;
    const double quantum = 1.0 / setup.counts_per_mm;
    EXPECT_NEAR(out.trigger_speed_mm_s, c.fraction * v, 1e-6 * v);
    EXPECT_LT(out.recorded_speed_mm_s, out.trigger_speed_mm_s);
    // Cycle lag lands on P2: at most the travel of one cycle at the trigger speed.
    const double cycle_lag = out.result(CompensationMethod::cycle_lag).error_mm;
    EXPECT_GE(cycle_lag, -quantum);
    EXPECT_LE(cycle_lag, out.trigger_speed_mm_s * period + quantum);
    // The timestamp is off only by the curvature inside one cycle: a T^2 / 8.
    const double a_max = c.model == AccelModel::time_constant ? v / setup.limits.time_constant_s
                                                              : setup.limits.max_accel_mm_s2;
    EXPECT_LE(std::abs(out.result(CompensationMethod::timestamp).error_mm),
              a_max * period * period / 8.0 + quantum);
    // The naive correction assumes the full feed through the delay: it removes
    // too much, by far more than a cycle's travel.
    const double naive = out.result(CompensationMethod::naive_v_tau).error_mm;
    EXPECT_LT(naive, 0.0);
    EXPECT_GT(std::abs(naive), 5.0 * std::max(std::abs(cycle_lag), v * period * 0.1));
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(
    Models, SimulatedBraking,
    testing::Values(
        BrakingCase{"TimeConstantHalf",  AccelModel::time_constant,  2000.0, 0.5,  8},
        BrakingCase{"TimeConstantSlow",  AccelModel::time_constant,  3000.0, 0.2,  9},
        BrakingCase{"StopsBeforeRecord", AccelModel::time_constant,  2000.0, 0.05, 8},
        BrakingCase{"ConstantAccel",     AccelModel::constant_accel, 5000.0, 0.3,  8},
        BrakingCase{"JerkLimited",       AccelModel::jerk_limited,   5000.0, 0.4,  10}),
    CompensationCaseName{});
// clang-format on

TEST(SimulatedLag, PublishedOrderOfMagnitude) {
    // Domain.md: about 0.31 mm uncompensated fell to about 0.01 mm (under one
    // cycle) after compensating 7-9 cycles. 2000 mm/min, 1 ms cycle, 8 cycles:
    // 33 mm/s * 8.6 ms = 0.29 mm, then under 33 um.
    CompensationSetup setup;
    const auto out = simulate_compensation(setup);
    EXPECT_NEAR(out.result(CompensationMethod::uncompensated).error_mm, 0.287, 0.001);
    EXPECT_LT(std::abs(out.result(CompensationMethod::cycle_lag).error_mm), 0.034);
}

TEST(BrakingSweep, NaiveErrorGrowsAsTheTriggerSpeedFalls) {
    CompensationSetup setup;
    const std::vector<double> fractions{1.0, 0.8, 0.6, 0.4, 0.2, 0.1};
    const auto rows = sweep_braking(setup, fractions);
    ASSERT_EQ(rows.size(), fractions.size());
    const auto naive = static_cast<std::size_t>(CompensationMethod::naive_v_tau);
    const auto cycle_lag = static_cast<std::size_t>(CompensationMethod::cycle_lag);
    const double period = setup.interpolation_period_s;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        EXPECT_DOUBLE_EQ(rows[i].speed_fraction, fractions[i]);
        EXPECT_LE(std::abs(rows[i].error_mm[cycle_lag]),
                  rows[i].trigger_speed_mm_s * period + 1e-4);
        if (i > 0) {
            EXPECT_LT(rows[i].error_mm[naive], rows[i - 1].error_mm[naive]);
        }
    }
}

TEST(CompensationSetup, ValidationNamesTheField) {
    CompensationSetup setup;
    EXPECT_TRUE(validate(setup).empty());
    setup.lag_cycles = 50;
    setup.trigger_phase = 1.0;
    setup.counter_bits = 8;
    const auto errors = validate(setup);
    ASSERT_EQ(errors.size(), 3u);
    EXPECT_EQ(errors[0].key, "lag-cycles");
    EXPECT_EQ(render(errors[0].allowed), "a number in [0, 49]");
    EXPECT_EQ(errors[1].key, "trigger-phase");
    EXPECT_EQ(errors[2].key, "counter-bits");

    CompensationSetup fast;
    fast.counter_bits = 16;
    fast.feed_mm_min = 100000.0;
    fast.counts_per_mm = 1e5;  // 166 667 counts per cycle: more than half of 65536
    const auto cross = validate(fast);
    ASSERT_EQ(cross.size(), 1u);
    EXPECT_EQ(cross[0].key, "counter-bits");
}

// The inverse of the simulator's naive delay (N + 1/2) T, within the ring.
TEST(LagCyclesForDelay, WholeCyclesOfAConstantSpeedDelay) {
    EXPECT_EQ(lag_cycles_for_delay(0.0085, 0.001), 8);  // 8 cycles + half a cycle
    EXPECT_EQ(lag_cycles_for_delay(0.0082, 0.001), 8);
    EXPECT_EQ(lag_cycles_for_delay(0.0079, 0.001), 7);
    EXPECT_EQ(lag_cycles_for_delay(0.0, 0.001), 0);
    EXPECT_EQ(lag_cycles_for_delay(1.0, 0.001), 49);  // the ring holds 50
    for (int n = 0; n < 50; ++n) {
        EXPECT_EQ(lag_cycles_for_delay((n + 0.5) * 0.002, 0.002), n) << n;
    }
}

}  // namespace
}  // namespace probecycle
