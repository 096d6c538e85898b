// probecycle-cli run as a subprocess, as a user runs it (docs/cli.md).

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/common/file_io.h"
#include "core/cycle/cycle_report.h"
#include "core/cycle/scenario.h"
#include "core/cycle/sweep.h"
#include "tests/cli/cli_run.h"

namespace probecycle {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kData = PROBECYCLE_TEST_DATA_DIR;

std::string data_file(const std::string& name) {
    return kData + "/" + name;
}

using cli_test::CliRun;

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) out.push_back(line);
    return out;
}

// The fields of one CSV row, an empty last field included ("a,true," has three).
std::vector<std::string> fields_of(const std::string& row) {
    std::vector<std::string> out(1);
    for (char ch : row) {
        if (ch == ',') {
            out.emplace_back();
        } else {
            out.back() += ch;
        }
    }
    return out;
}

class CycleCli : public testing::Test {
  protected:
    void SetUp() override {
        // Parameterised names hold a '/' ("Case/3"): flatten it, or TearDown
        // would remove only the inner directory and leave the outer one behind.
        std::string name = testing::UnitTest::GetInstance()->current_test_info()->name();
        std::replace(name.begin(), name.end(), '/', '_');
        dir_ = fs::temp_directory_path() /
               ("probecycle_cli_test_" + std::to_string(std::random_device{}()) + "_" + name);
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // Runs the CLI with stdin from /dev/null and stdout, stderr captured apart.
    static CliRun run(const std::vector<std::string>& args) { return cli_test::run(args); }

    // A successful run whose stdout is one JSON document.
    json run_json(const std::vector<std::string>& args) {
        const CliRun r = run(args);
        EXPECT_TRUE(r.exited) << r;
        EXPECT_EQ(r.exit_code, 0) << r;
        try {
            return json::parse(r.out);
        } catch (const json::exception& e) {
            ADD_FAILURE() << "stdout is not JSON: " << e.what() << "\n" << r;
            return json();
        }
    }

    fs::path dir_;
};

// ---------------------------------------------------------------------------
// defaults

TEST_F(CycleCli, DefaultsPrintsTheDefaultScenario) {
    const CliRun r = run({"defaults"});
    ASSERT_EQ(r.exit_code, 0) << r;
    EXPECT_TRUE(r.err.empty()) << r;
    const Scenario parsed = scenario_from_json(r.out);
    EXPECT_EQ(scenario_to_json(parsed), scenario_to_json(Scenario{}));
}

TEST_F(CycleCli, DefaultsAreAcceptedByEvaluate) {
    const CliRun defaults = run({"defaults"});
    ASSERT_EQ(defaults.exit_code, 0) << defaults;
    const fs::path file = dir_ / "defaults.json";
    std::ofstream(file, std::ios::binary) << defaults.out;
    const json from_file = run_json({"evaluate", file.string()});
    const json built_in = run_json({"evaluate"});
    EXPECT_EQ(from_file, built_in);
}

// A Chinese or Russian user's folders, in a path given on the command line
// (on Windows the CLI takes its words from the wide command line, not the
// code page's argv) and in the messages naming them.
TEST_F(CycleCli, PathsInChineseAndRussianAreReadWrittenAndNamed) {
    const std::string folder =
        utf8_from_path(dir_) +
        "/\u6d4b\u91cf \u0418\u0437\u043c\u0435\u0440\u0435\u043d\u0438\u044f";
    ASSERT_TRUE(fs::create_directory(path_from_utf8(folder)));
    const std::string scenario =
        folder + "/\u5b54_\u043e\u0442\u0432\u0435\u0440\u0441\u0442\u0438\u0435.json";
    write_file_atomically(scenario, run({"defaults"}).out);
    const std::string report = folder + "/\u62a5\u544a.csv";
    const CliRun r = run({"report", scenario, "--csv", report});
    ASSERT_EQ(r.exit_code, 0) << r;
    EXPECT_EQ(read_text_file(report).rfind("# ProbeCycle", 0), 0u) << read_text_file(report);
    const CliRun missing = run({"evaluate", folder + "/\u65e0.json"});
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find(folder + "/\u65e0.json"), std::string::npos) << missing;
}

// ---------------------------------------------------------------------------
// evaluate

