#include "core/cycle/cycle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/common/units.h"
#include "core/cycle/fixes.h"
#include "core/cycle/motion.h"
#include "core/cycle/motion_cache.h"
#include "core/cycle/scenario.h"
#include "core/cycle/sweep.h"

namespace probecycle {
namespace {

constexpr double kDefaultKneeTolerance = 0.01;  // cycle.knee_tolerance's default

constexpr double kUnchecked = -1.0;

double rel_tol(double expected, double rel = 1e-12) {
    return rel * std::abs(expected) + 1e-15;
}

// The defaults (T = 0.06 s, t_i = t_c = 2 ms, t_s = 4 ms, pretravel 5 um,
// return 10000 mm/min) with a surface, a 5 mm approach and the given feeds.
Scenario surface(Strategy strategy, double probe_feed_mm_min, double backoff_mm = 2.5) {
    Scenario s;
    s.cycle.part_position_uncertainty_mm = 0.0;  // a known part: searches by hand
    s.cycle.strategy = strategy;
    s.cycle.feature = Feature::surface;
    s.cycle.approach_mm = 5.0;
    s.cycle.probe_feed_mm_min = probe_feed_mm_min;
    s.cycle.measure_feed_mm_min = 30.0;
    s.cycle.backoff_mm = backoff_mm;
    s.cycle.return_feed_mm_min = 10000.0;
    s.cycle.target_uncertainty_mm = 0.0;
    s.probe.calibration_feed_mm_min = 0.0;
    // The hand computations are of the touches at their programmed feeds:
    // no feed override to check beyond them (see FeedOverride below).
    s.cycle.feed_override_max_pct = 100.0;
    return s;
}

std::vector<Phase> phases_of(const CycleResult& r) {
    std::vector<Phase> out;
    for (const PhaseRecord& p : r.phases()) out.push_back(p.phase);
    return out;
}

// The phases without the block changes between them.
std::vector<Phase> moves_of(const CycleResult& r) {
    std::vector<Phase> out;
    for (const PhaseRecord& p : r.phases()) {
        if (p.phase != Phase::block_change) out.push_back(p.phase);
    }
    return out;
}

// A phase that ends a block: a touch, a backoff, a return, a positioning move.
bool ends_a_block(Phase phase) {
    switch (phase) {
        case Phase::deceleration:
        case Phase::second_deceleration:
        case Phase::backoff:
        case Phase::return_move:
        case Phase::position:
        case Phase::lift:
        case Phase::lower:
            return true;
        default:
            return false;
    }
}

std::string describe(const CycleResult& r) {
    std::string out;
    for (const PhaseRecord& p : r.phases()) {
        out += std::string(to_string(p.phase)) + "[" + std::to_string(p.touch) +
               "] start=" + std::to_string(p.start_s) + " t=" + std::to_string(p.time_s) +
               " d=" + std::to_string(p.distance_mm) + "\n";
    }
    for (const Warning& w : r.warnings()) {
        out += std::string("warning ") + to_string(w.code) + " " + to_string(w.severity) + ": " +
               w.message() + "\n";
    }
    return out;
}

const Warning* find_warning(const CycleResult& r, WarningCode code, int touch = -1) {
    for (const Warning& w : r.warnings()) {
        if (w.code == code && (touch < 0 || accelerating_touch(w) == touch)) return &w;
    }
    return nullptr;
}

const PhaseRecord* find_phase(const CycleResult& r, Phase phase, int touch = 0) {
    for (const PhaseRecord& p : r.phases()) {
        if (p.phase == phase && p.touch == touch) return &p;
    }
    return nullptr;
}

// The phases of one touch point, in order.
std::vector<Phase> touch_sequence(Strategy strategy) {
    if (strategy == Strategy::single_touch) {
        return {Phase::approach,         Phase::pretravel,    Phase::interface_delay,
                Phase::controller_delay, Phase::deceleration, Phase::return_move};
    }
    return {Phase::approach,
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
            Phase::return_move};
}

// A pocket or bore from its centre and back; a boss or web from
// above its centre, lifting over the wall between touches.
std::vector<Phase> cycle_sequence(Strategy strategy, Feature feature) {
    std::vector<Phase> out;
    const int n = touch_count(feature);
    const bool lift = feature == Feature::boss || feature == Feature::web;
    const std::vector<Phase> one = touch_sequence(strategy);
    if (n == 1) return one;
    // Each touch from the centre and back to it (over and down, up and back
    // for a boss or web).
    for (int i = 0; i < n; ++i) {
        out.push_back(Phase::position);
        if (lift) out.push_back(Phase::lower);
        out.insert(out.end(), one.begin(), one.end());
        if (lift) out.push_back(Phase::lift);
        out.push_back(Phase::position);
    }
    return out;
}

bool is_subsequence(const std::vector<Phase>& part, const std::vector<Phase>& whole) {
    std::size_t k = 0;
    for (Phase p : whole) {
        if (k < part.size() && part[k] == p) ++k;
    }
    return k == part.size();
}

// ---------------------------------------------------------------------------
// Names.

TEST(PhaseNames, ExactAndInCanonicalOrder) {
    const std::vector<std::string> expected = {
        "approach",
        "pretravel",
        "interface_delay",
        "controller_delay",
        "deceleration",
        "backoff",
        "second_approach",
        "second_pretravel",
        "second_interface_delay",
        "second_controller_delay",
        "second_deceleration",
        "return",
        "position",
        "lift",
        "lower",
        "block_change",
    };
    ASSERT_EQ(all_phases().size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(to_string(all_phases()[i]), expected[i]);
        EXPECT_EQ(static_cast<std::size_t>(all_phases()[i]), i);
    }
}

TEST(WarningNames, Exact) {
    EXPECT_STREQ(to_string(WarningCode::overtravel_limit), "overtravel_limit");
    EXPECT_STREQ(to_string(WarningCode::backoff_too_small), "backoff_too_small");
    EXPECT_STREQ(to_string(WarningCode::backoff_excess), "backoff_excess");
    EXPECT_STREQ(to_string(WarningCode::touch_while_accelerating), "touch_while_accelerating");
    EXPECT_STREQ(to_string(WarningCode::feed_beyond_knee), "feed_beyond_knee");
    EXPECT_STREQ(to_string(WarningCode::uncertainty_over_target), "uncertainty_over_target");
    EXPECT_STREQ(to_string(WarningCode::calibration_feed_mismatch), "calibration_feed_mismatch");
    EXPECT_STREQ(to_string(WarningCode::feed_over_probe_limit), "feed_over_probe_limit");
    EXPECT_STREQ(to_string(WarningCode::start_inside_uncertainty), "start_inside_uncertainty");
    EXPECT_STREQ(to_string(WarningCode::search_ends_too_soon), "search_ends_too_soon");
    EXPECT_STREQ(to_string(WarningCode::protected_move_overtravel), "protected_move_overtravel");
    EXPECT_STREQ(to_string(Severity::info), "info");
    EXPECT_STREQ(to_string(Severity::warning), "warning");
    EXPECT_STREQ(to_string(Severity::error), "error");
}

TEST(TouchCount, PerFeature) {
    EXPECT_EQ(touch_count(Feature::surface), 1);
    EXPECT_EQ(touch_count(Feature::web), 2);
    EXPECT_EQ(touch_count(Feature::pocket), 2);
    EXPECT_EQ(touch_count(Feature::bore), 4);
    EXPECT_EQ(touch_count(Feature::boss), 4);
}

// ---------------------------------------------------------------------------
// Small closed forms (docs/model.md, "One touch").

TEST(ReactionTime, InterfacePlusLatencyPlusFullScan) {
    Machine m;
    Probe p;
    m.scan_period_s = 0.004;
    m.controller_latency_s = 0.002;
    p.interface_delay_s = 0.003;
    EXPECT_NEAR(reaction_time_s(m, p), 0.009, 1e-15);
}

struct ScanRangeCase {
    const char* name;
    double feed_mm_min;
    double scan_period_s;
    bool latched;
    double range_mm;
};

// clang-format off
const ScanRangeCase kScanRangeCases[] = {
    // name                  F [mm/min]  t_s [s]   latched  range [mm]
    {"standard_3000",        3000.0,     0.004,    false,   0.2},     // 50 mm/s x 4 ms
    {"high_speed_3000",      3000.0,     0.000004, false,   0.0002},  // 4 us -> 0.2 um
    {"delay_480_5ms",        480.0,      0.005,    false,   0.04},    // 480 mm/min, 5 ms
    {"slow_30",              30.0,       0.004,    false,   0.002},
    {"latched",              3000.0,     0.004,    true,    0.0},
};
// clang-format on

class ScanRange : public testing::TestWithParam<ScanRangeCase> {};

TEST_P(ScanRange, SpeedTimesScanPeriod) {
    const ScanRangeCase& c = GetParam();
    Machine m;
    m.scan_period_s = c.scan_period_s;
    m.latched_input = c.latched;
    EXPECT_NEAR(scan_range_mm(m, mm_min_to_mm_s(c.feed_mm_min)), c.range_mm, rel_tol(c.range_mm));
}

INSTANTIATE_TEST_SUITE_P(DomainExamples, ScanRange, testing::ValuesIn(kScanRangeCases),
                         [](const testing::TestParamInfo<ScanRangeCase>& case_info) {
                             return std::string(case_info.param.name);
                         });

TEST(ExpandedUncertainty, KTwoOfUniformRangeAndRepeatability) {
    // Uniform range R: sigma = R / sqrt(12); repeatability 2 sigma: sigma = rep / 2.
    EXPECT_NEAR(expanded_uncertainty_mm(0.2, 0.0), 0.2 / std::sqrt(3.0), 1e-15);
    EXPECT_NEAR(expanded_uncertainty_mm(0.0, 0.001), 0.001, 1e-18);
    EXPECT_EQ(expanded_uncertainty_mm(0.0, 0.0), 0.0);
    for (double range : {0.0002, 0.002, 0.04, 0.2}) {
        for (double rep : {0.0005, 0.001, 0.003}) {
            const double expected = 2.0 * std::sqrt(range * range / 12.0 + rep * rep / 4.0);
            EXPECT_NEAR(expanded_uncertainty_mm(range, rep), expected, rel_tol(expected));
        }
    }
}

TEST(SpeedError, SpeedMinusCalibratedTimesDelaysWithHalfTheScan) {
    Machine m;
    Probe p;
    m.scan_period_s = 0.004;
    m.controller_latency_s = 0.002;
    p.interface_delay_s = 0.002;
    // (0.5 - 1.0) * (0.002 + 0.002 + 0.004 / 2) = -0.003
    EXPECT_NEAR(speed_error_mm(m, p, 0.5, 1.0), -0.003, 1e-15);
    EXPECT_NEAR(speed_error_mm(m, p, 1.0, 0.5), 0.003, 1e-15);
    EXPECT_EQ(speed_error_mm(m, p, 0.5, 0.5), 0.0);
    // Latched: captured when the signal arrives, so only the interface
    // delay: (0.5 - 1.0) * 0.002 = -0.001. The latency and scan still lengthen the
    // overtravel (reaction_time_s).
    m.latched_input = true;
    EXPECT_NEAR(measurement_delay_s(m, p), 0.002, 1e-15);
    EXPECT_NEAR(speed_error_mm(m, p, 0.5, 1.0), -0.001, 1e-15);
    EXPECT_NEAR(reaction_time_s(m, p), 0.008, 1e-15);
}

// ---------------------------------------------------------------------------
// Whole cycles computed by hand.

struct PhaseExpectation {
    Phase phase;
    double time_s;  // kUnchecked: not fixed by the spec
    double distance_mm;
};

void expect_phases(const CycleResult& r, const std::vector<PhaseExpectation>& expected) {
    ASSERT_EQ(r.phases().size(), expected.size()) << describe(r);
    double start = 0.0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const PhaseRecord& p = r.phases()[i];
        SCOPED_TRACE(to_string(expected[i].phase));
        EXPECT_EQ(p.phase, expected[i].phase);
        EXPECT_EQ(p.touch, 0);
        EXPECT_NEAR(p.start_s, start, 1e-12);
        if (expected[i].time_s != kUnchecked) {
            EXPECT_NEAR(p.time_s, expected[i].time_s, rel_tol(expected[i].time_s, 1e-9));
        }
        EXPECT_NEAR(std::abs(p.distance_mm), expected[i].distance_mm,
                    rel_tol(expected[i].distance_mm, 1e-9));
        start += p.time_s;
    }
    EXPECT_NEAR(r.total(), start, 1e-12);
}

TEST(SingleTouch, SurfaceAt3000PhaseByPhase) {
    // v = 50 mm/s, T = 0.06: ramp 1.5 mm in 0.06 s, 3.5 mm cruise in 0.07 s.
    // Overtravel (worst case, a full 4 ms scan) 0.005 + 50 * (0.002 + 0.002 +
    // 0.004) + 50 * 0.06 / 2 = 1.905 mm. The timeline waits the mean scan, 2
    // ms: the controller delay is 4 ms and the axis stops 1.805 mm past.
    // Return 6.805 mm at 166.67 mm/s < v*T = 10 mm: 2 * sqrt(d * T / v).
    const CycleResult r = evaluate(surface(Strategy::single_touch, 3000.0));
    const double v_ret = 10000.0 / 60.0;
    // clang-format off
    expect_phases(r, {
        // phase                    time [s]                                    distance [mm]
        {Phase::approach,           0.13,                                       5.0},
        {Phase::pretravel,          0.0001,                                     0.005},
        {Phase::interface_delay,    0.002,                                      0.1},
        {Phase::controller_delay,   0.004,                                      0.2},
        {Phase::deceleration,       0.06,                                       1.5},
        {Phase::return_move,        2.0 * std::sqrt(6.805 * 0.06 / v_ret),      6.805},
    });
    // clang-format on
    EXPECT_NEAR(r.overtravel_mm(), 1.905, 1e-12);
    EXPECT_NEAR(r.first_touch().overtravel_mm, 1.905, 1e-12);
    EXPECT_NEAR(r.first_touch().mean_overtravel_mm, 1.805, 1e-12);
    // Recorded after the interface delay and a full scan (worst), or half of it.
    EXPECT_NEAR(r.first_touch().recorded_mm, 0.005 + 50.0 * 0.006, 1e-12);
    EXPECT_NEAR(r.first_touch().mean_recorded_mm, 0.005 + 50.0 * 0.004, 1e-12);
    EXPECT_NEAR(r.trigger_speed_mm_s(), 50.0, 1e-12);
    EXPECT_NEAR(r.first_touch().touch_speed_mm_s, 50.0, 1e-12);
    EXPECT_NEAR(r.first_touch().react_speed_mm_s, 50.0, 1e-12);
    EXPECT_NEAR(r.first_touch().programmed_feed_mm_s, 50.0, 1e-12);
    EXPECT_NEAR(r.scan_range_mm(), 0.2, 1e-12);  // 3000 mm/min, 4 ms
    EXPECT_NEAR(r.trigger_uncertainty_mm(), 2.0 * std::sqrt(0.04 / 12.0 + 0.001 * 0.001 / 4.0),
                1e-12);
    EXPECT_NEAR(r.recommended_backoff_mm(), 1.905 + 0.2, 1e-12);
    EXPECT_NEAR(r.phase_time(Phase::approach), 0.13, 1e-12);
    EXPECT_EQ(r.phase_time(Phase::backoff), 0.0);
    EXPECT_EQ(r.phase_time(Phase::position), 0.0);
    EXPECT_TRUE(r.warnings().empty()) << describe(r);
}

TEST(TwoTouch, SurfaceAt3000Then30PhaseByPhase) {
    // First touch as above (overtravel 1.905 mm, on average 1.805 mm); the
    // backoff 2.5 mm from where it stopped leaves on average 0.695 mm to the
    // surface, approached at 0.5 mm/s (ramp 0.015 mm in 0.06 s): 0.06 + 0.68 /
    // 0.5 = 1.42 s. Second overtravel 0.005 + 0.5 * 0.008 + 0.015 = 0.024 mm,
    // on average 0.023 mm; return 5.023 mm.
    const CycleResult r = evaluate(surface(Strategy::two_touch, 3000.0, 2.5));
    const double v_ret = 10000.0 / 60.0;
    // clang-format off
    expect_phases(r, {
        // phase                          time [s]                                 distance [mm]
        {Phase::approach,                 0.13,                                    5.0},
        {Phase::pretravel,                0.0001,                                  0.005},
        {Phase::interface_delay,          0.002,                                   0.1},
        {Phase::controller_delay,         0.004,                                   0.2},
        {Phase::deceleration,             0.06,                                    1.5},
        {Phase::backoff,                  kUnchecked,                              2.5},
        {Phase::second_approach,          1.42,                                    0.695},
        {Phase::second_pretravel,         0.01,                                    0.005},
        {Phase::second_interface_delay,   0.002,                                   0.001},
        {Phase::second_controller_delay,  0.004,                                   0.002},
        {Phase::second_deceleration,      0.06,                                    0.015},
        {Phase::return_move,              2.0 * std::sqrt(5.023 * 0.06 / v_ret),   5.023},
    });
    // clang-format on
    EXPECT_NEAR(r.first_touch().overtravel_mm, 1.905, 1e-12);
    EXPECT_NEAR(r.measuring_touch().overtravel_mm, 0.024, 1e-12);
    EXPECT_NEAR(r.overtravel_mm(), 1.905, 1e-12);
    EXPECT_NEAR(r.trigger_speed_mm_s(), 0.5, 1e-12);
    EXPECT_NEAR(r.measuring_touch().touch_speed_mm_s, 0.5, 1e-12);
    EXPECT_NEAR(r.scan_range_mm(), 0.002, 1e-12);
    EXPECT_NEAR(r.trigger_uncertainty_mm(),
                2.0 * std::sqrt(0.002 * 0.002 / 12.0 + 0.001 * 0.001 / 4.0), 1e-12);
    EXPECT_NEAR(r.recommended_backoff_mm(), 2.105, 1e-12);
    // The backoff move is no faster than a rest-to-rest move at rapid.
    const PhaseRecord* backoff = find_phase(r, Phase::backoff);
    ASSERT_NE(backoff, nullptr);
    EXPECT_GE(backoff->time_s,
              move_time_s(Scenario{}.motion_limits(), 2.5, mm_min_to_mm_s(30000.0)) * (1 - 1e-12));
}

struct PretravelCase {
    double feed_mm_min;
    double pretravel_mm;
    double time_s;
};

// Pretravel p/v: 2 um at 30 mm/min takes 0.004 s; 50 um at 30 mm/min 0.1 s.
// clang-format off
const PretravelCase kPretravelCases[] = {
    // F [mm/min]  p [mm]   t [s]
    {30.0,         0.002,   0.004},
    {30.0,         0.05,    0.1},
    {1000.0,       0.002,   0.00012},
    {3000.0,       0.005,   0.0001},
};
// clang-format on

class PretravelTime : public testing::TestWithParam<PretravelCase> {};

TEST_P(PretravelTime, PretravelOverTouchSpeed) {
    const PretravelCase& c = GetParam();
    Scenario s = surface(Strategy::single_touch, c.feed_mm_min);
    s.probe.pretravel_mm = c.pretravel_mm;
    const CycleResult r = evaluate(s);
    const PhaseRecord* p = find_phase(r, Phase::pretravel);
    ASSERT_NE(p, nullptr) << describe(r);
    EXPECT_NEAR(p->time_s, c.time_s, rel_tol(c.time_s, 1e-9));
    EXPECT_NEAR(p->distance_mm, c.pretravel_mm, 1e-15);
}

INSTANTIATE_TEST_SUITE_P(DomainExamples, PretravelTime, testing::ValuesIn(kPretravelCases));

TEST(TwoTouch, EveryExtraMillimetreOfBackoffAt30CostsTwoSeconds) {
    const CycleResult base = evaluate(surface(Strategy::two_touch, 3000.0, 2.5));
    const CycleResult more = evaluate(surface(Strategy::two_touch, 3000.0, 3.5));
    const PhaseRecord* a = find_phase(base, Phase::second_approach);
    const PhaseRecord* b = find_phase(more, Phase::second_approach);
    ASSERT_NE(a, nullptr);
    ASSERT_NE(b, nullptr);
    EXPECT_NEAR(b->time_s - a->time_s, 2.0, 1e-9);
    EXPECT_GE(more.total() - base.total(), 2.0 - 1e-9);
}

TEST(Cycle, TouchDuringAccelerationTriggersSlowerAndKeepsAccelerating) {
    // 6000 mm/min: a = 100 / 0.06 mm/s^2, full speed after 3 mm; the surface is at 0.75 mm.
    // Touch at sqrt(2 a 0.75) = 50 mm/s; the trigger after 5 um more; the axis keeps
    // accelerating through the 8 ms of delays, then brakes at a.
    Scenario s = surface(Strategy::single_touch, 6000.0);
    s.cycle.approach_mm = 0.75;
    const CycleResult r = evaluate(s);
    const double a = 100.0 / 0.06;
    const double t_touch = std::sqrt(2.0 * 0.75 / a);
    const double t_trigger = std::sqrt(2.0 * 0.755 / a);
    // The timeline reacts after the mean scan wait (6 ms in all), the
    // overtravel after a full scan (8 ms).
    const double t_react = t_trigger + 0.006;
    const double x_react = 0.5 * a * t_react * t_react;
    const double v_react = a * t_react;
    const double t_worst = t_trigger + 0.008;
    const double x_worst = 0.5 * a * t_worst * t_worst;
    const double v_worst = a * t_worst;
    EXPECT_NEAR(r.first_touch().touch_speed_mm_s, 50.0, 1e-9);
    EXPECT_NEAR(r.first_touch().trigger_speed_mm_s, a * t_trigger, 1e-9);
    EXPECT_NEAR(r.first_touch().react_speed_mm_s, v_react, 1e-9);
    EXPECT_NEAR(r.trigger_speed_mm_s(), a * t_trigger, 1e-9);
    // Overtravel: to the reaction point, then v^2 / (2 a).
    EXPECT_NEAR(r.overtravel_mm(), x_worst - 0.75 + v_worst * v_worst / (2.0 * a), 1e-9);
    EXPECT_NEAR(r.first_touch().mean_overtravel_mm, x_react - 0.75 + v_react * v_react / (2.0 * a),
                1e-9);
    // clang-format off
    expect_phases(r, {
        // phase                    time [s]                   distance [mm]
        {Phase::approach,           t_touch,                   0.75},
        {Phase::pretravel,          t_trigger - t_touch,       0.005},
        {Phase::interface_delay,    0.002,                     0.5 * a * (std::pow(t_trigger + 0.002, 2) - t_trigger * t_trigger)},
        {Phase::controller_delay,   0.004,                     x_react - 0.5 * a * std::pow(t_trigger + 0.002, 2)},
        {Phase::deceleration,       v_react / a,               v_react * v_react / (2.0 * a)},
        {Phase::return_move,        kUnchecked,                x_react + v_react * v_react / (2.0 * a)},
    });
    // clang-format on
    const Warning* w = find_warning(r, WarningCode::touch_while_accelerating);
    ASSERT_NE(w, nullptr) << describe(r);
    EXPECT_EQ(w->severity, Severity::warning);
    // The speed reached (at the touch or the trigger) and the programmed feed.
    EXPECT_GE(std::get<warning::TouchWhileAccelerating>(w->figures).speed_mm_s, 50.0 - 1e-9);
    EXPECT_LE(std::get<warning::TouchWhileAccelerating>(w->figures).speed_mm_s,
              a * t_trigger + 1e-9);
    EXPECT_NEAR(std::get<warning::TouchWhileAccelerating>(w->figures).feed_mm_s, 100.0, 1e-12);
    EXPECT_EQ(std::get<warning::TouchWhileAccelerating>(w->figures).touch, 1);
    // The error follows the real speed through the delay
    // tau = t_i + t_c + t_s/2 = 6 ms: calibration takes v tau = 0.6 mm; the axis,
    // still accelerating, travels v_t tau + a tau^2 / 2.
    const double tau = 0.006;
    const double v_t = a * t_trigger;
    EXPECT_NEAR(r.first_touch().delay_travel_mm, v_t * tau + 0.5 * a * tau * tau, 1e-12);
    EXPECT_NEAR(std::get<warning::TouchWhileAccelerating>(w->figures).error_mm,
                100.0 * tau - (v_t * tau + 0.5 * a * tau * tau), 1e-12);
    // Less than the (v - v_t) tau of a speed stepping at the trigger, by a tau^2 / 2.
    EXPECT_NEAR(speed_error_mm(s.machine, s.probe, 100.0, v_t) -
                    std::get<warning::TouchWhileAccelerating>(w->figures).error_mm,
                0.5 * a * tau * tau, 1e-12);
    EXPECT_FALSE(w->message().empty());
}

TEST(Cycle, LatchedInputRemovesTheScanFromTheMeasurementNotFromTheTravel) {
    Scenario s = surface(Strategy::single_touch, 3000.0);
    const CycleResult scanned = evaluate(s);
    s.machine.latched_input = true;
    const CycleResult latched = evaluate(s);
    EXPECT_EQ(latched.scan_range_mm(), 0.0);
    EXPECT_NEAR(latched.trigger_uncertainty_mm(), s.probe.repeatability_2sigma_mm, 1e-15);
    EXPECT_NEAR(latched.overtravel_mm(), scanned.overtravel_mm(), 1e-12);
    EXPECT_NEAR(latched.total(), scanned.total(), 1e-12);
}

TEST(Cycle, ZeroDelaysAndPretravelLeaveOnlyTheStop) {
    Scenario s = surface(Strategy::single_touch, 3000.0);
    s.probe.pretravel_mm = 0.0;
    s.probe.interface_delay_s = 0.0;
    s.machine.controller_latency_s = 0.0;
    s.machine.scan_period_s = 0.0;
    s.probe.repeatability_2sigma_mm = 0.0;
    const CycleResult r = evaluate(s);
    EXPECT_NEAR(r.overtravel_mm(), 1.5, 1e-12);  // v * T / 2
    EXPECT_EQ(r.trigger_uncertainty_mm(), 0.0);
    double sum = 0.0;
    for (const PhaseRecord& p : r.phases()) {
        EXPECT_TRUE(std::isfinite(p.time_s));
        EXPECT_GE(p.time_s, 0.0);
        sum += p.time_s;
    }
    EXPECT_NEAR(sum, r.total(), 1e-12);
}

TEST(Cycle, StartingAtTheSurfaceIsFinite) {
    // approach_mm = 0 is allowed: the touch happens at rest and the probe triggers
    // while accelerating through the pretravel.
    for (AccelModel model :
         {AccelModel::time_constant, AccelModel::constant_accel, AccelModel::jerk_limited}) {
        Scenario s = surface(Strategy::two_touch, 3000.0);
        s.machine.accel_model = model;
        s.cycle.approach_mm = 0.0;
        const CycleResult r = evaluate(s);
        SCOPED_TRACE(describe(r));
        EXPECT_TRUE(std::isfinite(r.total()));
        EXPECT_EQ(r.first_touch().touch_speed_mm_s, 0.0);
        EXPECT_GT(r.first_touch().trigger_speed_mm_s, 0.0);
        // The first touch of two-touch only finds the surface: no error to report.
        EXPECT_EQ(find_warning(r, WarningCode::touch_while_accelerating, 1), nullptr);
        double sum = 0.0;
        for (const PhaseRecord& p : r.phases()) {
            EXPECT_TRUE(std::isfinite(p.time_s));
            sum += p.time_s;
        }
        EXPECT_NEAR(sum, r.total(), 1e-12);
    }
}

TEST(Cycle, BackoffShorterThanOvertravelIsReportedNotACrash) {
    for (double backoff : {0.0, 0.5, 1.905}) {
        SCOPED_TRACE(backoff);
        const CycleResult r = evaluate(surface(Strategy::two_touch, 3000.0, backoff));
        double sum = 0.0;
        for (const PhaseRecord& p : r.phases()) {
            EXPECT_TRUE(std::isfinite(p.time_s)) << describe(r);
            EXPECT_GE(p.time_s, 0.0) << describe(r);
            EXPECT_TRUE(std::isfinite(p.distance_mm));
            sum += p.time_s;
        }
        EXPECT_TRUE(std::isfinite(r.total()));
        EXPECT_NEAR(sum, r.total(), 1e-9);
        const Warning* w = find_warning(r, WarningCode::backoff_too_small);
        ASSERT_NE(w, nullptr) << describe(r);
        EXPECT_EQ(w->severity, Severity::error);
    }
}

// ---------------------------------------------------------------------------
// Multi-touch features.

class FeatureCycle : public testing::TestWithParam<std::tuple<Feature, Strategy>> {};

TEST_P(FeatureCycle, TouchesInOrderWithProtectedPositioningMoves) {
    const auto [feature, strategy] = GetParam();
    Scenario s = surface(strategy, 3000.0, 2.5);
    s.cycle.feature = feature;
    s.cycle.feature_size_mm = 50.0;
    const CycleResult r = evaluate(s);
    EXPECT_EQ(phases_of(r), cycle_sequence(strategy, feature)) << describe(r);
    const MotionLimits limits = s.motion_limits();
    int touch = 0;
    for (const PhaseRecord& p : r.phases()) {
        if (p.phase == Phase::position || p.phase == Phase::lower) {
            // Protected moves, at the positioning feed.
            EXPECT_GT(p.distance_mm, 0.0);
            EXPECT_NEAR(
                p.time_s,
                move_time_s(limits, p.distance_mm, mm_min_to_mm_s(s.cycle.position_feed_mm_min)),
                1e-12);
        } else if (p.phase == Phase::lift) {
            // Away from the part, at the rapid feed.
            EXPECT_NEAR(p.distance_mm, s.cycle.clearance_mm, 1e-12);
            EXPECT_NEAR(
                p.time_s,
                move_time_s(limits, p.distance_mm, mm_min_to_mm_s(s.machine.rapid_feed_mm_min)),
                1e-12);
        } else {
            // The touches in order, each with the moves that lead to it.
            EXPECT_GE(p.touch, touch) << to_string(p.phase);
            touch = p.touch;
        }
    }
    EXPECT_EQ(touch + 1, touch_count(feature));
    // Every touch point repeats the same touch.
    const CycleResult one = evaluate(surface(strategy, 3000.0, 2.5));
    EXPECT_NEAR(r.phase_time(Phase::approach),
                touch_count(feature) * one.phase_time(Phase::approach), 1e-12);
    EXPECT_NEAR(r.overtravel_mm(), one.overtravel_mm(), 1e-12);
    EXPECT_NEAR(r.uncertainty_mm(), one.uncertainty_mm(), 1e-15);
    EXPECT_NEAR(r.total(),
                touch_count(feature) * one.total() + r.phase_time(Phase::position) +
                    r.phase_time(Phase::lift) + r.phase_time(Phase::lower),
                1e-9);
}

INSTANTIATE_TEST_SUITE_P(
    AllFeatures, FeatureCycle,
    testing::Combine(testing::Values(Feature::surface, Feature::web, Feature::pocket, Feature::bore,
                                     Feature::boss),
                     testing::Values(Strategy::single_touch, Strategy::two_touch)));

// By hand. Contact points 50 mm apart, 5 mm approach.
TEST(FeatureCycle, PocketFromItsCentreToEachStartAndBack) {
    Scenario s = surface(Strategy::single_touch, 3000.0);
    s.cycle.feature = Feature::pocket;
    s.cycle.feature_size_mm = 50.0;
    const CycleResult r = evaluate(s);
    // Centre to the X+ start: 25 - 5 = 20 mm and back, then the same to the
    // X- start: the probe stops at the centre between the touches, as the
    // programs move.
    std::vector<double> moves;
    for (const PhaseRecord& p : r.phases()) {
        if (p.phase == Phase::position) moves.push_back(p.distance_mm);
    }
    ASSERT_EQ(moves.size(), 4u) << describe(r);
    for (double move : moves) EXPECT_NEAR(move, 20.0, 1e-12);
    // At 3000 mm/min (50 mm/s), T = 0.06 s: a long move takes d / v + T.
    EXPECT_NEAR(r.phase_time(Phase::position), 4 * (20.0 / 50.0 + 0.06), 1e-9);
    EXPECT_EQ(r.phase_time(Phase::lift), 0.0);
}

TEST(FeatureCycle, BossLiftsOverTheWallBetweenTouches) {
    Scenario s = surface(Strategy::single_touch, 3000.0);
    s.cycle.feature = Feature::boss;
    s.cycle.feature_size_mm = 50.0;
    s.cycle.clearance_mm = 10.0;
    const CycleResult r = evaluate(s);
    // Starts 25 + 5 = 30 mm from the centre: for each side out 30 over its
    // start, down 10, the touch, up 10, back 30 over the centre.
    std::vector<double> moves;
    int lifts = 0;
    int lowers = 0;
    for (const PhaseRecord& p : r.phases()) {
        if (p.phase == Phase::position) moves.push_back(p.distance_mm);
        lifts += p.phase == Phase::lift ? 1 : 0;
        lowers += p.phase == Phase::lower ? 1 : 0;
    }
    ASSERT_EQ(moves.size(), 8u) << describe(r);
    for (double move : moves) EXPECT_NEAR(move, 30.0, 1e-12);
    EXPECT_NEAR(r.phase_time(Phase::position), 8 * (30.0 / 50.0 + 0.06), 1e-9);
    EXPECT_EQ(lifts, 4);
    EXPECT_EQ(lowers, 4);
    // Down at 50 mm/s: 10 / 50 + 0.06 s. Up at the 30000 mm/min rapid, which
    // 10 mm at a = v / T = 8333 mm/s^2 never reaches: 2 sqrt(10 / a).
    const double up_s = 2.0 * std::sqrt(10.0 / (500.0 / 0.06));
    EXPECT_NEAR(r.phase_time(Phase::lower), 4 * (0.2 + 0.06), 1e-9);
    EXPECT_NEAR(r.phase_time(Phase::lift), 4 * up_s, 1e-9);
    // A web lifts over too: after each of its two touches.
    s.cycle.feature = Feature::web;
    EXPECT_NEAR(evaluate(s).phase_time(Phase::lift), 2 * up_s, 1e-9);
    // The feature starts where it ends: the state at both ends is the start.
    EXPECT_EQ(r.state_at(0.0).position_mm, 0.0);
    EXPECT_NEAR(r.state_at(r.total()).position_mm, 0.0, 1e-9);
    EXPECT_EQ(r.phases().front().phase, Phase::position);
    EXPECT_EQ(r.phases().back().phase, Phase::position);
}

// The control's block change: after every move, the axis at rest. A two-touch
// bore has 24 blocks: per touch out, the fast touch, the backoff, the
// measuring touch, the return and back.
TEST(BlockChange, EveryMoveAddsItOnceAtRest) {
    for (const Feature feature : {Feature::surface, Feature::bore}) {
        SCOPED_TRACE(to_string(feature));
        Scenario s = surface(Strategy::two_touch, 3000.0, 2.5);
        s.cycle.feature = feature;
        const CycleResult without = evaluate(s);
        s.machine.block_change_s = 0.004;
        const CycleResult with = evaluate(s);
        const double blocks = feature == Feature::surface ? 4.0 : 24.0;
        EXPECT_NEAR(with.phase_time(Phase::block_change), blocks * 0.004, 1e-12);
        EXPECT_NEAR(with.total(), without.total() + blocks * 0.004, 1e-9);
        EXPECT_EQ(moves_of(with), phases_of(without));
        for (const PhaseRecord& p : with.phases()) {
            if (p.phase != Phase::block_change) continue;
            const CycleState at = with.state_at(p.start_s + 0.5 * p.time_s);
            EXPECT_NEAR(at.velocity_mm_s, 0.0, 1e-9);
            EXPECT_NEAR(at.position_mm, with.state_at(p.start_s).position_mm, 1e-9);
        }
        // Nothing else moves: the touches, the overtravel, the backoff advice.
        EXPECT_EQ(with.overtravel_mm(), without.overtravel_mm());
        EXPECT_EQ(with.recommended_backoff_mm(), without.recommended_backoff_mm());
    }
    // A longer backoff wastes the same time with block changes or without.
    Scenario s = surface(Strategy::two_touch, 3000.0, 3.5);
    const auto wasted = [](const CycleResult& r) {
        const Warning* w = find_warning(r, WarningCode::backoff_excess);
        return w != nullptr ? std::get<warning::BackoffExcess>(w->figures).wasted_s : -1.0;
    };
    const double before = wasted(evaluate(s));
    ASSERT_GT(before, 0.0);
    s.machine.block_change_s = 0.004;
    EXPECT_NEAR(wasted(evaluate(s)), before, 1e-12);
}

// ---------------------------------------------------------------------------
// State along the cycle (cycle.h conventions).

TEST(StateAt, SingleTouchAt3000) {
    const CycleResult r = evaluate(surface(Strategy::single_touch, 3000.0));
    const CycleState start = r.state_at(0.0);
    EXPECT_EQ(start.phase_index, 0u);
    EXPECT_EQ(start.touch, 0);
    EXPECT_EQ(start.position_mm, 0.0);
    EXPECT_EQ(start.velocity_mm_s, 0.0);
    // Mid-ramp: a = 50 / 0.06, at 0.03 s: 25 mm/s, 0.375 mm.
    const CycleState ramp = r.state_at(0.03);
    EXPECT_NEAR(ramp.velocity_mm_s, 25.0, 1e-9);
    EXPECT_NEAR(ramp.position_mm, 0.375, 1e-9);
    EXPECT_NEAR(ramp.path_speed_mm_s, 25.0, 1e-9);
    // The surface at the end of the approach, at full speed.
    const CycleState touch = r.state_at(0.13);
    EXPECT_NEAR(touch.position_mm, 5.0, 1e-9);
    EXPECT_NEAR(touch.velocity_mm_s, 50.0, 1e-9);
    // Stopped, after the mean scan wait, 1.805 mm beyond it.
    const double t_stop = 0.13 + 0.0001 + 0.002 + 0.004 + 0.06;
    const CycleState stop = r.state_at(t_stop);
    EXPECT_NEAR(stop.position_mm, 6.805, 1e-9);
    EXPECT_NEAR(stop.velocity_mm_s, 0.0, 1e-9);
    // Returning: moving away from the surface.
    const CycleState back = r.state_at(0.5 * (t_stop + r.total()));
    EXPECT_LT(back.velocity_mm_s, 0.0);
    EXPECT_NEAR(back.path_speed_mm_s, -back.velocity_mm_s, 1e-9);
    EXPECT_EQ(r.phases()[back.phase_index].phase, Phase::return_move);
    const CycleState end = r.state_at(r.total());
    EXPECT_NEAR(end.position_mm, 0.0, 1e-9);
    EXPECT_NEAR(end.velocity_mm_s, 0.0, 1e-9);
}

TEST(StateAt, TwoTouchBacksOffThenMeetsTheSurfaceAgain) {
    const CycleResult r = evaluate(surface(Strategy::two_touch, 3000.0, 2.5));
    const PhaseRecord* backoff = find_phase(r, Phase::backoff);
    const PhaseRecord* second = find_phase(r, Phase::second_approach);
    ASSERT_NE(backoff, nullptr);
    ASSERT_NE(second, nullptr);
    const CycleState mid_backoff = r.state_at(backoff->start_s + 0.5 * backoff->time_s);
    EXPECT_LT(mid_backoff.velocity_mm_s, 0.0);
    const CycleState backed = r.state_at(backoff->start_s + backoff->time_s);
    EXPECT_NEAR(backed.position_mm, 5.0 + 1.805 - 2.5, 1e-9);
    const CycleState met = r.state_at(second->start_s + second->time_s);
    EXPECT_NEAR(met.position_mm, 5.0, 1e-9);
    EXPECT_NEAR(met.velocity_mm_s, 0.5, 1e-9);
}

// ---------------------------------------------------------------------------
// Warnings, each from a scenario built for it.

// Two-touch at 3000/30 with the backoff at the recommendation: no warning at all.
Scenario clean_two_touch() {
    Scenario s = surface(Strategy::two_touch, 3000.0);
    s.cycle.backoff_mm = evaluate(s).recommended_backoff_mm();
    return s;
}

TEST(Warnings, NoneForACleanCycle) {
    const Scenario s = clean_two_touch();
    ASSERT_TRUE(validate(s).empty());
    const CycleResult r = evaluate(s);
    EXPECT_TRUE(r.warnings().empty()) << describe(r);
    EXPECT_NEAR(s.cycle.backoff_mm, 2.105, 1e-12);
}

TEST(Warnings, OvertravelLimit) {
    Scenario s = clean_two_touch();
    const double ot = evaluate(s).overtravel_mm();
    struct {
        double limit_mm;
        bool present;
        Severity severity;
    } const cases[] = {
        {ot, true, Severity::error},                       // at the limit
        {0.5 * ot, true, Severity::error},                 // beyond it
        {ot / 0.9, true, Severity::warning},               // 90 %
        {ot / 0.8 * (1 - 1e-9), true, Severity::warning},  // just over 80 %
        {ot / 0.8 * (1 + 1e-6), false, Severity::info},    // just under 80 %
        {ot / 0.5, false, Severity::info},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.limit_mm);
        s.probe.overtravel_limit_mm = c.limit_mm;
        const CycleResult r = evaluate(s);
        const Warning* w = find_warning(r, WarningCode::overtravel_limit);
        if (!c.present) {
            EXPECT_EQ(w, nullptr) << describe(r);
            continue;
        }
        ASSERT_NE(w, nullptr) << describe(r);
        EXPECT_EQ(w->severity, c.severity);
        EXPECT_NEAR(std::get<warning::OvertravelLimit>(w->figures).overtravel_mm, ot, 1e-12);
        EXPECT_EQ(std::get<warning::OvertravelLimit>(w->figures).limit_mm, c.limit_mm);
        EXPECT_FALSE(w->message().empty());
    }
}

