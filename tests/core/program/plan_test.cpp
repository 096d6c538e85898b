// The plans: start distances from the cycle model, the plan file read back
// as written, and bad files and options named.

#include "core/program/plan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "core/common/input_error.h"
#include "core/common/number_format.h"
#include "core/cycle/cycle.h"
#include "tests/core/common/line_ends.h"
#include "tests/core/program/program_test_plans.h"

namespace probecycle {
namespace {

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

TEST(ProbingPlan, AFileWithWindowsLineEndsReadsAsTheSamePlan) {
    for (const auto& [name, plan] : program_test::golden_plans()) {
        const std::string text = test::with_crlf(probing_plan_json(plan));
        EXPECT_EQ(plan_id(parse_probing_plan(text)), plan_id(plan)) << name;
    }
}

std::string first_error(const std::string& text) {
    try {
        parse_probing_plan(text);
    } catch (const PlanError& e) {
        return e.errors().front().message();
    }
    return "no error";
}

// A bad plan file is a plan's error, not a scenario's: a caller tells the
// kinds of file apart by type (FileContentError for all three).
TEST(ProbingPlan, ABadFileIsAPlanError) {
    try {
        (void)parse_probing_plan(R"({"format": "probecycle-scenario"})");
        ADD_FAILURE() << "accepted";
    } catch (const ScenarioError&) {
        ADD_FAILURE() << "a plan's problem thrown as a scenario's";
    } catch (const FileContentError& e) {
        EXPECT_NE(dynamic_cast<const PlanError*>(&e), nullptr);
        EXPECT_EQ(e.kind(), FileKind::plan);
        EXPECT_STREQ(to_string(e.kind()), "plan");
        ASSERT_FALSE(e.errors().empty());
        EXPECT_EQ(e.errors().front().key, "format");
    }
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
              "steps.2.feed_mm_min: got 0; allowed: a number from 1 to 100000 mm/min");
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

// --- The tuned cycle on a feature ---

double up(double distance_mm) {
    return round_up_to(distance_mm, 0.001);  // the programs' digits, the safe side
}

struct ExpectedStep {
    StepKind kind;
    const char* along;  // axis and direction of travel
    double distance_mm;
    double feed_mm_min;
    bool recorded;
};

void expect_steps(const ProbingPlan& plan, std::size_t first,
                  const std::vector<ExpectedStep>& expected) {
    ASSERT_LE(first + expected.size(), plan.steps.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const ProgramStep& step = plan.steps[first + i];
        const ExpectedStep& want = expected[i];
        SCOPED_TRACE("step " + std::to_string(first + i) + ": " + step.text);
        EXPECT_EQ(step.kind, want.kind);
        EXPECT_EQ(to_string(AxisDirection{step.axis, step.direction}), want.along);
        EXPECT_NEAR(step.distance_mm, want.distance_mm, 1e-9);
        EXPECT_EQ(step.feed_mm_min, want.feed_mm_min);
        EXPECT_EQ(step.recorded, want.recorded);
    }
}

// The model's touch on a surface from the feature's start distance: what
// every touch of the feature does (the same sequence in another direction).
CycleResult model_touch(const Scenario& scenario) {
    Scenario surface = scenario;
    surface.cycle.feature = Feature::surface;
    return evaluate(surface);
}

// Where a probe moving in `direction` along its axis meets the part, from
// where the plan starts (the feature's centre, or a surface's start), with
// the part `offset_mm` farther than nominal along the direction of travel.
double wall_at(const Scenario& scenario, int direction, double offset_mm = 0.0) {
    const Cycle& c = scenario.cycle;
    if (c.feature == Feature::surface) return direction * (c.approach_mm + offset_mm);
    const double half = 0.5 * c.feature_size_mm;
    return (lifts_over(c.feature) ? -direction * half : direction * half) + direction * offset_mm;
}

// A plan run on a machine whose part stands where `wall(axis, direction)`
// says a probe moving that way meets it, and where every probe stops where
// the model's single touch at its feed, from its real distance, stops. Every
// search must reach past that stop: a search that ends sooner would be
// braking when it touches (it would trigger below the feed and stop at its
// end). Where the plan leaves the probe (X, Y, Z from where it started), and
// how far from its wall each probe started.
struct PlanRun {
    std::array<double, 3> end{};
    std::vector<double> start_mm;
};
template <typename Wall>
PlanRun run_plan(const ProbingPlan& plan, const Scenario& scenario, Wall wall) {
    PlanRun run;
    for (const ProgramStep& step : plan.steps) {
        if (step.kind == StepKind::pause) continue;
        const std::size_t i = static_cast<std::size_t>(step.axis - 'X');
        double travel = step.distance_mm;
        if (step.kind == StepKind::probe) {
            const double to_wall = (wall(step.axis, step.direction) - run.end[i]) * step.direction;
            Scenario touch = scenario;
            touch.cycle.strategy = Strategy::single_touch;
            touch.cycle.feature = Feature::surface;
            touch.cycle.repeats = 1.0;
            touch.cycle.probe_feed_mm_min = step.feed_mm_min;
            touch.cycle.approach_mm = std::max(0.0, to_wall);
            const double overtravel = evaluate(touch).overtravel_mm();
            EXPECT_GT(step.distance_mm, to_wall + overtravel)
                << step.text << ": the search ends before the stop";
            run.start_mm.push_back(to_wall);
            travel = to_wall + overtravel;
        }
        run.end[i] += step.direction * travel;
    }
    return run;
}

// The same on the nominal part.
std::array<double, 3> end_of(const ProbingPlan& plan, const Scenario& scenario) {
    return run_plan(plan, scenario,
                    [&](char, int direction) { return wall_at(scenario, direction); })
        .end;
}

TEST(CyclePlan, ABoreTwoTouchGoesOutFromItsCentreAndBackProtected) {
    const Scenario bore = program_test::golden_bore();
    const ProbingPlan plan = make_cycle_plan(bore, CyclePlanOptions{});
    const Cycle& c = bore.cycle;
    // 50 mm less two approach distances of 5: each start 20 mm from the centre.
    EXPECT_DOUBLE_EQ(start_radius_mm(c), 20.0);
    const CycleResult model = model_touch(bore);
    const double s = c.approach_mm;
    const double measuring = model.measuring_touch().overtravel_mm;
    // Halfway from each touch's stop at the highest feed override
    // to the 5 mm overtravel limit.
    const double first_stop = model.first_touch().override_overtravel_mm;
    const double first_beyond = 0.5 * (first_stop + bore.probe.overtravel_limit_mm);
    const double measuring_beyond =
        0.5 * (model.measuring_touch().override_overtravel_mm + bore.probe.overtravel_limit_mm);
    EXPECT_DOUBLE_EQ(search_beyond_mm(bore, first_stop), first_beyond);
    ASSERT_EQ(plan.steps.size(), 1u + 4u * 6u);
    EXPECT_EQ(plan.steps[0].kind, StepKind::pause);
    EXPECT_EQ(plan.steps[0].text,
              "check: the probe ball stands at the centre of the bore at the measuring depth; "
              "resume to start");
    const char* walls[] = {"X+", "X-", "Y+", "Y-"};
    const char* back[] = {"X-", "X+", "Y-", "Y+"};
    for (std::size_t k = 0; k < 4; ++k) {
        SCOPED_TRACE(walls[k]);
        expect_steps(
            plan, 1 + 6 * k,
            {
                {StepKind::guard, walls[k], 20.0, 3000.0, false},
                // The fast touch searches past the wall by more
                // than its stop; the backoff (2 mm) from where it
                // stopped; the measuring touch searches the whole
                // backoff and past its own stop.
                {StepKind::probe, walls[k], up(s + first_beyond), 2000.0, false},
                {StepKind::move, back[k], 2.0, 10000.0, false},
                {StepKind::probe, walls[k], up(c.backoff_mm + measuring_beyond), 30.0, true},
                {StepKind::move, back[k], up(s + measuring), 10000.0, false},
                {StepKind::guard, back[k], 20.0, 3000.0, false},
            });
    }
    EXPECT_EQ(plan.recorded().size(), 4u);
    for (const double axis : end_of(plan, bore)) EXPECT_NEAR(axis, 0.0, 0.005);
    // The plan names the feature and what its moves use.
    std::vector<std::string> keys;
    for (const PlanValue& value : plan.values) keys.push_back(value.key);
    for (const char* key :
         {"cycle.feature", "cycle.feature_size_mm", "cycle.position_feed_mm_min"}) {
        EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << key;
    }
    EXPECT_EQ(std::find(keys.begin(), keys.end(), "cycle.clearance_mm"), keys.end());
}

TEST(CyclePlan, ABossSingleTouchGoesOverEachSideDownAndTouchesTowardTheCentre) {
    const Scenario boss = program_test::golden_boss();
    const ProbingPlan plan = make_cycle_plan(boss, CyclePlanOptions{});
    const Cycle& c = boss.cycle;
    // 50 mm plus two approach distances of 5: each start 30 mm from the centre.
    EXPECT_DOUBLE_EQ(start_radius_mm(c), 30.0);
    const TouchResult touch = model_touch(boss).first_touch();
    const double overtravel = touch.overtravel_mm;
    const double s = c.approach_mm;
    // Past the stop at the highest feed override.
    const double beyond = search_beyond_mm(boss, touch.override_overtravel_mm);
    // cycle.repeats 2: each side touched twice, back to the start in between.
    ASSERT_EQ(plan.steps.size(), 1u + 4u * 8u);
    EXPECT_EQ(plan.steps[0].text,
              "check: the probe ball stands over the centre of the boss, 10 mm above the "
              "measuring depth; resume to start");
    const char* sides[] = {"X+", "X-", "Y+", "Y-"};
    const char* inward[] = {"X-", "X+", "Y-", "Y+"};
    for (std::size_t k = 0; k < 4; ++k) {
        SCOPED_TRACE(sides[k]);
        expect_steps(plan, 1 + 8 * k,
                     {
                         {StepKind::guard, sides[k], 30.0, 3000.0, false},
                         {StepKind::guard, "Z-", 10.0, 3000.0, false},
                         // The X+ side is touched moving X-.
                         {StepKind::probe, inward[k], up(s + beyond), 300.0, true},
                         {StepKind::move, sides[k], up(s + overtravel), 10000.0, false},
                         // The repeat searches the whole return from its stop.
                         {StepKind::probe, inward[k], up(up(s + overtravel) + beyond), 300.0, true},
                         {StepKind::move, sides[k], up(s + overtravel), 10000.0, false},
                         // Up at the rapid (away from the part, as the model lifts).
                         {StepKind::move, "Z+", 10.0, 0.0, false},
                         {StepKind::guard, inward[k], 30.0, 3000.0, false},
                     });
    }
    EXPECT_EQ(plan.recorded().size(), 8u);
    EXPECT_EQ(plan.steps[3].text, "X- 1 of 2 at 300 mm/min");
    EXPECT_EQ(plan.steps[5].text, "X- 2 of 2 at 300 mm/min");
    for (const double axis : end_of(plan, boss)) EXPECT_NEAR(axis, 0.0, 0.005);
    // The clearance among the feature's values, then what the result needs.
    ASSERT_GE(plan.values.size(), 3u);
    ASSERT_GE(plan.values.size(), 6u);
    EXPECT_EQ(plan.values[plan.values.size() - 6].key, "cycle.clearance_mm");
    EXPECT_EQ(plan.values[plan.values.size() - 5].key, "ball_diameter_mm");
    EXPECT_EQ(plan.values[plan.values.size() - 4].key, "point_uncertainty_mm");
    EXPECT_EQ(plan.values[plan.values.size() - 3].key, "independent_uncertainty_mm");
    EXPECT_EQ(plan.values[plan.values.size() - 2].key, "probe.artefact_uncertainty_mm");
    EXPECT_EQ(plan.values.back().key, "machine.thermal_drift_mm");
}

// cycle.repeats on a two-touch surface: the measuring touch again, backed off
// from where it stopped, as the model repeats it (cycle.cpp); the plan says
// the repeats among its values, and a plan of one touch does not.
TEST(CyclePlan, RepeatsMakeTheMeasuringTouchAgainFromItsStop) {
    Scenario scenario = program_test::known_part();
    scenario.cycle.repeats = 3.0;
    const ProbingPlan plan = make_cycle_plan(scenario, CyclePlanOptions{});
    const Cycle& c = scenario.cycle;
    const CycleResult model = model_touch(scenario);
    const double s = c.approach_mm;
    const double measuring = model.measuring_touch().overtravel_mm;
    // Past each stop at the highest feed override.
    const double first_beyond =
        search_beyond_mm(scenario, model.first_touch().override_overtravel_mm);
    const double measuring_beyond =
        search_beyond_mm(scenario, model.measuring_touch().override_overtravel_mm);
    ASSERT_EQ(plan.steps.size(), 1u + 3u + 2u * 2u + 1u);
    expect_steps(plan, 1,
                 {
                     {StepKind::probe, "Z-", up(s + first_beyond), 2000.0, false},
                     {StepKind::move, "Z+", 2.0, 10000.0, false},
                     {StepKind::probe, "Z-", up(c.backoff_mm + measuring_beyond), 30.0, true},
                     // From the measuring touch's stop: the backoff, then the
                     // measuring touch over the whole backoff again.
                     {StepKind::move, "Z+", 2.0, 10000.0, false},
                     {StepKind::probe, "Z-", up(c.backoff_mm + measuring_beyond), 30.0, true},
                     {StepKind::move, "Z+", 2.0, 10000.0, false},
                     {StepKind::probe, "Z-", up(c.backoff_mm + measuring_beyond), 30.0, true},
                     {StepKind::move, "Z+", up(s + measuring), 10000.0, false},
                 });
    EXPECT_EQ(plan.recorded().size(), 3u);
    EXPECT_EQ(plan.steps[3].text, "Z- measuring touch 1 of 3 at 30 mm/min");
    EXPECT_EQ(plan.steps[7].text, "Z- measuring touch 3 of 3 at 30 mm/min");
    for (const double axis : end_of(plan, scenario)) EXPECT_NEAR(axis, 0.0, 0.005);
    const auto has_repeats = [](const ProbingPlan& p) {
        return std::any_of(p.values.begin(), p.values.end(),
                           [](const PlanValue& v) { return v.key == "cycle.repeats"; });
    };
    EXPECT_TRUE(has_repeats(plan));
    EXPECT_FALSE(has_repeats(make_cycle_plan(Scenario{}, CyclePlanOptions{})));
}

// The kind and direction of every step after the pause ("G" a protected move,
// "P" a probe, "M" a move, "R" a rapid), e.g. "GX+ PX+ MX- ...".
std::string outline(const ProbingPlan& plan) {
    std::string text;
    for (std::size_t i = 1; i < plan.steps.size(); ++i) {
        const ProgramStep& step = plan.steps[i];
        const char kind = step.kind == StepKind::guard   ? 'G'
                          : step.kind == StepKind::probe ? 'P'
                          : step.feed_mm_min > 0.0       ? 'M'
                                                         : 'R';
        if (!text.empty()) text += ' ';
        text += kind;
        text += to_string(AxisDirection{step.axis, step.direction});
    }
    return text;
}

TEST(CyclePlan, APocketAndAWebAlongXAndAlongY) {
    const struct {
        Feature feature;
        AxisDirection axis;
        const char* outline;
    } cases[] = {
        // Both walls from the centre, + first (the sign of the axis is not used).
        {Feature::pocket, {'X', 1}, "GX+ PX+ MX- PX+ MX- GX- GX- PX- MX+ PX- MX+ GX+"},
        {Feature::pocket, {'Y', -1}, "GY+ PY+ MY- PY+ MY- GY- GY- PY- MY+ PY- MY+ GY+"},
        // Both sides from above the centre, each touched toward it.
        {Feature::web,
         {'X', -1},
         "GX+ GZ- PX- MX+ PX- MX+ RZ+ GX- GX- GZ- PX+ MX- PX+ MX- RZ+ GX+"},
        {Feature::web, {'Y', 1}, "GY+ GZ- PY- MY+ PY- MY+ RZ+ GY- GY- GZ- PY+ MY- PY+ MY- RZ+ GY+"},
    };
    for (const auto& c : cases) {
        Scenario scenario;
        scenario.cycle.feature = c.feature;
        scenario.cycle.feature_size_mm = 30.0;
        SCOPED_TRACE(std::string(to_string(c.feature)) + " along " + to_string(c.axis));
        const ProbingPlan plan = make_cycle_plan(scenario, CyclePlanOptions{c.axis});
        EXPECT_EQ(outline(plan), c.outline);
        // 15 mm less (a pocket) or plus (a web) the approach of 5 mm.
        const double radius = c.feature == Feature::pocket ? 10.0 : 20.0;
        EXPECT_DOUBLE_EQ(plan.steps[1].distance_mm, radius);
        EXPECT_EQ(plan.recorded().size(), 2u);
        EXPECT_NE(plan.steps[0].text.find(std::string("the ") + to_string(c.feature) + " along " +
                                          c.axis.axis),
                  std::string::npos)
            << plan.steps[0].text;
        for (const double axis : end_of(plan, scenario)) EXPECT_NEAR(axis, 0.0, 0.005);
        // The plan file holds it, protected moves and all.
        EXPECT_EQ(probing_plan_json(parse_probing_plan(probing_plan_json(plan))),
                  probing_plan_json(plan));
    }
}

TEST(CyclePlan, WhatAFeaturesProgramCannotDoIsRefusedNamingTheKey) {
    const auto refusal = [](const Scenario& scenario, const CyclePlanOptions& options) {
        try {
            make_cycle_plan(scenario, options);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    Scenario pocket;
    pocket.cycle.feature = Feature::pocket;
    EXPECT_EQ(refusal(pocket, CyclePlanOptions{}),
              "axis: got Z-; allowed: X+, X-, Y+ or Y- for a pocket (touched from both sides along "
              "X or Y)");
    // A bore or boss is touched at X+, X-, Y+, Y- whatever the axis.
    Scenario bore;
    bore.cycle.feature = Feature::bore;
    EXPECT_EQ(refusal(bore, CyclePlanOptions{}), "no error");
    Scenario web;
    web.cycle.feature = Feature::web;
    web.cycle.clearance_mm = 0.0;
    EXPECT_EQ(refusal(web, CyclePlanOptions{{'X', 1}}),
              "cycle.clearance_mm: got 0; allowed: at least 0.001 mm for a web (the probe moves "
              "over its wall between touches)");
    // An obstruction met at 8000 mm/min stops 5.072 mm past it: over the limit.
    Scenario fast = bore;
    fast.cycle.feed_override_max_pct = 100.0;
    fast.cycle.position_feed_mm_min = 8000.0;
    EXPECT_EQ(refusal(fast, CyclePlanOptions{}),
              "cycle.position_feed_mm_min: got 8000; allowed: a feed at which an obstruction met "
              "by a protected move stops short of the probe's 5.000 mm limit (now 5.072 mm past "
              "it)");
    // At the default 120 % feed override, 7000 mm/min is 8400 mm/min.
    fast.cycle.feed_override_max_pct = 120.0;
    fast.cycle.position_feed_mm_min = 7000.0;
    EXPECT_EQ(refusal(fast, CyclePlanOptions{}),
              "cycle.position_feed_mm_min: got 7000; allowed: a feed at which an obstruction met "
              "by a protected move stops short of the probe's 5.000 mm limit (now 5.325 mm past "
              "it)");
    Scenario boss;
    boss.cycle.feature = Feature::boss;
    boss.cycle.feature_size_mm = 2000.0;
    EXPECT_EQ(refusal(boss, CyclePlanOptions{}),
              "cycle.feature_size_mm: got 2000; allowed: at most 1990 mm for a boss's program (its "
              "moves from the centre to the touches' starts are at most 1000 mm)");
}

TEST(ProbingPlan, EveryDelayTouchStartsFarEnoughOutToBeAtFullSpeed) {
    const Scenario scenario;
    DelayPlanOptions options;
    const ProbingPlan plan = make_delay_plan(scenario, options);
    EXPECT_EQ(plan.recorded().size(), 25u);  // 30 ... 2000 mm/min (2000 is the scenario's), 5 each
    EXPECT_EQ(plan.steps.front().kind, StepKind::pause);
    // The surface anywhere within the placement: at it, and half as far.
    for (const double placement : {options.placement_mm, 0.5 * options.placement_mm}) {
        SCOPED_TRACE(placement);
        const PlanRun run =
            run_plan(plan, scenario, [&](char, int direction) { return direction * placement; });
        std::size_t probe = 0;
        for (const ProgramStep& step : plan.steps) {
            if (step.kind != StepKind::probe) continue;
            const double start = run.start_mm[probe++];
            if (!step.recorded) continue;
            SCOPED_TRACE(step.text);
            EXPECT_GE(start, approach_room_mm(scenario, step.feed_mm_min / 60.0) +
                                 options.margin_mm - 1e-9);
            EXPECT_EQ(step.axis, 'Z');
            EXPECT_EQ(step.direction, -1);
        }
    }
}

// The defect a real controller found: a search that ended 1 mm past the
// nominal surface, less than the axis needs to brake, so LinuxCNC touched
// while already braking, stopped at the search end, and the next search,
// computed from the predicted stop, ended short of the surface. Every search
// of every plan must reach past its touch's stop, wherever the part lies
// within its uncertainty: on slow and fast machines, at slow feeds and where
// braking takes several mm, every feature and strategy, with repeats, and
// the delay and ring programs.
TEST(ProbingPlan, EverySearchReachesPastItsStopWhereverThePartLies) {
    struct Machine {
        const char* name;
        Scenario scenario;
    };
    std::vector<Machine> machines;
    machines.push_back({"time constant 60 ms", Scenario{}});
    for (const double accel : {400.0, 800.0}) {
        // A LinuxCNC machine in exact stop: its servo period scans the probe
        // and two more periods pass before it brakes.
        Scenario linuxcnc;
        linuxcnc.machine.accel_model = AccelModel::constant_accel;
        linuxcnc.machine.max_accel_mm_s2 = accel;
        linuxcnc.machine.scan_period_s = 0.001;
        linuxcnc.machine.controller_latency_s = 0.002;
        linuxcnc.probe.interface_delay_s = 0.0;
        machines.push_back(
            {accel == 400.0 ? "LinuxCNC 400 mm/s^2" : "LinuxCNC 800 mm/s^2", linuxcnc});
    }
    Scenario fanuc;  // acc/dec after interpolation and a servo lag
    fanuc.machine.accel_model = AccelModel::none;
    fanuc.machine.filter = FilterKind::exponential;
    fanuc.machine.filter_time_s = 0.032;
    fanuc.machine.servo_time_constant_s = 0.033;
    fanuc.machine.controller_latency_s = 0.018;
    machines.push_back({"Fanuc-type", fanuc});
    int plans = 0;
    for (Machine& machine : machines) {
        machine.scenario.probe.overtravel_limit_mm = 12.0;
        for (const double feed : {300.0, 2400.0, 4000.0}) {
            for (const Strategy strategy : {Strategy::single_touch, Strategy::two_touch}) {
                for (const Feature feature : {Feature::surface, Feature::bore, Feature::boss,
                                              Feature::pocket, Feature::web}) {
                    Scenario s = machine.scenario;
                    s.cycle.strategy = strategy;
                    s.cycle.feature = feature;
                    s.cycle.probe_feed_mm_min = feed;
                    s.cycle.measure_feed_mm_min = 100.0;
                    s.cycle.part_position_uncertainty_mm = 0.5;
                    s.cycle.approach_mm = 0.5 + approach_room_mm(s, feed / 60.0) + 0.5;
                    s.cycle.feature_size_mm = 2.0 * s.cycle.approach_mm + 40.0;
                    s.cycle.repeats = feature == Feature::bore ? 2.0 : 1.0;
                    s.cycle.backoff_mm = evaluate(s).recommended_backoff_mm() + 0.3;
                    SCOPED_TRACE(std::string(machine.name) + ", " + to_string(feature) + ", " +
                                 to_string(strategy) + " at " + format_number(feed));
                    const ProbingPlan plan = make_cycle_plan(s, CyclePlanOptions{{'X', 1}});
                    ++plans;
                    // The part nearer, at nominal and farther, by up to its
                    // uncertainty. (Back where it started on the nominal part;
                    // elsewhere each return is measured from the real wall.)
                    for (const double offset : {-0.5, 0.0, 0.5}) {
                        SCOPED_TRACE(offset);
                        const PlanRun run = run_plan(plan, s, [&](char, int direction) {
                            return wall_at(s, direction, offset);
                        });
                        if (offset != 0.0) continue;
                        for (const double axis : run.end) EXPECT_NEAR(axis, 0.0, 0.005);
                    }
                    if (HasFailure()) return;
                }
            }
            Scenario s = machine.scenario;
            s.cycle.probe_feed_mm_min = feed;
            DelayPlanOptions delay;
            delay.touch = {'Y', 1};
            delay.repeats = 2;
            const ProbingPlan delay_plan = make_delay_plan(s, delay);
            ++plans;
            for (const double wall : {delay.placement_mm, 0.3 * delay.placement_mm}) {
                run_plan(delay_plan, s, [&](char, int direction) { return direction * wall; });
            }
            RingPlanOptions ring;
            const double to_wall = 0.5 * (ring.gauge_diameter_mm - ring.ball_diameter_mm);
            Scenario from_centre = s;
            from_centre.cycle.approach_mm = to_wall;
            s.cycle.backoff_mm = evaluate(from_centre).recommended_backoff_mm() + 0.3;
            const ProbingPlan ring_plan = make_ring_plan(s, ring);
            ++plans;
            // The probe left off the gauge's centre, within the tolerance.
            for (const double off : {-ring.centre_tolerance_mm, ring.centre_tolerance_mm}) {
                const PlanRun run = run_plan(ring_plan, s, [&](char axis, int direction) {
                    return direction * to_wall - (axis == 'X' ? off : 0.0);
                });
                EXPECT_NEAR(run.end[0], -off, 0.005);  // on the gauge's centre
            }
            if (HasFailure()) return;
        }
    }
    EXPECT_EQ(plans, 4 * 3 * (2 * 5 + 2));
}

// cycle.search_beyond_mm set by hand is the searches' length past the
// farthest surface; one that does not reach a touch's stop is refused naming
// the key, as the model's error (search_ends_too_soon) says.
TEST(CyclePlan, ASearchSetByHandIsUsedOrRefusedWhenItEndsTooSoon) {
    Scenario scenario;  // two-touch at 2000 mm/min: the first touch stops 1.272 mm past
    scenario.cycle.feed_override_max_pct = 100.0;  // (FeedOverride: at the override)
    scenario.cycle.search_beyond_mm = 1.5;
    scenario.cycle.part_position_uncertainty_mm = 0.25;
    scenario.cycle.approach_mm = 6.0;
    const ProbingPlan plan = make_cycle_plan(scenario, CyclePlanOptions{});
    expect_steps(plan, 1,
                 {
                     {StepKind::probe, "Z-", 6.0 + 0.25 + 1.5, 2000.0, false},
                     {StepKind::move, "Z+", 2.0, 10000.0, false},
                     {StepKind::probe, "Z-", 2.0 + 1.5, 30.0, true},
                 });
    scenario.cycle.search_beyond_mm = 1.0;
    try {
        make_cycle_plan(scenario, CyclePlanOptions{});
        ADD_FAILURE() << "a search that ends before the stop was written";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "cycle.search_beyond_mm: got 1; allowed: at least 1.272 mm, the stop of the "
                  "touch at 2000 mm/min past its surface (a search that ends sooner is braking "
                  "when it touches), or 0 for automatic");
    }
    EXPECT_THROW(make_delay_plan(scenario, DelayPlanOptions{}), InputError);
    EXPECT_THROW(make_ring_plan(scenario, RingPlanOptions{}), InputError);
}

TEST(ProbingPlan, OptionsThatCannotWorkAreRefused) {
    const Scenario scenario;
    DelayPlanOptions one_feed;
    one_feed.feeds_mm_min = {100.0, 100.0};
    EXPECT_THROW(make_delay_plan(scenario, one_feed), InputError);
    RingPlanOptions tiny;
    tiny.gauge_diameter_mm = 6.5;
    EXPECT_THROW(make_ring_plan(scenario, tiny), InputError);
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