void expect_evaluation_shape(const json& j) {
    ASSERT_TRUE(j.is_object()) << j;
    for (const char* key : {"cycle_time_s", "overtravel_mm", "trigger_speed_mm_min",
                            "uncertainty_mm", "recommended_backoff_mm"}) {
        ASSERT_TRUE(j.contains(key)) << key;
        EXPECT_TRUE(j[key].is_number()) << key;
    }
    ASSERT_TRUE(j.contains("phases"));
    ASSERT_TRUE(j["phases"].is_array());
    ASSERT_FALSE(j["phases"].empty());
    double start = 0.0;
    for (const json& p : j["phases"]) {
        ASSERT_TRUE(p["name"].is_string()) << p;
        ASSERT_TRUE(p["start_s"].is_number()) << p;
        ASSERT_TRUE(p["time_s"].is_number()) << p;
        ASSERT_TRUE(p["distance_mm"].is_number()) << p;
        // Contiguous: each starts where the previous ended.
        EXPECT_NEAR(p["start_s"].get<double>(), start, 1e-9) << p;
        start = p["start_s"].get<double>() + p["time_s"].get<double>();
    }
    EXPECT_NEAR(start, j["cycle_time_s"].get<double>(), 1e-9);
    ASSERT_TRUE(j.contains("warnings"));
    ASSERT_TRUE(j["warnings"].is_array());
    for (const json& w : j["warnings"]) {
        ASSERT_TRUE(w["code"].is_string()) << w;
        ASSERT_TRUE(w["severity"].is_string()) << w;
        ASSERT_TRUE(w["message"].is_string()) << w;
        EXPECT_FALSE(w["message"].get<std::string>().empty());
        const std::string severity = w["severity"];
        EXPECT_TRUE(severity == "info" || severity == "warning" || severity == "error") << w;
    }
}

std::vector<std::string> phase_names(const json& j) {
    std::vector<std::string> names;
    for (const json& p : j["phases"]) names.push_back(p["name"]);
    return names;
}

bool has_warning(const json& j, const std::string& code) {
    for (const json& w : j["warnings"]) {
        if (w["code"] == code) return true;
    }
    return false;
}

TEST_F(CycleCli, EvaluatePrintsTheDocumentedKeys) {
    const json j = run_json({"evaluate"});
    expect_evaluation_shape(j);
    // The defaults are two-touch on a surface.
    EXPECT_EQ(phase_names(j),
              (std::vector<std::string>{
                  "approach", "pretravel", "interface_delay", "controller_delay", "deceleration",
                  "backoff", "second_approach", "second_pretravel", "second_interface_delay",
                  "second_controller_delay", "second_deceleration", "return"}));
}