TEST(Warnings, BackoffTooSmall) {
    Scenario s = clean_two_touch();
    const double recommended = s.cycle.backoff_mm;
    s.cycle.backoff_mm = recommended - 0.05;
    const CycleResult r = evaluate(s);
    const Warning* w = find_warning(r, WarningCode::backoff_too_small);
    ASSERT_NE(w, nullptr) << describe(r);
    EXPECT_EQ(w->severity, Severity::error);
    EXPECT_NEAR(std::get<warning::BackoffTooSmall>(w->figures).backoff_mm, recommended - 0.05,
                1e-12);
    EXPECT_NEAR(std::get<warning::BackoffTooSmall>(w->figures).recommended_mm, recommended, 1e-12);
    EXPECT_EQ(find_warning(r, WarningCode::backoff_excess), nullptr);
    EXPECT_FALSE(w->message().empty());
}

// An error makes the cycle invalid; warnings and notes do not.
TEST(Validity, AnErrorMakesTheCycleInvalidAndNamesWhy) {
    Scenario s = clean_two_touch();
    EXPECT_TRUE(evaluate(s).valid());
    EXPECT_EQ(evaluate(s).invalid_codes(), 0u);

    const double recommended = s.cycle.backoff_mm;
    s.cycle.backoff_mm = recommended - 0.05;  // second touch starts deflected
    CycleResult r = evaluate(s);
    EXPECT_FALSE(r.valid());
    EXPECT_EQ(r.invalid_codes(), invalid_code_bit(WarningCode::backoff_too_small));
    EXPECT_EQ(invalid_codes_text(r.invalid_codes(), ";"), "backoff_too_small");

    s.probe.overtravel_limit_mm = 0.5 * r.overtravel_mm();  // and the stylus is overrun
    r = evaluate(s);
    EXPECT_FALSE(r.valid());
    EXPECT_EQ(r.invalid_codes(), invalid_code_bit(WarningCode::backoff_too_small) |
                                     invalid_code_bit(WarningCode::overtravel_limit));
    EXPECT_EQ(invalid_codes_text(r.invalid_codes(), ";"), "overtravel_limit;backoff_too_small");

    // A warning (90 % of the limit) or a note (backoff longer than needed) leaves it valid.
    s = clean_two_touch();
    s.probe.overtravel_limit_mm = evaluate(s).overtravel_mm() / 0.9;
    s.cycle.backoff_mm += 1.0;
    r = evaluate(s);
    EXPECT_NE(find_warning(r, WarningCode::overtravel_limit), nullptr);
    EXPECT_NE(find_warning(r, WarningCode::backoff_excess), nullptr);
    EXPECT_TRUE(r.valid());
}

