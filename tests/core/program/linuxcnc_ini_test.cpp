// The machine from a LinuxCNC 2.9 INI file: the sample configurations in mm
// and inch, LinuxCNC's own reading of the file (first line of a key, first
// block of a section, comments, continued lines), and every refusal, each
// naming the section, the key, the line and what is allowed.

#include "core/program/linuxcnc_ini.h"
#include "core/cycle/preset.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "core/common/message_json.h"
#include "core/cycle/scenario.h"
#include "tests/core/common/message_checks.h"

namespace probecycle {
namespace {

std::string slurp(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string data(const std::string& name) {
    return slurp(std::filesystem::path(PROBECYCLE_TEST_DATA_DIR) / "linuxcnc" / name);
}

// The smallest INI ProbeCycle reads, in mm, with its line numbers fixed.
constexpr const char* kBase =
    "[EMCMOT]\n"                   // 1
    "SERVO_PERIOD = 1000000\n"     // 2
    "\n"                           // 3
    "[TRAJ]\n"                     // 4
    "LINEAR_UNITS = mm\n"          // 5
    "MAX_LINEAR_VELOCITY = 100\n"  // 6
    "\n"                           // 7
    "[AXIS_X]\n"                   // 8
    "MAX_VELOCITY = 150\n"         // 9
    "MAX_ACCELERATION = 1200\n"    // 10
    "\n"                           // 11
    "[AXIS_Y]\n"                   // 12
    "MAX_VELOCITY = 150\n"         // 13
    "MAX_ACCELERATION = 1200\n"    // 14
    "\n"                           // 15
    "[AXIS_Z]\n"                   // 16
    "MAX_VELOCITY = 120\n"         // 17
    "MAX_ACCELERATION = 1000\n";   // 18

// kBase with lines replaced, by their number in kBase: each by the text given
// (several lines, or none when empty).
std::string edit(const std::map<int, std::string>& lines) {
    std::istringstream in(kBase);
    std::string text;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const auto it = lines.find(number);
        if (it == lines.end()) {
            text += line + '\n';
        } else if (!it->second.empty()) {
            text += it->second + '\n';
        }
    }
    return text;
}

// Every problem of the refusal in English, one a line; empty when accepted.
std::string refusal(const std::string& text) {
    try {
        machine_from_linuxcnc_ini(text);
    } catch (const LinuxCncIniError& e) {
        return e.what();
    }
    return {};
}

void expect_linuxcnc_machine(const Machine& m) {
    EXPECT_EQ(m.accel_model, AccelModel::constant_accel);
    EXPECT_EQ(m.filter, FilterKind::none);
    EXPECT_EQ(m.servo_time_constant_s, 0.0);
    EXPECT_FALSE(m.latched_input);
    EXPECT_EQ(m.controller_latency_s, 2.0 * m.scan_period_s);
    // The INI says nothing of these: the defaults.
    const Machine defaults;
    EXPECT_EQ(m.time_constant_s, defaults.time_constant_s);
    EXPECT_EQ(m.max_jerk_mm_s3, defaults.max_jerk_mm_s3);
    EXPECT_EQ(m.filter_time_s, defaults.filter_time_s);
    EXPECT_EQ(m.filter2_time_s, defaults.filter2_time_s);
    EXPECT_EQ(m.in_position_mm, defaults.in_position_mm);
    Scenario s;
    s.machine = m;
    EXPECT_TRUE(validate(s).empty());
}

TEST(LinuxCncIni, TheMillInMillimetres) {
    const Machine m = machine_from_linuxcnc_ini(data("mill_mm.ini"));
    expect_linuxcnc_machine(m);
    // The smallest axis acceleration (Z); the joints' 4000 and [TRAJ]'s 5000 do not act.
    EXPECT_EQ(m.max_accel_mm_s2, 1000.0);
    // [TRAJ] MAX_LINEAR_VELOCITY 100 mm/s caps the axes' 150, 150, 120.
    EXPECT_EQ(m.rapid_feed_mm_min, 6000.0);
    EXPECT_EQ(m.scan_period_s, 0.001);
    EXPECT_EQ(m.controller_latency_s, 0.002);
}

TEST(LinuxCncIni, TheMillInInches) {
    const Machine m = machine_from_linuxcnc_ini(data("mill_inch.ini"));
    expect_linuxcnc_machine(m);
    EXPECT_EQ(m.max_accel_mm_s2, 635.0);     // 25 in/s^2, Z
    EXPECT_EQ(m.rapid_feed_mm_min, 3810.0);  // 2.5 in/s, Z, under [TRAJ]'s 3
    EXPECT_EQ(m.scan_period_s, 0.0005);
    EXPECT_EQ(m.controller_latency_s, 0.001);
}

// The machine section as `machine linuxcnc` prints it reads back as the same machine.
TEST(LinuxCncIni, ItsMachineSectionIsAScenarioFile) {
    Scenario s;
    s.machine = machine_from_linuxcnc_ini(data("mill_inch.ini"));
    const std::string json = scenario_section_to_json(s, "machine");
    EXPECT_EQ(json.find("\"probe\""), std::string::npos);
    for (const std::string& key : section_key_names("machine")) {
        EXPECT_NE(json.find('"' + key + '"'), std::string::npos) << key;
    }
    EXPECT_EQ(scenario_to_json(scenario_from_json(json)), scenario_to_json(s));
}

// The window's LinuxCNC preset is the sample mill's machine, but for the rapid
// feed (a machine's own, which no preset sets).
TEST(LinuxCncIni, ThePresetIsTheSampleMill) {
    const std::filesystem::path preset =
        std::filesystem::path(PROBECYCLE_RESOURCES_DIR) / "presets" / "machine_linuxcnc.json";
    const Scenario from_preset = merge_json(Scenario{}, parse_preset(slurp(preset)).scenario_json);
    Scenario from_ini;
    from_ini.machine = machine_from_linuxcnc_ini(data("mill_mm.ini"));
    from_ini.machine.rapid_feed_mm_min = Scenario{}.machine.rapid_feed_mm_min;
    EXPECT_EQ(scenario_to_json(from_preset), scenario_to_json(from_ini));
}

struct Units {
    const char* linear_units;
    double mm_per_unit;
};

class LinuxCncIniUnits : public testing::TestWithParam<Units> {};

TEST_P(LinuxCncIniUnits, ScaleTheAxesLimits) {
    const Units& u = GetParam();
    const Machine m =
        machine_from_linuxcnc_ini(edit({{5, std::string("LINEAR_UNITS = ") + u.linear_units}}));
    EXPECT_NEAR(m.max_accel_mm_s2, 1000.0 * u.mm_per_unit, 1e-9) << u.linear_units;
    EXPECT_NEAR(m.rapid_feed_mm_min, 6000.0 * u.mm_per_unit, 1e-9) << u.linear_units;
}

// What LinuxCNC's emcIniFile.cc accepts, in any case, and a number of units per mm.
// clang-format off
INSTANTIATE_TEST_SUITE_P(LinuxCncIni, LinuxCncIniUnits, testing::Values(
    Units{"mm",              1.0},
    Units{"MM",              1.0},
    Units{"metric",          1.0},
    Units{"in",              25.4},
    Units{"inch",            25.4},
    Units{"Imperial",        25.4},
    Units{"1",               1.0},
    Units{"0.03937007874",   25.4},
    Units{"0.5",             2.0}));
// clang-format on

struct Reading {
    const char* what;
    std::string text;
    double max_accel_mm_s2;
    double rapid_feed_mm_min;
};

class LinuxCncIniReading : public testing::TestWithParam<Reading> {};

TEST_P(LinuxCncIniReading, AsLinuxCncReadsTheFile) {
    const Reading& r = GetParam();
    const Machine m = machine_from_linuxcnc_ini(r.text);
    EXPECT_EQ(m.max_accel_mm_s2, r.max_accel_mm_s2) << r.what;
    EXPECT_EQ(m.rapid_feed_mm_min, r.rapid_feed_mm_min) << r.what;
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(LinuxCncIni, LinuxCncIniReading, testing::Values(
    Reading{"the base",                    kBase,                                                                                           1000, 6000},
    Reading{"without [TRAJ]'s cap",        edit({{6, ""}}),                                                     1000, 7200},
    Reading{"[TRAJ] MAX_VELOCITY, older",  edit({{6, "MAX_VELOCITY = 90"}}),                                    1000, 5400},
    Reading{"MAX_LINEAR_VELOCITY first",   edit({{6, "MAX_VELOCITY = 90\nMAX_LINEAR_VELOCITY = 100"}}),         1000, 6000},
    Reading{"the first line of a key",     edit({{18, "MAX_ACCELERATION = 1000\nMAX_ACCELERATION = 10"}}),         1000, 6000},
    Reading{"the first block of a section", std::string(kBase) + "[AXIS_Z]\nMAX_ACCELERATION = 10\n[AXIS_X]\nMAX_VELOCITY = 1\n",          1000, 6000},
    Reading{"comments and blanks",         edit({{18, "  # MAX_ACCELERATION = 10\n\t; MAX_ACCELERATION = 20\nMAX_ACCELERATION\t=\t900  "}}), 900, 6000},
    Reading{"no space around =",           edit({{18, "MAX_ACCELERATION=800"}}),                                   800,  6000},
    Reading{"a longer name is another key", edit({{18, "MAX_ACCELERATION_Z = 10\nMAX_ACCELERATION = 700"}}),       700,  6000},
    Reading{"a name alone is no line of it", edit({{18, "MAX_ACCELERATION\nMAX_ACCELERATION = 600"}}),             600,  6000},
    Reading{"a line continued",            edit({{18, "MAX_ACCELERATION = 5\\\n50"}}),                             550,  6000},
    Reading{"CRLF line ends",              "[EMCMOT]\r\nSERVO_PERIOD = 1000000\r\n[TRAJ]\r\nLINEAR_UNITS = mm\r\n[AXIS_X]\r\nMAX_VELOCITY = 50\r\nMAX_ACCELERATION = 500\r\n[AXIS_Y]\r\nMAX_VELOCITY = 50\r\nMAX_ACCELERATION = 500\r\n[AXIS_Z]\r\nMAX_VELOCITY = 50\r\nMAX_ACCELERATION = 500\r\n", 500, 3000},
    Reading{"keys before any section",     "MAX_ACCELERATION = 1\n" + std::string(kBase),                                                  1000, 6000},
    Reading{"joints do not act",           std::string(kBase) + "[JOINT_2]\nMAX_VELOCITY = 1\nMAX_ACCELERATION = 1\n",                      1000, 6000},
    Reading{"a comment after the section", edit({{16, "[AXIS_Z] # the spindle's axis"}}),                                        1000, 6000}));
// clang-format on

TEST(LinuxCncIni, TheServoPeriodGivesTheScanAndTwoPeriodsOfLatency) {
    const Machine m = machine_from_linuxcnc_ini(edit({{2, "SERVO_PERIOD = 250000"}}));
    EXPECT_EQ(m.scan_period_s, 0.00025);
    EXPECT_EQ(m.controller_latency_s, 0.0005);
}

// Two servo periods and 1.6 task cycles a block (measured on LinuxCNC 2.9);
// without [TASK] CYCLE_TIME, LinuxCNC's default 0.1 s.
TEST(LinuxCncIni, TheBlockChangeFromTheServoPeriodAndTheTaskCycle) {
    EXPECT_DOUBLE_EQ(machine_from_linuxcnc_ini(data("mill_mm.ini")).block_change_s,
                     2 * 0.001 + 1.6 * 0.001);
    EXPECT_DOUBLE_EQ(machine_from_linuxcnc_ini(std::string("[TASK]\nCYCLE_TIME = 0.010\n") + kBase)
                         .block_change_s,
                     2 * 0.001 + 1.6 * 0.010);
    EXPECT_DOUBLE_EQ(machine_from_linuxcnc_ini(kBase).block_change_s, 2 * 0.001 + 1.6 * 0.1);
    EXPECT_DOUBLE_EQ(
        machine_from_linuxcnc_ini(std::string("[TASK]\nTASK = milltask\n") + kBase).block_change_s,
        2 * 0.001 + 1.6 * 0.1);
    EXPECT_EQ(refusal(std::string("[TASK]\nCYCLE_TIME = 1 ms\n") + kBase),
              "[TASK] CYCLE_TIME, line 2: got 1 ms; allowed: a number from 0.0001 to 0.5 s (for "
              "machine.block_change_s)");
    EXPECT_EQ(refusal(std::string("[TASK]\nCYCLE_TIME = 0\n") + kBase),
              "[TASK] CYCLE_TIME, line 2: got 0; allowed: a number from 0.0001 to 0.5 s (for "
              "machine.block_change_s)");
}

struct Refusal {
    const char* what;
    std::string text;
    std::string says;  // the whole English refusal, one problem a line
};

class LinuxCncIniRefusal : public testing::TestWithParam<Refusal> {};

TEST_P(LinuxCncIniRefusal, NamesTheSectionKeyLineAndWhatIsAllowed) {
    const Refusal& r = GetParam();
    EXPECT_EQ(refusal(r.text), r.says) << r.what;
}

const std::string kAccelMm =
    "allowed: a number from 1 to 200000 mm/s^2 (for machine.max_accel_mm_s2)";
const std::string kSpeedMm =
    "allowed: a number from 1.66667 to 3333.33 mm/s (for machine.rapid_feed_mm_min)";
const std::string kPeriod =
    "a whole number from 1 to 100000000 ns (for machine.scan_period_s, "
    "machine.controller_latency_s)";
const std::string kUnits =
    "one of mm, metric, in, inch, imperial, or a number of units per mm from 0.001 to 1000 (for "
    "machine.max_accel_mm_s2, machine.rapid_feed_mm_min)";

// clang-format off
INSTANTIATE_TEST_SUITE_P(LinuxCncIni, LinuxCncIniRefusal, testing::Values(
    Refusal{"an empty file", "",
            "[EMCMOT]: missing section; expected SERVO_PERIOD (for machine.scan_period_s, machine.controller_latency_s)\n"
            "[TRAJ]: missing section; expected LINEAR_UNITS (for machine.max_accel_mm_s2, machine.rapid_feed_mm_min)\n"
            "[AXIS_X]: missing section; expected MAX_VELOCITY, MAX_ACCELERATION (for machine.max_accel_mm_s2, machine.rapid_feed_mm_min)\n"
            "[AXIS_Y]: missing section; expected MAX_VELOCITY, MAX_ACCELERATION (for machine.max_accel_mm_s2, machine.rapid_feed_mm_min)\n"
            "[AXIS_Z]: missing section; expected MAX_VELOCITY, MAX_ACCELERATION (for machine.max_accel_mm_s2, machine.rapid_feed_mm_min)"},
    Refusal{"no [AXIS_Y]", edit({{12, "[AXIS_B]"}}),
            "[AXIS_Y]: missing section; expected MAX_VELOCITY, MAX_ACCELERATION (for machine.max_accel_mm_s2, machine.rapid_feed_mm_min)"},
    Refusal{"a section's name is case-sensitive", edit({{12, "[axis_y]"}}),
            "[AXIS_Y]: missing section; expected MAX_VELOCITY, MAX_ACCELERATION (for machine.max_accel_mm_s2, machine.rapid_feed_mm_min)"},
    Refusal{"no servo period", edit({{2, "BASE_PERIOD = 50000"}}),
            "[EMCMOT] SERVO_PERIOD: missing; expected " + kPeriod},
    Refusal{"an empty servo period", edit({{2, "SERVO_PERIOD ="}}),
            "[EMCMOT] SERVO_PERIOD, line 2: no value; expected " + kPeriod},
    Refusal{"a servo period in ms", edit({{2, "SERVO_PERIOD = 1 ms"}}),
            "[EMCMOT] SERVO_PERIOD, line 2: got 1 ms; allowed: " + kPeriod},
    Refusal{"a fraction of a ns", edit({{2, "SERVO_PERIOD = 1000000.5"}}),
            "[EMCMOT] SERVO_PERIOD, line 2: got 1000000.5; allowed: " + kPeriod},
    Refusal{"a servo period of 0", edit({{2, "SERVO_PERIOD = 0"}}),
            "[EMCMOT] SERVO_PERIOD, line 2: got 0; allowed: " + kPeriod},
    Refusal{"a servo period over 0.1 s", edit({{2, "SERVO_PERIOD = 100000001"}}),
            "[EMCMOT] SERVO_PERIOD, line 2: got 100000001; allowed: " + kPeriod},
    Refusal{"no LINEAR_UNITS", edit({{5, ""}}),
            "[TRAJ] LINEAR_UNITS: missing; expected " + kUnits},
    Refusal{"centimetres", edit({{5, "LINEAR_UNITS = cm"}}),
            "[TRAJ] LINEAR_UNITS, line 5: got cm; allowed: " + kUnits},
    Refusal{"no units per mm", edit({{5, "LINEAR_UNITS = 0"}}),
            "[TRAJ] LINEAR_UNITS, line 5: got 0; allowed: " + kUnits},
    Refusal{"a unit smaller than a micrometre", edit({{5, "LINEAR_UNITS = 4.9e-324"}}),
            "[TRAJ] LINEAR_UNITS, line 5: got 4.9e-324; allowed: " + kUnits},
    Refusal{"a unit larger than a metre", edit({{5, "LINEAR_UNITS = 1e308"}}),
            "[TRAJ] LINEAR_UNITS, line 5: got 1e308; allowed: " + kUnits},
    Refusal{"units unknown: any number", edit({{5, "LINEAR_UNITS = furlong\nMAX_LINEAR_VELOCITY = fast"}}),
            "[TRAJ] LINEAR_UNITS, line 5: got furlong; allowed: " + kUnits + "\n"
            "[TRAJ] MAX_LINEAR_VELOCITY, line 6: got fast; allowed: a decimal number (for machine.rapid_feed_mm_min)"},
    Refusal{"no acceleration of Z", edit({{18, ""}}),
            "[AXIS_Z] MAX_ACCELERATION: missing; expected a number from 1 to 200000 mm/s^2 (for machine.max_accel_mm_s2)"},
    Refusal{"only a later block has it", edit({{18, ""}}) + "[AXIS_Z]\nMAX_ACCELERATION = 1000\n",
            "[AXIS_Z] MAX_ACCELERATION: missing; expected a number from 1 to 200000 mm/s^2 (for machine.max_accel_mm_s2)"},
    Refusal{"a decimal comma", edit({{18, "MAX_ACCELERATION = 1000,5"}}),
            "[AXIS_Z] MAX_ACCELERATION, line 18: got 1000,5; " + kAccelMm},
    Refusal{"a comment after a value", edit({{18, "MAX_ACCELERATION = 1000 ; Z is slower"}}),
            "[AXIS_Z] MAX_ACCELERATION, line 18: got 1000 ; Z is slower; " + kAccelMm},
    Refusal{"the first line of a key wins", edit({{18, "MAX_ACCELERATION = x\nMAX_ACCELERATION = 1000"}}),
            "[AXIS_Z] MAX_ACCELERATION, line 18: got x; " + kAccelMm},
    Refusal{"an acceleration under the range", edit({{18, "MAX_ACCELERATION = 0.5"}}),
            "[AXIS_Z] MAX_ACCELERATION, line 18: got 0.5; " + kAccelMm},
    Refusal{"the smallest double as an acceleration (a fuzz finding)", edit({{18, "MAX_ACCELERATION = 4.9e-324"}}),
            "[AXIS_Z] MAX_ACCELERATION, line 18: got 4.9e-324; " + kAccelMm},
    Refusal{"the smallest double as a speed", edit({{17, "MAX_VELOCITY = 4.9e-324"}}),
            "[AXIS_Z] MAX_VELOCITY, line 17: got 4.9e-324; " + kSpeedMm},
    Refusal{"a negative acceleration", edit({{10, "MAX_ACCELERATION = -1200"}}),
            "[AXIS_X] MAX_ACCELERATION, line 10: got -1200; " + kAccelMm},
    Refusal{"an acceleration under the range in inches",
            edit({{5, "LINEAR_UNITS = inch"}, {18, "MAX_ACCELERATION = 0.03"}}),
            "[AXIS_Z] MAX_ACCELERATION, line 18: got 0.03; allowed: a number from 0.0393701 to 7874.01 in/s^2 (for machine.max_accel_mm_s2)"},
    Refusal{"an axis too slow", edit({{17, "MAX_VELOCITY = 1"}}),
            "[AXIS_Z] MAX_VELOCITY, line 17: got 1; " + kSpeedMm},
    Refusal{"[TRAJ] too slow", edit({{6, "MAX_LINEAR_VELOCITY = 1.5"}}),
            "[TRAJ] MAX_LINEAR_VELOCITY, line 6: got 1.5; " + kSpeedMm},
    Refusal{"every speed too fast", edit({{6, "MAX_LINEAR_VELOCITY = 4000"}, {9, "MAX_VELOCITY = 5000"}, {13, "MAX_VELOCITY = 5000"},
                                          {17, "MAX_VELOCITY = 3500"}}),
            "[AXIS_Z] MAX_VELOCITY, line 17: got 3500; " + kSpeedMm},
    Refusal{"every problem at once", edit({{2, "BASE_PERIOD = 50000"}, {9, "MAX_VELOCITY = abc"}}),
            "[EMCMOT] SERVO_PERIOD: missing; expected " + kPeriod + "\n"
            "[AXIS_X] MAX_VELOCITY, line 9: got abc; " + kSpeedMm},
    Refusal{"#INCLUDE", "#INCLUDE axes.inc\n" + std::string(kBase) + "  #INCLUDE ~/more.inc\n",
            "line 1: #INCLUDE is not followed; LinuxCNC writes the configuration with its includes to NAME.ini.expanded beside the INI file when it starts: read that file\n"
            "line 20: #INCLUDE is not followed; LinuxCNC writes the configuration with its includes to NAME.ini.expanded beside the INI file when it starts: read that file"},
    Refusal{"a long value is cut", edit({{18, "MAX_ACCELERATION = " + std::string(100, '9') + "x"}}),
            "[AXIS_Z] MAX_ACCELERATION, line 18: got " + std::string(40, '9') + "...; " + kAccelMm}));
// clang-format on

TEST(LinuxCncIni, ACommentThatNamesInclude) {
    // "#INCLUDES" is a comment to LinuxCNC: only the word #INCLUDE includes.
    EXPECT_EQ(refusal("#INCLUDES are expanded by the start script\n" + std::string(kBase)), "");
}

// The window translates every problem: a template with its context, and
// the position's parts as arguments.
TEST(LinuxCncIni, EveryProblemIsATranslatableMessage) {
    try {
        machine_from_linuxcnc_ini(edit({{18, "MAX_ACCELERATION = 0.5"}}));
        FAIL() << "accepted";
    } catch (const LinuxCncIniError& e) {
        ASSERT_EQ(e.problems().size(), 1u);
        const IniProblem& p = e.problems().front();
        EXPECT_EQ(p.section, "AXIS_Z");
        EXPECT_EQ(p.key, "MAX_ACCELERATION");
        EXPECT_EQ(p.line, 18u);
        test::expect_translatable(
            p.to_message(), {"section", "key", "line", "value", "min", "max", "unit", "gives"});
        EXPECT_EQ(std::string(p.to_message().context), "LinuxCncIni");
    }
    for (const std::string& text : {std::string(), std::string("#INCLUDE x\n"), edit({{5, ""}})}) {
        try {
            machine_from_linuxcnc_ini(text);
            ADD_FAILURE() << "accepted";
        } catch (const LinuxCncIniError& e) {
            for (const IniProblem& p : e.problems()) {
                const Message m = p.to_message();
                EXPECT_FALSE(m.code.empty());
                EXPECT_EQ(std::string(m.context), "LinuxCncIni");
                EXPECT_EQ(m.args.back().kind, ArgKind::message);
            }
        }
    }
}

}  // namespace
}  // namespace probecycle