TEST_F(CycleCli, EvaluateSingleTouchFileMatchesTheHandComputation) {
    // 3000 mm/min, T = 0.06 s: approach 0.13 s, pretravel 0.0001 s, delays 0.002 + 0.004 s
    // (the latency and the mean scan wait), braking 0.06 s; overtravel (worst, a full scan)
    // 0.005 + 50 * 0.008 + 1.5 = 1.905 mm, on average 1.805 mm; return 6.805 mm at
    // 10000 mm/min, a triangle: 2 sqrt(6.805 * 0.06 / 166.67).
    const json j = run_json({"evaluate", data_file("scenario_single_touch_3000.json")});
    expect_evaluation_shape(j);
    const double ret = 2.0 * std::sqrt(6.805 * 0.06 / (10000.0 / 60.0));
    const double total = 0.13 + 0.0001 + 0.002 + 0.004 + 0.06 + ret;
    EXPECT_NEAR(j["cycle_time_s"].get<double>(), total, 1e-6 * total);
    EXPECT_NEAR(j["overtravel_mm"].get<double>(), 1.905, 1e-6);
    EXPECT_NEAR(j["trigger_speed_mm_min"].get<double>(), 3000.0, 1e-6);
    EXPECT_NEAR(j["trigger_uncertainty_mm"].get<double>(),
                2.0 * std::sqrt(0.2 * 0.2 / 12.0 + 0.001 * 0.001 / 4.0), 1e-7);
    // With the budget's fixed terms at their defaults (lobing +-1 um,
    // artefact 1 um k = 2, machine 2 um 2 sigma, thermal +-2 um).
    const double fixed_u2 = 1e-6 * (1.0 / 3.0 + 0.25 + 1.0 + 4.0 / 3.0);
    EXPECT_NEAR(j["uncertainty_mm"].get<double>(),
                2.0 * std::sqrt(0.2 * 0.2 / 12.0 + 0.001 * 0.001 / 4.0 + fixed_u2), 1e-7);
    const json& budget = j["uncertainty_budget"];
    ASSERT_EQ(budget["lines"].size(), 6u);
    EXPECT_EQ(budget["lines"][5]["key"], "machine.thermal_drift_mm");
    EXPECT_NEAR(budget["lines"][5]["standard_mm"].get<double>(), 0.002 / std::sqrt(3.0), 1e-12);
    EXPECT_NEAR(budget["expanded_mm"].get<double>(), j["uncertainty_mm"].get<double>(), 1e-15);
    // The same touch at the default 120 % feed override, 3600 mm/min,
    // stops 0.005 + 60 x 0.038 = 2.285 mm past: the checks and the
    // recommended backoff take that (2.285 + 0.2 reseat).
    EXPECT_NEAR(j["checked_overtravel_mm"].get<double>(), 2.285, 1e-6);
    EXPECT_NEAR(j["recommended_backoff_mm"].get<double>(), 2.485, 1e-6);
    EXPECT_EQ(phase_names(j),
              (std::vector<std::string>{"approach", "pretravel", "interface_delay",
                                        "controller_delay", "deceleration", "return"}));
    const double times[] = {0.13, 0.0001, 0.002, 0.004, 0.06, ret};
    const double distances[] = {5.0, 0.005, 0.1, 0.2, 1.5, 6.805};
    for (std::size_t k = 0; k < 6; ++k) {
        EXPECT_NEAR(j["phases"][k]["time_s"].get<double>(), times[k], 1e-6 * times[k]) << k;
        EXPECT_NEAR(j["phases"][k]["distance_mm"].get<double>(), distances[k], 1e-6 * distances[k])
            << k;
    }
}

TEST_F(CycleCli, EvaluateMatchesTheCore) {
    Scenario s = scenario_from_json(slurp(data_file("scenario_single_touch_3000.json")));
    s.cycle.strategy = Strategy::two_touch;
    s.cycle.feature = Feature::bore;
    const json j = run_json({"evaluate", data_file("scenario_single_touch_3000.json"), "--set",
                             "cycle.strategy=two_touch", "--set", "cycle.feature=bore"});
    expect_evaluation_shape(j);
    const Analysis a = analyse(s);
    EXPECT_NEAR(j["cycle_time_s"].get<double>(), a.cycle.total(), 1e-9 * a.cycle.total());
    EXPECT_EQ(j["phases"].size(), a.cycle.phases().size());
    EXPECT_EQ(j["warnings"].size(), a.cycle.warnings().size());
}

TEST_F(CycleCli, SetOverridesTheFileInOrder) {
    const std::string file = data_file("scenario_single_touch_3000.json");
    const json j480 = run_json({"evaluate", file, "--set", "cycle.probe_feed_mm_min=480"});
    EXPECT_NEAR(j480["trigger_speed_mm_min"].get<double>(), 480.0, 1e-6);
    // 480 mm/min = 8 mm/s, 4 ms scan: a 0.032 mm range.
    EXPECT_NEAR(j480["trigger_uncertainty_mm"].get<double>(),
                2.0 * std::sqrt(0.032 * 0.032 / 12.0 + 0.001 * 0.001 / 4.0), 1e-7);
    const json last = run_json({"evaluate", file, "--set", "cycle.probe_feed_mm_min=480", "--set",
                                "cycle.probe_feed_mm_min=600"});
    EXPECT_NEAR(last["trigger_speed_mm_min"].get<double>(), 600.0, 1e-6);
    const json latched = run_json({"evaluate", file, "--set", "machine.latched_input=true"});
    EXPECT_NEAR(latched["trigger_uncertainty_mm"].get<double>(), 0.001, 1e-9);
    const json two = run_json({"evaluate", file, "--set", "cycle.strategy=two_touch"});
    EXPECT_EQ(phase_names(two).size(), 12u);
    const json over = run_json({"evaluate", file, "--set", "probe.overtravel_limit_mm=1.905"});
    EXPECT_TRUE(has_warning(over, "overtravel_limit")) << over.dump(2);
}