// With a reseat distance shorter than the distance to
// reach the measuring feed, the recommended backoff leaves that distance.
// 600 mm/min = 10 mm/s, T = 0.06 s: reach = v T / 2 = 0.3 mm > reseat 0.005 mm.
TEST(RecommendedBackoff, LeavesTheSecondTouchRoomToReachTheMeasuringFeed) {
    Scenario s;  // two-touch surface at 2000 mm/min: overtravel_1 = 1.2716667 mm
    s.cycle.feed_override_max_pct = 100.0;  // at the programmed feeds
    s.probe.reseat_mm = 0.005;
    s.cycle.measure_feed_mm_min = 600.0;
    const CycleResult r = evaluate(s);
    ASSERT_NEAR(r.first_touch().overtravel_mm, 1.27166667, 1e-8);
    // Rounded up to the micrometre, the value shown.
    EXPECT_DOUBLE_EQ(r.recommended_backoff_mm(), 1.572);
    // Following it: no touch while accelerating, no backoff warning.
    s.cycle.backoff_mm = r.recommended_backoff_mm();
    const CycleResult followed = evaluate(s);
    EXPECT_TRUE(followed.valid()) << describe(followed);
    EXPECT_EQ(find_warning(followed, WarningCode::touch_while_accelerating), nullptr)
        << describe(followed);
    EXPECT_NEAR(followed.measuring_touch().trigger_speed_mm_s, 10.0, 1e-9);
    // Overtravel plus reseat alone (the old rule) touches while accelerating.
    s.cycle.backoff_mm = 1.27166667 + 0.005 + 1e-6;
    const CycleResult old_rule = evaluate(s);
    EXPECT_NE(find_warning(old_rule, WarningCode::touch_while_accelerating), nullptr);
    EXPECT_NE(find_warning(old_rule, WarningCode::backoff_too_small), nullptr);
}

