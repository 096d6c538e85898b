// probecycle-cli optimise, run as a user runs it: the JSON's keys, --apply's
// file evaluates to the best setting's figures, and bad input is named with
// what is allowed. The golden output is in golden_test.cpp.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_run.h"

namespace probecycle::cli_test {
namespace {

using nlohmann::json;

const char* const kBore =
    "'" PROBECYCLE_TEST_DATA_DIR "/../../resources/examples/bore_two_touch.json'";

TEST(OptimiseCli, PrintsBestCurrentSavedBindingAndPareto) {
    const CliRun r = run(std::string("optimise ") + kBore + " --pareto-points 4");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json out = json::parse(r.out);
    for (const char* key :
         {"strategy", "probe_feed_mm_min", "measure_feed_mm_min", "backoff_mm", "approach_mm",
          "repeats", "cycle_time_s", "uncertainty_mm", "checked_overtravel_mm"}) {
        EXPECT_TRUE(out["best"].contains(key)) << key;
        EXPECT_TRUE(out["current"].contains(key)) << key;
    }
    EXPECT_DOUBLE_EQ(out["saved_s"].get<double>(), out["current"]["cycle_time_s"].get<double>() -
                                                       out["best"]["cycle_time_s"].get<double>());
    EXPECT_LE(out["best"]["uncertainty_mm"].get<double>(), 0.005);  // the example's target
    // The target holds for the whole budget (3.4 um of it fixed
    // by default), so the measuring feed spends what is left of 5 um and the
    // target binds.
    EXPECT_EQ(out["binding"], json::array({"target_uncertainty"}));
    EXPECT_GE(out["best"]["approach_mm"].get<double>(), 1.0);  // cycle.min_start_mm
    EXPECT_TRUE(out["savings"].is_null());                     // parts_per_year 0: not shown
    ASSERT_TRUE(out["pareto"].is_array());
    EXPECT_GE(out["pareto"].size(), 2u);
    EXPECT_LE(out["pareto"].size(), 4u);
}

TEST(OptimiseCli, SavingsAYearWithPartsAndRate) {
    const CliRun r = run(std::string("optimise ") + kBore +
                         " --set cycle.parts_per_year=20000 --set cycle.cycles_per_part=2"
                         " --set cycle.machine_rate_per_hour=75 --pareto-points 1");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json out = json::parse(r.out);
    const double saved = out["saved_s"].get<double>();
    EXPECT_DOUBLE_EQ(out["savings"]["saved_per_part_s"].get<double>(), 2.0 * saved);
    EXPECT_DOUBLE_EQ(out["savings"]["hours_per_year"].get<double>(), 2.0 * saved * 20000 / 3600);
    EXPECT_DOUBLE_EQ(out["savings"]["cost_per_year"].get<double>(),
                     2.0 * saved * 20000 / 3600 * 75);
}

TEST(OptimiseCli, ApplyWritesAScenarioThatEvaluatesToTheBest) {
    const TempDir dir;
    const std::string file = quote((dir / "best.json").string());
    const CliRun r = run(std::string("optimise ") + kBore + " --pareto-points 1 --apply " + file);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json best = json::parse(r.out)["best"];
    const CliRun evaluated = run("evaluate " + file);
    ASSERT_EQ(evaluated.exit_code, 0) << evaluated.err;
    const json e = json::parse(evaluated.out);
    EXPECT_TRUE(e["valid"].get<bool>());
    EXPECT_EQ(e["cycle_time_s"], best["cycle_time_s"]);
    EXPECT_EQ(e["uncertainty_mm"], best["uncertainty_mm"]);
    EXPECT_EQ(e["checked_overtravel_mm"], best["checked_overtravel_mm"]);
    const json applied = json::parse(read(dir / "best.json"));
    EXPECT_EQ(applied["cycle"]["probe_feed_mm_min"], best["probe_feed_mm_min"]);
    EXPECT_EQ(applied["cycle"]["measure_feed_mm_min"], best["measure_feed_mm_min"]);
    EXPECT_EQ(applied["cycle"]["backoff_mm"], best["backoff_mm"]);
    EXPECT_EQ(applied["cycle"]["approach_mm"], best["approach_mm"]);
    EXPECT_EQ(applied["cycle"]["strategy"], best["strategy"]);
    // The rest of the scenario is the example's.
    EXPECT_EQ(applied["cycle"]["feature"], "bore");
    EXPECT_EQ(applied["cycle"]["target_uncertainty_mm"].get<double>(), 0.005);
    // Optimising the applied file again finds nothing more to save.
    const CliRun again = run("optimise " + file + " --pareto-points 1");
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_NEAR(json::parse(again.out)["saved_s"].get<double>(), 0.0, 1e-9);
}

struct Refusal {
    const char* arguments;
    const char* says;
};

class OptimiseCliRefuses : public testing::TestWithParam<Refusal> {};

TEST_P(OptimiseCliRefuses, NamingTheOptionOrRequirementAndWhatIsAllowed) {
    const Refusal& c = GetParam();
    const CliRun r = run(std::string("optimise ") + c.arguments);
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(Optimise, OptimiseCliRefuses, testing::Values(
    Refusal{"--max-overtravel-fraction 1.5",                "--max-overtravel-fraction: got '1.5'; allowed: a number from 0.01 to 1"},
    Refusal{"--max-overtravel-fraction 0",                  "--max-overtravel-fraction: got '0'; allowed: a number from 0.01 to 1"},
    Refusal{"--pareto-points 0",                            "--pareto-points: got '0'; allowed: a whole number from 1 to 200"},
    Refusal{"--pareto-points 2.5",                          "--pareto-points: got '2.5'"},
    Refusal{"--bogus",                                      "--bogus"},
    Refusal{"--set cycle.target_uncertainty_mm=0.0002",     "probecycle-cli optimise: no setting meets the target uncertainty 0.0002 mm (cycle.target_uncertainty_mm): the smallest achievable is"},
    Refusal{"--set probe.overtravel_limit_mm=0.1 --max-overtravel-fraction 0.01", "the overtravel must stay at or under 1 % of the probe's limit 0.1 mm"}));
// clang-format on

}  // namespace
}  // namespace probecycle::cli_test