TEST_F(CycleCli, SetWorksWithoutAFile) {
    const json j = run_json({"evaluate", "--set", "cycle.strategy=single_touch", "--set",
                             "cycle.probe_feed_mm_min=3000"});
    EXPECT_NEAR(j["trigger_speed_mm_min"].get<double>(), 3000.0, 1e-6);
    EXPECT_EQ(phase_names(j).size(), 6u);
}

// A cycle the model cannot run is flagged, with the errors that say why.
TEST_F(CycleCli, EvaluateFlagsAnInvalidCycle) {
    EXPECT_EQ(run_json({"evaluate"})["valid"], true);
    const json j = run_json({"evaluate", "--set", "cycle.backoff_mm=0.5"});
    EXPECT_EQ(j["valid"], false) << j.dump(2);
    EXPECT_EQ(j["invalid_reasons"], json::array({"backoff_too_small"})) << j.dump(2);
    EXPECT_TRUE(has_warning(j, "backoff_too_small"));
}

// ---------------------------------------------------------------------------
// move

struct MoveCase {
    const char* name;
    std::vector<std::string> set;
    const char* distance;
    const char* feed;
    double time_s;
    double peak_mm_min;
};

// clang-format off
const MoveCase kMoveCases[] = {
    // name            --set                                       d [mm]   F [mm/min]  t [s]  peak [mm/min]
    {"tc_cruise",      {},                                         "10",    "6000",     0.16,  6000.0},
    {"tc_triangle",    {},                                         "1.5",   "6000",     0.06,  3000.0},
    {"tc_2mm_at_30",   {},                                         "2",     "30",       4.06,  30.0},
    {"ca_trapezoid",   {"machine.accel_model=constant_accel",
                        "machine.max_accel_mm_s2=2000"},           "20",    "6000",     0.25,  6000.0},
    {"ca_triangle",    {"machine.accel_model=constant_accel",
                        "machine.max_accel_mm_s2=2000"},           "1.25",  "6000",     0.05,  3000.0},
    {"jl_short",       {"machine.accel_model=jerk_limited",
                        "machine.max_accel_mm_s2=2000",
                        "machine.max_jerk_mm_s3=40000"},           "1.25",  "6000",     0.10,  1500.0},
    {"jl_long",        {"machine.accel_model=jerk_limited",
                        "machine.max_accel_mm_s2=2000",
                        "machine.max_jerk_mm_s3=40000"},           "100",   "12000",    0.65,  12000.0},
};
// clang-format on

class CycleCliMove : public CycleCli, public testing::WithParamInterface<MoveCase> {};

TEST_P(CycleCliMove, TimeAndPeakSpeed) {
    const MoveCase& c = GetParam();
    std::vector<std::string> args = {"move"};
    for (const std::string& s : c.set) {
        args.push_back("--set");
        args.push_back(s);
    }
    args.insert(args.end(), {"--distance", c.distance, "--feed", c.feed});
    const json j = run_json(args);
    ASSERT_TRUE(j.contains("time_s")) << j;
    ASSERT_TRUE(j.contains("peak_speed_mm_min")) << j;
    EXPECT_NEAR(j["time_s"].get<double>(), c.time_s, 1e-9 * c.time_s);
    EXPECT_NEAR(j["peak_speed_mm_min"].get<double>(), c.peak_mm_min, 1e-9 * c.peak_mm_min);
}

INSTANTIATE_TEST_SUITE_P(HandComputed, CycleCliMove, testing::ValuesIn(kMoveCases),
                         [](const testing::TestParamInfo<MoveCase>& case_info) {
                             return std::string(case_info.param.name);
                         });

TEST_F(CycleCli, MoveUsesTheScenarioFilesModel) {
    const json j = run_json({"move", data_file("scenario_single_touch_3000.json"), "--distance",
                             "10", "--feed", "6000"});
    EXPECT_NEAR(j["time_s"].get<double>(), 0.16, 1e-9);
}

// ---------------------------------------------------------------------------
// sweep