// The backoff from the recorded trigger position (cycle.backoff_from = trigger).
// At 2000 mm/min (33.33 mm/s) the control records the touch after pretravel,
// interface delay and a full scan: 0.005 + 33.33 (0.002 + 0.004) = 0.205 mm past
// the surface; the axis stops at 1.27167 mm. A 2 mm backoff from there moves
// 2 + 1.27167 - 0.205 = 3.06667 mm. On average (half a scan, 2 ms, less of
// both) it is recorded 0.13833 mm past and starts the second touch 1.86167 mm out.
TEST(BackoffFrom, TheRecordedTriggerPosition) {
    Scenario s;
    s.cycle.feed_override_max_pct = 100.0;  // at the programmed feeds
    s.cycle.backoff_from = BackoffFrom::trigger;
    const CycleResult r = evaluate(s);
    EXPECT_NEAR(r.first_touch().recorded_mm, 0.205, 1e-12);
    EXPECT_NEAR(r.first_touch().mean_recorded_mm, 0.005 + 0.4 / 3.0, 1e-12);
    EXPECT_NEAR(find_phase(r, Phase::backoff)->distance_mm, 2.0 + 1.27166667 - 0.205, 1e-8);
    EXPECT_NEAR(find_phase(r, Phase::second_approach)->distance_mm, 2.0 - 0.005 - 0.4 / 3.0, 1e-12);
    // Recommended: 0.205 + max(reseat 0.2, reach 0.5 mm/s x 0.03 s) = 0.405 mm.
    EXPECT_NEAR(r.recommended_backoff_mm(), 0.405, 1e-12);
    EXPECT_NE(find_warning(r, WarningCode::backoff_excess), nullptr);

    // Latched: recorded when the signal arrives, 0.005 + 33.33 x 0.002.
    Scenario latched = s;
    latched.machine.latched_input = true;
    EXPECT_NEAR(evaluate(latched).first_touch().recorded_mm, 0.005 + 0.2 / 3.0, 1e-12);

    // Too small: its own message, naming the reference.
    s.cycle.backoff_mm = 0.3;
    const CycleResult small = evaluate(s);
    const Warning* w = find_warning(small, WarningCode::backoff_too_small);
    ASSERT_NE(w, nullptr) << describe(small);
    EXPECT_EQ(std::get<warning::BackoffTooSmall>(w->figures).from, BackoffFrom::trigger);
    EXPECT_NE(w->message().find("from the recorded trigger position"), std::string::npos);
    EXPECT_FALSE(small.valid());

    // The same backoff from the stop starts the second touch closer and is quicker;
    // the recommended cycles of the two references are the same cycle, but for
    // their rounding up to the micrometre: under 1 um of second approach at
    // 30 mm/min, 2 ms.
    Scenario from_stop;
    from_stop.cycle.feed_override_max_pct = 100.0;
    Scenario from_trigger = from_stop;
    from_trigger.cycle.backoff_from = BackoffFrom::trigger;
    EXPECT_LT(evaluate(from_stop).total(), evaluate(from_trigger).total());
    from_stop.cycle.backoff_mm = evaluate(from_stop).recommended_backoff_mm();
    from_trigger.cycle.backoff_mm = evaluate(from_trigger).recommended_backoff_mm();
    EXPECT_NEAR(evaluate(from_stop).total(), evaluate(from_trigger).total(), 0.002);
    // The reseat distance, and the half scan by which the mean stop falls short
    // of the worst.
    EXPECT_NEAR(find_phase(evaluate(from_trigger), Phase::second_approach)->distance_mm,
                0.2 + 0.2 / 3.0, kBackoffStep_mm);
}

// A recommendation written back rounded to the editors' 0.001 mm is followed
// (2.1050000000000004 was once refused as 2.105): 1 nm of tolerance.
// Errors first, then warnings, then notes, each in the order computed.
TEST(Warnings, ErrorsComeFirst) {
    Scenario s;                 // two-touch surface at 2000 mm/min
    s.cycle.approach_mm = 0.2;  // start_inside_uncertainty (a warning)
    s.cycle.part_position_uncertainty_mm = 0.3;
    s.cycle.backoff_mm = 0.5;                 // backoff_too_small (an error)
    s.probe.calibration_feed_mm_min = 100.0;  // calibration_feed_mismatch (a warning)
    const CycleResult r = evaluate(s);
    ASSERT_GE(r.warnings().size(), 3u) << describe(r);
    EXPECT_EQ(r.warnings().front().code, WarningCode::backoff_too_small) << describe(r);
    for (std::size_t i = 1; i < r.warnings().size(); ++i) {
        EXPECT_GE(static_cast<int>(r.warnings()[i - 1].severity),
                  static_cast<int>(r.warnings()[i].severity))
            << describe(r);
    }
    std::vector<Warning> mixed = {{Severity::info, warning::BackoffExcess{}},
                                  {Severity::warning, warning::TouchWhileAccelerating{}},
                                  {Severity::error, warning::OvertravelLimit{}},
                                  {Severity::warning, warning::CalibrationFeedMismatch{}}};
    order_by_severity(mixed);
    EXPECT_EQ(mixed[0].code, WarningCode::overtravel_limit);
    EXPECT_EQ(mixed[1].code, WarningCode::touch_while_accelerating);  // stable
    EXPECT_EQ(mixed[2].code, WarningCode::calibration_feed_mismatch);
    EXPECT_EQ(mixed[3].code, WarningCode::backoff_excess);
}

TEST(Warnings, BackoffWithinANanometreOfTheRecommendationIsEnough) {
    Scenario s = clean_two_touch();
    const double recommended = evaluate(s).recommended_backoff_mm();
    s.cycle.backoff_mm = recommended - 1e-7;
    EXPECT_EQ(find_warning(evaluate(s), WarningCode::backoff_too_small), nullptr);
    s.cycle.backoff_mm = recommended - 1e-5;
    EXPECT_NE(find_warning(evaluate(s), WarningCode::backoff_too_small), nullptr);
}

TEST(Warnings, BackoffExcessWithTheTimeItWastes) {
    const Scenario clean = clean_two_touch();
    Scenario s = clean;
    s.cycle.backoff_mm = clean.cycle.backoff_mm + 1.0;
    const CycleResult r = evaluate(s);
    const Warning* w = find_warning(r, WarningCode::backoff_excess);
    ASSERT_NE(w, nullptr) << describe(r);
    EXPECT_EQ(w->severity, Severity::info);
    EXPECT_NEAR(std::get<warning::BackoffExcess>(w->figures).backoff_mm, s.cycle.backoff_mm, 1e-12);
    EXPECT_NEAR(std::get<warning::BackoffExcess>(w->figures).recommended_mm, clean.cycle.backoff_mm,
                1e-12);
    // 1 mm at 30 mm/min is 2 s, plus at most the longer backoff move.
    const double extra = r.total() - evaluate(clean).total();
    EXPECT_GE(std::get<warning::BackoffExcess>(w->figures).wasted_s, 2.0 - 1e-9);
    EXPECT_LE(std::get<warning::BackoffExcess>(w->figures).wasted_s, extra + 1e-9);
    EXPECT_EQ(find_warning(r, WarningCode::backoff_too_small), nullptr);
    EXPECT_FALSE(w->message().empty());
}

TEST(Warnings, NoBackoffWarningsForSingleTouch) {
    Scenario s = surface(Strategy::single_touch, 3000.0);
    for (double backoff : {0.0, 50.0}) {
        s.cycle.backoff_mm = backoff;
        const CycleResult r = evaluate(s);
        EXPECT_EQ(find_warning(r, WarningCode::backoff_too_small), nullptr);
        EXPECT_EQ(find_warning(r, WarningCode::backoff_excess), nullptr);
    }
}

TEST(Warnings, TouchWhileAcceleratingOnTheFirstTouch) {
    Scenario s = surface(Strategy::single_touch, 3000.0);             // the touch that measures
    const double reach = reach_distance_mm(s.motion_limits(), 50.0);  // 1.5 mm
    s.cycle.approach_mm = 0.5 * reach;
    const CycleResult r = evaluate(s);
    const Warning* w = find_warning(r, WarningCode::touch_while_accelerating, 1);
    ASSERT_NE(w, nullptr) << describe(r);
    EXPECT_EQ(w->severity, Severity::warning);
    EXPECT_LT(std::get<warning::TouchWhileAccelerating>(w->figures).speed_mm_s, 50.0);
    EXPECT_NEAR(std::get<warning::TouchWhileAccelerating>(w->figures).feed_mm_s, 50.0, 1e-12);
    s.cycle.approach_mm = reach;  // just reaches the feed
    EXPECT_EQ(find_warning(evaluate(s), WarningCode::touch_while_accelerating), nullptr);
}

TEST(Warnings, TouchWhileAcceleratingOnTheSecondTouch) {
    // Second approach 0.005 mm from where the first touch stops on average
    // (1.805 mm past), the trigger 0.005 mm later, short of the 0.015 mm
    // needed to reach 30 mm/min.
    Scenario s = clean_two_touch();
    s.cycle.backoff_mm = 1.805 + 0.005;
    const CycleResult r = evaluate(s);
    const Warning* w = find_warning(r, WarningCode::touch_while_accelerating, 2);
    ASSERT_NE(w, nullptr) << describe(r);
    EXPECT_LT(std::get<warning::TouchWhileAccelerating>(w->figures).speed_mm_s, 0.5);
    EXPECT_NEAR(std::get<warning::TouchWhileAccelerating>(w->figures).feed_mm_s, 0.5, 1e-12);
    EXPECT_NEAR(r.measuring_touch().touch_speed_mm_s, std::sqrt(2.0 * (0.5 / 0.06) * 0.005), 1e-9);
    EXPECT_EQ(find_warning(r, WarningCode::touch_while_accelerating, 1), nullptr);
}

TEST(Warnings, UncertaintyOverTarget) {
    Scenario s = clean_two_touch();
    const double u = evaluate(s).uncertainty_mm();
    s.cycle.target_uncertainty_mm = 0.5 * u;
    const CycleResult r = evaluate(s);
    const Warning* w = find_warning(r, WarningCode::uncertainty_over_target);
    ASSERT_NE(w, nullptr) << describe(r);
    EXPECT_NEAR(std::get<warning::UncertaintyOverTarget>(w->figures).uncertainty_mm, u, 1e-15);
    EXPECT_NEAR(std::get<warning::UncertaintyOverTarget>(w->figures).target_mm, 0.5 * u, 1e-15);
    EXPECT_FALSE(w->message().empty());
    s.cycle.target_uncertainty_mm = 2.0 * u;
    EXPECT_EQ(find_warning(evaluate(s), WarningCode::uncertainty_over_target), nullptr);
    s.cycle.target_uncertainty_mm = 0.0;  // no target
    EXPECT_EQ(find_warning(evaluate(s), WarningCode::uncertainty_over_target), nullptr);
}

// Repeated measuring touches (cycle.repeats).
TEST(Repeats, SingleTouchReturnsToTheStartAndTouchesAgain) {
    Scenario s = surface(Strategy::single_touch, 3000.0);
    const CycleResult once = evaluate(s);
    s.cycle.repeats = 3.0;
    const CycleResult thrice = evaluate(s);
    // Each repeat is the whole single-touch cycle again: touch, back to the start.
    std::vector<Phase> expected;
    for (int k = 0; k < 3; ++k) {
        const std::vector<Phase> one = phases_of(once);
        expected.insert(expected.end(), one.begin(), one.end());
    }
    EXPECT_EQ(phases_of(thrice), expected) << describe(thrice);
    EXPECT_NEAR(thrice.total(), 3.0 * once.total(), rel_tol(3.0 * once.total()));
    EXPECT_NEAR(thrice.phase_time(Phase::approach), 3.0 * once.phase_time(Phase::approach),
                rel_tol(3.0 * once.phase_time(Phase::approach)));
    // The mean of three: the random parts over sqrt(3); the travel as before.
    EXPECT_NEAR(thrice.trigger_uncertainty_mm(), once.trigger_uncertainty_mm() / std::sqrt(3.0),
                1e-15);
    EXPECT_EQ(thrice.overtravel_mm(), once.overtravel_mm());
    EXPECT_EQ(thrice.scan_range_mm(), once.scan_range_mm());
}

TEST(Repeats, TwoTouchBacksOffFromTheMeasuringTouchAndMeasuresAgain) {
    Scenario s = clean_two_touch();
    const CycleResult once = evaluate(s);
    s.cycle.repeats = 3.0;
    const CycleResult r = evaluate(s);
    ASSERT_TRUE(r.valid()) << describe(r);
    const std::vector<Phase> second = {Phase::backoff,
                                       Phase::second_approach,
                                       Phase::second_pretravel,
                                       Phase::second_interface_delay,
                                       Phase::second_controller_delay,
                                       Phase::second_deceleration};
    std::vector<Phase> expected = {Phase::approach, Phase::pretravel, Phase::interface_delay,
                                   Phase::controller_delay, Phase::deceleration};
    for (int k = 0; k < 3; ++k) expected.insert(expected.end(), second.begin(), second.end());
    expected.push_back(Phase::return_move);
    EXPECT_EQ(phases_of(r), expected) << describe(r);
    // A repeat backs off b from where the measuring touch stopped and
    // approaches b less that touch's overtravel (on average) at the measuring
    // feed.
    const double b = s.cycle.backoff_mm;
    const double o2 = once.measuring_touch().mean_overtravel_mm;
    std::vector<const PhaseRecord*> backoffs;
    std::vector<const PhaseRecord*> approaches;
    for (const PhaseRecord& p : r.phases()) {
        if (p.phase == Phase::backoff) backoffs.push_back(&p);
        if (p.phase == Phase::second_approach) approaches.push_back(&p);
    }
    ASSERT_EQ(backoffs.size(), 3u);
    ASSERT_EQ(approaches.size(), 3u);
    for (int k = 1; k < 3; ++k) {
        EXPECT_NEAR(backoffs[k]->distance_mm, b, 1e-12);
        EXPECT_NEAR(approaches[k]->distance_mm, b - o2, 1e-9);
        // At full measuring feed (the recommended backoff leaves room): (b - o2) / v.
        EXPECT_NEAR(approaches[k]->time_s - approaches[k]->distance_mm / 0.5, 0.5 * 0.06, 1e-9);
    }
    // The two repeats are the same moves.
    EXPECT_EQ(backoffs[1]->time_s, backoffs[2]->time_s);
    EXPECT_EQ(approaches[1]->time_s, approaches[2]->time_s);
    double sum = 0.0;
    for (const PhaseRecord& p : r.phases()) sum += p.time_s;
    EXPECT_NEAR(r.total(), sum, rel_tol(sum, 1e-12));
    EXPECT_NEAR(r.trigger_uncertainty_mm(), once.trigger_uncertainty_mm() / std::sqrt(3.0), 1e-15);
    EXPECT_GT(r.total(), once.total());
}

TEST(Repeats, EveryTouchPointOfAFeatureRepeatsAndEveryBackoffCountsAsWasted) {
    Scenario s = clean_two_touch();
    s.cycle.feature = Feature::bore;
    s.cycle.repeats = 2.0;
    const CycleResult r = evaluate(s);
    int measuring = 0;
    for (const PhaseRecord& p : r.phases()) measuring += p.phase == Phase::second_approach;
    EXPECT_EQ(measuring, 4 * 2);
    // 1 mm more backoff at 30 mm/min: 2 s per backoff, two per touch point.
    s.cycle.backoff_mm += 1.0;
    const CycleResult longer = evaluate(s);
    const Warning* w = find_warning(longer, WarningCode::backoff_excess);
    ASSERT_NE(w, nullptr) << describe(longer);
    EXPECT_GE(std::get<warning::BackoffExcess>(w->figures).wasted_s, 4 * 2 * 2.0 - 1e-9);
    EXPECT_LE(std::get<warning::BackoffExcess>(w->figures).wasted_s,
              longer.total() - r.total() + 1e-9);
}

