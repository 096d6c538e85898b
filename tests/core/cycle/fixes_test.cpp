// One-click fixes (core/cycle/fixes.h): each fix offered clears the
// warning it fixes, on hand-made cases and on every example and preset.

#include "core/cycle/fixes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/common/number_format.h"
#include "core/cycle/preset.h"
#include "core/cycle/scenario.h"
#include "core/cycle/sweep.h"

namespace probecycle {
namespace {

const Warning* find(const CycleResult& r, WarningCode code) {
    for (const Warning& w : r.warnings()) {
        if (w.code == code) return &w;
    }
    return nullptr;
}

std::string slurp(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The fix for `code` in the analysis of `s`, which must carry that warning.
std::optional<Fix> fix_of(const Scenario& s, WarningCode code) {
    const Analysis a = analyse(s);
    const Warning* w = find(a.cycle, code);
    EXPECT_NE(w, nullptr) << to_string(code);
    if (w == nullptr) return std::nullopt;
    return fix_for(s, a, *w);
}

TEST(Fixes, BackoffTooSmallSetsTheRecommendedBackoffOnTheMicrometreGrid) {
    Scenario s;  // two-touch surface, 2000 mm/min: overtravel 1.2717 mm, reseat 0.2 mm
    s.cycle.feed_override_max_pct = 100.0;  // the touches at their programmed feeds
    s.cycle.backoff_mm = 1.0;
    const std::optional<Fix> fix = fix_of(s, WarningCode::backoff_too_small);
    ASSERT_TRUE(fix);
    EXPECT_EQ(fix->kind, FixKind::backoff_to_recommended);
    EXPECT_DOUBLE_EQ(fix->scenario.cycle.backoff_mm, 1.472);  // 1.47166667 rounded up
    const CycleResult fixed = evaluate(fix->scenario);
    EXPECT_TRUE(fixed.valid());
    EXPECT_EQ(find(fixed, WarningCode::backoff_too_small), nullptr);
    EXPECT_EQ(find(fixed, WarningCode::backoff_excess), nullptr);
}

TEST(Fixes, TheRecommendationShownIsTheValueThatClearsTheWarning) {
    // Reseat 0.2002 mm made the recommendation 2.1052 mm, shown as
    // 2.105; typed back, it was refused. Now it is 2.106, and 2.106 passes.
    Scenario s;
    s.cycle.feed_override_max_pct = 100.0;  // the touches at their programmed feeds
    s.probe.reseat_mm = 0.2002;
    s.cycle.backoff_mm = 1.0;
    const double recommended = evaluate(s).recommended_backoff_mm();
    EXPECT_DOUBLE_EQ(recommended, 1.472);  // 1.27166667 + 0.2002 = 1.47186667, up
    s.cycle.backoff_mm = 1.472;
    EXPECT_EQ(find(evaluate(s), WarningCode::backoff_too_small), nullptr);
    s.cycle.backoff_mm = 1.471;
    EXPECT_NE(find(evaluate(s), WarningCode::backoff_too_small), nullptr);
}

TEST(Fixes, FeedBeyondTheKneeDropsToTheKneeRoundedDown) {
    Scenario s;
    s.cycle.strategy = Strategy::single_touch;
    s.cycle.probe_feed_mm_min = 9000.0;
    const Analysis a = analyse(s);
    ASSERT_TRUE(a.knee_feed_mm_min);
    const std::optional<Fix> fix = fix_of(s, WarningCode::feed_beyond_knee);
    ASSERT_TRUE(fix);
    EXPECT_EQ(fix->kind, FixKind::feed_to_knee);
    EXPECT_DOUBLE_EQ(fix->scenario.cycle.probe_feed_mm_min, std::floor(*a.knee_feed_mm_min));
    EXPECT_EQ(find(analyse(fix->scenario).cycle, WarningCode::feed_beyond_knee), nullptr);
}

TEST(Fixes, OvertravelDropsTheFeedUnderEightyPercentOfTheLimit) {
    // Single touch, T = 0.06 s, delays 8 ms: overtravel = v (0.008 + 0.03) + 0.005
    // (pretravel) for v in mm/s. A 2 mm limit warns from 1.6 mm: v = 41.97 mm/s,
    // 2518.4 mm/min.
    Scenario s;
    s.cycle.feed_override_max_pct = 100.0;  // the touch at its programmed feed
    s.cycle.strategy = Strategy::single_touch;
    s.probe.overtravel_limit_mm = 2.0;
    s.cycle.probe_feed_mm_min = 2900.0;  // 1.842 mm: a warning
    const std::optional<Fix> fix = fix_of(s, WarningCode::overtravel_limit);
    ASSERT_TRUE(fix);
    EXPECT_EQ(fix->kind, FixKind::feed_for_overtravel);
    const double feed = fix->scenario.cycle.probe_feed_mm_min;
    EXPECT_EQ(feed, std::floor(feed));
    const double expected = std::floor((1.6 - 0.005) / 0.038 * 60.0);
    // The knee, when slower, is taken instead.
    const Analysis a = analyse(s);
    EXPECT_DOUBLE_EQ(feed, std::min(expected, std::floor(*a.knee_feed_mm_min)));
    EXPECT_EQ(find(evaluate(fix->scenario), WarningCode::overtravel_limit), nullptr);

    // Over the limit (an error): the same fix.
    s.cycle.probe_feed_mm_min = 4000.0;
    const std::optional<Fix> from_error = fix_of(s, WarningCode::overtravel_limit);
    ASSERT_TRUE(from_error);
    EXPECT_DOUBLE_EQ(from_error->scenario.cycle.probe_feed_mm_min, feed);
}

TEST(Fixes, NoneWhenEvenTheSlowestFeedOvertravels) {
    Scenario s;
    s.cycle.strategy = Strategy::single_touch;
    s.probe.overtravel_limit_mm = 0.006;  // pretravel alone is 0.005 mm
    const Analysis a = analyse(s);
    const Warning* w = find(a.cycle, WarningCode::overtravel_limit);
    ASSERT_NE(w, nullptr);
    EXPECT_FALSE(fix_for(s, a, *w));
    // And the analysis says why there is no knee.
    EXPECT_FALSE(a.knee_feed_mm_min);
    const Warning* none = find(a.cycle, WarningCode::no_valid_feed);
    ASSERT_NE(none, nullptr);
    EXPECT_DOUBLE_EQ(std::get<warning::NoValidFeed>(none->figures).from_feed_mm_s, 10.0 / 60.0);
    EXPECT_NE(none->message().find("No probing feed from 10 mm/min to 10000 mm/min"),
              std::string::npos)
        << none->message();
}

TEST(Fixes, FirstTouchWhileAcceleratingStartsFartherOut) {
    Scenario s;
    s.cycle.part_position_uncertainty_mm = 0.0;  // a known part: only the feed's room
    s.cycle.strategy = Strategy::single_touch;
    s.cycle.approach_mm = 0.5;  // 2000 mm/min needs v T / 2 = 1 mm
    const std::optional<Fix> fix = fix_of(s, WarningCode::touch_while_accelerating);
    ASSERT_TRUE(fix);
    EXPECT_EQ(fix->kind, FixKind::approach_to_reach_feed);
    EXPECT_DOUBLE_EQ(fix->scenario.cycle.approach_mm, 1.0);
    EXPECT_EQ(find(evaluate(fix->scenario), WarningCode::touch_while_accelerating), nullptr);
}

// The bore example on the Fanuc-type machine with the recommended backoff is
// valid. Its first touch is still accelerating when it touches, but it only
// finds the bore: no warning (the one that was there offered to start 15.68
// mm out, where the faster first touch overran the backoff).
TEST(Fixes, TheFirstTouchOfTwoTouchMayTouchWhileAccelerating) {
    const std::filesystem::path resources = PROBECYCLE_RESOURCES_DIR;
    Scenario s =
        merge_json(scenario_from_json(slurp(resources / "examples/bore_two_touch.json")),
                   parse_preset(slurp(resources / "presets/machine_fanuc_exponential_servo.json"))
                       .scenario_json);
    // (At the default 150 % override its protected moves at 3000 mm/min
    // overrun the stylus: FeedOverride tests that.)
    s.cycle.feed_override_max_pct = 100.0;
    s.cycle.backoff_mm = evaluate(s).recommended_backoff_mm();
    const Analysis a = analyse(s);
    ASSERT_TRUE(a.cycle.valid());
    EXPECT_LT(a.cycle.first_touch().trigger_speed_mm_s,
              0.999 * a.cycle.first_touch().programmed_feed_mm_s);
    EXPECT_EQ(find(a.cycle, WarningCode::touch_while_accelerating), nullptr);
    for (const Warning& w : a.cycle.warnings()) {
        const std::optional<Fix> fix = fix_for(s, a, w);
        if (fix) {
            EXPECT_TRUE(evaluate(fix->scenario).valid()) << to_string(w.code);
        }
    }
    // Single-touch measures at its first touch: there it is reported.
    s.cycle.strategy = Strategy::single_touch;
    EXPECT_NE(find(evaluate(s), WarningCode::touch_while_accelerating), nullptr);
}

// A start inside the part's position uncertainty: the fix starts far enough
// out to touch at full feed, where the first touch stops farther than the
// backoff set for the short start allows; the fix sets the recommended
// backoff with it, one change, and the cycle stays valid.
TEST(Fixes, AFixThatWouldMakeTheBackoffTooSmallSetsItToo) {
    Scenario s =
        merge_json(Scenario{}, parse_preset(slurp(std::filesystem::path(PROBECYCLE_RESOURCES_DIR) /
                                                  "presets/machine_fanuc_exponential_servo.json"))
                                   .scenario_json);
    s.cycle.part_position_uncertainty_mm = 2.0;
    s.cycle.approach_mm = 1.5;  // inside the uncertainty
    s.cycle.backoff_mm = evaluate(s).recommended_backoff_mm();
    const Analysis a = analyse(s);
    ASSERT_TRUE(a.cycle.valid()) << invalid_codes_text(a.cycle.invalid_codes(), ", ");
    const Warning* w = find(a.cycle, WarningCode::start_inside_uncertainty);
    ASSERT_NE(w, nullptr);
    EXPECT_TRUE(std::get<warning::StartInsideUncertainty>(w->figures).inside);
    Scenario alone = s;
    alone.cycle.approach_mm =
        round_up_to(2.0 + approach_room_mm(s, s.cycle.probe_feed_mm_min / 60.0), 0.01);
    ASSERT_FALSE(evaluate(alone).valid());  // the start alone overruns the backoff
    const std::optional<Fix> fix = fix_for(s, a, *w);
    ASSERT_TRUE(fix.has_value());
    EXPECT_EQ(fix->kind, FixKind::approach_to_reach_feed);
    EXPECT_TRUE(fix->with_backoff);
    EXPECT_EQ(fix->scenario.cycle.approach_mm, alone.cycle.approach_mm);
    const CycleResult fixed = evaluate(fix->scenario);
    EXPECT_TRUE(fixed.valid());
    EXPECT_EQ(fix->scenario.cycle.backoff_mm, evaluate(alone).recommended_backoff_mm());
    const std::vector<std::pair<std::string, double>> changes = fix_changes(s, *fix);
    ASSERT_EQ(changes.size(), 2u);
    EXPECT_EQ(changes[0].first, "cycle.approach_mm");
    EXPECT_EQ(changes[1].first, "cycle.backoff_mm");
}

// Two-touch: a start that covers the uncertainty but not the room to reach
// the feed is no warning (the first touch only finds the surface); inside
// the uncertainty itself it is.
TEST(Fixes, TwoTouchStartsOnlyNeedToClearTheUncertainty) {
    Scenario s;
    s.cycle.part_position_uncertainty_mm = 1.0;
    s.cycle.approach_mm = 1.2;  // 2000 mm/min needs 1 mm more to reach the feed
    EXPECT_EQ(find(evaluate(s), WarningCode::start_inside_uncertainty), nullptr);
    s.cycle.approach_mm = 0.9;
    EXPECT_NE(find(evaluate(s), WarningCode::start_inside_uncertainty), nullptr);
    s.cycle.strategy = Strategy::single_touch;
    s.cycle.approach_mm = 1.2;
    EXPECT_NE(find(evaluate(s), WarningCode::start_inside_uncertainty), nullptr);
}

TEST(Fixes, WarningsWithoutAFixOfferNone) {
    Scenario s;
    s.cycle.target_uncertainty_mm = 0.0001;  // under the repeatability
    const Analysis a = analyse(s);
    const Warning* w = find(a.cycle, WarningCode::uncertainty_over_target);
    ASSERT_NE(w, nullptr);
    EXPECT_FALSE(fix_for(s, a, *w));
}

// A search set by hand to 1 mm past the surface ends before the default
// two-touch's first stop, 1.272 mm past it at 2000 mm/min: the fix searches
// that far, rounded up to the editor's 0.01 mm.
TEST(Fixes, SearchEndingBeforeTheStopSearchesPastIt) {
    Scenario s;
    s.cycle.feed_override_max_pct = 100.0;  // the touches at their programmed feeds
    s.cycle.search_beyond_mm = 1.0;
    const std::optional<Fix> fix = fix_of(s, WarningCode::search_ends_too_soon);
    ASSERT_TRUE(fix.has_value());
    EXPECT_EQ(fix->kind, FixKind::search_past_stop);
    EXPECT_DOUBLE_EQ(fix->scenario.cycle.search_beyond_mm, 1.28);
    EXPECT_EQ(find(evaluate(fix->scenario), WarningCode::search_ends_too_soon), nullptr);
}

// Every fix offered on every example and preset, both strategies, from slow to
// past the limit, clears the warning it fixes in the full analysis, and the
// scenario it makes is valid input.
TEST(Fixes, EveryFixOnEveryExampleAndPresetClearsItsWarning) {
    const std::filesystem::path resources = PROBECYCLE_RESOURCES_DIR;
    std::vector<std::pair<std::string, Scenario>> bases = {
        {"defaults", Scenario{}},
        {"bore_two_touch", scenario_from_json(slurp(resources / "examples/bore_two_touch.json"))}};
    std::vector<std::filesystem::path> presets;
    for (const auto& entry : std::filesystem::directory_iterator(resources / "presets")) {
        presets.push_back(entry.path());
    }
    ASSERT_GE(presets.size(), 10u);
    int offered = 0;
    std::map<FixKind, int> by_kind;
    for (const auto& [base_name, base] : bases) {
        for (const std::filesystem::path& preset : presets) {
            const Scenario with_preset =
                merge_json(base, parse_preset(slurp(preset)).scenario_json);
            for (Strategy strategy : {Strategy::single_touch, Strategy::two_touch}) {
                for (double feed : {300.0, 3000.0, 6000.0, 9500.0, 15000.0}) {
                    // A start too close to reach the feed; a search set
                    // by hand to 1 mm past the surface.
                    for (double approach : {0.2, 5.0}) {
                        Scenario s = with_preset;
                        s.cycle.strategy = strategy;
                        s.cycle.probe_feed_mm_min = feed;
                        s.cycle.approach_mm = approach;
                        s.cycle.search_beyond_mm = approach > 1.0 ? 1.0 : 0.0;
                        if (!validate(s).empty()) continue;
                        const Analysis a = analyse(s);
                        for (const Warning& w : a.cycle.warnings()) {
                            const std::optional<Fix> fix = fix_for(s, a, w);
                            if (!fix) continue;
                            ++offered;
                            ++by_kind[fix->kind];
                            SCOPED_TRACE(base_name + " + " + preset.filename().string() + ", " +
                                         to_string(strategy) + " at " + std::to_string(feed) +
                                         " mm/min, start " + std::to_string(approach) + ": " +
                                         to_string(w.code) + " by " + to_string(fix->kind));
                            EXPECT_TRUE(validate(fix->scenario).empty());
                            const Analysis fixed = analyse(fix->scenario);
                            EXPECT_FALSE(still_warns(fixed.cycle, w));
                            // No offered change creates an error.
                            EXPECT_EQ(fixed.cycle.invalid_codes() & ~a.cycle.invalid_codes(), 0u)
                                << invalid_codes_text(fixed.cycle.invalid_codes(), ", ");
                        }
                    }
                }
            }
        }
    }
    // Every kind of fix was exercised, not a handful.
    EXPECT_GT(offered, 100);
    for (FixKind kind :
         {FixKind::backoff_to_recommended, FixKind::feed_to_knee, FixKind::feed_for_overtravel,
          FixKind::approach_to_reach_feed, FixKind::search_past_stop}) {
        EXPECT_GT(by_kind[kind], 0) << to_string(kind);
    }
}

}  // namespace
}  // namespace probecycle