TEST_F(CycleCli, SweepPrintsOnlyTheCsvAndTheSummaryOnStderr) {
    const CliRun r = run({"sweep", "--from", "100", "--to", "1000", "--step", "100"});
    ASSERT_EQ(r.exit_code, 0) << r;
    const std::vector<std::string> lines = lines_of(r.out);
    ASSERT_EQ(lines.size(), 11u) << r;
    const std::vector<std::string> header = fields_of(lines[0]);
    ASSERT_EQ(header.size(), 8u + kPhaseCount) << lines[0];
    EXPECT_EQ(
        lines[0].rfind(
            "feed_mm_min,cycle_time_s,overtravel_mm,checked_overtravel_mm,uncertainty_mm,", 0),
        0u);
    EXPECT_EQ(header[5 + kPhaseCount], "valid");
    EXPECT_EQ(header[6 + kPhaseCount], "invalid_reasons");
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const std::vector<std::string> fields = fields_of(lines[i]);
        ASSERT_EQ(fields.size(), header.size()) << lines[i];
        for (std::size_t k = 0; k < 4 + kPhaseCount; ++k) {
            const std::string& f = fields[k];
            std::size_t used = 0;
            EXPECT_NO_THROW(std::stod(f, &used)) << lines[i];
            EXPECT_EQ(used, f.size()) << lines[i];
        }
        // Up to 1000 mm/min the default cycle is valid.
        EXPECT_EQ(fields[5 + kPhaseCount], "true") << lines[i];
        EXPECT_EQ(fields[6 + kPhaseCount], "") << lines[i];
        EXPECT_NEAR(std::stod(fields[0]), 100.0 * static_cast<double>(i), 1e-9);
    }
    // The same bytes as the golden sweep (100 to 3000 mm/min) up to 1000 mm/min.
    const std::string golden = slurp(data_file("golden/sweep_default.csv"));
    std::size_t end = 0;
    for (int line = 0; line < 11; ++line) end = golden.find('\n', end) + 1;
    EXPECT_EQ(r.out, golden.substr(0, end));
    // One summary line on stderr naming the knee.
    const std::vector<std::string> err_lines = lines_of(r.err);
    ASSERT_EQ(err_lines.size(), 1u) << r;
    EXPECT_NE(err_lines[0].find("knee"), std::string::npos) << r;
}

TEST_F(CycleCli, SweepWithAFileAndSettings) {
    const CliRun r =
        run({"sweep", data_file("scenario_single_touch_3000.json"), "--set",
             "cycle.target_uncertainty_mm=0.05", "--from", "100", "--to", "3000", "--step", "100"});
    ASSERT_EQ(r.exit_code, 0) << r;
    EXPECT_EQ(lines_of(r.out).size(), 31u);
    // Single touch, 4 ms scan, 1 um repeatability: 1200 mm/min is the fastest within 0.05 mm.
    EXPECT_NE(r.err.find("1200"), std::string::npos) << r;
}

// The knee among valid feeds with the scenario's tolerance; a fastest
// cycle at the end of the sweep is said on the summary line.
TEST_F(CycleCli, SweepSummarySaysWhenTheFastestCycleIsAtTheEndOfTheRange) {
    const CliRun at_end =
        run({"sweep", "--set", "cycle.strategy=single_touch", "--set", "cycle.approach_mm=50",
             "--from", "100", "--to", "5000", "--step", "100"});
    ASSERT_EQ(at_end.exit_code, 0) << at_end;
    EXPECT_NE(at_end.err.find("; knee_at_range_end: The fastest cycle lies at the highest feed "
                              "searched, 5000 mm/min"),
              std::string::npos)
        << at_end;
    EXPECT_NE(at_end.err.find("search faster feeds too"), std::string::npos) << at_end;
    EXPECT_EQ(lines_of(at_end.err).size(), 1u) << at_end;

    const CliRun inside = run({"sweep", "--set", "cycle.strategy=single_touch", "--from", "100",
                               "--to", "12000", "--step", "100"});
    ASSERT_EQ(inside.exit_code, 0) << inside;
    EXPECT_EQ(inside.err.find("knee_at_range_end"), std::string::npos) << inside;

    // A looser tolerance, a slower knee; a limit that no feed meets, no knee.
    const CliRun loose =
        run({"sweep", "--set", "cycle.strategy=single_touch", "--set", "cycle.knee_tolerance=0.2",
             "--from", "100", "--to", "12000", "--step", "100"});
    ASSERT_EQ(loose.exit_code, 0) << loose;
    EXPECT_NE(loose.err, inside.err);
    const CliRun none = run({"sweep", "--set", "probe.overtravel_limit_mm=0.01", "--from", "100",
                             "--to", "1000", "--step", "100"});
    ASSERT_EQ(none.exit_code, 0) << none;
    EXPECT_NE(none.err.find("none (no valid feed: each overtravels the probe's limit or backs "
                            "off too little)"),
              std::string::npos)
        << none;
    // One valid feed is its own knee (before: "none (no feed within ...)").
    const CliRun one = run({"sweep", "--from", "1000", "--to", "1000", "--step", "10"});
    ASSERT_EQ(one.exit_code, 0) << one;
    EXPECT_NE(one.err.find("from 1000 to 1000 mm/min: 1000 mm/min;"), std::string::npos) << one;
}