TEST(Warnings, FeedOverTheProbesRatingIsAnError) {
    Scenario s = clean_two_touch();  // 3000 then 30 mm/min
    s.probe.max_feed_mm_min = 2000.0;
    CycleResult r = evaluate(s);
    const Warning* w = find_warning(r, WarningCode::feed_over_probe_limit);
    ASSERT_NE(w, nullptr) << describe(r);
    EXPECT_EQ(w->severity, Severity::error);
    EXPECT_FALSE(r.valid());
    EXPECT_NEAR(std::get<warning::FeedOverProbeLimit>(w->figures).feed_mm_s, 50.0, 1e-12);
    EXPECT_NEAR(std::get<warning::FeedOverProbeLimit>(w->figures).max_feed_mm_s, 2000.0 / 60.0,
                1e-12);
    EXPECT_FALSE(std::get<warning::FeedOverProbeLimit>(w->figures).measuring);
    EXPECT_NE(w->message().find("Probing feed 3000 mm/min is over the probe's rated maximum 2000"),
              std::string::npos)
        << w->message();
    // At the rating, or with no rating, it is no error.
    s.probe.max_feed_mm_min = 3000.0;
    EXPECT_EQ(find_warning(evaluate(s), WarningCode::feed_over_probe_limit), nullptr);
    s.probe.max_feed_mm_min = 0.0;
    EXPECT_EQ(find_warning(evaluate(s), WarningCode::feed_over_probe_limit), nullptr);
    // A measuring feed over it is named as such.
    s.probe.max_feed_mm_min = 40.0;
    s.cycle.probe_feed_mm_min = 35.0;
    s.cycle.measure_feed_mm_min = 50.0;
    r = evaluate(s);
    w = find_warning(r, WarningCode::feed_over_probe_limit);
    ASSERT_NE(w, nullptr) << describe(r);
    EXPECT_TRUE(std::get<warning::FeedOverProbeLimit>(w->figures).measuring);
    EXPECT_NE(w->message().find("Measuring feed"), std::string::npos) << w->message();
}

TEST(Warnings, StartInsideThePartsPositionUncertainty) {
    // Single-touch: the touch measures, so it must be at full feed wherever
    // the part lies (two-touch: Fixes.TwoTouchStartsOnlyNeedToClearTheUncertainty).
    Scenario s = surface(Strategy::single_touch, 3000.0);
    const double room = approach_room_mm(s, 50.0);  // 1.5 mm to reach 3000 mm/min
    ASSERT_NEAR(room, 1.5, 1e-9);
    s.cycle.part_position_uncertainty_mm = 2.0;
    struct {
        double approach_mm;
        bool warns;
        bool inside;
    } cases[] = {{1.0, true, true},
                 {2.0, true, true},
                 {3.0, true, false},
                 {3.5, false, false},
                 {5.0, false, false}};
    for (const auto& c : cases) {
        SCOPED_TRACE(c.approach_mm);
        s.cycle.approach_mm = c.approach_mm;
        const CycleResult r = evaluate(s);
        const Warning* w = find_warning(r, WarningCode::start_inside_uncertainty);
        ASSERT_EQ(w != nullptr, c.warns) << describe(r);
        if (w == nullptr) continue;
        EXPECT_EQ(w->severity, Severity::warning);
        EXPECT_EQ(std::get<warning::StartInsideUncertainty>(w->figures).inside, c.inside);
        EXPECT_NE(w->message().find("start at least 3.500 mm out"), std::string::npos)
            << w->message();
        // The one-click fix starts the uncertainty plus the room out, and clears it.
        const std::optional<Fix> fix = fix_for(s, analyse(s), *w);
        ASSERT_TRUE(fix.has_value());
        EXPECT_NEAR(fix->scenario.cycle.approach_mm, 3.5, 1e-12);
        EXPECT_EQ(find_warning(evaluate(fix->scenario), WarningCode::start_inside_uncertainty),
                  nullptr);
    }
    // A known part (0) never warns.
    s.cycle.part_position_uncertainty_mm = 0.0;
    s.cycle.approach_mm = 1.5;
    EXPECT_EQ(find_warning(evaluate(s), WarningCode::start_inside_uncertainty), nullptr);
}

// Where each touch's probing move ends, by hand. At 3000 mm/min (T = 0.06 s)
// the first touch stops 1.905 mm past the surface (pretravel 0.005, 50 mm/s
// through 8 ms of delays, 1.5 mm of braking), the measuring touch at 30
// mm/min 0.024 mm past it; the probe's limit is 5 mm.
TEST(Search, EachTouchSearchesPastItsStopFromTheFarthestSurface) {
    Scenario s = clean_two_touch();  // backoff 2.105 mm
    CycleResult r = evaluate(s);
    ASSERT_NEAR(r.first_touch().overtravel_mm, 1.905, 1e-12);
    ASSERT_NEAR(r.measuring_touch().overtravel_mm, 0.024, 1e-12);
    // Automatic: halfway from the stop to the limit, past the farthest surface:
    // the nominal one for the first touch, the first touch's stop (the whole
    // backoff away) for the measuring touch.
    EXPECT_NEAR(search_beyond_mm(s, 1.905), 3.4525, 1e-12);
    EXPECT_NEAR(r.first_touch().search_mm, 5.0 + 3.4525, 1e-12);
    EXPECT_NEAR(r.measuring_touch().search_mm, 2.105 + 2.512, 1e-12);
    // The part may lie 0.75 mm farther: the first search goes that much farther.
    s.cycle.part_position_uncertainty_mm = 0.75;
    s.cycle.approach_mm = 5.0;
    r = evaluate(s);
    EXPECT_NEAR(r.first_touch().search_mm, 5.75 + 3.4525, 1e-12);
    EXPECT_NEAR(r.measuring_touch().search_mm, 2.105 + 2.512, 1e-12);
    // Backed off from the recorded trigger, the backoff move is longer by the
    // stop's distance from it, and the measuring search covers it too.
    s.cycle.backoff_from = BackoffFrom::trigger;
    r = evaluate(s);
    const TouchResult& first = r.first_touch();
    EXPECT_NEAR(r.measuring_touch().search_mm,
                2.105 + first.overtravel_mm - first.recorded_mm + 2.512, 1e-12);
    // Set by hand, every search goes that far past its farthest surface.
    s = clean_two_touch();
    s.cycle.search_beyond_mm = 2.0;
    r = evaluate(s);
    EXPECT_NEAR(r.first_touch().search_mm, 7.0, 1e-12);
    EXPECT_NEAR(r.measuring_touch().search_mm, 4.105, 1e-12);
    EXPECT_EQ(find_warning(r, WarningCode::search_ends_too_soon), nullptr) << describe(r);
    // A probe whose limit its stop already overruns searches to the stop.
    EXPECT_DOUBLE_EQ(search_beyond_mm(Scenario{}, 6.0), 6.0);
}

TEST(Search, ASearchSetByHandThatEndsBeforeTheStopIsAnError) {
    Scenario s = clean_two_touch();
    s.cycle.search_beyond_mm = 1.5;
    CycleResult r = evaluate(s);
    const Warning* w = find_warning(r, WarningCode::search_ends_too_soon);
    ASSERT_NE(w, nullptr) << describe(r);
    EXPECT_EQ(w->severity, Severity::error);
    EXPECT_FALSE(r.valid());
    EXPECT_NEAR(std::get<warning::SearchEndsTooSoon>(w->figures).search_beyond_mm, 1.5, 1e-12);
    EXPECT_NEAR(std::get<warning::SearchEndsTooSoon>(w->figures).stop_mm, 1.905, 1e-12);
    EXPECT_EQ(std::get<warning::SearchEndsTooSoon>(w->figures).touch, 1);
    EXPECT_EQ(w->message(),
              "The search ends 1.500 mm past the farthest place the surface can be, before the "
              "first touch's stop 1.905 mm past it: the axis is braking when it touches, "
              "triggers below the feed and stops at the search end; search at least 1.905 mm "
              "past the surface");
    // A measuring touch faster than the first stops farther: that touch is named.
    s = surface(Strategy::two_touch, 300.0);
    s.cycle.measure_feed_mm_min = 3000.0;
    s.cycle.backoff_mm = evaluate(s).recommended_backoff_mm();
    s.cycle.search_beyond_mm = 1.0;
    r = evaluate(s);
    w = find_warning(r, WarningCode::search_ends_too_soon);
    ASSERT_NE(w, nullptr) << describe(r);
    EXPECT_EQ(std::get<warning::SearchEndsTooSoon>(w->figures).touch, 2);
    EXPECT_NEAR(std::get<warning::SearchEndsTooSoon>(w->figures).stop_mm, 1.905, 1e-12);
    EXPECT_EQ(w->to_message().args.back().number, 2.0);  // the touch, a whole number
    // Automatic never ends too soon.
    s.cycle.search_beyond_mm = 0.0;
    EXPECT_EQ(find_warning(evaluate(s), WarningCode::search_ends_too_soon), nullptr);
}

// A feature's protected moves, by hand. An obstruction met at 8000 mm/min
// (133.33 mm/s, T = 0.06 s) stops 0.005 + 133.33 * 0.008 + 133.33 * 0.03 =
// 5.0717 mm past it: over the 5 mm limit, an error. The fix: the highest
// feed under 80 % of the limit, 0.005 + 0.038 v < 4, 6307 mm/min.
TEST(Warnings, ProtectedMovesAreTouchesAtThePositioningFeed) {
    Scenario s;
    s.cycle.feed_override_max_pct = 100.0;  // at the programmed feeds
    s.cycle.feature = Feature::bore;
    s.cycle.position_feed_mm_min = 8000.0;
    EXPECT_NEAR(protected_move_overtravel_mm(s, 8000.0 / 60.0), 0.005 + 0.038 * 8000.0 / 60.0,
                1e-12);
    const Analysis a = analyse(s);
    const Warning* w = find_warning(a.cycle, WarningCode::protected_move_overtravel);
    ASSERT_NE(w, nullptr) << describe(a.cycle);
    EXPECT_EQ(w->severity, Severity::error);
    EXPECT_FALSE(a.cycle.valid());
    EXPECT_NEAR(std::get<warning::ProtectedMoveOvertravel>(w->figures).overtravel_mm,
                5.0716666666666, 1e-9);
    EXPECT_EQ(w->message(),
              "A protected move at the positioning feed 8000 mm/min that meets an obstruction "
              "stops 5.072 mm past it, 101 % of the probe's 5.000 mm limit: the stylus would be "
              "overrun; lower the positioning feed");
    const std::optional<Fix> fix = fix_for(s, a, *w);
    ASSERT_TRUE(fix.has_value());
    EXPECT_EQ(fix->kind, FixKind::position_feed_for_overtravel);
    EXPECT_EQ(fix->scenario.cycle.position_feed_mm_min, 6307.0);
    EXPECT_TRUE(evaluate(fix->scenario).valid());
    // No probing feed changes it: the knee still says where the probing feed
    // is best, not that no feed is valid.
    EXPECT_TRUE(a.knee_feed_mm_min.has_value());
    EXPECT_EQ(find_warning(a.cycle, WarningCode::no_valid_feed), nullptr);
    // Between 80 % and the limit, a warning; a surface has no protected moves.
    s.cycle.position_feed_mm_min = 7000.0;
    const CycleResult near = evaluate(s);
    w = find_warning(near, WarningCode::protected_move_overtravel);
    ASSERT_NE(w, nullptr);
    EXPECT_EQ(w->severity, Severity::warning);
    s.cycle.feature = Feature::surface;
    s.cycle.position_feed_mm_min = 8000.0;
    EXPECT_EQ(find_warning(evaluate(s), WarningCode::protected_move_overtravel), nullptr);
    // The Fanuc-type machine drains its lags too: 11.3 mm at 8000 mm/min.
    Scenario fanuc = merge_json(Scenario{}, R"({"machine": {"accel_model": "none",
        "filter": "exponential", "filter_time_s": 0.032, "servo_time_constant_s": 0.033,
        "controller_latency_s": 0.014}, "cycle": {"feed_override_max_pct": 100}})");
    EXPECT_NEAR(protected_move_overtravel_mm(fanuc, 8000.0 / 60.0),
                0.005 + 8000.0 / 60.0 * (0.002 + 0.014 + 0.004 + 0.032 + 0.033), 1e-9);
    // At 150 % feed override the move runs at 12000 mm/min: 17.0 mm.
    fanuc.cycle.feed_override_max_pct = 150.0;
    EXPECT_NEAR(protected_move_overtravel_mm(fanuc, 8000.0 / 60.0),
                0.005 + 12000.0 / 60.0 * (0.002 + 0.014 + 0.004 + 0.032 + 0.033), 1e-9);
}

TEST(Warnings, CalibrationFeedMismatch) {
    Scenario s = clean_two_touch();
    s.probe.calibration_feed_mm_min = 60.0;  // measuring at 30
    const CycleResult r = evaluate(s);
    const Warning* w = find_warning(r, WarningCode::calibration_feed_mismatch);
    ASSERT_NE(w, nullptr) << describe(r);
    EXPECT_NEAR(std::get<warning::CalibrationFeedMismatch>(w->figures).speed_mm_s, 0.5, 1e-12);
    EXPECT_NEAR(std::get<warning::CalibrationFeedMismatch>(w->figures).calibration_speed_mm_s, 1.0,
                1e-12);
    // (0.5 - 1.0) * (0.002 + 0.002 + 0.004 / 2) = -0.003 mm
    EXPECT_NEAR(std::abs(std::get<warning::CalibrationFeedMismatch>(w->figures).error_mm), 0.003,
                1e-12);
    EXPECT_NEAR(std::get<warning::CalibrationFeedMismatch>(w->figures).error_mm,
                speed_error_mm(s.machine, s.probe, 0.5, 1.0), 1e-12);
    EXPECT_FALSE(w->message().empty());

    s.probe.calibration_feed_mm_min = 30.0;
    EXPECT_EQ(find_warning(evaluate(s), WarningCode::calibration_feed_mismatch), nullptr);
    s.probe.calibration_feed_mm_min = 0.0;
    EXPECT_EQ(find_warning(evaluate(s), WarningCode::calibration_feed_mismatch), nullptr);

    // Single-touch measures at the probe feed.
    Scenario single = surface(Strategy::single_touch, 3000.0);
    single.probe.calibration_feed_mm_min = 3000.0;
    EXPECT_EQ(find_warning(evaluate(single), WarningCode::calibration_feed_mismatch), nullptr);
    single.probe.calibration_feed_mm_min = 30.0;
    const CycleResult single_result = evaluate(single);
    const Warning* ws = find_warning(single_result, WarningCode::calibration_feed_mismatch);
    ASSERT_NE(ws, nullptr);
    // (50 - 0.5) * 0.006 = 0.297 mm
    EXPECT_NEAR(std::abs(std::get<warning::CalibrationFeedMismatch>(ws->figures).error_mm), 0.297,
                1e-12);
}

TEST(Warnings, FeedBeyondKneeOnlyFromAnalyse) {
    Scenario s = surface(Strategy::single_touch, 9000.0);
    s.probe.overtravel_limit_mm = 50.0;
    const Analysis fast = analyse(s);
    ASSERT_TRUE(fast.knee_feed_mm_min.has_value());
    ASSERT_LT(*fast.knee_feed_mm_min, 9000.0);
    const Warning* w = find_warning(fast.cycle, WarningCode::feed_beyond_knee);
    ASSERT_NE(w, nullptr) << describe(fast.cycle);
    EXPECT_EQ(w->severity, Severity::info);
    EXPECT_NEAR(std::get<warning::FeedBeyondKnee>(w->figures).feed_mm_s, 150.0, 1e-9);
    EXPECT_NEAR(std::get<warning::FeedBeyondKnee>(w->figures).knee_feed_mm_s,
                mm_min_to_mm_s(*fast.knee_feed_mm_min), 1e-9);
    EXPECT_LT(std::get<warning::FeedBeyondKnee>(w->figures).time_saved_s,
              kDefaultKneeTolerance * fast.cycle.total());
    EXPECT_FALSE(w->message().empty());
    // evaluate() alone never gives it.
    EXPECT_EQ(find_warning(evaluate(s), WarningCode::feed_beyond_knee), nullptr);
    // Below the knee: absent.
    s.cycle.probe_feed_mm_min = 0.5 * *fast.knee_feed_mm_min;
    const Analysis slow = analyse(s);
    EXPECT_EQ(find_warning(slow.cycle, WarningCode::feed_beyond_knee), nullptr)
        << describe(slow.cycle);
}

