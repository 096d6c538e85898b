// The lab subcommands (docs/cli.md) run as a user runs them: a subprocess, its
// stdout, stderr and exit status, and the files it writes or must not write.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <ostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/common/file_io.h"
#include "core/cycle/cycle_report.h"
#include "core/lab/calibration_report.h"
#include "tests/cli/cli_run.h"

namespace {

namespace fs = std::filesystem;
namespace cli_test = probecycle::cli_test;
using Json = nlohmann::json;

using cli_test::CliRun;
using cli_test::TempDir;

Json lab_json(const CliRun& run) {
    return Json::parse(run.out);
}

bool lab_has_warning(const Json& out, const std::string& code) {
    for (const auto& w : out.at("warnings")) {
        if (w.at("code") == code) return true;
    }
    return false;
}

// Names parameterized cases after their `name` field.
struct LabCaseName {
    template <typename T>
    std::string operator()(const testing::TestParamInfo<T>& case_info) const {
        return case_info.param.name;
    }
};

constexpr double kFileRounding = 1e-8;  // the data files hold 9 decimals

// ---------------------------------------------------------------------------
// calibrate ring

TEST(LabCalibrateRing, ExactFileGivesTheKnownAnswers) {
    // lab_ring.csv: gauge 50 mm centred at X100 Y-200, ball 2.995 mm, runout
    // (0.003, -0.002), four points at each orientation.
    const auto run =
        cli_test::run("calibrate ring " + cli_test::quote(cli_test::data("lab_ring.csv")) +
                      " --gauge-diameter 50");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");
    const Json out = lab_json(run);
    EXPECT_NEAR(out.at("center_x_mm").get<double>(), 100.0, kFileRounding);
    EXPECT_NEAR(out.at("center_y_mm").get<double>(), -200.0, kFileRounding);
    EXPECT_NEAR(out.at("runout_x_mm").get<double>(), 0.003, kFileRounding);
    EXPECT_NEAR(out.at("runout_y_mm").get<double>(), -0.002, kFileRounding);
    EXPECT_NEAR(out.at("effective_radius_mm").get<double>(), 2.995, kFileRounding);
    for (const char* direction : {"x_plus", "x_minus", "y_plus", "y_minus"}) {
        EXPECT_NEAR(out.at("radius_by_direction").at(direction).get<double>(), 2.995, kFileRounding)
            << direction;
    }
    EXPECT_NEAR(out.at("residual_max_mm").get<double>(), 0.0, kFileRounding);
    EXPECT_EQ(out.at("fits").size(), 2u);
    EXPECT_TRUE(out.at("warnings").empty());
}

// Runs a command with --report FILE on the golden files' day (golden_test.cpp)
// and returns the report ("" when the command failed).
std::string report_on_golden_day(const std::string& arguments, const fs::path& report) {
    cli_test::set_env("SOURCE_DATE_EPOCH", "1764115200");
    const CliRun run = cli_test::run(arguments + " --report " + cli_test::quote(report.string()));
    cli_test::set_env("SOURCE_DATE_EPOCH", nullptr);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return run.exit_code == 0 ? cli_test::read(report) : std::string();
}

// --report writes the Calibration tab's CSV report: the core's text for the same fit.
TEST(LabCalibrateRing, ReportFileIsTheCalibrationReport) {
    const TempDir dir;
    const std::string text =
        report_on_golden_day("calibrate ring " + cli_test::quote(cli_test::data("lab_ring.csv")) +
                                 " --gauge-diameter 50",
                             dir / "ring_report.csv");
    EXPECT_EQ(text, cli_test::read(cli_test::data("golden/calibrate_ring_report.csv")));
    EXPECT_EQ(text.rfind("# ProbeCycle calibration report\n# date,2025-11-26\n", 0), 0u) << text;
    EXPECT_NE(text.find("\n# points,lab_ring.csv\n\n# ring\n"), std::string::npos) << text;
}

// `latency fit --report` writes the Latency tab's report, the
// golden file of its example (golden_test.cpp) with its header.
TEST(LabLatencyFit, ReportFileIsTheDelayFitReport) {
    const TempDir dir;
    const std::string text = report_on_golden_day(
        "latency fit " + cli_test::quote(cli_test::data("lab_delay_report.csv")) +
            " --interpolation-period-s 0.001",
        dir / "delay_report.csv");
    EXPECT_EQ(text, cli_test::read(cli_test::data("golden/latency_fit_scatter_report.csv")));
    EXPECT_EQ(text.rfind("# ProbeCycle delay fit report\n# date,2025-11-26\n", 0), 0u) << text;
    EXPECT_NE(text.find("\n# touches,lab_delay_report.csv\n\n# fit\n"), std::string::npos) << text;
    // A bad file writes no report.
    const fs::path none = dir / "none.csv";
    const auto bad =
        cli_test::run("latency fit " + cli_test::quote(cli_test::data("lab_delay_one_feed.csv")) +
                      " --report " + cli_test::quote(none.string()));
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_FALSE(fs::exists(none));
}

TEST(LabCalibrateRing, OneOrientationSaysThereIsNoRunout) {
    const auto run = cli_test::run("calibrate ring " +
                                   cli_test::quote(cli_test::data("lab_ring_one_orientation.csv")) +
                                   " --gauge-diameter=50");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = lab_json(run);
    EXPECT_TRUE(out.at("runout_x_mm").is_null());
    EXPECT_TRUE(out.at("runout_y_mm").is_null());
    EXPECT_NEAR(out.at("effective_radius_mm").get<double>(), 2.995, kFileRounding);
    EXPECT_TRUE(lab_has_warning(out, "single_orientation"));
    EXPECT_EQ(out.at("warnings")[0].at("severity"), "warning");
    EXPECT_EQ(out.at("warnings")[0].at("values").at("orientation_deg"), 0.0);
    EXPECT_EQ(out.at("warnings")[0].at("values").at("missing_orientation_deg"), 180.0);
}

TEST(LabCalibrateRing, WarningLimitsAreOptions) {
    const auto run =
        cli_test::run("calibrate ring " + cli_test::quote(cli_test::data("lab_ring.csv")) +
                      " --gauge-diameter 50 --runout-limit 0.001");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(lab_has_warning(lab_json(run), "large_runout"));
}

// ---------------------------------------------------------------------------
// calibrate length

TEST(LabCalibrateLength, LengthAndWear) {
    const auto run = cli_test::run(
        "calibrate length --surface-z 25 --trigger-z 25.029 --trigger-z 25.031 "
        "--active-length 150 --nominal-length 150");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = lab_json(run);
    EXPECT_NEAR(out.at("effective_length_mm").get<double>(), 150.030, 1e-9);
    EXPECT_NEAR(out.at("wear_mm").get<double>(), 0.030, 1e-9);
    EXPECT_NEAR(out.at("trigger_z_range_mm").get<double>(), 0.002, 1e-9);
    EXPECT_EQ(out.at("touches"), 2);
}

TEST(LabCalibrateLength, NoNominalNoWear) {
    const auto run = cli_test::run("calibrate length --surface-z -400 --trigger-z -249.75");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = lab_json(run);
    EXPECT_NEAR(out.at("effective_length_mm").get<double>(), 150.25, 1e-9);
    EXPECT_TRUE(out.at("wear_mm").is_null());
}

// ---------------------------------------------------------------------------
// latency fit

TEST(LabLatencyFit, ExactFileGivesTheDelays) {
    // lab_delay.csv: X+ 8.5 ms from 10.000 over 5 feeds, Z- 9 ms from -50.000 over 3.
    const auto run =
        cli_test::run("latency fit " + cli_test::quote(cli_test::data("lab_delay.csv")) +
                      " --interpolation-period-s 0.001");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = lab_json(run);
    ASSERT_EQ(out.at("groups").size(), 2u);
    const Json& x = out.at("groups")[0];
    EXPECT_EQ(x.at("axis"), "X");
    EXPECT_EQ(x.at("direction"), 1);
    EXPECT_NEAR(x.at("delay_s").get<double>(), 0.0085, 1e-8);
    EXPECT_NEAR(x.at("zero_speed_position_mm").get<double>(), 10.0, kFileRounding);
    EXPECT_NEAR(x.at("lag_cycles").get<double>(), 8.5, 1e-5);
    EXPECT_NEAR(x.at("residual_2sigma_mm").get<double>(), 0.0, kFileRounding);
    ASSERT_EQ(x.at("feeds").size(), 5u);
    EXPECT_EQ(x.at("feeds")[0].at("feed_mm_min"), 100.0);
    EXPECT_EQ(x.at("feeds")[0].at("n"), 3);
    EXPECT_NEAR(x.at("feeds")[4].at("range_mm").get<double>(), 0.0, 1e-12);
    const Json& z = out.at("groups")[1];
    EXPECT_EQ(z.at("axis"), "Z");
    EXPECT_EQ(z.at("direction"), -1);
    EXPECT_NEAR(z.at("delay_s").get<double>(), 0.009, 1e-8);
    EXPECT_NEAR(z.at("zero_speed_position_mm").get<double>(), -50.0, kFileRounding);
    EXPECT_TRUE(out.at("warnings").empty());
}

TEST(LabLatencyFit, NoLagCyclesWithoutThePeriod) {
    const auto run =
        cli_test::run("latency fit " + cli_test::quote(cli_test::data("lab_delay.csv")));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_FALSE(lab_json(run).at("groups")[0].contains("lag_cycles"));
}

TEST(LabLatencyFit, FewFeedsWarnWithTheGroup) {
    const TempDir dir;
    cli_test::write(dir / "two_feeds.csv",
                    "axis,direction,feed_mm_min,measured_mm\nY,-1,100,-1.0\nY,-1,2000,-1.3\n");
    const auto run =
        cli_test::run("latency fit " + cli_test::quote((dir / "two_feeds.csv").string()));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = lab_json(run);
    ASSERT_TRUE(lab_has_warning(out, "few_feeds"));
    EXPECT_EQ(out.at("warnings")[0].at("group"), "Y-");
    // The warning's numbers by name, beside its English text.
    const Json& values = out.at("warnings")[0].at("values");
    EXPECT_EQ(values.at("group"), "Y-");
    EXPECT_EQ(values.at("feeds"), 2);
    EXPECT_TRUE(out.at("groups")[0].at("residual_2sigma_mm").is_null());
}

// Writes the default scenario, with `interface_delay_s`, into `path`.
void lab_write_scenario(const fs::path& path, double interface_delay_s) {
    const auto defaults = cli_test::run("defaults");
    ASSERT_EQ(defaults.exit_code, 0) << defaults.err;
    Json scenario = Json::parse(defaults.out);
    scenario["probe"]["interface_delay_s"] = interface_delay_s;
    cli_test::write(path, scenario.dump(2));
}

TEST(LabLatencyFit, ApplyToWritesTheControllerLatency) {
    const TempDir dir;
    const fs::path scenario = dir / "scenario.json";
    lab_write_scenario(scenario, 0.002);
    // Default scenario: scanned input, 4 ms scan. X+ measured 8.5 ms in all:
    // 2 ms interface + 2 ms half scan + 4.5 ms controller.
    const auto run =
        cli_test::run("latency fit " + cli_test::quote(cli_test::data("lab_delay.csv")) +
                      " --apply-to " + cli_test::quote(scenario.string()) + " --group x+");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json applied = lab_json(run).at("applied");
    EXPECT_EQ(applied.at("group"), "X+");
    EXPECT_EQ(applied.at("key"), "machine.controller_latency_s");
    EXPECT_NEAR(applied.at("value_s").get<double>(), 0.0045, 1e-8);
    EXPECT_NEAR(applied.at("total_delay_s").get<double>(), 0.0085, 1e-8);
    const Json written = Json::parse(cli_test::read(scenario));
    EXPECT_NEAR(written.at("machine").at("controller_latency_s").get<double>(), 0.0045, 1e-8);
    // The file is still a scenario the CLI accepts.
    EXPECT_EQ(cli_test::run("evaluate " + cli_test::quote(scenario.string())).exit_code, 0);
}

// With a latched input the fit is the interface delay: the position is
// captured when the signal reaches the control.
TEST(LabLatencyFit, ApplyToALatchedScenarioWritesTheInterfaceDelayAndSaysSo) {
    const TempDir dir;
    const fs::path scenario = dir / "scenario.json";
    const auto defaults = cli_test::run("defaults");
    ASSERT_EQ(defaults.exit_code, 0) << defaults.err;
    Json json = Json::parse(defaults.out);
    json["machine"]["latched_input"] = true;
    cli_test::write(scenario, json.dump(2));
    const auto run =
        cli_test::run("latency fit " + cli_test::quote(cli_test::data("lab_delay.csv")) +
                      " --apply-to " + cli_test::quote(scenario.string()) + " --group x+");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json applied = lab_json(run).at("applied");
    EXPECT_EQ(applied.at("key"), "probe.interface_delay_s");
    EXPECT_NEAR(applied.at("value_s").get<double>(), 0.0085, 1e-8);
    EXPECT_NE(applied.at("note").get<std::string>().find("controller_latency_s is left"),
              std::string::npos);
    const Json written = Json::parse(cli_test::read(scenario));
    EXPECT_NEAR(written.at("probe").at("interface_delay_s").get<double>(), 0.0085, 1e-8);
    EXPECT_EQ(written.at("machine").at("controller_latency_s"),
              json.at("machine").at("controller_latency_s"));
}

TEST(LabLatencyFit, SeveralGroupsApplyTheLongestDelayAndSaySo) {
    const TempDir dir;
    const fs::path scenario = dir / "scenario.json";
    lab_write_scenario(scenario, 0.002);
    const auto run =
        cli_test::run("latency fit " + cli_test::quote(cli_test::data("lab_delay.csv")) +
                      " --apply-to " + cli_test::quote(scenario.string()));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json applied = lab_json(run).at("applied");
    EXPECT_EQ(applied.at("group"), "Z-");
    EXPECT_NE(applied.at("rule").get<std::string>().find("longest delay of 2 groups"),
              std::string::npos);
    EXPECT_NEAR(applied.at("value_s").get<double>(), 0.005, 1e-8);
}

struct LabApplyErrorCase {
    const char* name;
    const char* csv;    // in the data directory
    const char* extra;  // more arguments
    double interface_delay_s;
    const char* says;
};
// Test names in ctest show the case name, not the bytes.
void PrintTo(const LabApplyErrorCase& c, std::ostream* os) {
    *os << c.name;
}

class LabApplyErrors : public testing::TestWithParam<LabApplyErrorCase> {};

TEST_P(LabApplyErrors, WriteNothing) {
    const auto& c = GetParam();
    const TempDir dir;
    const fs::path scenario = dir / "scenario.json";
    lab_write_scenario(scenario, c.interface_delay_s);
    const std::string before = cli_test::read(scenario);
    // With --report too: a refusal writes no report either.
    const auto run =
        cli_test::run("latency fit " + cli_test::quote(cli_test::data(c.csv)) + " --apply-to " +
                      cli_test::quote(scenario.string()) + " --report " +
                      cli_test::quote((dir / "report.csv").string()) + " " + c.extra);
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.out, "");
    EXPECT_NE(run.err.find(c.says), std::string::npos) << run.err;
    EXPECT_EQ(cli_test::read(scenario), before);
    // No report and no temporary left behind either.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 1);
}