TEST_F(CycleCli, SweepCsvWritesTheFile) {
    const fs::path file = dir_ / "sweep.csv";
    const CliRun to_stdout = run({"sweep", "--from", "100", "--to", "2000", "--step", "50"});
    const CliRun to_file =
        run({"sweep", "--from", "100", "--to", "2000", "--step", "50", "--csv", file.string()});
    ASSERT_EQ(to_file.exit_code, 0) << to_file;
    EXPECT_EQ(slurp(file), to_stdout.out);
    EXPECT_TRUE(to_file.out.empty()) << to_file;
    EXPECT_FALSE(to_file.err.empty());
    // Replaces an existing file.
    std::ofstream(file, std::ios::binary) << "old";
    ASSERT_EQ(
        run({"sweep", "--from", "100", "--to", "2000", "--step", "50", "--csv", file.string()})
            .exit_code,
        0);
    EXPECT_EQ(slurp(file), to_stdout.out);
}

// `report` writes the window's CSV report: the core's csv_report of the scenario.
TEST_F(CycleCli, ReportIsTheCoreCsvReportOnStdoutOrInAFile) {
    // The golden file's day (golden_test.cpp).
    cli_test::set_env("SOURCE_DATE_EPOCH", "1764115200");
    const CliRun printed = run({"report", "--set", "cycle.feature=bore"});
    ASSERT_EQ(printed.exit_code, 0) << printed;
    EXPECT_EQ(printed.out, slurp(data_file("golden/report_feature_bore.csv")));
    const fs::path file = dir_ / "report.csv";
    const CliRun written = run({"report", "--set", "cycle.feature=bore", "--csv", file.string()});
    ASSERT_EQ(written.exit_code, 0) << written;
    EXPECT_TRUE(written.out.empty()) << written;
    EXPECT_EQ(slurp(file), printed.out);
    EXPECT_EQ(run({"report", "--set", "cycle.feature=sphere"}).exit_code, 2);
    cli_test::set_env("SOURCE_DATE_EPOCH", nullptr);
}

// The report opens with its title, today's date, the version and
// the scenario's file name ("untitled" for the defaults).
TEST_F(CycleCli, ReportHeaderNamesTheDateVersionAndScenarioFile) {
    const std::string file = data_file("scenario_single_touch_3000.json");
    for (const auto& [arguments, name] :
         {std::pair<std::vector<std::string>, std::string>{{"report"}, "untitled"},
          {{"report", file}, "scenario_single_touch_3000.json"}}) {
        const CliRun r = run(arguments);
        ASSERT_EQ(r.exit_code, 0) << r;
        EXPECT_EQ(r.out.rfind("# ProbeCycle cycle report\n# date," + report_date() +
                                  "\n# version," + program_version() + "\n# scenario," + name +
                                  "\n\n# scenario\nkey,value,unit\n",
                              0),
                  0U)
            << r.out.substr(0, 200);
    }
}

TEST_F(CycleCli, FailedSweepLeavesAnExistingFileUntouched) {
    const fs::path file = dir_ / "sweep.csv";
    const std::vector<std::vector<std::string>> bad = {
        {"--set", "probe.pretravel_mm=-1", "--from", "100", "--to", "1000", "--step", "100"},
        {"--from", "100", "--to", "1000", "--step", "0"},
        {"--from", "100", "--to", "1000"},
        {"--set", "machine.scan_period_s=nan", "--from", "100", "--to", "1000", "--step", "100"},
    };
    for (const std::vector<std::string>& extra : bad) {
        std::ofstream(file, std::ios::binary) << "old content\n";
        std::vector<std::string> args = {"sweep"};
        args.insert(args.end(), extra.begin(), extra.end());
        args.insert(args.end(), {"--csv", file.string()});
        const CliRun r = run(args);
        EXPECT_EQ(r.exit_code, 2) << r;
        EXPECT_EQ(slurp(file), "old content\n") << r;
    }
}

