#include "core/lab/delay_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/csv_reader.h"
#include "core/common/input_error.h"
#include "core/common/units.h"
#include "tests/core/common/line_ends.h"
#include "tests/core/common/message_checks.h"

namespace probecycle {
namespace {

constexpr double kExact = 1e-12;

struct LatencyCaseName {
    template <typename T>
    std::string operator()(const testing::TestParamInfo<T>& case_info) const {
        return case_info.param.name;
    }
};

// Touches on the delay-stability test's model: measured = p0 + dir * v * tau.
void add_touches(std::vector<DelayTouch>& touches, const std::string& axis, int direction,
                 double p0_mm, double tau_s, std::initializer_list<double> feeds_mm_min,
                 int repeats) {
    for (const double feed : feeds_mm_min) {
        for (int i = 0; i < repeats; ++i) {
            touches.push_back({axis, direction, feed,
                               p0_mm + direction * mm_min_to_mm_s(feed) * tau_s,
                               touches.size() + 2});
        }
    }
}

bool has_warning(const DelayGroup& group, LatencyWarningCode code) {
    for (const auto& w : group.warnings) {
        if (w.code == code) return true;
    }
    return false;
}

TEST(LineFit, ExactAndDegenerate) {
    const std::vector<double> x{1.0, 2.0, 4.0};
    const std::vector<double> y{3.0, 5.0, 9.0};
    const auto line = fit_line(x, y);
    ASSERT_TRUE(line);
    EXPECT_NEAR(line->slope, 2.0, kExact);
    EXPECT_NEAR(line->intercept, 1.0, kExact);
    const std::vector<double> same{2.0, 2.0};
    EXPECT_FALSE(fit_line(same, same));
    EXPECT_FALSE(fit_line(std::vector<double>{1.0}, std::vector<double>{1.0}));
}

TEST(DelayFit, ExactDataBothDirections) {
    std::vector<DelayTouch> touches;
    add_touches(touches, "X", +1, 10.0, 0.0085, {50, 100, 500, 1000, 2000, 3000}, 5);
    add_touches(touches, "X", -1, -10.0, 0.0085, {50, 100, 500, 1000, 2000, 3000}, 5);
    add_touches(touches, "Z", -1, -123.456, 0.012, {30, 300, 3000}, 3);
    DelayFitOptions options;
    options.interpolation_period_s = 0.001;
    const auto fit = fit_delay(touches, options);
    ASSERT_EQ(fit.groups.size(), 3u);
    const auto& xp = fit.groups[0];
    EXPECT_EQ(xp.name(), "X+");
    EXPECT_NEAR(xp.delay_s, 0.0085, kExact);
    EXPECT_NEAR(xp.zero_speed_position_mm, 10.0, 1e-12);
    ASSERT_TRUE(xp.lag_cycles);
    EXPECT_NEAR(*xp.lag_cycles, 8.5, 1e-9);
    ASSERT_TRUE(xp.residual_2sigma_mm);
    EXPECT_NEAR(*xp.residual_2sigma_mm, 0.0, 1e-12);
    ASSERT_EQ(xp.feeds.size(), 6u);
    EXPECT_EQ(xp.feeds[0].feed_mm_min, 50.0);
    EXPECT_EQ(xp.feeds[0].n, 5u);
    EXPECT_NEAR(xp.feeds[5].mean_mm, 10.0 + 50.0 * 0.0085, 1e-12);
    EXPECT_EQ(xp.feeds[5].range_mm, 0.0);
    EXPECT_TRUE(xp.warnings.empty()) << xp.warnings.front().text();
    EXPECT_EQ(xp.lines.size(), 30u);

    const auto& xm = fit.groups[1];
    EXPECT_EQ(xm.name(), "X-");
    EXPECT_NEAR(xm.delay_s, 0.0085, kExact);
    EXPECT_NEAR(xm.zero_speed_position_mm, -10.0, 1e-12);
    EXPECT_NEAR(xm.predicted_mm(3000.0), -10.0 - 50.0 * 0.0085, 1e-12);

    const auto& zm = fit.groups[2];
    EXPECT_EQ(zm.name(), "Z-");
    EXPECT_NEAR(zm.delay_s, 0.012, kExact);
    EXPECT_NEAR(zm.zero_speed_position_mm, -123.456, 1e-11);
}

// Apply: controller latency = tau - t_i - t_s/2 (no t_s/2 when latched).
TEST(ApplyDelay, ControllerLatencyIsTheDelayLessInterfaceAndHalfScan) {
    std::vector<DelayTouch> touches;
    add_touches(touches, "X", +1, 10.0, 0.0085, {100, 1000, 2000}, 2);
    add_touches(touches, "Z", -1, -5.0, 0.012, {100, 1000, 2000}, 2);
    const DelayFit fit = fit_delay(touches);
    Scenario scenario;  // t_i = 2 ms, t_s = 4 ms, t_c = 2 ms
    scenario.probe.interface_delay_s = 0.002;
    scenario.machine.scan_period_s = 0.004;

    // Two groups, none chosen: the longer delay (Z-, 12 ms), the safe side.
    const AppliedDelay longest = delay_to_apply(fit, scenario);
    EXPECT_EQ(longest.group, "Z-");
    EXPECT_EQ(longest.key, "machine.controller_latency_s");
    EXPECT_NEAR(longest.value_s, 0.012 - 0.002 - 0.002, 1e-12);
    EXPECT_NEAR(longest.previous_s, 0.002, 0.0);

    // A chosen group, case-insensitive.
    const AppliedDelay x = delay_to_apply(fit, scenario, std::string("x+"));
    EXPECT_EQ(x.group, "X+");
    EXPECT_NEAR(x.value_s, 0.0085 - 0.002 - 0.002, 1e-12);
    EXPECT_NEAR(apply_delay(scenario, x).machine.controller_latency_s, 0.0045, 1e-12);

    // Latched: the position is captured when the signal arrives, so
    // the whole fitted delay is the interface delay; the latency is left alone.
    scenario.machine.latched_input = true;
    const AppliedDelay latched = delay_to_apply(fit, scenario, std::string("X+"));
    EXPECT_TRUE(latched.latched);
    EXPECT_EQ(latched.key, "probe.interface_delay_s");
    EXPECT_NEAR(latched.value_s, 0.0085, 1e-12);
    EXPECT_EQ(latched.previous_s, 0.002);
    const Scenario applied = apply_delay(scenario, latched);
    EXPECT_NEAR(applied.probe.interface_delay_s, 0.0085, 1e-12);
    EXPECT_EQ(applied.machine.controller_latency_s, scenario.machine.controller_latency_s);
}

TEST(ChooseGroup, NamedOnlyOrLongest) {
    std::vector<DelayTouch> touches;
    add_touches(touches, "X", +1, 10.0, 0.0085, {100, 1000, 2000}, 2);
    add_touches(touches, "Z", -1, -5.0, 0.012, {100, 1000, 2000}, 2);
    const DelayFit fit = fit_delay(touches);
    EXPECT_EQ(choose_group(fit, std::nullopt).group->name(), "Z-");
    EXPECT_EQ(choose_group(fit, std::string("x+")).group->name(), "X+");
    EXPECT_THROW((void)choose_group(fit, std::string("Y+")), std::invalid_argument);
    DelayFit one;
    one.groups.push_back(fit.groups.front());
    EXPECT_EQ(render(choose_group(one, std::nullopt).rule), "the only group");
}

TEST(DelayCsv, CoordinateBeyondTheMachineNamesTheLine) {
    try {
        (void)parse_delay_csv("axis,direction,feed_mm_min,measured_mm\nX,1,100,1e6\n");
        FAIL() << "accepted";
    } catch (const CsvError& e) {
        EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("measured_mm"), std::string::npos) << e.what();
    }
}

TEST(ApplyDelay, RefusesAnUnknownGroupAndANegativeLatency) {
    std::vector<DelayTouch> touches;
    add_touches(touches, "X", +1, 10.0, 0.003, {100, 1000, 2000}, 2);
    const DelayFit fit = fit_delay(touches);
    Scenario scenario;
    try {
        (void)delay_to_apply(fit, scenario, std::string("Y+"));
        FAIL() << "an unknown group was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("Y+"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("X+"), std::string::npos) << e.what();
    }
    // 3 ms < t_i (2 ms) + t_s/2 (2 ms): the latency would be -1 ms.
    try {
        (void)delay_to_apply(fit, scenario);
        FAIL() << "a negative controller latency was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("negative"), std::string::npos) << e.what();
    }
    EXPECT_THROW((void)delay_to_apply(DelayFit{}, scenario), std::invalid_argument);
}

TEST(DelayFit, NoLagCyclesWithoutAPeriod) {
    std::vector<DelayTouch> touches;
    add_touches(touches, "Y", +1, 0.0, 0.01, {100, 1000, 2000}, 2);
    EXPECT_FALSE(fit_delay(touches).groups[0].lag_cycles);
}

TEST(DelayFit, ScannedInputNoisyFixedSeed) {
    // A scanned skip input: the wait for the next scan is uniform in [0, t_s],
    // so the touches measure tau + t_s / 2 on average (docs/model.md, "One
    // touch", phase 4), with scatter v * t_s / sqrt(12) plus the repeatability.
    // Tolerance: 4 standard errors of the least-squares slope and intercept,
    // computed from those variances.
    const double tau_s = 0.006, scan_s = 0.004, repeatability_mm = 0.0005, p0_mm = 50.0;
    const std::vector<double> feeds{100, 500, 1000, 2000, 3000};
    const int repeats = 10;
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> scan(0.0, scan_s);
    std::normal_distribution<double> noise(0.0, repeatability_mm);
    std::vector<DelayTouch> touches;
    for (const double feed : feeds) {
        for (int i = 0; i < repeats; ++i) {
            const double v = mm_min_to_mm_s(feed);
            touches.push_back({"X", 1, feed, p0_mm + v * (tau_s + scan(rng)) + noise(rng), 0});
        }
    }
    double mean_v = 0.0;
    for (const auto& t : touches) mean_v += mm_min_to_mm_s(t.feed_mm_min);
    mean_v /= static_cast<double>(touches.size());
    double sxx = 0.0, var_slope = 0.0, var_mean = 0.0;
    for (const auto& t : touches) sxx += std::pow(mm_min_to_mm_s(t.feed_mm_min) - mean_v, 2);
    for (const auto& t : touches) {
        const double v = mm_min_to_mm_s(t.feed_mm_min);
        const double var = v * v * scan_s * scan_s / 12.0 + repeatability_mm * repeatability_mm;
        var_slope += std::pow(v - mean_v, 2) * var / (sxx * sxx);
        var_mean += var / std::pow(static_cast<double>(touches.size()), 2);
    }
    const double se_slope = std::sqrt(var_slope);
    const double se_p0 = std::sqrt(var_mean + mean_v * mean_v * var_slope);

    const auto fit = fit_delay(touches);
    ASSERT_EQ(fit.groups.size(), 1u);
    const auto& g = fit.groups[0];
    EXPECT_NEAR(g.delay_s, tau_s + scan_s / 2.0, 4.0 * se_slope);
    EXPECT_NEAR(g.zero_speed_position_mm, p0_mm, 4.0 * se_p0);
    // The scatter at each feed stays within the scan range plus the repeatability.
    for (const auto& f : g.feeds) {
        EXPECT_LE(f.range_mm, mm_min_to_mm_s(f.feed_mm_min) * scan_s + 8.0 * repeatability_mm);
    }
    // Scatter that grows with the speed is a jittering delay, not an unstable one.
    EXPECT_FALSE(has_warning(g, LatencyWarningCode::unstable_delay));
    EXPECT_FALSE(has_warning(g, LatencyWarningCode::curved_residuals));
    ASSERT_TRUE(g.residual_2sigma_mm);
    EXPECT_GT(*g.residual_2sigma_mm, 0.0);
}

TEST(DelayFit, TwoFeedsWarn) {
    std::vector<DelayTouch> touches;
    add_touches(touches, "X", 1, 0.0, 0.01, {100, 2000}, 3);
    const auto fit = fit_delay(touches);
    EXPECT_TRUE(has_warning(fit.groups[0], LatencyWarningCode::few_feeds));
    EXPECT_NEAR(fit.groups[0].delay_s, 0.01, kExact);
}

TEST(DelayFit, OneUnstableFeedWarns) {
    // Stable to 1 um everywhere but at 1000 mm/min, where the touches spread
    // over 40 um: 24 ms of delay jitter at that speed.
    std::vector<DelayTouch> touches;
    for (const double feed : {100.0, 500.0, 1000.0, 2000.0}) {
        for (const double offset : {0.0, 0.001, 0.0005}) {
            const double spread = feed == 1000.0 ? 40.0 : 1.0;
            touches.push_back({"X", 1, feed, mm_min_to_mm_s(feed) * 0.01 + offset * spread, 0});
        }
    }
    const auto fit = fit_delay(touches);
    const auto& g = fit.groups[0];
    ASSERT_TRUE(has_warning(g, LatencyWarningCode::unstable_delay));
    int count = 0;
    for (const auto& w : g.warnings) {
        if (w.code != LatencyWarningCode::unstable_delay) continue;
        ++count;
        EXPECT_NE(w.text().find("1000 mm/min"), std::string::npos) << w.text();
    }
    EXPECT_EQ(count, 1);
}

TEST(DelayFit, ScatterProportionalToSpeedIsNotUnstable) {
    // Range = v * 4 ms at every feed: a scanned input, the same jitter in time.
    std::vector<DelayTouch> touches;
    for (const double feed : {100.0, 1000.0, 5000.0}) {
        const double v = mm_min_to_mm_s(feed);
        for (const double phase : {0.0, 0.5, 1.0}) {
            touches.push_back({"Y", -1, feed, -v * (0.005 + phase * 0.004), 0});
        }
    }
    const auto fit = fit_delay(touches);
    const auto& g = fit.groups[0];
    EXPECT_FALSE(has_warning(g, LatencyWarningCode::unstable_delay));
    EXPECT_NEAR(g.delay_s, 0.007, 1e-12);
}

TEST(DelayFit, DelayGrowingWithSpeedCurves) {
    // tau(v) = 5 ms + 0.1 ms per mm/s: the line cannot follow it.
    std::vector<DelayTouch> touches;
    for (const double feed : {60.0, 600.0, 1200.0, 2400.0, 3600.0}) {
        const double v = mm_min_to_mm_s(feed);
        for (int i = 0; i < 3; ++i) touches.push_back({"X", 1, feed, v * (0.005 + 0.0001 * v), 0});
    }
    const auto fit = fit_delay(touches);
    const auto& g = fit.groups[0];
    ASSERT_TRUE(has_warning(g, LatencyWarningCode::curved_residuals));
    for (const auto& w : g.warnings) {
        if (w.code == LatencyWarningCode::curved_residuals) {
            // The secant delay at the ends: 5.1 ms at 60 mm/min, 11 ms at 3600.
            EXPECT_NE(w.text().find("5.1 ms"), std::string::npos) << w.text();
            EXPECT_NE(w.text().find("11 ms"), std::string::npos) << w.text();
        }
    }
}

TEST(DelayFit, WrongDirectionGivesANegativeDelay) {
    std::vector<DelayTouch> touches;
    add_touches(touches, "X", 1, 0.0, 0.008, {100, 1000, 2000}, 2);
    for (auto& t : touches) t.direction = -1;  // labelled against the travel
    const auto fit = fit_delay(touches);
    const auto& g = fit.groups[0];
    EXPECT_NEAR(g.delay_s, -0.008, kExact);
    EXPECT_TRUE(has_warning(g, LatencyWarningCode::negative_delay));
}

TEST(DelayFit, SingleTouchesAreNoted) {
    std::vector<DelayTouch> touches;
    add_touches(touches, "X", 1, 0.0, 0.008, {100, 1000, 2000}, 1);
    const auto fit = fit_delay(touches);
    const auto& g = fit.groups[0];
    EXPECT_TRUE(has_warning(g, LatencyWarningCode::single_touch_feed));
    ASSERT_TRUE(g.residual_2sigma_mm);  // 3 touches, 1 degree of freedom
}

TEST(DelayFit, TwoTouchesHaveNoResidual) {
    std::vector<DelayTouch> touches;
    add_touches(touches, "X", 1, 0.0, 0.008, {100, 1000}, 1);
    EXPECT_FALSE(fit_delay(touches).groups[0].residual_2sigma_mm);
}

// ---------------------------------------------------------------------------
// Files

TEST(DelayCsv, ParsesAndNormalisesTheAxis) {
    const std::string text =
        "# delay-stability test, X+ and Z-\n"
        "axis,direction,feed_mm_min,measured_mm\n"
        "x,+1,100,10.0017\n"
        "X,1,1000,10.017\n"
        "z,-1,100,-5.0\n";
    const auto touches = parse_delay_csv(text);
    ASSERT_EQ(touches.size(), 3u);
    EXPECT_EQ(touches[0].axis, "X");
    EXPECT_EQ(touches[0].direction, 1);
    EXPECT_EQ(touches[0].line, 3u);
    EXPECT_EQ(touches[2].axis, "Z");
    EXPECT_EQ(touches[2].direction, -1);
    EXPECT_DOUBLE_EQ(touches[1].measured_mm, 10.017);
}

struct BadDelayFileCase {
    const char* name;
    const char* text;
    std::size_t line;
    const char* column;
    const char* says;
};
// Test names in ctest show the case name, not the bytes.
void PrintTo(const BadDelayFileCase& c, std::ostream* os) {
    *os << c.name;
}

class DelayFileErrors : public testing::TestWithParam<BadDelayFileCase> {};

TEST_P(DelayFileErrors, NameTheLine) {
    const auto& c = GetParam();
    try {
        fit_delay(parse_delay_csv(c.text));
        FAIL() << "no error";
    } catch (const CsvError& e) {
        EXPECT_EQ(e.line(), c.line) << e.what();
        EXPECT_EQ(e.column(), c.column) << e.what();
        EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
}

constexpr const char* kHeader = "axis,direction,feed_mm_min,measured_mm\n";

// clang-format off
INSTANTIATE_TEST_SUITE_P(
    Files, DelayFileErrors,
    testing::Values(
        BadDelayFileCase{"Empty",           "",                                                                                   0, "",            "empty"},
        BadDelayFileCase{"HeaderOnly",      "axis,direction,feed_mm_min,measured_mm\n",                                           0, "",            "no data"},
        BadDelayFileCase{"MissingColumn",   "axis,direction,measured_mm\nX,1,2\n",                                                1, "",            "missing column 'feed_mm_min'"},
        BadDelayFileCase{"TextInNumber",    "axis,direction,feed_mm_min,measured_mm\nX,1,100,1\nX,1,fast,2\n",                    3, "feed_mm_min", "'fast' is not a number"},
        BadDelayFileCase{"DirectionZero",   "axis,direction,feed_mm_min,measured_mm\nX,0,100,1\n",                                2, "direction",   "+1 or -1"},
        BadDelayFileCase{"DirectionWord",   "axis,direction,feed_mm_min,measured_mm\nX,plus,100,1\n",                             2, "direction",   "'plus' is not a number"},
        BadDelayFileCase{"FeedZero",        "axis,direction,feed_mm_min,measured_mm\nX,1,0,1\n",                                  2, "feed_mm_min", "(0, 100000]"},
        BadDelayFileCase{"FeedNegative",    "axis,direction,feed_mm_min,measured_mm\nX,1,-100,1\n",                               2, "feed_mm_min", "out of range"},
        BadDelayFileCase{"BadAxis",         "axis,direction,feed_mm_min,measured_mm\n1,1,100,1\n",                                2, "axis",        "not an axis name"},
        BadDelayFileCase{"EmptyAxis",       "axis,direction,feed_mm_min,measured_mm\n,1,100,1\n",                                 2, "axis",        "not an axis name"},
        BadDelayFileCase{"MissingField",    "axis,direction,feed_mm_min,measured_mm\nX,1,100\n",                                  2, "",            "3 fields"},
        BadDelayFileCase{"OnePoint",        "axis,direction,feed_mm_min,measured_mm\nX,1,100,1\n",                                2, "feed_mm_min", "X+: only one touch (100 mm/min, line 2)"},
        BadDelayFileCase{"OneFeedOnly",     "axis,direction,feed_mm_min,measured_mm\nX,1,500,1\nX,1,500,1.001\nX,1,500,1.0005\n", 2, "feed_mm_min", "X+: all 3 touches are at one feed (500 mm/min, lines 2, 3, 4)"},
        BadDelayFileCase{"OneGroupOneFeed", "axis,direction,feed_mm_min,measured_mm\nX,1,100,1\nX,1,900,2\nY,-1,500,3\n",         4, "feed_mm_min", "Y-: only one touch"}),
    LatencyCaseName{});
// clang-format on

TEST(DelayCsv, ColumnsAreFoundByNameInAnyOrderWithExtraColumns) {
    // The documented header, shuffled and with a column of the user's own: each
    // value lands in its field, the axis upper-cased, the line remembered.
    const std::vector<DelayTouch> touches = parse_delay_csv(
        "# exported by hand\n"
        "measured_mm,note,feed_mm_min,direction,axis\n"
        "10.25,first,1500,-1,y\n"
        "\n"
        "-3.5,second,30,+1,Z2\n");
    ASSERT_EQ(touches.size(), 2u);
    EXPECT_EQ(touches[0].axis, "Y");
    EXPECT_EQ(touches[0].direction, -1);
    EXPECT_DOUBLE_EQ(touches[0].feed_mm_min, 1500.0);
    EXPECT_DOUBLE_EQ(touches[0].measured_mm, 10.25);
    EXPECT_EQ(touches[0].line, 3u);
    EXPECT_EQ(touches[1].axis, "Z2");
    EXPECT_EQ(touches[1].direction, 1);
    EXPECT_DOUBLE_EQ(touches[1].feed_mm_min, 30.0);
    EXPECT_DOUBLE_EQ(touches[1].measured_mm, -3.5);
    EXPECT_EQ(touches[1].line, 5u);
}

// ---------------------------------------------------------------------------
// Messages: every warning and error a code, a template and its numbers named

TEST(DelayFitMessages, EveryWarningNamesItsNumbers) {
    std::vector<LatencyWarning> all;
    const auto collect = [&all](const std::vector<DelayTouch>& touches) {
        for (const DelayGroup& g : fit_delay(touches).groups) {
            all.insert(all.end(), g.warnings.begin(), g.warnings.end());
        }
    };
    // Two feeds, one touch each, against the travel: few feeds, single
    // touches, a negative delay.
    std::vector<DelayTouch> sparse;
    add_touches(sparse, "X", 1, 0.0, 0.008, {100, 1000}, 1);
    for (auto& t : sparse) t.direction = -1;
    collect(sparse);
    // One unstable feed.
    std::vector<DelayTouch> unstable;
    for (const double feed : {100.0, 500.0, 1000.0, 2000.0}) {
        for (const double offset : {0.0, 0.001, 0.0005}) {
            const double spread = feed == 1000.0 ? 40.0 : 1.0;
            unstable.push_back({"Y", 1, feed, mm_min_to_mm_s(feed) * 0.01 + offset * spread, 0});
        }
    }
    collect(unstable);
    // A delay that grows with the speed.
    std::vector<DelayTouch> curved;
    for (const double feed : {60.0, 600.0, 1200.0, 2400.0, 3600.0}) {
        const double v = mm_min_to_mm_s(feed);
        for (int i = 0; i < 3; ++i) curved.push_back({"Z", -1, feed, -v * (0.005 + 0.0001 * v), 0});
    }
    collect(curved);

    struct Expected {
        LatencyWarningCode code;
        std::vector<std::string> values;
    };
    const std::vector<Expected> expected{
        {LatencyWarningCode::few_feeds, {"group", "feeds"}},
        {LatencyWarningCode::negative_delay, {"group", "delay_s"}},
        {LatencyWarningCode::single_touch_feed, {"group", "feed_1_mm_min", "feed_2_mm_min"}},
        {LatencyWarningCode::unstable_delay,
         {"group", "feed_mm_min", "range_mm", "travel_time_s", "ratio", "predicted_range_mm"}},
        {LatencyWarningCode::curved_residuals,
         {"group", "bow_mm", "delay_low_s", "feed_low_mm_min", "delay_high_s", "feed_high_mm_min"}},
    };
    for (const Expected& e : expected) {
        bool found = false;
        for (const LatencyWarning& w : all) {
            if (w.code != e.code) continue;
            found = true;
            EXPECT_EQ(w.message.code, to_string(w.code));
            EXPECT_STREQ(w.message.context, "DelayFit");
            test::expect_translatable(w.message, e.values);
            EXPECT_EQ(w.text(), render(w.message));
        }
        EXPECT_TRUE(found) << to_string(e.code);
    }
    // The English is the CLI's, numbers in their units in the values.
    for (const LatencyWarning& w : all) {
        if (w.code == LatencyWarningCode::single_touch_feed) {
            EXPECT_EQ(w.text(),
                      "X-: one touch only at 100 mm/min, 1000 mm/min: no scatter there; repeat "
                      "each touch (5 or more) to see the stability");
        }
        if (w.code == LatencyWarningCode::negative_delay) {
            EXPECT_NE(w.text().find("(-8 ms)"), std::string::npos) << w.text();
            EXPECT_NEAR(message_values(w.message).at("delay_s").get<double>(), -0.008, 1e-12);
        }
    }
}

TEST(DelayFitMessages, TheRuleAndTheRefusalsAreMessages) {
    std::vector<DelayTouch> touches;
    add_touches(touches, "X", +1, 10.0, 0.0085, {100, 1000, 2000}, 2);
    add_touches(touches, "Z", -1, -5.0, 0.012, {100, 1000, 2000}, 2);
    const DelayFit fit = fit_delay(touches);
    const ChosenGroup longest = choose_group(fit, std::nullopt);
    EXPECT_EQ(render(longest.rule),
              "the longest delay of 2 groups (the safe side for overtravel); choose one to "
              "override");
    test::expect_translatable(longest.rule, {"groups"});
    test::expect_translatable(choose_group(fit, std::string("x+")).rule, {});

    try {
        (void)choose_group(fit, std::string("q+"));
        FAIL() << "an unknown group was accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "got 'q+'; allowed: a group of the file (X+, Z-)");
        test::expect_translatable(e.to_message(), {"group", "groups"});
    }
    Scenario scenario;
    scenario.probe.interface_delay_s = 0.008;
    scenario.machine.scan_period_s = 0.004;
    try {
        (void)delay_to_apply(fit, scenario, std::string("X+"));
        FAIL() << "a negative latency was accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("the fitted delay of X+, 8.5 ms, is shorter than the "
                                              "scenario's probe.interface_delay_s + half of "
                                              "machine.scan_period_s (10 ms)",
                                              0),
                  0u)
            << e.what();
        test::expect_translatable(e.to_message(),
                                  {"group", "delay_s", "interface_and_half_scan_s"});
    }
}

