#include "core/cycle/sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "core/common/units.h"
#include "core/cycle/cycle.h"
#include "core/cycle/scenario.h"

namespace probecycle {
namespace {

constexpr double kDefaultKneeTolerance = 0.01;  // cycle.knee_tolerance's default

Scenario single_touch_surface() {
    Scenario s;
    s.cycle.strategy = Strategy::single_touch;
    s.cycle.feature = Feature::surface;
    s.cycle.approach_mm = 5.0;
    s.probe.overtravel_limit_mm = 50.0;
    return s;
}

// The knee by its definition (docs/model.md, "Cycle time against feed"): among
// the valid points (CycleResult::valid()) whose first touch reaches its feed,
// the lowest feed whose cycle time is within the tolerance of the fastest.
std::optional<double> knee_of(const std::vector<SweepPoint>& points,
                              double tolerance = kDefaultKneeTolerance) {
    double best = std::numeric_limits<double>::infinity();
    for (const SweepPoint& p : points) {
        if (p.valid() && p.feed_reached) best = std::min(best, p.cycle_time_s);
    }
    std::optional<double> knee;
    for (const SweepPoint& p : points) {
        if (p.valid() && p.feed_reached && p.cycle_time_s <= best * (1.0 + tolerance)) {
            if (!knee || p.feed_mm_min < *knee) knee = p.feed_mm_min;
        }
    }
    return knee;
}

std::optional<double> max_feed_meeting(const std::vector<SweepPoint>& points, double target) {
    std::optional<double> best;
    if (target <= 0.0) return best;
    for (const SweepPoint& p : points) {
        // Valid feeds only.
        if (p.valid() && p.uncertainty_mm <= target && (!best || p.feed_mm_min > *best)) {
            best = p.feed_mm_min;
        }
    }
    return best;
}

TEST(LinearFeeds, FromToStepInclusive) {
    const std::vector<double> feeds = linear_feeds(100.0, 1000.0, 100.0);
    ASSERT_EQ(feeds.size(), 10u);
    for (std::size_t i = 0; i < feeds.size(); ++i) {
        EXPECT_NEAR(feeds[i], 100.0 * static_cast<double>(i + 1), 1e-9);
    }
}

TEST(LinearFeeds, EndIncludedDespiteRounding) {
    // 0.1 + 0.1 + 0.1 > 0.3 in binary; the end is still included.
    const std::vector<double> feeds = linear_feeds(0.1, 0.3, 0.1);
    ASSERT_EQ(feeds.size(), 3u);
    EXPECT_NEAR(feeds.back(), 0.3, 1e-12);
    EXPECT_EQ(linear_feeds(10.0, 10.0, 5.0).size(), 1u);
    // A range that is not a whole number of steps stops at the last step below the end.
    const std::vector<double> partial = linear_feeds(100.0, 1020.0, 100.0);
    ASSERT_EQ(partial.size(), 10u);
    EXPECT_NEAR(partial.back(), 1000.0, 1e-9);
}

// The CLI refuses absurd sweeps by this count before any feed is made.
TEST(LinearFeeds, CountIsTheSizeWithoutMakingThem) {
    for (const auto& [from, to, step] :
         {std::tuple{100.0, 2000.0, 50.0}, std::tuple{10.0, 10.0, 1.0}, std::tuple{0.1, 0.7, 0.1},
          std::tuple{100.0, 50.0, 10.0}, std::tuple{100.0, 200.0, 0.0}}) {
        EXPECT_EQ(linear_feed_count(from, to, step),
                  static_cast<double>(linear_feeds(from, to, step).size()))
            << from << " " << to << " " << step;
    }
    EXPECT_EQ(linear_feed_count(1.0, 100000.0, 1e-6), std::floor(99999.0 / 1e-6 + 1e-9) + 1.0);
}

TEST(LogFeeds, EvenOnALogScaleWithBothEnds) {
    const std::vector<double> feeds = log_feeds(10.0, 10000.0, 4);
    ASSERT_EQ(feeds.size(), 4u);
    const double expected[] = {10.0, 100.0, 1000.0, 10000.0};
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(feeds[i], expected[i], 1e-9 * expected[i]);
    const std::vector<double> two = log_feeds(30.0, 3000.0, 2);
    ASSERT_EQ(two.size(), 2u);
    EXPECT_NEAR(two[0], 30.0, 1e-12);
    EXPECT_NEAR(two[1], 3000.0, 1e-9);
}

TEST(Sweep, EachPointIsTheCycleAtThatFeed) {
    for (Strategy strategy : {Strategy::single_touch, Strategy::two_touch}) {
        Scenario s = single_touch_surface();
        s.cycle.strategy = strategy;
        const std::vector<double> feeds = linear_feeds(100.0, 5000.0, 350.0);
        const SweepResult sweep = sweep_feeds(s, feeds);
        ASSERT_EQ(sweep.points.size(), feeds.size());
        for (std::size_t i = 0; i < feeds.size(); ++i) {
            Scenario at = s;
            at.cycle.probe_feed_mm_min = feeds[i];
            const CycleResult r = evaluate(at);
            const SweepPoint& p = sweep.points[i];
            SCOPED_TRACE(feeds[i]);
            EXPECT_EQ(p.feed_mm_min, feeds[i]);
            EXPECT_NEAR(p.cycle_time_s, r.total(), 1e-12 * r.total());
            EXPECT_NEAR(p.overtravel_mm, r.overtravel_mm(), 1e-12);
            EXPECT_NEAR(p.uncertainty_mm, r.uncertainty_mm(), 1e-15);
            double sum = 0.0;
            for (Phase phase : all_phases()) {
                const std::size_t k = static_cast<std::size_t>(phase);
                EXPECT_NEAR(p.phase_time_s[k], r.phase_time(phase), 1e-12) << to_string(phase);
                sum += p.phase_time_s[k];
            }
            EXPECT_NEAR(sum, p.cycle_time_s, 1e-12 * p.cycle_time_s);
        }
    }
}

TEST(Sweep, KneeIsTheLowestFeedWithinOnePercentOfTheMinimum) {
    const Scenario s = single_touch_surface();
    const std::vector<double> feeds = linear_feeds(50.0, 10000.0, 50.0);
    const SweepResult sweep = sweep_feeds(s, feeds);
    const std::optional<double> expected = knee_of(sweep.points);
    ASSERT_TRUE(expected.has_value());
    ASSERT_TRUE(sweep.knee_feed_mm_min.has_value());
    EXPECT_EQ(*sweep.knee_feed_mm_min, *expected);
    // A knee strictly inside the range: cycle time falls, then stops falling.
    EXPECT_GT(*expected, 50.0);
    EXPECT_LT(*expected, 10000.0);
}

TEST(Sweep, KneeOfAnyOrderOfFeedsIsTheSame) {
    const Scenario s = single_touch_surface();
    std::vector<double> feeds = linear_feeds(100.0, 6000.0, 100.0);
    const SweepResult ascending = sweep_feeds(s, feeds);
    std::reverse(feeds.begin(), feeds.end());
    const SweepResult descending = sweep_feeds(s, feeds);
    ASSERT_TRUE(ascending.knee_feed_mm_min.has_value());
    ASSERT_TRUE(descending.knee_feed_mm_min.has_value());
    EXPECT_EQ(*ascending.knee_feed_mm_min, *descending.knee_feed_mm_min);
}

TEST(Sweep, MaxFeedMeetingTheTarget) {
    // Single touch, t_s = 4 ms, repeatability 1 um: U = 2 sqrt((v t_s)^2 / 12 + 0.0005^2).
    // 1200 mm/min: R = 0.08, U = 0.04619; 1300 mm/min: R = 0.08667, U = 0.05005 > 0.05.
    Scenario s = single_touch_surface();
    s.cycle.target_uncertainty_mm = 0.05;
    const SweepResult sweep = sweep_feeds(s, linear_feeds(100.0, 3000.0, 100.0));
    ASSERT_TRUE(sweep.max_feed_meeting_target_mm_min.has_value());
    EXPECT_NEAR(*sweep.max_feed_meeting_target_mm_min, 1200.0, 1e-9);
    EXPECT_EQ(sweep.max_feed_meeting_target_mm_min, max_feed_meeting(sweep.points, 0.05));
}

TEST(Sweep, NoTargetOrUnreachableTargetGivesNoFeed) {
    Scenario s = single_touch_surface();
    s.cycle.target_uncertainty_mm = 0.0;
    EXPECT_FALSE(sweep_feeds(s, linear_feeds(100.0, 3000.0, 100.0))
                     .max_feed_meeting_target_mm_min.has_value());
    s.cycle.target_uncertainty_mm = 0.0001;  // below the repeatability alone
    EXPECT_FALSE(sweep_feeds(s, linear_feeds(100.0, 3000.0, 100.0))
                     .max_feed_meeting_target_mm_min.has_value());
}

TEST(Sweep, TwoTouchTargetDependsOnTheMeasuringFeedOnly) {
    Scenario s = single_touch_surface();
    s.cycle.strategy = Strategy::two_touch;
    s.cycle.target_uncertainty_mm = 0.01;  // met at 30 mm/min whatever the first feed
    // With the recommended backoff every feed is valid (a fixed backoff is too
    // small from 2900 mm/min, and invalid feeds do not count).
    const SweepResult sweep =
        sweep_feeds(s, linear_feeds(100.0, 3000.0, 100.0), {.recommended_backoff = true});
    ASSERT_TRUE(sweep.max_feed_meeting_target_mm_min.has_value());
    EXPECT_NEAR(*sweep.max_feed_meeting_target_mm_min, 3000.0, 1e-9);
    const SweepResult fixed = sweep_feeds(s, linear_feeds(100.0, 3000.0, 100.0));
    ASSERT_FALSE(fixed.points.back().valid());
    EXPECT_EQ(fixed.max_feed_meeting_target_mm_min, max_feed_meeting(fixed.points, 0.01));
    EXPECT_LT(*fixed.max_feed_meeting_target_mm_min, 3000.0);
}

TEST(Sweep, RandomScenariosKneeAndTargetByDefinition) {
    std::mt19937_64 rng{42};
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        Scenario s = single_touch_surface();
        s.cycle.strategy = static_cast<Strategy>(rng() % 2);
        s.cycle.feature = static_cast<Feature>(rng() % 5);
        s.machine.accel_model = static_cast<AccelModel>(rng() % 3);
        s.machine.time_constant_s = 0.02 + 0.15 * u(rng);
        s.machine.scan_period_s = 0.0001 + 0.008 * u(rng);
        s.cycle.approach_mm = 0.5 + 10.0 * u(rng);
        s.cycle.target_uncertainty_mm = (i % 2 == 0) ? 0.0 : 0.002 + 0.1 * u(rng);
        if (!validate(s).empty()) continue;
        const std::vector<double> feeds = linear_feeds(100.0, 8000.0, 100.0);
        const SweepResult sweep = sweep_feeds(s, feeds);
        ASSERT_EQ(sweep.points.size(), feeds.size());
        EXPECT_EQ(sweep.knee_feed_mm_min, knee_of(sweep.points)) << "case " << i;
        EXPECT_EQ(sweep.max_feed_meeting_target_mm_min,
                  max_feed_meeting(sweep.points, s.cycle.target_uncertainty_mm))
            << "case " << i;
    }
}

TEST(Sweep, RecommendedBackoffOptionSweepsTheOptimisedTwoTouchCycle) {
    Scenario s;  // two-touch, backoff 2 mm
    SweepOptions options;
    options.recommended_backoff = true;
    const std::vector<double> feeds = linear_feeds(500.0, 8000.0, 500.0);
    const SweepResult sweep = sweep_feeds(s, feeds, options);
    ASSERT_EQ(sweep.points.size(), feeds.size());
    for (std::size_t i = 0; i < feeds.size(); ++i) {
        Scenario at = s;
        at.cycle.probe_feed_mm_min = feeds[i];
        at.cycle.backoff_mm = evaluate(at).recommended_backoff_mm();
        const CycleResult r = evaluate(at);
        EXPECT_NEAR(sweep.points[i].cycle_time_s, r.total(), 1e-12 * r.total()) << feeds[i];
        EXPECT_NEAR(sweep.points[i].overtravel_mm, r.overtravel_mm(), 1e-12) << feeds[i];
    }
    EXPECT_EQ(sweep.knee_feed_mm_min, knee_of(sweep.points));
}

TEST(Sweep, IntoReusesTheBufferAndMatchesSweepFeeds) {
    const Scenario s = single_touch_surface();
    SweepResult out;
    sweep_feeds_into(s, linear_feeds(100.0, 10000.0, 10.0), out);
    const std::vector<double> feeds = linear_feeds(200.0, 2000.0, 200.0);
    sweep_feeds_into(s, feeds, out);
    const SweepResult fresh = sweep_feeds(s, feeds);
    ASSERT_EQ(out.points.size(), fresh.points.size());
    for (std::size_t i = 0; i < feeds.size(); ++i) {
        EXPECT_EQ(out.points[i].feed_mm_min, fresh.points[i].feed_mm_min);
        EXPECT_EQ(out.points[i].cycle_time_s, fresh.points[i].cycle_time_s);
    }
    EXPECT_EQ(out.knee_feed_mm_min, fresh.knee_feed_mm_min);
    EXPECT_EQ(out.max_feed_meeting_target_mm_min, fresh.max_feed_meeting_target_mm_min);
}

TEST(Sweep, EmptyFeedsGiveAnEmptyResult) {
    const SweepResult sweep = sweep_feeds(single_touch_surface(), std::vector<double>{});
    EXPECT_TRUE(sweep.points.empty());
    EXPECT_FALSE(sweep.knee_feed_mm_min.has_value());
    EXPECT_FALSE(sweep.max_feed_meeting_target_mm_min.has_value());
}

double cycle_time_at(Scenario s, double feed) {
    s.cycle.probe_feed_mm_min = feed;
    return evaluate(s).total();
}

TEST(FindKnee, ContinuousKneeMatchesTheDefinition) {
    for (AccelModel model :
         {AccelModel::time_constant, AccelModel::constant_accel, AccelModel::jerk_limited}) {
        Scenario s = single_touch_surface();
        s.machine.accel_model = model;
        SCOPED_TRACE(to_string(model));
        const std::optional<double> knee = find_knee(s, 10.0, 10000.0).knee_feed_mm_min;
        ASSERT_TRUE(knee.has_value());
        EXPECT_GE(*knee, 10.0);
        EXPECT_LE(*knee, 10000.0);
        // The minimum over a fine grid stands in for the continuous minimum.
        double best = std::numeric_limits<double>::infinity();
        for (double f : log_feeds(10.0, 10000.0, 2000)) best = std::min(best, cycle_time_at(s, f));
        EXPECT_LE(cycle_time_at(s, *knee), best * (1.0 + kDefaultKneeTolerance) * (1.0 + 1e-6));
        // Every lower feed is outside the tolerance.
        for (double f : log_feeds(10.0, *knee * (1.0 - 1e-3), 500)) {
            ASSERT_GT(cycle_time_at(s, f), best * (1.0 + kDefaultKneeTolerance) * (1.0 - 1e-6))
                << "feed " << f << " knee " << *knee;
        }
    }
}

TEST(FindKnee, OneValidFeedIsItsOwnKnee) {
    const Scenario s = single_touch_surface();
    const KneeSearch one = find_knee(s, 1000.0, 1000.0);
    ASSERT_TRUE(one.knee_feed_mm_min.has_value());
    EXPECT_EQ(*one.knee_feed_mm_min, 1000.0);
    EXPECT_EQ(one.best_feed_mm_min, 1000.0);
    EXPECT_EQ(one.best_cycle_time_s, cycle_time_at(s, 1000.0));
    EXPECT_FALSE(one.range_end_warning.has_value());
    // An invalid one has none.
    Scenario tight = s;
    tight.probe.overtravel_limit_mm = 0.01;
    EXPECT_FALSE(find_knee(tight, 1000.0, 1000.0).knee_feed_mm_min.has_value());
}

TEST(FindKnee, AgreesWithAFineSweep) {
    const Scenario s = single_touch_surface();
    const std::optional<double> knee = find_knee(s, 100.0, 8000.0).knee_feed_mm_min;
    const SweepResult sweep = sweep_feeds(s, linear_feeds(100.0, 8000.0, 1.0));
    ASSERT_TRUE(knee.has_value());
    ASSERT_TRUE(sweep.knee_feed_mm_min.has_value());
    EXPECT_NEAR(*knee, *sweep.knee_feed_mm_min, 2.0);
}

TEST(Analyse, IsEvaluatePlusTheKneeOverTheSearchRange) {
    Scenario s = single_touch_surface();
    s.cycle.probe_feed_mm_min = 2000.0;
    const Analysis a = analyse(s);
    const CycleResult r = evaluate(s);
    EXPECT_EQ(a.cycle.total(), r.total());
    EXPECT_EQ(a.cycle.phases().size(), r.phases().size());
    ASSERT_TRUE(a.knee_feed_mm_min.has_value());
    const std::optional<double> knee =
        find_knee(s, kKneeSearchFrom_mm_min, kKneeSearchTo_mm_min).knee_feed_mm_min;
    ASSERT_TRUE(knee.has_value());
    EXPECT_NEAR(*a.knee_feed_mm_min, *knee, 1e-6 * *knee);
    // The same warnings as evaluate(), plus at most feed_beyond_knee and knee_at_range_end.
    std::size_t extra = 0;
    for (const Warning& w : a.cycle.warnings()) {
        if (w.code == WarningCode::feed_beyond_knee || w.code == WarningCode::knee_at_range_end)
            ++extra;
    }
    EXPECT_LE(extra, 2u);
    EXPECT_EQ(a.cycle.warnings().size(), r.warnings().size() + extra);
}

TEST(Analyse, FeedBeyondKneeReportsTheTimeSaved) {
    Scenario s = single_touch_surface();
    s.cycle.probe_feed_mm_min = 9000.0;
    const Analysis a = analyse(s);
    ASSERT_TRUE(a.knee_feed_mm_min.has_value());
    const Warning* w = nullptr;
    for (const Warning& warning : a.cycle.warnings()) {
        if (warning.code == WarningCode::feed_beyond_knee) w = &warning;
    }
    ASSERT_NE(w, nullptr);
    // Time saved beyond the knee: the cycle at the knee less the cycle at the feed,
    // under 1 % of the minimum.
    // (Faster may even be slower, when the longer return outweighs the approach.)
    const double saved = cycle_time_at(s, *a.knee_feed_mm_min) - a.cycle.total();
    if (saved >= 0.0) {
        EXPECT_NEAR(std::get<warning::FeedBeyondKnee>(w->figures).time_saved_s, saved, 1e-9);
    } else {
        EXPECT_TRUE(std::abs(std::get<warning::FeedBeyondKnee>(w->figures).time_saved_s - saved) <
                        1e-9 ||
                    std::get<warning::FeedBeyondKnee>(w->figures).time_saved_s == 0.0)
            << std::get<warning::FeedBeyondKnee>(w->figures).time_saved_s << " vs " << saved;
    }
    EXPECT_LT(std::get<warning::FeedBeyondKnee>(w->figures).time_saved_s,
              kDefaultKneeTolerance * a.cycle.total() * 1.01);
}

// A feed above 10000 mm/min is judged on a curve that reaches it: with a
// 50 mm approach the best single-touch feed lies far above 10000.
TEST(Analyse, KneeSearchReachesAFeedBeyond10000) {
    Scenario s = single_touch_surface();
    s.cycle.approach_mm = 50.0;
    s.cycle.probe_feed_mm_min = 20000.0;
    const Analysis a = analyse(s);
    ASSERT_TRUE(a.knee_feed_mm_min.has_value());
    EXPECT_GT(*a.knee_feed_mm_min, kKneeSearchTo_mm_min);
    EXPECT_LE(*a.knee_feed_mm_min, 20000.0);
    // By the knee's definition, no feed up to 20000 is more than 1 % faster than it.
    const SweepResult fine = sweep_feeds(s, log_feeds(10.0, 20000.0, 400));
    double best = fine.points.front().cycle_time_s;
    for (const SweepPoint& p : fine.points) best = std::min(best, p.cycle_time_s);
    ASSERT_TRUE(a.knee_cycle_time_s.has_value());
    EXPECT_LE(*a.knee_cycle_time_s, best * (1.0 + kDefaultKneeTolerance) + 1e-12);
    for (const Warning& w : a.cycle.warnings()) {
        if (w.code == WarningCode::feed_beyond_knee) {
            EXPECT_LT(std::get<warning::FeedBeyondKnee>(w.figures).time_saved_s,
                      kDefaultKneeTolerance * a.cycle.total() * 1.01);
        }
    }
}

// --- The knee among valid feeds, its tolerance, the range's ends ---

const Warning* find_warning(const std::vector<Warning>& warnings, WarningCode code) {
    for (const Warning& w : warnings) {
        if (w.code == code) return &w;
    }
    return nullptr;
}

// Single touch, T = 0.06 s: overtravel = 0.005 + v (0.002 + 0.002 + 0.004 + 0.03),
// 2 mm at v = 52.5 mm/s = 3151 mm/min, well below the unlimited knee (about 6800).
TEST(Sweep, KneeIsSearchedAmongValidFeedsOnly) {
    Scenario s = single_touch_surface();
    s.cycle.feed_override_max_pct = 100.0;  // the touch at its programmed feed
    s.probe.overtravel_limit_mm = 2.0;
    const SweepResult sweep = sweep_feeds(s, linear_feeds(100.0, 10000.0, 50.0));
    ASSERT_TRUE(sweep.knee_feed_mm_min.has_value());
    EXPECT_EQ(sweep.knee_feed_mm_min, knee_of(sweep.points));
    for (const SweepPoint& p : sweep.points) {
        EXPECT_EQ(p.valid(), p.checked_overtravel_mm < 2.0) << p.feed_mm_min;
        EXPECT_EQ(p.invalid_codes,
                  p.valid() ? 0u : invalid_code_bit(WarningCode::overtravel_limit));
    }
    Scenario unlimited = s;
    unlimited.probe.overtravel_limit_mm = 100.0;
    const SweepResult all = sweep_feeds(unlimited, linear_feeds(100.0, 10000.0, 50.0));
    ASSERT_TRUE(all.knee_feed_mm_min.has_value());
    EXPECT_GT(*all.knee_feed_mm_min, 5000.0);
    EXPECT_LE(*sweep.knee_feed_mm_min, 3150.0);
    // The limit, not the range, ends the valid feeds: nothing to say about the range.
    EXPECT_TRUE(sweep.warnings.empty());
}

TEST(Sweep, NoValidFeedGivesNoKnee) {
    Scenario s = single_touch_surface();
    s.probe.overtravel_limit_mm = 0.01;  // 0.0113 mm already at 10 mm/min
    const SweepResult sweep = sweep_feeds(s, linear_feeds(10.0, 1000.0, 10.0));
    EXPECT_FALSE(sweep.knee_feed_mm_min.has_value());
    EXPECT_TRUE(sweep.warnings.empty());
    EXPECT_FALSE(find_knee(s, 10.0, 1000.0).knee_feed_mm_min.has_value());
}

// The Renishaw note's geometry (single touch, 2.5 mm start,
// T = 0.06 s, return at 5000 mm/min). Its cycle time is lowest near 4500
// mm/min, rises, then falls again above about 6500 mm/min only because the
// touch no longer reaches the programmed feed in 2.5 mm: those feeds are not
// the programmed feed, and the knee is not among them (it was 9326 mm/min,
// at the end of the range). The time-constant plan reaches v in v T / 2 and
// is at sqrt(2 (v / T) s) after s, so the touch is within 0.1 % of the feed
// up to v = 2 s / (T 0.999^2).
TEST(FindKnee, FeedsTheFirstTouchNeverReachesDoNotCount) {
    Scenario s = single_touch_surface();
    s.cycle.approach_mm = 2.5;
    s.cycle.return_feed_mm_min = 5000.0;
    s.cycle.feed_override_max_pct = 100.0;
    const double reached_to = mm_s_to_mm_min(2.0 * 2.5 / (0.06 * 0.999 * 0.999));
    const KneeSearch knee = find_knee(s, 10.0, 10000.0);
    ASSERT_TRUE(knee.knee_feed_mm_min.has_value());
    EXPECT_NEAR(knee.valid_to_mm_min, reached_to, 1e-3);
    EXPECT_LT(*knee.knee_feed_mm_min, reached_to);
    EXPECT_GT(*knee.knee_feed_mm_min, 3000.0);
    EXPECT_FALSE(knee.range_end_warning.has_value());  // the feeds reached end there
    // The sweep flags the feeds that are not reached; the one that looks
    // fastest is among them.
    const SweepResult sweep = sweep_feeds(s, linear_feeds(3000.0, 10000.0, 250.0));
    const auto at = [&](double feed) {
        for (const SweepPoint& p : sweep.points) {
            if (p.feed_mm_min == feed) return p;
        }
        return SweepPoint{};
    };
    EXPECT_TRUE(at(4500.0).feed_reached);
    EXPECT_FALSE(at(6500.0).feed_reached);
    EXPECT_LT(at(10000.0).cycle_time_s, at(4500.0).cycle_time_s);
    for (const SweepPoint& p : sweep.points) {
        EXPECT_EQ(p.feed_reached, p.feed_mm_min <= reached_to) << p.feed_mm_min;
    }
    EXPECT_EQ(sweep.knee_feed_mm_min, knee_of(sweep.points));
    ASSERT_TRUE(sweep.knee_feed_mm_min.has_value());
    EXPECT_LT(*sweep.knee_feed_mm_min, reached_to);
    EXPECT_TRUE(sweep.warnings.empty());
    // analyse() agrees, and a feed beyond that is not called "no faster".
    s.cycle.probe_feed_mm_min = 9000.0;
    const Analysis a = analyse(s);
    ASSERT_TRUE(a.knee_feed_mm_min.has_value());
    EXPECT_LT(*a.knee_feed_mm_min, reached_to);
    for (const Warning& w : a.cycle.warnings()) {
        EXPECT_NE(w.code, WarningCode::feed_beyond_knee) << w.message();
        EXPECT_NE(w.code, WarningCode::knee_at_range_end) << w.message();
    }
    // A touch that starts at the surface reaches no feed: no knee, and the
    // warning says that, not that the overtravel is over the limit.
    s.cycle.approach_mm = 0.0;
    const Analysis none = analyse(s);
    EXPECT_FALSE(none.knee_feed_mm_min.has_value());
    bool said = false;
    for (const Warning& w : none.cycle.warnings()) {
        if (w.code != WarningCode::no_valid_feed) continue;
        said = true;
        EXPECT_EQ(w.message(),
                  "No probing feed from 10 mm/min to 10000 mm/min is reached: the first touch "
                  "meets the surface before it reaches even 10 mm/min, so there is no knee; "
                  "start the touch farther out");
    }
    EXPECT_TRUE(said);
}

TEST(FindKnee, StopsWhereTheOvertravelReachesTheLimit) {
    Scenario s = single_touch_surface();
    s.cycle.feed_override_max_pct = 100.0;  // the touch at its programmed feed
    s.probe.overtravel_limit_mm = 2.0;
    const KneeSearch knee = find_knee(s, 10.0, 10000.0);
    ASSERT_TRUE(knee.knee_feed_mm_min.has_value());
    ASSERT_TRUE(knee.best_feed_mm_min.has_value());
    // (2 - 0.005) / 0.038 mm/s = 52.5 mm/s.
    // Found to 1e-7 of the feed, on the valid side.
    EXPECT_NEAR(knee.valid_to_mm_min, mm_s_to_mm_min((2.0 - 0.005) / 0.038), 1e-3);
    Scenario at = s;
    at.cycle.probe_feed_mm_min = knee.valid_to_mm_min;
    EXPECT_NEAR(evaluate(at).overtravel_mm(), 2.0, 1e-6);
    EXPECT_TRUE(evaluate(at).valid());
    EXPECT_LE(*knee.best_feed_mm_min, knee.valid_to_mm_min);
    EXPECT_LE(*knee.knee_feed_mm_min, *knee.best_feed_mm_min);
    EXPECT_FALSE(knee.range_end_warning.has_value());
    // The same knee as a fine sweep of the valid feeds.
    const SweepResult fine = sweep_feeds(s, linear_feeds(10.0, 10000.0, 1.0));
    ASSERT_TRUE(fine.knee_feed_mm_min.has_value());
    EXPECT_NEAR(*knee.knee_feed_mm_min, *fine.knee_feed_mm_min, 2.0);
    // Beyond the limit the cycle is faster still: the unlimited knee is elsewhere.
    Scenario unlimited = s;
    unlimited.probe.overtravel_limit_mm = 100.0;
    EXPECT_GT(*find_knee(unlimited, 10.0, 10000.0).knee_feed_mm_min, 5000.0);
}

TEST(FindKnee, TheToleranceMovesTheKnee) {
    Scenario s = single_touch_surface();
    std::vector<double> knees;
    for (double tolerance : {0.0, 0.01, 0.05, 0.2}) {
        SCOPED_TRACE(tolerance);
        s.cycle.knee_tolerance = tolerance;
        const KneeSearch knee = find_knee(s, 10.0, 10000.0);
        ASSERT_TRUE(knee.knee_feed_mm_min.has_value());
        EXPECT_LE(cycle_time_at(s, *knee.knee_feed_mm_min),
                  knee.best_cycle_time_s * (1.0 + tolerance) * (1.0 + 1e-9));
        knees.push_back(*knee.knee_feed_mm_min);
        // A feed of the editors' digits (whole mm/min from 100 mm/min up) ...
        EXPECT_EQ(*knee.knee_feed_mm_min, std::round(*knee.knee_feed_mm_min));
        if (tolerance == 0.0) {
            // ... so with no tolerance, the fastest feed to within that step.
            EXPECT_NEAR(*knee.knee_feed_mm_min, *knee.best_feed_mm_min, 1.0);
        }
    }
    // A looser tolerance lets a slower feed count: strictly lower knees.
    for (std::size_t i = 1; i < knees.size(); ++i) EXPECT_LT(knees[i], knees[i - 1]);
    // The sweep uses the same key.
    s.cycle.knee_tolerance = 0.05;
    const SweepResult sweep = sweep_feeds(s, linear_feeds(100.0, 10000.0, 50.0));
    EXPECT_EQ(sweep.knee_feed_mm_min, knee_of(sweep.points, 0.05));
}

// A 50 mm approach: every faster feed up to 10000 mm/min still saves time.
TEST(FindKnee, FastestAtTheHighestFeedSearchedIsSaid) {
    Scenario s = single_touch_surface();
    s.cycle.approach_mm = 50.0;
    const KneeSearch knee = find_knee(s, 10.0, 10000.0);
    ASSERT_TRUE(knee.knee_feed_mm_min.has_value());
    EXPECT_EQ(knee.best_feed_mm_min, 10000.0);
    ASSERT_TRUE(knee.range_end_warning.has_value());
    const Warning& w = *knee.range_end_warning;
    EXPECT_EQ(w.code, WarningCode::knee_at_range_end);
    EXPECT_EQ(w.severity, Severity::info);
    EXPECT_DOUBLE_EQ(std::get<warning::KneeAtRangeEnd>(w.figures).end_feed_mm_s,
                     mm_min_to_mm_s(10000.0));
    EXPECT_DOUBLE_EQ(std::get<warning::KneeAtRangeEnd>(w.figures).knee_feed_mm_s,
                     mm_min_to_mm_s(*knee.knee_feed_mm_min));
    EXPECT_TRUE(std::get<warning::KneeAtRangeEnd>(w.figures).highest);
    EXPECT_EQ(w.message(),
              "The fastest cycle lies at the highest feed searched, 10000 mm/min: the "
              "knee at " +
                  std::to_string(static_cast<long>(std::lround(*knee.knee_feed_mm_min))) +
                  " mm/min depends on that range; search faster feeds too");
}

// The defaults' single-touch minimum lies near 8900 mm/min: from 9500 up, slower is faster.
TEST(FindKnee, FastestAtTheLowestFeedSearchedIsSaid) {
    const Scenario s = single_touch_surface();
    const KneeSearch knee = find_knee(s, 9500.0, 12000.0);
    ASSERT_TRUE(knee.knee_feed_mm_min.has_value());
    EXPECT_EQ(knee.knee_feed_mm_min, 9500.0);
    EXPECT_EQ(knee.best_feed_mm_min, 9500.0);
    ASSERT_TRUE(knee.range_end_warning.has_value());
    EXPECT_FALSE(std::get<warning::KneeAtRangeEnd>(knee.range_end_warning->figures).highest);
    EXPECT_NE(knee.range_end_warning->message().find("lowest feed searched, 9500 mm/min"),
              std::string::npos);
    EXPECT_NE(knee.range_end_warning->message().find("search slower feeds too"), std::string::npos);
    // A range around the minimum says nothing.
    EXPECT_FALSE(find_knee(s, 10.0, 12000.0).range_end_warning.has_value());
}

TEST(Sweep, FastestAtAnEndOfTheSweepIsSaid) {
    Scenario s = single_touch_surface();
    EXPECT_TRUE(sweep_feeds(s, linear_feeds(100.0, 12000.0, 100.0)).warnings.empty());

    const SweepResult low = sweep_feeds(s, linear_feeds(9500.0, 12000.0, 100.0));
    ASSERT_EQ(low.warnings.size(), 1u);
    EXPECT_EQ(low.warnings[0].code, WarningCode::knee_at_range_end);
    EXPECT_FALSE(std::get<warning::KneeAtRangeEnd>(low.warnings[0].figures).highest);
    EXPECT_DOUBLE_EQ(std::get<warning::KneeAtRangeEnd>(low.warnings[0].figures).end_feed_mm_s,
                     mm_min_to_mm_s(9500.0));

    s.cycle.approach_mm = 50.0;
    const SweepResult high = sweep_feeds(s, linear_feeds(100.0, 5000.0, 100.0));
    ASSERT_EQ(high.warnings.size(), 1u);
    EXPECT_TRUE(std::get<warning::KneeAtRangeEnd>(high.warnings[0].figures).highest);
    EXPECT_DOUBLE_EQ(std::get<warning::KneeAtRangeEnd>(high.warnings[0].figures).end_feed_mm_s,
                     mm_min_to_mm_s(5000.0));
    ASSERT_TRUE(high.knee_feed_mm_min.has_value());
    EXPECT_DOUBLE_EQ(std::get<warning::KneeAtRangeEnd>(high.warnings[0].figures).knee_feed_mm_s,
                     mm_min_to_mm_s(*high.knee_feed_mm_min));

    // One feed is no range.
    EXPECT_TRUE(sweep_feeds(s, std::vector<double>{2000.0}).warnings.empty());
}

TEST(Analyse, KneeAtTheEndOfTheSearchRangeIsAWarning) {
    Scenario s = single_touch_surface();
    s.cycle.approach_mm = 50.0;
    s.cycle.probe_feed_mm_min = 2000.0;
    const Analysis a = analyse(s);
    const Warning* w = find_warning(a.cycle.warnings(), WarningCode::knee_at_range_end);
    ASSERT_NE(w, nullptr);
    EXPECT_DOUBLE_EQ(std::get<warning::KneeAtRangeEnd>(w->figures).end_feed_mm_s,
                     mm_min_to_mm_s(kKneeSearchTo_mm_min));
    EXPECT_EQ(find_warning(analyse(single_touch_surface()).cycle.warnings(),
                           WarningCode::knee_at_range_end),
              nullptr);
}

TEST(Analyse, FeedBeyondKneeNamesTheTolerance) {
    Scenario s = single_touch_surface();
    s.cycle.probe_feed_mm_min = 9000.0;
    s.cycle.knee_tolerance = 0.05;
    const Analysis a = analyse(s);
    const Warning* w = find_warning(a.cycle.warnings(), WarningCode::feed_beyond_knee);
    ASSERT_NE(w, nullptr);
    EXPECT_EQ(std::get<warning::FeedBeyondKnee>(w->figures).knee_tolerance, 0.05);
    EXPECT_NE(w->message().find("(under 5 %)"), std::string::npos) << w->message();
}

}  // namespace
}  // namespace probecycle