TEST_F(CycleCli, SweepIntoAMissingDirectoryIsAnErrorNotACrash) {
    const fs::path file = dir_ / "missing" / "sweep.csv";
    const CliRun r =
        run({"sweep", "--from", "100", "--to", "1000", "--step", "100", "--csv", file.string()});
    EXPECT_TRUE(r.exited) << r;
    EXPECT_EQ(r.exit_code, 2) << r;
    EXPECT_NE(r.err.find(file.string()), std::string::npos) << r;
    EXPECT_FALSE(fs::exists(dir_ / "missing"));
}

// ---------------------------------------------------------------------------
// Bad input: exit 2, a message naming the culprit, nothing on stdout, no crash.

struct BadCase {
    const char* name;
    std::vector<std::string> args;
    std::vector<std::string> mentions;
};

const std::vector<BadCase>& bad_cases() {
    static const std::vector<BadCase> cases = {
        // clang-format off
        // name                     args                                                                   stderr names
        {"no_arguments",            {},                                                                    {}},
        {"unknown_subcommand",      {"frobnicate"},                                                        {"frobnicate"}},
        {"unknown_option",          {"evaluate", "--bogus"},                                               {"--bogus"}},
        {"unknown_move_option",     {"move", "--distance", "1", "--feed", "60", "--speed", "3"},           {"--speed"}},
        {"missing_file",            {"evaluate", "/nonexistent/scenario.json"},                            {"/nonexistent/scenario.json"}},
        {"malformed_file",          {"evaluate", data_file("scenario_malformed.json")},                         {"line"}},
        {"unknown_key_file",        {"evaluate", data_file("scenario_unknown_key.json")},                       {"machine.scan_perod_s"}},
        {"wrong_type_file",         {"evaluate", data_file("scenario_wrong_type.json")},                        {"probe.pretravel_mm", "5 um"}},
        {"unknown_word_file",       {"evaluate", data_file("scenario_unknown_feature.json")},                   {"cycle.feature", "sphere", "bore"}},
        {"negative_file",           {"evaluate", data_file("scenario_negative_delay.json")},                    {"probe.interface_delay_s", "-0.002"}},
        {"set_unknown_key",         {"evaluate", "--set", "machine.nope=1"},                               {"machine.nope"}},
        {"set_unknown_section",     {"evaluate", "--set", "spindle.speed=1"},                              {"spindle"}},
        {"set_nan",                 {"evaluate", "--set", "machine.scan_period_s=nan"},                    {"machine.scan_period_s", "nan"}},
        {"set_negative",            {"evaluate", "--set", "probe.pretravel_mm=-1"},                        {"probe.pretravel_mm", "-1"}},
        {"set_out_of_range",        {"evaluate", "--set", "machine.scan_period_s=5"},                      {"machine.scan_period_s", "5"}},
        {"set_knee_tolerance_high", {"evaluate", "--set", "cycle.knee_tolerance=0.6"},                    {"cycle.knee_tolerance", "0.6", "from 0 to 0.5"}},
        {"set_unknown_backoff_from", {"evaluate", "--set", "cycle.backoff_from=touch"},                   {"cycle.backoff_from", "touch", "stop", "trigger"}},
        {"set_unknown_word",        {"evaluate", "--set", "cycle.strategy=three_touch"},                   {"cycle.strategy", "three_touch", "two_touch"}},
        {"set_wrong_type",          {"evaluate", "--set", "machine.latched_input=maybe"},                  {"machine.latched_input", "maybe"}},
        {"set_without_value",       {"evaluate", "--set"},                                                 {"--set"}},
        {"set_without_equals",      {"evaluate", "--set", "cycle.strategy"},                               {"cycle.strategy"}},
        {"move_missing_distance",   {"move", "--feed", "6000"},                                            {"--distance"}},
        {"move_missing_feed",       {"move", "--distance", "10"},                                          {"--feed"}},
        {"move_negative_distance",  {"move", "--distance", "-1", "--feed", "6000"},                        {"--distance", "-1"}},
        {"move_text_distance",      {"move", "--distance", "ten", "--feed", "6000"},                       {"--distance", "ten"}},
        {"move_nan_feed",           {"move", "--distance", "10", "--feed", "nan"},                         {"--feed", "nan"}},
        {"move_zero_feed",          {"move", "--distance", "10", "--feed", "0"},                           {"--feed"}},
        {"move_bad_set",            {"move", "--set", "probe.reseat_mm=-1", "--distance", "1",
                                     "--feed", "60"},                                                      {"probe.reseat_mm"}},
        {"sweep_missing_step",      {"sweep", "--from", "100", "--to", "1000"},                            {"--step"}},
        {"sweep_zero_step",         {"sweep", "--from", "100", "--to", "1000", "--step", "0"},             {"--step"}},
        {"sweep_negative_from",     {"sweep", "--from", "-100", "--to", "1000", "--step", "100"},          {"--from"}},
        {"sweep_too_many_points",   {"sweep", "--from", "1", "--to", "100000", "--step", "0.01"},          {"--step"}},
        {"sweep_bad_file",          {"sweep", data_file("scenario_unknown_key.json"), "--from", "100",
                                     "--to", "1000", "--step", "100"},                                     {"machine.scan_perod_s"}},
        // clang-format on
    };
    return cases;
}