TEST(LabLatencyFit, TheReportAndTheScenarioInOneFileAreRefused) {
    // Before, the scenario was replaced by the CSV report, then exit 2.
    const TempDir dir;
    const fs::path scenario = dir / "scenario.json";
    lab_write_scenario(scenario, 0.002);
    const std::string before = cli_test::read(scenario);
    const auto run =
        cli_test::run("latency fit " + cli_test::quote(cli_test::data("lab_delay.csv")) +
                      " --group Z- --apply-to " + cli_test::quote(scenario.string()) +
                      " --report " + cli_test::quote(scenario.string()));
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.err.find("give each output a file of its own"), std::string::npos) << run.err;
    EXPECT_EQ(cli_test::read(scenario), before);
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(Lab, LabApplyErrors,
                         testing::Values(
        LabApplyErrorCase{"NegativeLatency", "lab_delay.csv",                "--group X+", 0.008, "controller latency would be negative"},
        LabApplyErrorCase{"UnknownGroup",    "lab_delay.csv",                "--group Y+", 0.002, "allowed: a group of the file (X+, Z-)"},
        LabApplyErrorCase{"BadFile",         "lab_delay_text_in_number.csv", "",           0.002, "line 3, column feed_mm_min"},
        LabApplyErrorCase{"OneFeed",         "lab_delay_one_feed.csv",       "",           0.002, "line 2"}),
                         LabCaseName{});