TEST(DelayFitMessages, FileErrorsCarryTheirValues) {
    try {
        (void)fit_delay(parse_delay_csv(std::string(kHeader) + "X,1,500,1\nX,1,500,1.001\n"));
        FAIL() << "one feed accepted";
    } catch (const CsvError& e) {
        test::expect_translatable(e.problem(), {"group", "touches", "feed_mm_min", "lines"});
        test::expect_translatable(e.to_message(),
                                  {"line", "column", "group", "touches", "feed_mm_min", "lines"});
    }
    try {
        (void)parse_delay_csv(std::string(kHeader) + "X,1,-5,1\n");
        FAIL() << "a negative feed accepted";
    } catch (const CsvError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "line 2, column feed_mm_min: -5 is out of range: (0, 100000] mm/min");
        test::expect_translatable(e.problem(), {"feed_mm_min", "max_feed_mm_min"});
    }
}

TEST(DelayCsv, WindowsLineEndsReadAsUnixOnes) {
    const std::string text =
        "# delay test\naxis,direction,feed_mm_min,measured_mm\nX,+1,100,10.0017\n"
        "X,-1,2000,-9.966\n";
    const std::vector<DelayTouch> unix_ends = parse_delay_csv(text);
    const std::vector<DelayTouch> windows_ends = parse_delay_csv(test::with_crlf(text));
    ASSERT_EQ(windows_ends.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(windows_ends[i].axis, unix_ends[i].axis);
        EXPECT_EQ(windows_ends[i].direction, unix_ends[i].direction);
        EXPECT_EQ(windows_ends[i].feed_mm_min, unix_ends[i].feed_mm_min);
        EXPECT_EQ(windows_ends[i].measured_mm, unix_ends[i].measured_mm);
        EXPECT_EQ(windows_ends[i].line, unix_ends[i].line);
    }
}

}  // namespace
}  // namespace probecycle