// ---------------------------------------------------------------------------
// Randomized properties, fixed seed.

Scenario random_scenario(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto log_uniform = [&](double lo, double hi) {
        return std::exp(std::log(lo) + u(rng) * (std::log(hi) - std::log(lo)));
    };
    Scenario s;
    s.machine.accel_model = static_cast<AccelModel>(rng() % 3);
    s.machine.time_constant_s = log_uniform(0.02, 0.2);
    s.machine.max_accel_mm_s2 = log_uniform(300.0, 10000.0);
    s.machine.max_jerk_mm_s3 = log_uniform(5000.0, 1e6);
    s.machine.rapid_feed_mm_min = log_uniform(10000.0, 60000.0);
    s.machine.scan_period_s = log_uniform(1e-6, 0.01);
    s.machine.controller_latency_s = log_uniform(1e-4, 0.01);
    s.machine.latched_input = rng() % 4 == 0;
    s.probe.pretravel_mm = log_uniform(0.001, 0.05);
    s.probe.interface_delay_s = log_uniform(1e-4, 0.01);
    s.probe.repeatability_2sigma_mm = log_uniform(1e-4, 0.005);
    s.probe.overtravel_limit_mm = log_uniform(1.0, 20.0);
    s.probe.reseat_mm = log_uniform(0.05, 0.5);
    s.probe.calibration_feed_mm_min = rng() % 3 == 0 ? log_uniform(10.0, 3000.0) : 0.0;
    s.cycle.strategy = static_cast<Strategy>(rng() % 2);
    s.cycle.feature = static_cast<Feature>(rng() % 5);
    s.cycle.feature_size_mm = log_uniform(30.0, 200.0);
    s.cycle.approach_mm = log_uniform(0.05, 10.0);
    s.cycle.probe_feed_mm_min = log_uniform(50.0, 8000.0);
    s.cycle.measure_feed_mm_min = log_uniform(10.0, 200.0);
    s.cycle.backoff_mm = log_uniform(0.2, 10.0);
    // No programmed feed above the rapid.
    s.cycle.return_feed_mm_min = log_uniform(1000.0, s.machine.rapid_feed_mm_min);
    s.cycle.position_feed_mm_min = log_uniform(500.0, s.machine.rapid_feed_mm_min);
    s.cycle.clearance_mm = log_uniform(1.0, 50.0);
    s.cycle.target_uncertainty_mm = rng() % 2 == 0 ? log_uniform(1e-4, 0.05) : 0.0;
    s.machine.block_change_s = rng() % 3 == 0 ? log_uniform(1e-4, 0.02) : 0.0;
    s.cycle.feed_override_max_pct = rng() % 2 == 0 ? 100.0 : 100.0 + 100.0 * u(rng);
    return s;
}

constexpr int kRandomCycles = 3000;

// Whether `value` is clearly on one side of `threshold`; ties are left alone.
bool clearly_above(double value, double threshold) {
    return value > threshold * (1 + 1e-9);
}
bool clearly_below(double value, double threshold) {
    return value < threshold * (1 - 1e-9);
}

class RandomCycles : public testing::Test {
  protected:
    template <typename Check>
    void for_each_cycle(Check check) {
        std::mt19937_64 rng{42};
        int valid = 0;
        for (int i = 0; i < kRandomCycles; ++i) {
            const Scenario s = random_scenario(rng);
            if (!validate(s).empty()) continue;
            ++valid;
            const CycleResult r = evaluate(s);
            SCOPED_TRACE("case " + std::to_string(i) + "\n" + scenario_to_json(s) + "\n" +
                         describe(r));
            check(s, r);
            if (HasFailure()) return;
        }
        EXPECT_GT(valid, kRandomCycles * 9 / 10);
    }
};

TEST_F(RandomCycles, PhaseTimesSumToTheTotalAndPhasesAreContiguous) {
    for_each_cycle([](const Scenario&, const CycleResult& r) {
        ASSERT_FALSE(r.phases().empty());
        EXPECT_EQ(r.phases()[0].start_s, 0.0);
        double sum = 0.0;
        std::array<double, kPhaseCount> by_phase{};
        for (std::size_t k = 0; k < r.phases().size(); ++k) {
            const PhaseRecord& p = r.phases()[k];
            EXPECT_GE(p.time_s, 0.0);
            EXPECT_GE(p.distance_mm, 0.0);
            if (k > 0) {
                const PhaseRecord& prev = r.phases()[k - 1];
                EXPECT_NEAR(p.start_s, prev.start_s + prev.time_s, rel_tol(r.total()));
            }
            sum += p.time_s;
            by_phase[static_cast<std::size_t>(p.phase)] += p.time_s;
        }
        EXPECT_NEAR(sum, r.total(), rel_tol(r.total()));
        for (Phase phase : all_phases()) {
            EXPECT_NEAR(r.phase_time(phase), by_phase[static_cast<std::size_t>(phase)],
                        rel_tol(r.total()))
                << to_string(phase);
        }
    });
}

TEST_F(RandomCycles, PhaseSequencePerTouchPoint) {
    for_each_cycle([](const Scenario& s, const CycleResult& r) {
        const std::vector<Phase> expected = cycle_sequence(s.cycle.strategy, s.cycle.feature);
        const double ot1 = r.first_touch().overtravel_mm;
        if (s.cycle.strategy == Strategy::single_touch || s.cycle.backoff_mm > ot1 * 1.001) {
            EXPECT_EQ(moves_of(r), expected);
        } else {
            EXPECT_TRUE(is_subsequence(moves_of(r), expected));
        }
        // With a block change, after every block and nowhere else.
        const std::vector<Phase> all = phases_of(r);
        for (std::size_t k = 0; k < all.size(); ++k) {
            const bool change = all[k] == Phase::block_change;
            if (change) {
                ASSERT_GT(k, 0u);
                EXPECT_TRUE(ends_a_block(all[k - 1])) << to_string(all[k - 1]);
            }
            if (ends_a_block(all[k]) && s.machine.block_change_s > 0.0) {
                ASSERT_LT(k + 1, all.size());
                EXPECT_EQ(all[k + 1], Phase::block_change) << "after " << to_string(all[k]);
            }
            if (change) {
                EXPECT_NEAR(r.phases()[k].time_s, s.machine.block_change_s, 1e-15);
            }
        }
        if (s.machine.block_change_s == 0.0) {
            EXPECT_EQ(r.phase_time(Phase::block_change), 0.0);
        }
        // Touch indices: 0, 1, ... in order, one per touch point.
        int last = 0;
        for (const PhaseRecord& p : r.phases()) {
            EXPECT_GE(p.touch, last);
            EXPECT_LE(p.touch, last + 1);
            last = p.touch;
        }
        EXPECT_EQ(last, touch_count(s.cycle.feature) - 1);
    });
}

TEST_F(RandomCycles, FormulasOfATouchAtFullSpeed) {
    for_each_cycle([](const Scenario& s, const CycleResult& r) {
        const MotionLimits limits = s.motion_limits();
        const double v = mm_min_to_mm_s(s.cycle.probe_feed_mm_min);
        const TouchResult& first = r.first_touch();
        EXPECT_NEAR(first.programmed_feed_mm_s, v, rel_tol(v));
        // Room to reseat and to reach the measuring feed, whichever is more.
        const double room =
            std::max(s.probe.reseat_mm,
                     reach_distance_mm(limits, mm_min_to_mm_s(s.cycle.measure_feed_mm_min)));
        // Rounded up to the micrometre; and at the highest feed override, room
        // to reseat.
        const double needed =
            std::max(first.overtravel_mm + room, first.override_overtravel_mm + s.probe.reseat_mm);
        EXPECT_GE(r.recommended_backoff_mm(), needed - rel_tol(needed));
        EXPECT_LT(r.recommended_backoff_mm(), needed + kBackoffStep_mm);
        EXPECT_NEAR(std::remainder(r.recommended_backoff_mm(), kBackoffStep_mm), 0.0, 1e-9);
        EXPECT_NEAR(r.overtravel_mm(),
                    std::max(first.overtravel_mm, r.measuring_touch().overtravel_mm), 1e-12);
        EXPECT_NEAR(
            r.checked_overtravel_mm(),
            std::max(first.override_overtravel_mm, r.measuring_touch().override_overtravel_mm),
            1e-12);
        EXPECT_GE(first.override_overtravel_mm, first.overtravel_mm);
        EXPECT_GE(r.measuring_touch().override_overtravel_mm, r.measuring_touch().overtravel_mm);
        const double s_approach = s.cycle.approach_mm;
        const double touch_expected = speed_after_mm_s(limits, v, s_approach);
        EXPECT_NEAR(first.touch_speed_mm_s, touch_expected, rel_tol(touch_expected, 1e-9));
        if (s_approach < reach_distance_mm(limits, v)) return;
        const double t_react = reaction_time_s(s.machine, s.probe);
        EXPECT_NEAR(
            t_react,
            s.probe.interface_delay_s + s.machine.controller_latency_s + s.machine.scan_period_s,
            1e-15);
        EXPECT_NEAR(first.trigger_speed_mm_s, v, rel_tol(v));
        EXPECT_NEAR(first.react_speed_mm_s, v, rel_tol(v));
        const double ot = s.probe.pretravel_mm + v * t_react + stop_distance_mm(limits, v, v);
        EXPECT_NEAR(first.overtravel_mm, ot, rel_tol(ot, 1e-9));
        // The timeline waits half a scan on average.
        const double wait = s.machine.controller_latency_s + 0.5 * s.machine.scan_period_s;
        const double mean_ot = ot - 0.5 * v * s.machine.scan_period_s;
        EXPECT_NEAR(first.mean_overtravel_mm, mean_ot, rel_tol(mean_ot, 1e-9));
        // clang-format off
        const struct { Phase phase; double time_s; double distance_mm; } expected[] = {
            {Phase::approach,         reach_time_s(limits, v) + (s_approach - reach_distance_mm(limits, v)) / v, s_approach},
            {Phase::pretravel,        s.probe.pretravel_mm / v,            s.probe.pretravel_mm},
            {Phase::interface_delay,  s.probe.interface_delay_s,           v * s.probe.interface_delay_s},
            {Phase::controller_delay, wait,                                v * wait},
            {Phase::deceleration,     stop_time_s(limits, v, v),           stop_distance_mm(limits, v, v)},
        };
        // clang-format on
        for (const auto& e : expected) {
            const PhaseRecord* p = find_phase(r, e.phase);
            ASSERT_NE(p, nullptr) << to_string(e.phase);
            EXPECT_NEAR(p->time_s, e.time_s, rel_tol(e.time_s, 1e-9)) << to_string(e.phase);
            EXPECT_NEAR(p->distance_mm, e.distance_mm, rel_tol(e.distance_mm, 1e-9))
                << to_string(e.phase);
        }
    });
}

TEST_F(RandomCycles, SecondTouchAndReturn) {
    for_each_cycle([](const Scenario& s, const CycleResult& r) {
        const MotionLimits limits = s.motion_limits();
        const TouchResult& m = r.measuring_touch();
        const double v_return = mm_min_to_mm_s(s.cycle.return_feed_mm_min);
        // Return from where the last touch stopped to the start position.
        const PhaseRecord* ret = find_phase(r, Phase::return_move);
        ASSERT_NE(ret, nullptr);
        const double stopped_at = r.state_at(ret->start_s).position_mm;
        EXPECT_NEAR(ret->distance_mm, stopped_at, 1e-9 * (1.0 + stopped_at));
        EXPECT_NEAR(ret->time_s, move_time_s(limits, ret->distance_mm, v_return),
                    rel_tol(ret->time_s, 1e-9));
        const bool reseated = s.cycle.strategy == Strategy::single_touch ||
                              s.cycle.backoff_mm >= r.first_touch().overtravel_mm;
        if (reseated) {
            // Stopped, on average, `mean_overtravel` beyond the surface.
            const double d_return = s.cycle.approach_mm + m.mean_overtravel_mm;
            EXPECT_NEAR(ret->distance_mm, d_return, rel_tol(d_return, 1e-9));
        }
        // Uncertainty of the measuring touch.
        const double range =
            s.machine.latched_input ? 0.0 : m.trigger_speed_mm_s * s.machine.scan_period_s;
        EXPECT_NEAR(r.trigger_speed_mm_s(), m.trigger_speed_mm_s, 1e-15);
        EXPECT_NEAR(r.scan_range_mm(), range, rel_tol(range));
        EXPECT_NEAR(r.trigger_uncertainty_mm(),
                    expanded_uncertainty_mm(range, s.probe.repeatability_2sigma_mm),
                    rel_tol(r.trigger_uncertainty_mm()));
        if (s.cycle.strategy == Strategy::single_touch) {
            EXPECT_NEAR(m.overtravel_mm, r.first_touch().overtravel_mm, 1e-15);
            EXPECT_NEAR(m.trigger_speed_mm_s, r.first_touch().trigger_speed_mm_s, 1e-15);
            return;
        }
        const double vm = mm_min_to_mm_s(s.cycle.measure_feed_mm_min);
        EXPECT_NEAR(m.programmed_feed_mm_s, vm, rel_tol(vm));
        const PhaseRecord* backoff = find_phase(r, Phase::backoff);
        ASSERT_NE(backoff, nullptr);
        EXPECT_NEAR(backoff->distance_mm, s.cycle.backoff_mm, rel_tol(s.cycle.backoff_mm));
        EXPECT_GE(backoff->time_s, move_time_s(limits, s.cycle.backoff_mm,
                                               mm_min_to_mm_s(s.machine.rapid_feed_mm_min)) *
                                       (1 - 1e-12));
        const double gap = s.cycle.backoff_mm - r.first_touch().mean_overtravel_mm;
        if (gap < reach_distance_mm(limits, vm) * 1.001) return;
        const PhaseRecord* second = find_phase(r, Phase::second_approach);
        ASSERT_NE(second, nullptr);
        EXPECT_NEAR(second->distance_mm, gap, rel_tol(gap, 1e-9));
        const double t = reach_time_s(limits, vm) + (gap - reach_distance_mm(limits, vm)) / vm;
        EXPECT_NEAR(second->time_s, t, rel_tol(t, 1e-9));
        EXPECT_NEAR(m.touch_speed_mm_s, vm, rel_tol(vm));
        const double ot2 = s.probe.pretravel_mm + vm * reaction_time_s(s.machine, s.probe) +
                           stop_distance_mm(limits, vm, vm);
        EXPECT_NEAR(m.overtravel_mm, ot2, rel_tol(ot2, 1e-9));
    });
}