// clang-format on

TEST(LabLatencyFit, ApplyToABadScenarioNamesIt) {
    const TempDir dir;
    const fs::path scenario = dir / "broken.json";
    cli_test::write(scenario, "{\"machine\": {\"scan_period_s\": \"fast\"}}");
    const auto run =
        cli_test::run("latency fit " + cli_test::quote(cli_test::data("lab_delay.csv")) +
                      " --apply-to " + cli_test::quote(scenario.string()));
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.err.find("broken.json"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("scan_period_s"), std::string::npos) << run.err;
    EXPECT_EQ(cli_test::read(scenario), "{\"machine\": {\"scan_period_s\": \"fast\"}}");
}

// ---------------------------------------------------------------------------
// latency compensate

double lab_method_error(const Json& out, const std::string& method) {
    for (const auto& m : out.at("methods")) {
        if (m.at("method") == method) return m.at("error_mm").get<double>();
    }
    ADD_FAILURE() << "no method " << method;
    return std::nan("");
}

TEST(LabLatencyCompensate, ConstantSpeedDefaults) {
    const auto run = cli_test::run("latency compensate --trace");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = lab_json(run);
    EXPECT_EQ(out.at("setup").at("touch"), "constant_speed");
    EXPECT_EQ(out.at("recorded").at("counter_wraps"), 1);
    EXPECT_EQ(out.at("trace").size(), 51u);
    // 2000 mm/min, 1 ms cycles, lag 8, trigger at 0.4 of its cycle.
    const double v = 2000.0 / 60.0;
    EXPECT_NEAR(lab_method_error(out, "uncompensated"), v * 0.0086, 1e-4);
    EXPECT_NEAR(lab_method_error(out, "cycle_lag"), v * 0.0006, 1e-4);
    EXPECT_NEAR(lab_method_error(out, "timestamp"), 0.0, 1e-4);
}

