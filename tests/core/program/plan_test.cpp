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
              "steps.2.feed_mm_min: got -5; allowed: a number from 1 to 100000 mm/min");
    // A probe's feed and a ring touch's orientation are ones the lab reads back
    // (found by fuzz_machine_log: an edited plan imported to a CSV the lab refused).
    feed.replace(feed.find("\"feed_mm_min\": -5"), 17, "\"feed_mm_min\": 150000");
    EXPECT_EQ(first_error(feed),
              "steps.2.feed_mm_min: got 150000; allowed: a number from 1 to 100000 mm/min");
    std::string ring = probing_plan_json(program_test::golden_plans()[1].plan);
    ASSERT_NE(ring.find("\"orientation_deg\": 180.0"), std::string::npos);
    ring.replace(ring.find("\"orientation_deg\": 180.0"), 24, "\"orientation_deg\": 90");
    EXPECT_NE(first_error(ring).find("orientation_deg: got 90; allowed: one of 0, 180"),
              std::string::npos)
        << first_error(ring);
    std::string axis = good;
    axis.replace(axis.find(R"("axis": "Z")"), 11, R"("axis": "Q")");
    EXPECT_EQ(first_error(axis), "steps.2.axis: got \"Q\"; allowed: one of X, Y, Z");
    EXPECT_EQ(
        first_error("{\"format\": \"probecycle-probing-plan\", \"version\": 1, \"steps\": []}"),
        "steps: no recorded probe; a plan needs one or more");
}

// A value's key is kept whole, a NUL in it too (found by fuzz_probing_plan:
// the lookup cut the key at the NUL and lost its text).
TEST(ProbingPlan, AValueKeyWithANulKeepsItsText) {
    ProbingPlan plan = program_test::golden_plans()[2].plan;
    plan.values.push_back({std::string("a\0b", 3), "7"});
    const ProbingPlan back = parse_probing_plan(probing_plan_json(plan));
    ASSERT_EQ(back.values.size(), plan.values.size());
    EXPECT_EQ(back.values.back().key, std::string("a\0b", 3));
    EXPECT_EQ(back.values.back().text, "7");
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