TEST_F(RandomCycles, EveryWarningExactlyWhenItsConditionHolds) {
    for_each_cycle([](const Scenario& s, const CycleResult& r) {
        const MotionLimits limits = s.motion_limits();
        const double ot = r.checked_overtravel_mm();
        const double limit = s.probe.overtravel_limit_mm;
        const Warning* w = find_warning(r, WarningCode::overtravel_limit);
        if (clearly_above(ot, limit)) {
            ASSERT_NE(w, nullptr);
            EXPECT_EQ(w->severity, Severity::error);
        } else if (clearly_above(ot, 0.8 * limit) && clearly_below(ot, limit)) {
            ASSERT_NE(w, nullptr);
            EXPECT_EQ(w->severity, Severity::warning);
        } else if (clearly_below(ot, 0.8 * limit)) {
            EXPECT_EQ(w, nullptr);
        }

        const bool two = s.cycle.strategy == Strategy::two_touch;
        const double b = s.cycle.backoff_mm;
        const double rec = r.recommended_backoff_mm();
        const bool too_small = find_warning(r, WarningCode::backoff_too_small) != nullptr;
        const bool excess = find_warning(r, WarningCode::backoff_excess) != nullptr;
        if (!two) {
            EXPECT_FALSE(too_small);
            EXPECT_FALSE(excess);
        } else {
            if (clearly_below(b, rec)) {
                EXPECT_TRUE(too_small);
            }
            if (clearly_above(b, rec)) {
                EXPECT_FALSE(too_small);
            }
            if (b <= rec) {
                EXPECT_FALSE(excess);
            }
            // Reported past 10 % of the recommendation, at least 0.05 mm.
            if (b - rec > std::max(0.1 * rec, 0.05) + 1e-6) {
                EXPECT_TRUE(excess);
            }
        }

        const double v = mm_min_to_mm_s(s.cycle.probe_feed_mm_min);
        const double reach = reach_distance_mm(limits, v);
        // Reported for the touch that measures: the only one of single-touch.
        const bool accel_first =
            find_warning(r, WarningCode::touch_while_accelerating, 1) != nullptr;
        if (two) {
            EXPECT_FALSE(accel_first);
        }
        // Certainly when the probe also triggers before reaching the feed and
        // the error is over what counts as negligible.
        const double tau = measurement_delay_s(s.machine, s.probe);
        const auto error_of = [&](const TouchResult& t) {
            return t.programmed_feed_mm_s * tau - t.delay_travel_mm;
        };
        if (!two && clearly_below(s.cycle.approach_mm + s.probe.pretravel_mm, reach) &&
            clearly_above(error_of(r.first_touch()), kAccelErrorTolerance_mm)) {
            EXPECT_TRUE(accel_first);
        }
        if (clearly_above(s.cycle.approach_mm, reach)) {
            EXPECT_FALSE(accel_first);
        }
        if (two) {
            const double vm = mm_min_to_mm_s(s.cycle.measure_feed_mm_min);
            const double gap = b - r.first_touch().mean_overtravel_mm;
            const bool accel_second =
                find_warning(r, WarningCode::touch_while_accelerating, 2) != nullptr;
            if (gap > 0.0 &&
                clearly_below(gap + s.probe.pretravel_mm, reach_distance_mm(limits, vm)) &&
                clearly_above(error_of(r.measuring_touch()), kAccelErrorTolerance_mm)) {
                EXPECT_TRUE(accel_second);
            }
            if (clearly_above(gap, reach_distance_mm(limits, vm))) {
                EXPECT_FALSE(accel_second);
            }
        }

        const double target = s.cycle.target_uncertainty_mm;
        const bool over = find_warning(r, WarningCode::uncertainty_over_target) != nullptr;
        if (target == 0.0 || clearly_below(r.uncertainty_mm(), target)) {
            EXPECT_FALSE(over);
        }
        if (target > 0.0 && clearly_above(r.uncertainty_mm(), target)) {
            EXPECT_TRUE(over);
        }

        const double measuring_feed = two ? s.cycle.measure_feed_mm_min : s.cycle.probe_feed_mm_min;
        const double cal = s.probe.calibration_feed_mm_min;
        const Warning* mismatch = find_warning(r, WarningCode::calibration_feed_mismatch);
        if (cal == 0.0 || cal == measuring_feed) {
            EXPECT_EQ(mismatch, nullptr);
        } else {
            ASSERT_NE(mismatch, nullptr);
            const double expected = speed_error_mm(
                s.machine, s.probe, mm_min_to_mm_s(measuring_feed), mm_min_to_mm_s(cal));
            EXPECT_NEAR(
                std::abs(std::get<warning::CalibrationFeedMismatch>(mismatch->figures).error_mm),
                std::abs(expected), rel_tol(expected, 1e-9));
        }
        EXPECT_EQ(find_warning(r, WarningCode::feed_beyond_knee), nullptr);
        for (const Warning& warning : r.warnings()) EXPECT_FALSE(warning.message().empty());
    });
}

TEST_F(RandomCycles, StateAlongTheCycle) {
    for_each_cycle([](const Scenario& s, const CycleResult& r) {
        const double v_max = mm_min_to_mm_s(std::max(
            {s.cycle.probe_feed_mm_min, s.cycle.measure_feed_mm_min, s.cycle.return_feed_mm_min,
             s.machine.rapid_feed_mm_min, s.cycle.position_feed_mm_min}));
        const CycleState start = r.state_at(0.0);
        EXPECT_EQ(start.position_mm, 0.0);
        EXPECT_EQ(start.velocity_mm_s, 0.0);
        // Surface at the end of the approach; stop at approach + the mean overtravel.
        const PhaseRecord& approach = *find_phase(r, Phase::approach);
        const CycleState touch = r.state_at(approach.start_s + approach.time_s);
        EXPECT_NEAR(touch.position_mm, s.cycle.approach_mm, 1e-9 * (1 + s.cycle.approach_mm));
        EXPECT_NEAR(touch.velocity_mm_s, r.first_touch().touch_speed_mm_s, 1e-9 * v_max);
        const PhaseRecord* decel = find_phase(r, Phase::deceleration);
        ASSERT_NE(decel, nullptr);
        const CycleState stop = r.state_at(decel->start_s + decel->time_s);
        EXPECT_NEAR(stop.position_mm, s.cycle.approach_mm + r.first_touch().mean_overtravel_mm,
                    1e-9);
        EXPECT_NEAR(stop.velocity_mm_s, 0.0, 1e-9 * v_max);
        const CycleState end = r.state_at(r.total());
        EXPECT_NEAR(end.position_mm, 0.0, 1e-9);
        EXPECT_NEAR(end.velocity_mm_s, 0.0, 1e-9 * v_max);

        const int samples = 400;
        const double dt = r.total() / samples;
        CycleState prev = start;
        for (int k = 0; k <= samples; ++k) {
            const double t = dt * k;
            const CycleState st = r.state_at(t);
            ASSERT_LT(st.phase_index, r.phases().size());
            const PhaseRecord& p = r.phases()[st.phase_index];
            EXPECT_GE(t, p.start_s - 1e-12);
            EXPECT_LE(t, p.start_s + p.time_s + 1e-12);
            EXPECT_EQ(st.touch, p.touch);
            EXPECT_GE(st.path_speed_mm_s, -1e-12 * v_max);
            EXPECT_LE(st.path_speed_mm_s, v_max * (1 + 1e-9));
            if (p.phase == Phase::block_change) {
                EXPECT_NEAR(st.velocity_mm_s, 0.0, 1e-9 * v_max);  // at rest
            } else if (p.phase == Phase::position || p.phase == Phase::lift ||
                       p.phase == Phase::lower) {
                EXPECT_EQ(st.velocity_mm_s, 0.0);
            } else {
                EXPECT_NEAR(st.path_speed_mm_s, std::abs(st.velocity_mm_s), 1e-9 * v_max);
            }
            // Toward the surface while approaching and braking, away while backing off
            // and returning.
            const double eps = 1e-9 * v_max;
            switch (p.phase) {
                case Phase::approach:
                case Phase::pretravel:
                case Phase::interface_delay:
                case Phase::controller_delay:
                case Phase::deceleration:
                case Phase::second_approach:
                case Phase::second_pretravel:
                case Phase::second_interface_delay:
                case Phase::second_controller_delay:
                case Phase::second_deceleration:
                    EXPECT_GE(st.velocity_mm_s, -eps) << to_string(p.phase);
                    break;
                case Phase::backoff:
                case Phase::return_move:
                    EXPECT_LE(st.velocity_mm_s, eps) << to_string(p.phase);
                    break;
                case Phase::position:
                case Phase::lift:
                case Phase::lower:
                case Phase::block_change:
                    break;
            }
            // Continuous: no jump beyond the fastest feed.
            if (k > 0) {
                EXPECT_LE(std::abs(st.position_mm - prev.position_mm),
                          v_max * dt * (1 + 1e-9) + 1e-9)
                    << "t=" << t;
            }
            // A backoff longer than approach + the (mean) overtravel goes
            // behind the start.
            EXPECT_GE(st.position_mm,
                      std::min(0.0, s.cycle.approach_mm + r.first_touch().mean_overtravel_mm -
                                        s.cycle.backoff_mm) -
                          1e-9);
            EXPECT_LE(st.position_mm, s.cycle.approach_mm + r.overtravel_mm() + 1e-9);
            prev = st;
        }
    });
}

TEST_F(RandomCycles, SegmentsCoverTheCycleContiguously) {
    for_each_cycle([](const Scenario&, const CycleResult& r) {
        ASSERT_FALSE(r.segments().empty());
        double t = 0.0;
        for (const TimedSegment& seg : r.segments()) {
            EXPECT_NEAR(seg.start_s, t, rel_tol(r.total()));
            EXPECT_GE(seg.duration_s, 0.0);
            t = seg.start_s + seg.duration_s;
        }
        EXPECT_NEAR(t, r.total(), rel_tol(r.total()));
    });
}

TEST(CycleProperty, OvertravelGrowsWithFeed) {
    std::mt19937_64 rng{42};
    for (int i = 0; i < 500; ++i) {
        Scenario s = random_scenario(rng);
        if (!validate(s).empty()) continue;
        double previous_ot = 0.0;
        double previous_trigger = 0.0;
        for (double feed = 20.0; feed <= 12000.0; feed *= 1.25) {
            s.cycle.probe_feed_mm_min = feed;
            const CycleResult r = evaluate(s);
            ASSERT_GE(r.first_touch().overtravel_mm, previous_ot * (1 - 1e-12))
                << "case " << i << " feed " << feed << "\n"
                << scenario_to_json(s);
            ASSERT_GE(r.first_touch().trigger_speed_mm_s, previous_trigger * (1 - 1e-12))
                << "case " << i << " feed " << feed;
            previous_ot = r.first_touch().overtravel_mm;
            previous_trigger = r.first_touch().trigger_speed_mm_s;
        }
    }
}

TEST(CycleProperty, EvaluateIntoReusesBuffersWithoutLeftovers) {
    Scenario bore = surface(Strategy::two_touch, 3000.0, 0.5);  // warnings and 4 touches
    bore.cycle.feature = Feature::bore;
    const Scenario clean = clean_two_touch();
    CycleResult reused;
    evaluate_into(bore, reused);
    evaluate_into(clean, reused);
    const CycleResult fresh = evaluate(clean);
    ASSERT_EQ(reused.phases().size(), fresh.phases().size());
    for (std::size_t k = 0; k < fresh.phases().size(); ++k) {
        EXPECT_EQ(reused.phases()[k].phase, fresh.phases()[k].phase);
        EXPECT_EQ(reused.phases()[k].time_s, fresh.phases()[k].time_s);
    }
    EXPECT_EQ(reused.warnings().size(), fresh.warnings().size());
    EXPECT_EQ(reused.total(), fresh.total());
    EXPECT_EQ(reused.segments().size(), fresh.segments().size());
    for (Phase phase : all_phases()) EXPECT_EQ(reused.phase_time(phase), fresh.phase_time(phase));
}

// The worst overtravel says which touch it is: a slow first touch followed by
// a fast second one (a measuring feed above the probing feed) overtravels most
// on the second touch, and the sweep carries both touches' overtravel.
TEST(Overtravel, NamesTheTouchThatOvertravelsMost) {
    Scenario s;
    s.cycle.feed_override_max_pct = 100.0;  // at the programmed feeds
    s.cycle.strategy = Strategy::two_touch;
    s.cycle.probe_feed_mm_min = 100.0;
    s.cycle.measure_feed_mm_min = 3000.0;
    s.cycle.backoff_mm = 20.0;
    s.probe.overtravel_limit_mm = 2.0;
    const CycleResult r = evaluate(s);
    ASSERT_GT(r.measuring_touch().overtravel_mm, r.first_touch().overtravel_mm);
    EXPECT_EQ(r.overtravel_touch(), 2);
    EXPECT_DOUBLE_EQ(r.overtravel_mm(), r.measuring_touch().overtravel_mm);
    const Warning* w = find_warning(r, WarningCode::overtravel_limit);
    ASSERT_NE(w, nullptr);
    const std::vector<MessageArg> args = w->to_message().args;
    const auto touch = std::find_if(args.begin(), args.end(),
                                    [](const MessageArg& a) { return a.name == "touch"; });
    ASSERT_NE(touch, args.end());
    EXPECT_EQ(render_arg(*touch), "2");

    s.cycle.measure_feed_mm_min = 30.0;
    EXPECT_EQ(evaluate(s).overtravel_touch(), 1);
    s.cycle.strategy = Strategy::single_touch;
    EXPECT_EQ(evaluate(s).overtravel_touch(), 1);
}

// The operator may turn the feed override up to
// cycle.feed_override_max_pct. The touches then run at that multiple of their
// feeds from the same starts, and every overtravel check holds there; the
// cycle time stays the programmed one.
TEST(FeedOverride, EveryOvertravelCheckHoldsAtTheHighestOverride) {
    Scenario s = surface(Strategy::single_touch, 3000.0);
    Scenario fast = s;  // the same touch programmed at 150 % of the feed
    fast.cycle.probe_feed_mm_min = 4500.0;
    const CycleResult at_100 = evaluate(s);
    const double fast_ot = evaluate(fast).first_touch().overtravel_mm;
    s.cycle.feed_override_max_pct = 150.0;
    const CycleResult r = evaluate(s);
    EXPECT_DOUBLE_EQ(r.total(), at_100.total());  // the timeline at 100 %
    EXPECT_DOUBLE_EQ(r.overtravel_mm(), 1.905);   // as SingleTouch.SurfaceAt3000
    EXPECT_DOUBLE_EQ(r.first_touch().override_overtravel_mm, fast_ot);
    EXPECT_DOUBLE_EQ(r.checked_overtravel_mm(), fast_ot);
    // At cruise the overtravel is the pretravel plus v times the reaction
    // and half the time constant: (1.905 - 0.005) / 50 mm/s = 0.038 s, so at
    // 75 mm/s 0.005 + 75 x 0.038.
    EXPECT_NEAR(fast_ot, 0.005 + 75.0 * 0.038, 1e-9);

    // The limit between the two: no word at 100 %, an error at 150 % that says so.
    s.probe.overtravel_limit_mm = 2.5;
    const CycleResult limited = evaluate(s);
    const Warning* w = find_warning(limited, WarningCode::overtravel_limit);
    ASSERT_NE(w, nullptr) << describe(limited);
    EXPECT_EQ(w->severity, Severity::error);
    EXPECT_EQ(w->message(),
              "Overtravel 2.855 mm at 150 % feed override is 114 % of the probe's 2.500 mm "
              "limit: the probe or stylus will be damaged; lower the feed or the delays");
    Scenario unchanged = s;
    unchanged.cycle.feed_override_max_pct = 100.0;
    EXPECT_TRUE(evaluate(unchanged).valid());
    // The fix lowers the feed until the stop at 150 % is under 80 % of the limit.
    const std::optional<Fix> fix = fix_for(s, analyse(s), *w);
    ASSERT_TRUE(fix.has_value());
    const CycleResult fixed = evaluate(fix->scenario);
    EXPECT_TRUE(fixed.valid());
    EXPECT_LT(fixed.checked_overtravel_mm(), 0.8 * 2.5);

    // Two-touch: the backoff must clear the first touch's stop at 150 % and
    // reseat; the second touch then starts nearer and is checked too.
    Scenario two = surface(Strategy::two_touch, 3000.0);
    two.cycle.feed_override_max_pct = 150.0;
    const CycleResult t = evaluate(two);
    EXPECT_NEAR(
        t.recommended_backoff_mm(),
        std::max(1.905 + std::max(two.probe.reseat_mm, reach_distance_mm(two.motion_limits(), 0.5)),
                 fast_ot + two.probe.reseat_mm),
        kBackoffStep_mm);
    EXPECT_GT(t.recommended_backoff_mm(), 1.905 + 0.2 + kBackoffStep_mm);
    two.cycle.backoff_mm = 2.2;  // clears the stop at 100 %, not at 150 %
    EXPECT_NE(find_warning(evaluate(two), WarningCode::backoff_too_small), nullptr);
    // Every search reaches past the stop at 150 %.
    two.cycle.backoff_mm = t.recommended_backoff_mm();
    const CycleResult searched = evaluate(two);
    EXPECT_DOUBLE_EQ(searched.first_touch().search_mm, 5.0 + search_beyond_mm(two, fast_ot));
    two.cycle.search_beyond_mm = 2.0;  // past the stop at 100 %, short of 150 %'s
    const CycleResult short_search = evaluate(two);
    w = find_warning(short_search, WarningCode::search_ends_too_soon);
    ASSERT_NE(w, nullptr);
    EXPECT_DOUBLE_EQ(std::get<warning::SearchEndsTooSoon>(w->figures).stop_mm, fast_ot);
}