// The true lag and the compensated lag apart: a compensation may subtract
// fewer cycles than the machine lags.
TEST(LabLatencyCompensate, CompensatedLagApartFromTheTrueLag) {
    const auto run =
        cli_test::run("latency compensate --lag-cycles 10 --compensated-lag-cycles 8 --lag-sweep");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = lab_json(run);
    EXPECT_EQ(out.at("setup").at("lag_cycles"), 10);
    EXPECT_EQ(out.at("setup").at("compensated_lag_cycles"), 8);
    const double v = 2000.0 / 60.0;
    // (1 + 10 - 8) cycles less the 0.4 cycle phase: 2.6 ms of travel.
    EXPECT_NEAR(lab_method_error(out, "cycle_lag"), v * 0.0026, 1e-4);
    const Json& sweep = out.at("lag_sweep");
    ASSERT_EQ(sweep.size(), 50u);
    EXPECT_EQ(sweep.at(8).at("compensated_lag_cycles"), 8);
    EXPECT_NEAR(sweep.at(8).at("cycle_lag_error_mm").get<double>(), v * 0.0026, 1e-4);
    EXPECT_NEAR(sweep.at(10).at("cycle_lag_error_mm").get<double>(), v * 0.0006, 1e-4);

    const auto bad = cli_test::run("latency compensate --compensated-lag-cycles 50");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("--compensated-lag-cycles"), std::string::npos) << bad.err;
}

