// probecycle-cli machine linuxcnc, run as a user runs it: the machine section
// of the sample INI files, which evaluate reads as a scenario, and bad files
// refused with exit 2, naming the file, the section, the key, the line and
// what is allowed.

#include <gtest/gtest.h>

#include <string>

#include "tests/cli/cli_run.h"

namespace probecycle::cli_test {
namespace {

TEST(MachineCli, PrintsEveryMachineKeyOfTheMillInMillimetres) {
    const CliRun r = run("machine linuxcnc " + quote(data("linuxcnc/mill_mm.ini")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(r.out,
              "{\n"
              "  \"machine\": {\n"
              "    \"accel_model\": \"constant_accel\",\n"
              "    \"time_constant_s\": 0.06,\n"
              "    \"max_accel_mm_s2\": 1000.0,\n"
              "    \"max_jerk_mm_s3\": 40000.0,\n"
              "    \"filter\": \"none\",\n"
              "    \"filter_time_s\": 0.03,\n"
              "    \"filter2_time_s\": 0.01,\n"
              "    \"servo_time_constant_s\": 0.0,\n"
              "    \"in_position_mm\": 0.01,\n"
              "    \"block_change_s\": 0.0036,\n"
              "    \"rapid_feed_mm_min\": 6000.0,\n"
              "    \"scan_period_s\": 0.001,\n"
              "    \"controller_latency_s\": 0.002,\n"
              "    \"latched_input\": false,\n"
              "    \"repeatability_2sigma_mm\": 0.002,\n"
              "    \"thermal_drift_mm\": 0.002\n"
              "  }\n"
              "}\n");
}

// A scenario file holding only the machine section is valid input to evaluate.
TEST(MachineCli, EvaluateReadsItsOutput) {
    const TempDir dir;
    const CliRun machine = run("machine linuxcnc " + quote(data("linuxcnc/mill_inch.ini")));
    ASSERT_EQ(machine.exit_code, 0) << machine.err;
    EXPECT_NE(machine.out.find("\"max_accel_mm_s2\": 635.0"), std::string::npos) << machine.out;
    EXPECT_NE(machine.out.find("\"rapid_feed_mm_min\": 3810.0"), std::string::npos) << machine.out;
    write(dir / "machine.json", machine.out);
    const CliRun evaluate = run("evaluate " + quote((dir / "machine.json").string()));
    ASSERT_EQ(evaluate.exit_code, 0) << evaluate.err;
    EXPECT_NE(evaluate.out.find("\"cycle_time_s\""), std::string::npos);
}

struct BadIni {
    const char* what;
    std::string text;
    std::string says;
};

class MachineCliRefusal : public testing::TestWithParam<BadIni> {};

TEST_P(MachineCliRefusal, ExitsTwoNamingTheFileSectionKeyLineAndRange) {
    const BadIni& b = GetParam();
    const TempDir dir;
    const std::string path = (dir / "mill.ini").string();
    std::string text = read(data("linuxcnc/mill_mm.ini"));
    const std::size_t at = text.find("MAX_ACCELERATION = 1000\n");  // [AXIS_Z], line 44
    ASSERT_NE(at, std::string::npos);
    write(path, text.replace(at, 24, b.text));
    const CliRun r = run("machine linuxcnc " + quote(path));
    EXPECT_EQ(r.exit_code, 2) << b.what;
    EXPECT_EQ(r.out, "") << b.what;
    EXPECT_EQ(r.err, "probecycle-cli machine: " + path + ": invalid LinuxCNC configuration:\n" +
                         b.says + "\n")
        << b.what;
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(MachineCli, MachineCliRefusal, testing::Values(
    BadIni{"missing", "",
           "[AXIS_Z] MAX_ACCELERATION: missing; expected a number from 1 to 200000 mm/s^2 (for machine.max_accel_mm_s2)"},
    BadIni{"malformed", "MAX_ACCELERATION = 1e3.5\n",
           "[AXIS_Z] MAX_ACCELERATION, line 44: got 1e3.5; allowed: a number from 1 to 200000 mm/s^2 (for machine.max_accel_mm_s2)"},
    BadIni{"out of range", "MAX_ACCELERATION = 0.5\n",
           "[AXIS_Z] MAX_ACCELERATION, line 44: got 0.5; allowed: a number from 1 to 200000 mm/s^2 (for machine.max_accel_mm_s2)"},
    BadIni{"an include", "MAX_ACCELERATION = 1000\n#INCLUDE joints.inc\n",
           "line 45: #INCLUDE is not followed; LinuxCNC writes the configuration with its includes to NAME.ini.expanded beside the INI file when it starts: read that file"}));
// clang-format on

TEST(MachineCli, AFileThatCannotBeReadIsNamed) {
    const CliRun r = run("machine linuxcnc /nonexistent/mill.ini");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("probecycle-cli machine: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("/nonexistent/mill.ini"), std::string::npos) << r.err;
}

TEST(MachineCli, UsageIsNamed) {
    const CliRun none = run("machine");
    EXPECT_EQ(none.exit_code, 2);
    EXPECT_EQ(none.err, "probecycle-cli machine: missing what to do; allowed: linuxcnc\n");
    const CliRun other = run("machine fanuc x.ini");
    EXPECT_EQ(other.exit_code, 2);
    EXPECT_EQ(other.err, "probecycle-cli machine: unknown control 'fanuc'; allowed: linuxcnc\n");
    const CliRun no_file = run("machine linuxcnc");
    EXPECT_EQ(no_file.exit_code, 2);
    EXPECT_EQ(no_file.err, "probecycle-cli machine: missing the input file (FILE.ini)\n");
}

}  // namespace
}  // namespace probecycle::cli_test