// The same with dynamics after interpolation (a Fanuc-type machine): the
// touch at the override is the touch programmed at that feed.
TEST(FeedOverride, WithDynamicsTheStopIsTheTouchAtTheFasterFeed) {
    Scenario s = merge_json(Scenario{}, R"({"machine": {"accel_model": "none",
        "filter": "exponential", "filter_time_s": 0.032, "servo_time_constant_s": 0.033,
        "controller_latency_s": 0.014}, "cycle": {"strategy": "two_touch",
        "probe_feed_mm_min": 1000, "backoff_mm": 4, "approach_mm": 10}})");
    for (double pct : {120.0, 150.0, 200.0}) {
        s.cycle.feed_override_max_pct = pct;
        Scenario fast = s;
        fast.cycle.feed_override_max_pct = 100.0;
        fast.cycle.probe_feed_mm_min = 1000.0 * pct / 100.0;
        const CycleResult r = evaluate(s);
        const CycleResult f = evaluate(fast);
        EXPECT_DOUBLE_EQ(r.first_touch().override_overtravel_mm, f.first_touch().overtravel_mm)
            << pct;
        // Grows with the override: at 1000 mm/min x k, v x (t_r + lags) +
        // pretravel, within what the lags' tails have not settled 10 mm in
        // (under 0.2 um at 2000 mm/min).
        EXPECT_NEAR(r.first_touch().override_overtravel_mm,
                    0.005 + 1000.0 * pct / 100.0 / 60.0 * (0.002 + 0.014 + 0.004 + 0.032 + 0.033),
                    2e-4)
            << pct;
    }
}

TEST(Overtravel, SweepCarriesEachTouch) {
    Scenario s;
    s.cycle.feed_override_max_pct = 100.0;  // at the programmed feeds
    s.cycle.strategy = Strategy::two_touch;
    const std::vector<double> feeds = {100.0, 1000.0, 5000.0};
    for (const SweepPoint& p : sweep_feeds(s, feeds).points) {
        EXPECT_GT(p.second_overtravel_mm, 0.0) << p.feed_mm_min;
        EXPECT_DOUBLE_EQ(p.overtravel_mm, std::max(p.first_overtravel_mm, p.second_overtravel_mm));
    }
    s.cycle.strategy = Strategy::single_touch;
    for (const SweepPoint& p : sweep_feeds(s, feeds).points) {
        EXPECT_EQ(p.second_overtravel_mm, 0.0);
        EXPECT_DOUBLE_EQ(p.overtravel_mm, p.first_overtravel_mm);
    }
}

// MotionCache: the solves kept between evaluations of one machine must give
// the evaluations bit for bit what fresh ones give, whatever was evaluated
// before with the same cache (other feeds, backoffs, features, machines).
void expect_same_cycle(const CycleResult& cached, const CycleResult& fresh) {
    EXPECT_EQ(cached.total(), fresh.total());
    EXPECT_EQ(cached.overtravel_mm(), fresh.overtravel_mm());
    EXPECT_EQ(cached.recommended_backoff_mm(), fresh.recommended_backoff_mm());
    ASSERT_EQ(cached.phases().size(), fresh.phases().size());
    for (std::size_t i = 0; i < fresh.phases().size(); ++i) {
        EXPECT_EQ(cached.phases()[i].time_s, fresh.phases()[i].time_s) << "phase " << i;
    }
    ASSERT_EQ(cached.warnings().size(), fresh.warnings().size());
    for (std::size_t i = 0; i < fresh.warnings().size(); ++i) {
        EXPECT_EQ(cached.warnings()[i].code, fresh.warnings()[i].code);
        EXPECT_TRUE(cached.warnings()[i].figures == fresh.warnings()[i].figures);
    }
    for (double t = 0.0; t < fresh.total(); t += fresh.total() / 37.0) {
        EXPECT_EQ(cached.state_at(t).position_mm, fresh.state_at(t).position_mm) << "t " << t;
    }
}

TEST(MotionCache, EvaluationsThroughOneCacheAreThoseOfFreshOnes) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> log_feed(std::log(20.0), std::log(6000.0));
    std::uniform_int_distribution<int> pick(0, 3);
    const std::array<Feature, 4> features = {Feature::surface, Feature::bore, Feature::boss,
                                             Feature::web};
    const std::array<FilterKind, 4> filters = {FilterKind::none, FilterKind::linear,
                                               FilterKind::exponential, FilterKind::bell};
    MotionCache cache;
    CycleResult cached;
    for (int i = 0; i < 200; ++i) {
        Scenario s;
        s.cycle.strategy = Strategy::two_touch;
        s.cycle.feature = features[static_cast<std::size_t>(pick(rng))];
        s.cycle.feature_size_mm = 40.0;
        s.cycle.probe_feed_mm_min = std::round(std::exp(log_feed(rng)));
        s.cycle.backoff_mm = i % 3 == 0 ? 1.0 : 3.0;  // too small, or more than enough
        s.cycle.backoff_from = i % 5 == 0 ? BackoffFrom::trigger : BackoffFrom::stop;
        s.cycle.repeats = 1 + i % 3;
        // Runs of ten evaluations of one machine (the cache kept), then
        // another machine (the cache rebound).
        s.machine.accel_model = (i / 10) % 2 == 0 ? AccelModel::none : AccelModel::time_constant;
        s.machine.filter = filters[static_cast<std::size_t>((i / 20) % 4)];
        s.machine.filter_time_s = 0.032;
        s.machine.servo_time_constant_s = (i / 80) % 2 == 0 ? 0.033 : 0.0;
        s.machine.in_position_mm = 0.02;
        ASSERT_TRUE(validate(s).empty()) << i;
        evaluate_into(s, cached, cache);
        SCOPED_TRACE(i);
        expect_same_cycle(cached, evaluate(s));
    }
}

// Detail::summary (what a sweep reads): the same numbers as the full
// evaluation, bit for bit, without the timeline and the notes that take
// solves of their own; summaries and full evaluations share one cache.
TEST(Detail, ASummaryIsTheFullEvaluationWithoutItsTimeline) {
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> log_feed(std::log(20.0), std::log(6000.0));
    std::uniform_int_distribution<int> pick(0, 3);
    const std::array<Feature, 4> features = {Feature::surface, Feature::bore, Feature::pocket,
                                             Feature::boss};
    const std::array<FilterKind, 4> filters = {FilterKind::none, FilterKind::linear,
                                               FilterKind::exponential, FilterKind::bell};
    MotionCache cache;
    CycleResult summary;
    CycleResult full;
    int left_out = 0;  // notes and warnings the full results had that summaries leave out
    for (int i = 0; i < 160; ++i) {
        Scenario s;
        s.cycle.strategy = i % 4 == 3 ? Strategy::single_touch : Strategy::two_touch;
        s.cycle.feature = features[static_cast<std::size_t>(pick(rng))];
        s.cycle.feature_size_mm = 40.0;
        s.cycle.probe_feed_mm_min = std::round(std::exp(log_feed(rng)));
        s.cycle.backoff_mm = i % 3 == 0 ? 1.0 : 3.0;
        s.cycle.backoff_from = i % 5 == 0 ? BackoffFrom::trigger : BackoffFrom::stop;
        s.cycle.repeats = 1 + i % 2;
        s.cycle.approach_mm = i % 7 == 0 ? 0.05 : 2.0;  // some touches while accelerating
        s.machine.accel_model = (i / 8) % 2 == 0 ? AccelModel::none : AccelModel::jerk_limited;
        s.machine.filter = filters[static_cast<std::size_t>((i / 16) % 4)];
        s.machine.filter_time_s = 0.032;
        s.machine.servo_time_constant_s = (i / 64) % 2 == 0 ? 0.033 : 0.0;
        s.machine.in_position_mm = 0.02;
        ASSERT_TRUE(validate(s).empty()) << i;
        SCOPED_TRACE(i);
        evaluate_into(s, summary, cache, Detail::summary);
        evaluate_into(s, full, cache);
        const CycleResult fresh = evaluate(s);
        expect_same_cycle(full, fresh);

        EXPECT_EQ(summary.total(), fresh.total());
        ASSERT_EQ(summary.phases().size(), fresh.phases().size());
        for (std::size_t k = 0; k < fresh.phases().size(); ++k) {
            EXPECT_EQ(summary.phases()[k].phase, fresh.phases()[k].phase);
            EXPECT_EQ(summary.phases()[k].start_s, fresh.phases()[k].start_s);
            EXPECT_EQ(summary.phases()[k].time_s, fresh.phases()[k].time_s);
            EXPECT_EQ(summary.phases()[k].distance_mm, 0.0);
        }
        for (Phase phase : all_phases())
            EXPECT_EQ(summary.phase_time(phase), fresh.phase_time(phase));
        for (const auto& [a, b] :
             {std::pair{&summary.first_touch(), &fresh.first_touch()},
              std::pair{&summary.measuring_touch(), &fresh.measuring_touch()}}) {
            EXPECT_EQ(a->overtravel_mm, b->overtravel_mm);
            EXPECT_EQ(a->recorded_mm, b->recorded_mm);
            EXPECT_EQ(a->trigger_speed_mm_s, b->trigger_speed_mm_s);
            EXPECT_EQ(a->touch_speed_mm_s, b->touch_speed_mm_s);
            EXPECT_EQ(a->react_speed_mm_s, 0.0);
            EXPECT_EQ(a->delay_travel_mm, 0.0);
        }
        EXPECT_EQ(summary.overtravel_mm(), fresh.overtravel_mm());
        EXPECT_EQ(summary.overtravel_touch(), fresh.overtravel_touch());
        EXPECT_EQ(summary.uncertainty_mm(), fresh.uncertainty_mm());
        EXPECT_EQ(summary.recommended_backoff_mm(), fresh.recommended_backoff_mm());
        EXPECT_EQ(summary.invalid_codes(), fresh.invalid_codes());
        EXPECT_TRUE(summary.segments().empty());
        EXPECT_TRUE(summary.motions().empty());

        // Every warning of the full result but the left-out ones, in order.
        std::vector<WarningCode> expected;
        for (const Warning& w : fresh.warnings()) {
            if (w.code == WarningCode::backoff_excess ||
                w.code == WarningCode::touch_while_accelerating) {
                ++left_out;
                continue;
            }
            expected.push_back(w.code);
        }
        std::vector<WarningCode> got;
        for (const Warning& w : summary.warnings()) got.push_back(w.code);
        EXPECT_EQ(got, expected);
    }
    EXPECT_GT(left_out, 20);  // the comparison above met both kinds often
}

TEST(MotionCache, KeepsTheSolvesOfOneMachineOnly) {
    Scenario s;
    MotionCache cache;
    cache.bind(s.motion_limits(), s.axis_dynamics());
    cache.store_move(3.0, 50.0, {0.125, 3.0});
    cache.store_approach_room(50.0, 0.004, 0.2);
    cache.bind(s.motion_limits(), s.axis_dynamics());  // the same machine: kept
    EXPECT_EQ(cache.move(3.0, 50.0), std::optional<MotionCache::Move>({0.125, 3.0}));
    EXPECT_EQ(cache.approach_room_mm(50.0, 0.004), std::optional<double>(0.2));
    EXPECT_FALSE(cache.move(3.0, 50.5).has_value());  // keyed by the exact inputs
    EXPECT_FALSE(cache.approach_room_mm(50.0, 0.005).has_value());

    Scenario other = s;
    other.machine.servo_time_constant_s = 0.03;
    cache.bind(other.motion_limits(), other.axis_dynamics());  // another machine: emptied
    EXPECT_FALSE(cache.move(3.0, 50.0).has_value());
    EXPECT_FALSE(cache.approach_room_mm(50.0, 0.004).has_value());
}

TEST(MotionCache, KeepsTouchesByTimingAndDistanceTheMostRecentlyUsedLongest) {
    Scenario s;
    MotionCache cache;
    cache.bind(s.motion_limits(), s.axis_dynamics());
    const MotionCache::TouchKey key{0.5, 0.005, 0.002, 0.008, 0.004, 0.004};
    MotionCache::SolvedTouch exact;
    exact.distance_mm = 0.0;
    exact.touch_s = 0.25;
    cache.store_touch(key, exact);
    MotionCache::SolvedTouch reference;
    reference.distance_mm = 1.5;
    reference.touch_s = 3.0;
    reference.reference = true;
    cache.store_touch(key, reference);

    ASSERT_TRUE(cache.touch(key, 0.0).has_value());  // its exact distance
    EXPECT_EQ(cache.touch(key, 0.0)->touch_s, 0.25);
    EXPECT_FALSE(cache.touch(key, 0.5).has_value());  // neither that nor settled
    ASSERT_TRUE(cache.touch(key, 4.0).has_value());   // the reference, to be shifted
    EXPECT_EQ(cache.touch(key, 4.0)->distance_mm, 1.5);
    EXPECT_TRUE(cache.touch(key, 1.5).has_value());
    EXPECT_FALSE(cache.touch(key, 1.4).has_value());  // shorter: not settled
    MotionCache::TouchKey other = key;
    other.record_delay_s = 0.0;  // a latched input: another touch
    EXPECT_FALSE(cache.touch(other, 4.0).has_value());

    // Eight are kept; a lookup keeps the reference among the most recent.
    for (int i = 0; i < 7; ++i) {
        MotionCache::TouchKey first = key;
        first.feed_mm_s = 10.0 + i;
        cache.store_touch(first, exact);
        EXPECT_TRUE(cache.touch(key, 4.0).has_value()) << i;
    }
    EXPECT_FALSE(cache.touch(key, 0.0).has_value());  // the exact one, pushed out

    Scenario lagging = s;
    lagging.machine.servo_time_constant_s = 0.03;
    cache.bind(lagging.motion_limits(), lagging.axis_dynamics());  // another machine: emptied
    EXPECT_FALSE(cache.touch(key, 4.0).has_value());
}

TEST(MotionCache, ForgetsTheOldestWhenFull) {
    MotionCache cache;
    Scenario s;
    cache.bind(s.motion_limits(), s.axis_dynamics());
    for (int i = 0; i < 17; ++i) cache.store_move(1.0 + i, 50.0, {0.1 * i, 1.0 + i});
    EXPECT_FALSE(cache.move(1.0, 50.0).has_value());  // the first, overwritten
    for (int i = 1; i < 17; ++i) {
        EXPECT_EQ(cache.move(1.0 + i, 50.0), std::optional<MotionCache::Move>({0.1 * i, 1.0 + i}))
            << i;
    }
}

}  // namespace
}  // namespace probecycle