TEST(LabLatencyCompensate, BrakingOnlyRealIncrementsAreRight) {
    const auto run = cli_test::run(
        "latency compensate --touch braking --speed-fraction 0.3 --lag-cycles 9 "
        "--set cycle.probe_feed_mm_min=3000 --sweep 4");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = lab_json(run);
    EXPECT_EQ(out.at("setup").at("feed_mm_min"), 3000.0);
    const double naive = lab_method_error(out, "naive_v_tau");
    const double cycle_lag = lab_method_error(out, "cycle_lag");
    EXPECT_GT(std::abs(naive), 10.0 * std::abs(cycle_lag));
    ASSERT_EQ(out.at("braking_sweep").size(), 4u);
    EXPECT_EQ(out.at("braking_sweep")[3].at("speed_fraction"), 0.25);
}

TEST(LabLatencyCompensate, SixteenBitCounterWrapsDuringTheLag) {
    // At 10000 counts/mm the counter reads 53536 + 12000 = 65536 = 0 at 1.2 mm,
    // between the trigger (1.03 mm) and the recording (1.32 mm).
    const auto wrapped =
        cli_test::run("latency compensate --counter-bits 16 --counter-at-zero 53536");
    const auto plain =
        cli_test::run("latency compensate --counter-bits 16 --counter-at-zero 30000");
    ASSERT_EQ(wrapped.exit_code, 0) << wrapped.err;
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    EXPECT_EQ(lab_json(wrapped).at("recorded").at("counter_wraps"), 1);
    EXPECT_EQ(lab_json(plain).at("recorded").at("counter_wraps"), 0);
    EXPECT_EQ(lab_json(wrapped).at("methods"), lab_json(plain).at("methods"));
}

