// The plans: start distances from the cycle model, the plan file read back
// as written, and bad files and options named.

#include "core/program/plan.h"

#include <gtest/gtest.h>

#include "core/common/input_error.h"
#include "core/cycle/cycle.h"
#include "tests/core/program/program_test_plans.h"

namespace probecycle {
namespace {

TEST(ProbingPlan, EveryDelayTouchStartsFarEnoughOutToBeAtFullSpeed) {
    const Scenario scenario;
    DelayPlanOptions options;
    const ProbingPlan plan = make_delay_plan(scenario, options);
    EXPECT_EQ(plan.recorded().size(), 25u);  // 30 ... 2000 mm/min (2000 is the scenario's), 5 each
    const double beyond = 1.0;
    for (const ProgramStep* step : plan.recorded()) {
        const double start = step->distance_mm - beyond;
        EXPECT_GE(start,
                  approach_room_mm(scenario, step->feed_mm_min / 60.0) + options.margin_mm - 1e-9);
        EXPECT_EQ(step->axis, 'Z');
        EXPECT_EQ(step->direction, -1);
    }
    EXPECT_EQ(plan.steps.front().kind, StepKind::pause);
}

TEST(ProbingPlan, DefaultFeedsAddTheScenariosOwn) {
    Scenario scenario;
    scenario.cycle.probe_feed_mm_min = 1500.0;
    EXPECT_EQ(default_delay_feeds(scenario),
              (std::vector<double>{30.0, 100.0, 300.0, 1000.0, 1500.0, 2000.0}));
}

TEST(ProbingPlan, FileReadsBackAsWritten) {
    for (const auto& [name, plan] : program_test::golden_plans()) {
        const std::string text = probing_plan_json(plan);
        const ProbingPlan back = parse_probing_plan(text);
        EXPECT_EQ(probing_plan_json(back), text) << name;
        EXPECT_EQ(plan_id(back), plan_id(plan)) << name;
    }
}

std::string first_error(const std::string& text) {
    try {
        parse_probing_plan(text);
    } catch (const ScenarioError& e) {
        return e.errors().front().message();
    }
    return "no error";
}

TEST(ProbingPlan, BadFilesNameTheKey) {
    const std::string good = probing_plan_json(program_test::golden_plans()[2].plan);
    EXPECT_EQ(first_error("{}"),
              "format: \"probecycle-probing-plan\" (a plan that probecycle-cli program wrote)");
    std::string version = good;
    version.replace(version.find("\"version\": 1"), 12, "\"version\": 2");
    EXPECT_EQ(first_error(version),
              "version: got 2; allowed: 1 (a newer ProbeCycle wrote this file)");
    std::string feed = good;
    feed.replace(feed.find("\"feed_mm_min\": 2000.0"), 21, "\"feed_mm_min\": -5");
    EXPECT_EQ(first_error(feed),
              "steps.2.feed_mm_min: got -5; allowed: a number from 1 to 200000 mm/min");
    std::string axis = good;
    axis.replace(axis.find(R"("axis": "Z")"), 11, R"("axis": "Q")");
    EXPECT_EQ(first_error(axis), "steps.2.axis: got \"Q\"; allowed: one of X, Y, Z");
    EXPECT_EQ(
        first_error("{\"format\": \"probecycle-probing-plan\", \"version\": 1, \"steps\": []}"),
        "steps: no recorded probe; a plan needs one or more");
}

TEST(ProbingPlan, ProtectedMovesReadBackAsWritten) {
    const ProbingPlan plan = program_test::guarded_plan();
    const std::string text = probing_plan_json(plan);
    // A protected move is written as a plain move is: no recorded flag, no orientation.
    EXPECT_NE(text.find(R"({
      "step": "guard",
      "axis": "X",
      "direction": 1,
      "distance_mm": 20.0,
      "feed_mm_min": 3000.0,
      "text": "out to the X+ start"
    })"),
              std::string::npos)
        << text;
    const ProbingPlan back = parse_probing_plan(text);
    EXPECT_EQ(probing_plan_json(back), text);
    EXPECT_EQ(plan_id(back), plan_id(plan));
    ASSERT_EQ(back.steps.size(), 6u);
    EXPECT_EQ(back.steps[1].kind, StepKind::guard);
    EXPECT_EQ(back.steps[5].kind, StepKind::guard);
    EXPECT_EQ(back.steps[5].axis, 'Z');
    EXPECT_EQ(back.steps[5].direction, -1);
    EXPECT_FALSE(back.steps[5].recorded);
    EXPECT_TRUE(back.has_guards());
    // The recorded touches are the probes alone.
    ASSERT_EQ(back.recorded().size(), 1u);
    EXPECT_EQ(back.recorded()[0], &back.steps[2]);
    EXPECT_FALSE(program_test::golden_plans()[0].plan.has_guards());
}

TEST(ProbingPlan, BadProtectedMovesNameTheKey) {
    const std::string good = probing_plan_json(program_test::guarded_plan());
    // The first protected move is steps.2; its fields as written.
    const auto with = [&good](const std::string& from, const std::string& to) {
        std::string text = good;
        text.replace(text.find(from, text.find("\"step\": \"guard\"")), from.size(), to);
        return first_error(text);
    };
    // A protected move runs at a feed, never at the rapid.
    EXPECT_EQ(with("\"feed_mm_min\": 3000.0", "\"feed_mm_min\": 0"),
              "steps.2.feed_mm_min: got 0; allowed: a number from 1 to 200000 mm/min");
    EXPECT_EQ(with("\"distance_mm\": 20.0", "\"distance_mm\": 0"),
              "steps.2.distance_mm: got 0; allowed: a number from 0.001 to 1000 mm");
    EXPECT_EQ(with("\"direction\": 1", "\"direction\": 2"),
              "steps.2.direction: got 2; allowed: one of 1, -1");
    EXPECT_EQ(with("\"axis\": \"X\"", "\"axis\": \"A\""),
              "steps.2.axis: got \"A\"; allowed: one of X, Y, Z");
    // Only a probe is recorded.
    EXPECT_EQ(with("\"direction\": 1", "\"direction\": 1, \"recorded\": true"),
              "steps.2.recorded: got true; allowed: true or false (true on a probe only)");
    EXPECT_EQ(with("\"step\": \"guard\"", "\"step\": \"gaurd\""),
              "steps.2.step: got \"gaurd\"; allowed: one of pause, probe, move, guard");
}

TEST(ProbingPlan, OptionsThatCannotWorkAreRefused) {
    const Scenario scenario;
    DelayPlanOptions one_feed;
    one_feed.feeds_mm_min = {100.0, 100.0};
    EXPECT_THROW(make_delay_plan(scenario, one_feed), InputError);
    RingPlanOptions tiny;
    tiny.gauge_diameter_mm = 6.5;
    EXPECT_THROW(make_ring_plan(scenario, tiny), InputError);
    Scenario bore = scenario;
    bore.cycle.feature = Feature::bore;
    try {
        make_cycle_plan(bore, CyclePlanOptions{});
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "cycle.feature: got bore; allowed: surface (a program for a feature's touches "
                  "is not written yet)");
    }
    Scenario fast = scenario;
    fast.probe.overtravel_limit_mm = 0.5;
    DelayPlanOptions high;
    high.feeds_mm_min = {100.0, 20000.0};
    EXPECT_THROW(make_delay_plan(fast, high), InputError);
    EXPECT_EQ(to_string(*axis_direction_from_string("x+")), "X+");
    EXPECT_FALSE(axis_direction_from_string("A+"));
}

}  // namespace
}  // namespace probecycle