class CycleCliBadInput : public CycleCli, public testing::WithParamInterface<BadCase> {};

TEST_P(CycleCliBadInput, ExitTwoWithAMessageNamingTheCulprit) {
    const BadCase& c = GetParam();
    const CliRun r = run(c.args);
    ASSERT_TRUE(r.exited) << "crashed\n" << r;
    EXPECT_EQ(r.exit_code, 2) << r;
    EXPECT_TRUE(r.out.empty()) << r;
    EXPECT_FALSE(r.err.empty()) << r;
    for (const std::string& word : c.mentions) {
        EXPECT_NE(r.err.find(word), std::string::npos) << "stderr lacks '" << word << "'\n" << r;
    }
}

INSTANTIATE_TEST_SUITE_P(EveryPath, CycleCliBadInput, testing::ValuesIn(bad_cases()),
                         [](const testing::TestParamInfo<BadCase>& case_info) {
                             return std::string(case_info.param.name);
                         });

TEST_F(CycleCli, ExtremeButValidNumbersNeverCrash) {
    const std::vector<std::vector<std::string>> cases = {
        {"move", "--distance", "0", "--feed", "6000"},
        {"move", "--distance", "100000", "--feed", "1"},
        {"move", "--distance", "1e-12", "--feed", "100000"},
        {"evaluate", "--set", "cycle.approach_mm=0"},
        {"evaluate", "--set", "cycle.backoff_mm=0"},
        {"evaluate", "--set", "probe.pretravel_mm=0", "--set", "machine.scan_period_s=0", "--set",
         "machine.controller_latency_s=0", "--set", "probe.interface_delay_s=0"},
        {"evaluate", "--set", "cycle.feature=boss", "--set", "cycle.feature_size_mm=0"},
        {"evaluate", "--set", "machine.accel_model=jerk_limited", "--set",
         "machine.max_jerk_mm_s3=10", "--set", "cycle.probe_feed_mm_min=100000"},
        {"sweep", "--from", "1", "--to", "1", "--step", "1"},
    };
    for (const std::vector<std::string>& args : cases) {
        const CliRun r = run(args);
        ASSERT_TRUE(r.exited) << "crashed\n" << r;
        EXPECT_EQ(r.exit_code, 0) << r;
        if (args[0] != "sweep") {
            const json j = json::parse(r.out, nullptr, false);
            EXPECT_FALSE(j.is_discarded()) << r;
            // JSON has no NaN or infinity: nlohmann writes them as null. A
            // missing knee is null too, and then a warning says why (a start at
            // the surface reaches no feed).
            std::string out = r.out;
            if (j.contains("knee_feed_mm_min") && j["knee_feed_mm_min"].is_null()) {
                EXPECT_NE(out.find("no_valid_feed"), std::string::npos) << r;
                for (const char* key :
                     {"\"knee_feed_mm_min\": null", "\"knee_cycle_time_s\": null"}) {
                    const std::size_t at = out.find(key);
                    if (at != std::string::npos) out.erase(at, std::string(key).size());
                }
            }
            EXPECT_EQ(out.find("null"), std::string::npos) << r;
        }
    }
}

}  // namespace
}  // namespace probecycle