// ---------------------------------------------------------------------------
// Bad input: exit 2, nothing on stdout, a message naming the line or option.

struct InputErrorCase {
    const char* name;
    std::string arguments;
    const char* says;
};
// Test names in ctest show the case name, not the bytes.
void PrintTo(const InputErrorCase& c, std::ostream* os) {
    *os << c.name;
}

class LabCliErrors : public testing::TestWithParam<InputErrorCase> {};

TEST_P(LabCliErrors, ExitTwoAndNameTheProblem) {
    const auto& c = GetParam();
    const auto run = cli_test::run(c.arguments);
    EXPECT_EQ(run.exit_code, 2) << run.out;
    EXPECT_EQ(run.out, "");
    EXPECT_NE(run.err.find(c.says), std::string::npos) << run.err;
}

std::string lab_ring(const char* file) {
    return "calibrate ring " + cli_test::quote(cli_test::data(file)) + " --gauge-diameter 50";
}
std::string lab_fit(const char* file) {
    return "latency fit " + cli_test::quote(cli_test::data(file));
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(
    Lab, LabCliErrors,
    testing::Values(
        InputErrorCase{"RingTextInNumber",     lab_ring("lab_ring_text_in_number.csv"),                                          "lab_ring_text_in_number.csv: line 4, column y_mm: 'abc' is not a number"},
        InputErrorCase{"RingMissingColumn",    lab_ring("lab_ring_missing_column.csv"),                                          "line 1: missing column 'y_mm'"},
        InputErrorCase{"RingOnePoint",         lab_ring("lab_ring_one_point.csv"),                                               "line 2: orientation 0 deg has only 1 point"},
        InputErrorCase{"RingEmpty",            lab_ring("lab_ring_empty.csv"),                                                   "the file is empty"},
        InputErrorCase{"RingNoFile",           lab_ring("lab_no_such_file.csv"),                                                 "lab_no_such_file.csv"},
        InputErrorCase{"RingNoGauge",          "calibrate ring " + cli_test::quote(cli_test::data("lab_ring.csv")),                          "missing required option --gauge-diameter"},
        InputErrorCase{"RingGaugeText",        lab_ring("lab_ring.csv") + " --gauge-diameter abc",                               "--gauge-diameter: got 'abc'"},
        InputErrorCase{"RingGaugeTooSmall",    "calibrate ring " + cli_test::quote(cli_test::data("lab_ring.csv")) + " --gauge-diameter 25", "check the gauge diameter"},
        InputErrorCase{"RingNoInput",          "calibrate ring --gauge-diameter 50",                                             "missing the input file"},
        InputErrorCase{"CalibrateWhat",        "calibrate sphere",                                                               "allowed: ring, length"},
        InputErrorCase{"LengthBelowSurface",   "calibrate length --surface-z 25 --trigger-z 20",                                 "not positive"},
        InputErrorCase{"LengthNoTouch",        "calibrate length --surface-z 25",                                                "--trigger-z"},
        InputErrorCase{"FitOneFeed",           lab_fit("lab_delay_one_feed.csv"),                                                "line 2, column feed_mm_min: X+: all 4 touches are at one feed"},
        InputErrorCase{"FitTextInNumber",      lab_fit("lab_delay_text_in_number.csv"),                                          "line 3, column feed_mm_min: 'fast' is not a number"},
        InputErrorCase{"FitMissingColumn",     lab_fit("lab_delay_missing_column.csv"),                                          "line 1: missing column 'direction'"},
        InputErrorCase{"FitEmpty",             lab_fit("lab_ring_empty.csv"),                                                    "the file is empty"},
        InputErrorCase{"FitRingFile",          lab_fit("lab_ring.csv"),                                                          "missing column 'axis'"},
        InputErrorCase{"FitBadPeriod",         lab_fit("lab_delay.csv") + " --interpolation-period-s 0",                         "--interpolation-period-s: got '0'"},
        InputErrorCase{"FitGroupWithoutApply", lab_fit("lab_delay.csv") + " --group X+",                                         "--apply-to"},
        InputErrorCase{"LatencyWhat",          "latency measure",                                                                "allowed: fit, compensate"},
        InputErrorCase{"CompensateLag",        "latency compensate --lag-cycles 50",                                             "--lag-cycles: got '50'; allowed: a whole number from 0 to 49"},
        InputErrorCase{"CompensateTouch",      "latency compensate --touch slow",                                                "allowed: constant, braking"},
        InputErrorCase{"CompensateFraction",   "latency compensate --speed-fraction 0.5",                                        "--touch braking"},
        InputErrorCase{"CompensatePhase",      "latency compensate --trigger-phase 1",                                           "--trigger-phase"},
        InputErrorCase{"CompensateCounter",    "latency compensate --counter-bits 16 --counter-at-zero 70000",                     "from 0 to 65535"},
        InputErrorCase{"CompensateNarrow",     "latency compensate --counter-bits 16 --counts-per-mm 1e7 --feed 100000",         "--counter-bits"},
        InputErrorCase{"CompensateScenario",   "latency compensate --set machine.scan_period_s=5",                               "machine.scan_period_s"}),
    LabCaseName{});
// clang-format on

TEST(LabCliHelp, SubcommandHelpExitsZero) {
    for (const char* command : {"calibrate --help", "latency help"}) {
        const auto run = cli_test::run(command);
        EXPECT_EQ(run.exit_code, 0) << command;
        EXPECT_NE(run.out.find("usage:"), std::string::npos) << command;
    }
}

}  // namespace
