// Reading back what the control recorded: LinuxCNC's LOG and PROBEOPEN files
// and a grbl sender's console, written here in each format, good and broken;
// and the round trip: plan, program, a machine simulated by the cycle model
// running the program's lines, the import, the fit: the known delay returns.

#include "core/program/machine_log.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <tuple>

#include "core/common/csv_reader.h"
#include "core/common/input_error.h"
#include "core/cycle/cycle.h"
#include "core/lab/calibration.h"
#include "core/lab/delay_fit.h"
#include "core/program/program_writer.h"
#include "tests/core/program/program_test_plans.h"

namespace probecycle {
namespace {

using program_test::grbl_console;
using program_test::prb;
using program_test::small_delay_plan;

int line_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const CsvError& e) {
        return static_cast<int>(e.line());
    }
    ADD_FAILURE() << "no CsvError";
    return -1;
}

TEST(MachineLog, GrblConsoleGivesTheDelayCsvOfTheRecordedTouches) {
    const ProbingPlan plan = small_delay_plan();
    const std::string csv = import_machine_log(plan, DialectId::grbl, grbl_console());
    const std::vector<DelayTouch> touches = parse_delay_csv(csv);
    ASSERT_EQ(touches.size(), 4u);
    EXPECT_EQ(touches[0].axis, "Z");
    EXPECT_EQ(touches[0].direction, -1);
    EXPECT_EQ(touches[0].feed_mm_min, 100.0);
    EXPECT_DOUBLE_EQ(touches[0].measured_mm, -20.017);
    EXPECT_EQ(touches[3].feed_mm_min, 1000.0);
    EXPECT_DOUBLE_EQ(touches[3].measured_mm, -20.151);
}

TEST(MachineLog, GrblBrokenLogsNameTheLine) {
    const ProbingPlan plan = small_delay_plan();
    const std::string good = grbl_console();
    // A touch that did not trigger: ":0" (line 17), and the alarm grbl raises then (18).
    const std::string no_trigger = good.substr(0, good.find("[PRB:0.000,0.000,-20.018:1]")) +
                                   "[PRB:0.000,0.000,-20.018:0]\nALARM:5\n";
    EXPECT_EQ(line_of([&] { import_machine_log(plan, DialectId::grbl, no_trigger); }), 18);
    EXPECT_EQ(line_of([&] { import_machine_log(plan, DialectId::grbl, "ok\nALARM:5\n"); }), 2);
    // A missing touch: the log ends early (its last position named).
    const std::string missing = good.substr(0, good.rfind("[PRB:"));
    EXPECT_EQ(line_of([&] { import_machine_log(plan, DialectId::grbl, missing); }), 19);
    // An extra touch: a "$#" printout after the run repeats the last probe.
    EXPECT_EQ(
        line_of([&] { import_machine_log(plan, DialectId::grbl, good + prb(0, 0, -20.151)); }), 23);
    // Another plan: Y moved between two touches this plan makes along Z alone.
    std::string other = good;
    other.replace(other.find("[PRB:0.000,0.000,-20.150:1]"), 27, "[PRB:0.000,5.000,-20.150:1]");
    EXPECT_EQ(line_of([&] { import_machine_log(plan, DialectId::grbl, other); }), 19);
    // An unreadable report.
    EXPECT_EQ(line_of([&] { import_machine_log(plan, DialectId::grbl, "[PRB:1,2:1]\n"); }), 1);
}

TEST(MachineLog, AGrblConsoleOfAnotherPlanIsToldByItsSignature) {
    // Before the signature, a console from another plan with the same count and
    // axis imported silently, every touch under the wrong feed.
    const ProbingPlan plan = small_delay_plan();
    ProbingPlan other = plan;
    other.values.push_back({"probe_feeds", "another"});  // another plan, another id
    ASSERT_NE(plan_id(other), plan_id(plan));
    ASSERT_NE(plan_signature(other).codes, plan_signature(plan).codes);
    std::string console = grbl_console();
    const std::string own = program_test::grbl_signature(plan);
    console.replace(console.find(own), own.size(), program_test::grbl_signature(other, {5, 7, -3}));
    const auto says = [&](const std::string& text) {
        try {
            (void)import_machine_log(plan, DialectId::grbl, text);
        } catch (const CsvError& e) {
            return std::string(e.what());
        }
        return std::string("imported");
    };
    EXPECT_NE(says(console).find("line 10: the console is from another plan"), std::string::npos)
        << says(console);
    // The signature is read from differences: any start gives the plan.
    std::string moved = grbl_console();
    moved.replace(moved.find(own), own.size(), program_test::grbl_signature(plan, {5, 7, -3}));
    EXPECT_EQ(says(moved), "imported");
    // A console without one (an older ProbeCycle's program) is refused too.
    std::string unsigned_console = grbl_console();
    unsigned_console.erase(unsigned_console.find(own), own.size());
    EXPECT_NE(says(unsigned_console).find("does not open with the plan's signature"),
              std::string::npos)
        << says(unsigned_console);
    // The probe touched something during them: named as such.
    std::string touched = grbl_console();
    const std::size_t first = touched.find(":0]");
    touched.replace(first, 3, ":1]");
    EXPECT_NE(says(touched).find("line 3: the console does not open with the plan's signature"),
              std::string::npos)
        << says(touched);
}

using program_test::linuxcnc_log;

// The DPRNT output of the small plan's program: 4 touches, lines ending in
// `ending`, numbers as DPRNT pads them.
std::string fanuc_log(const ProbingPlan& plan, const std::string& ending) {
    std::string log = "PROBECYCLE PLAN " + id_letters(plan_id(plan)) + " DELAY" + ending;
    const double zs[] = {-20.0171, -20.0172, -20.1501, -20.1502};
    for (int i = 0; i < 4; ++i) {
        log += "TOUCH   " + std::to_string(i + 1) + " X   1.0000 Y   2.0000 Z" +
               (i % 2 == 0 ? " -20." : "-  20.") + std::to_string(zs[i]).substr(4, 4) + ending;
    }
    return log + "PROBECYCLE END" + ending;
}

TEST(MachineLog, FanucDprntOutputInEveryLineEnding) {
    const ProbingPlan plan = small_delay_plan();
    const std::string expected = import_machine_log(
        plan, DialectId::linuxcnc, linuxcnc_log(plan, {-20.0171, -20.0172, -20.1501, -20.1502}));
    for (const std::string ending : {"\n", "\r", "\r\n", "\n\r\r"}) {
        EXPECT_EQ(import_machine_log(plan, DialectId::fanuc, fanuc_log(plan, ending)), expected)
            << ending.size();
    }
    // A Haas serial port's DC2 ... DC4, a '%' leader, leading spaces, a plus
    // sign, blank lines and another program's output on the same channel.
    std::string framed = "%\n\x12  " + fanuc_log(plan, "\n\r\r") + "\x14\n%\n";
    framed.insert(framed.find("TOUCH   2"), "\n\nSPINDLE WARM UP DONE\n   ");
    framed.replace(framed.find("X   1.0000", framed.find("TOUCH   3")), 10, "X  +1.0000");
    EXPECT_EQ(import_machine_log(plan, DialectId::fanuc, framed), expected);
}

TEST(MachineLog, FanucBrokenLogsNameTheLine) {
    const ProbingPlan plan = small_delay_plan();
    const std::string good = fanuc_log(plan, "\n");
    const auto import = [&plan](const std::string& log) {
        import_machine_log(plan, DialectId::fanuc, log);
    };
    // A missing touch (the log ends after touch 3, line 4).
    std::string missing = good.substr(0, good.find("TOUCH   4"));
    EXPECT_EQ(line_of([&] { import(missing); }), 4);
    // An extra touch: a fifth, or a second run (touch 1 where 5 was due).
    EXPECT_EQ(line_of([&] { import(good + "TOUCH   5 X 1.0 Y 2.0 Z -20.0\n"); }), 7);
    EXPECT_EQ(line_of([&] { import(good + good); }), 8);
    // Another plan's id (line 1), and the same in CR endings.
    std::string other = good;
    other.replace(16, 16, "AAAAAAAAAAAAAAAA");
    EXPECT_EQ(line_of([&] { import(other); }), 1);
    try {
        import(other);
    } catch (const CsvError& e) {
        EXPECT_NE(std::string(e.what()).find("plan 0000000000000000"), std::string::npos)
            << e.what();
    }
    // The alarm branch's marker (a probe did not trigger) on line 3.
    std::string no_trigger = good.substr(0, good.find("TOUCH   2")) + "PROBECYCLE NO TRIGGER\r";
    EXPECT_EQ(line_of([&] { import(no_trigger); }), 3);
    // A garbled touch, a touch before the plan line, no plan line at all.
    EXPECT_EQ(
        line_of([&] {
            import("PROBECYCLE PLAN " + id_letters(plan_id(plan)) + " DELAY\nTOUCH   1 X 1.0 Y\n");
        }),
        2);
    EXPECT_EQ(line_of([&] { import("\nTOUCH   1 X 1.0 Y 2.0 Z -20.0\n"); }), 2);
    EXPECT_EQ(line_of([&] { import("HELLO\n"); }), 0);
    // Y moved between two touches along Z: another plan's log.
    std::string moved = good;
    moved.replace(moved.find("Y   2.0000", moved.find("TOUCH   3")), 10, "Y   7.0000");
    EXPECT_EQ(line_of([&] { import(moved); }), 4);
}

TEST(MachineLog, LinuxCncLogAndProbeFileGiveTheSameTable) {
    const ProbingPlan plan = small_delay_plan();
    const std::vector<double> zs = {-20.0171, -20.0172, -20.1501, -20.1502};
    const std::string from_log =
        import_machine_log(plan, DialectId::linuxcnc, linuxcnc_log(plan, zs));
    std::string probe_file = "1.000000 2.000000 -20.000000 0 0 0 0 0 0\n";
    for (double z : zs) {
        char line[160];
        std::snprintf(line, sizeof line, "%f %f %f %f %f %f %f %f %f\n", 1.0, 2.0, z, 0.0, 0.0, 0.0,
                      0.0, 0.0, 0.0);
        probe_file += line;
    }
    EXPECT_EQ(import_machine_log(plan, DialectId::linuxcnc, probe_file), from_log);
    EXPECT_EQ(parse_delay_csv(from_log).size(), 4u);
}

TEST(MachineLog, ALogOfAnotherDialectIsNamedAtItsFirstLine) {
    // Before: "the log ends after 0 of the plan's 5 probe positions" or
    // "cannot read '[PRB:...'; expected 9 numbers".
    const ProbingPlan plan = small_delay_plan();
    const std::vector<double> zs = {-20.0171, -20.0172, -20.1501, -20.1502};
    const std::string lcnc = linuxcnc_log(plan, zs);
    const std::string grbl = grbl_console();
    const std::string fanuc = fanuc_log(plan, "\n");
    const auto says = [&](DialectId chosen, const std::string& text) {
        try {
            (void)import_machine_log(plan, chosen, text);
        } catch (const CsvError& e) {
            return std::string(e.what());
        }
        return std::string("imported");
    };
    EXPECT_EQ(says(DialectId::grbl, lcnc),
              "line 1: this line is from a linuxcnc log, and no line is from a grbl log: import "
              "it as linuxcnc (--dialect linuxcnc); nothing imported");
    EXPECT_EQ(says(DialectId::fanuc, lcnc).substr(0, 45),
              "line 1: this line is from a linuxcnc log, and");
    EXPECT_NE(
        says(DialectId::linuxcnc, grbl).find("from a grbl log, and no line is from a linuxcnc"),
        std::string::npos);
    EXPECT_NE(says(DialectId::grbl, fanuc).find("from a fanuc log"), std::string::npos);
    // Each in its own dialect is read.
    EXPECT_EQ(says(DialectId::linuxcnc, lcnc), "imported");
    EXPECT_EQ(says(DialectId::grbl, grbl), "imported");
    EXPECT_EQ(says(DialectId::fanuc, fanuc), "imported");
}

TEST(MachineLog, LinuxCncBrokenLogsNameTheLine) {
    const ProbingPlan plan = small_delay_plan();
    const std::vector<double> zs = {-20.0171, -20.0172, -20.1501, -20.1502};
    const std::string good = linuxcnc_log(plan, zs);
    // Another plan's id (line 1).
    std::string other = good;
    other.replace(16, 16, "0123456789abcdef");
    EXPECT_EQ(line_of([&] { import_machine_log(plan, DialectId::linuxcnc, other); }), 1);
    // A missing touch (the program stopped: G38.2 without a trip halts it).
    EXPECT_EQ(line_of([&] {
                  import_machine_log(plan, DialectId::linuxcnc,
                                     linuxcnc_log(plan, {-20.0171, -20.0172, -20.1501}));
              }),
              4);
    // An extra touch: two runs in one log restart the numbering.
    EXPECT_EQ(line_of([&] {
                  import_machine_log(plan, DialectId::linuxcnc,
                                     good + "probecycle touch 1 1 2 -20.0\n");
              }),
              6);
    // A PROBEOPEN file that lost a touch tripping at the previous one's place.
    EXPECT_EQ(line_of([&] {
                  import_machine_log(plan, DialectId::linuxcnc,
                                     "1 2 -20 0 0 0 0 0 0\n1 2 -20.017 0 0 0 0 0 0\n");
              }),
              2);
    EXPECT_EQ(line_of([&] { import_machine_log(plan, DialectId::linuxcnc, "1 2 three\n"); }), 1);
}

// fuzz_machine_log: a line holding only "probecycle" read the second word of a
// one-word line (past the end of its words).
TEST(MachineLog, LinuxCncLogLineOfOneWordIsUnreadable) {
    const ProbingPlan plan = small_delay_plan();
    const std::string first = "probecycle plan " + plan_id(plan) + " delay\n";
    EXPECT_EQ(line_of([&] { import_machine_log(plan, DialectId::linuxcnc, "probecycle"); }), 1);
    EXPECT_EQ(
        line_of([&] { import_machine_log(plan, DialectId::linuxcnc, first + "  probecycle  \n"); }),
        2);
    EXPECT_EQ(line_of([&] {
                  import_machine_log(plan, DialectId::linuxcnc, first + "probecycle touch\n");
              }),
              2);
}

// fuzz_machine_log: blank lines before the LOG file made the import take it
// for the PROBEOPEN file (one position per probe) and refuse it as short.
TEST(MachineLog, LinuxCncLogAfterBlankLinesGivesTheSameTable) {
    const ProbingPlan plan = small_delay_plan();
    const std::string log = linuxcnc_log(plan, {-20.0171, -20.0172, -20.1501, -20.1502});
    const std::string csv = import_machine_log(plan, DialectId::linuxcnc, log);
    EXPECT_EQ(import_machine_log(plan, DialectId::linuxcnc, "\n" + log), csv);
    EXPECT_EQ(import_machine_log(plan, DialectId::linuxcnc, "\r\n \t\r\n  " + log), csv);
    EXPECT_EQ(parse_delay_csv(csv).size(), 4u);
}

TEST(MachineLog, RingLogGivesTheRingCsvAndACyclePlanHasNoTable) {
    const ProbingPlan ring = make_ring_plan(Scenario{}, RingPlanOptions{});
    const double r = program_test::kRingLogRadius_mm;
    const std::string log = program_test::linuxcnc_ring_log(ring);
    const std::string csv = import_machine_log(ring, DialectId::linuxcnc, log);
    const std::vector<RingPoint> parsed = parse_ring_csv(csv);
    ASSERT_EQ(parsed.size(), 8u);
    EXPECT_EQ(parsed[4].orientation_deg, 180.0);
    RingCalibrationOptions options;
    const RingCalibration calibration = calibrate_ring(parsed, options);
    EXPECT_NEAR(*calibration.runout_x_mm, -0.002, 1e-9);
    EXPECT_NEAR(calibration.effective_radius_mm, 25.0 - r, 1e-9);

    const ProbingPlan cycle = make_cycle_plan(Scenario{}, CyclePlanOptions{});
    EXPECT_THROW(import_machine_log(cycle, DialectId::grbl, prb(0, 0, -5)), InputError);
}

// A plan with protected moves (a cycle plan: no lab table, but its recorded
// touches are matched as the import matches any plan's). grbl reports every
// G38.3: ":0" where it touched nothing; a ":1" there is an obstruction, which
// grbl itself cannot stop on. LinuxCNC's PROBEOPEN file holds a G38.3's end
// too; its LOG and the Fanuc-type DPRNT output the recorded touches alone.
TEST(MachineLog, ProtectedMovesAreMatchedAndATouchOnOneIsRefused) {
    const ProbingPlan plan = program_test::guarded_plan();
    // Out to X20 (line 1), the touch at X25.03 (2), back to the start and
    // the centre (4), down to Z-10 (5).
    // After the signature (lines 1 to 10).
    const std::string console = program_test::grbl_signature(plan) + prb(20, 0, 0, 0) +
                                prb(25.03, 0, 0) + "ok\n" + prb(0, 0, 0, 0) + prb(0, 0, -10, 0);
    const std::vector<RecordedPosition> touches =
        recorded_touch_positions(plan, DialectId::grbl, console);
    ASSERT_EQ(touches.size(), 1u);
    EXPECT_EQ(touches[0].line, 12u);
    EXPECT_DOUBLE_EQ(touches[0].xyz[0], 25.03);
    // The cycle has no table in the lab.
    EXPECT_THROW(import_machine_log(plan, DialectId::grbl, console), InputError);

    // A protected move that touched (line 14), and a probe that did not (line 12).
    std::string obstructed = console;
    obstructed.replace(obstructed.rfind(prb(0, 0, 0, 0)), prb(0, 0, 0, 0).size(), prb(3, 0, 0));
    EXPECT_EQ(line_of([&] { recorded_touch_positions(plan, DialectId::grbl, obstructed); }), 14);
    try {
        recorded_touch_positions(plan, DialectId::grbl, obstructed);
    } catch (const CsvError& e) {
        EXPECT_NE(std::string(e.what()).find("during a protected move ([PRB:3.000,0.000,0.000:1])"),
                  std::string::npos)
            << e.what();
    }
    std::string no_trigger = console;
    no_trigger.replace(no_trigger.find(prb(25.03, 0, 0)), prb(25.03, 0, 0).size(),
                       prb(26, 0, 0, 0));
    EXPECT_EQ(line_of([&] { recorded_touch_positions(plan, DialectId::grbl, no_trigger); }), 12);
    // A console of the touch alone: its report stands where the first
    // protected move's is due, and reads as a touch there.
    EXPECT_EQ(line_of([&] { recorded_touch_positions(plan, DialectId::grbl, prb(25.03, 0, 0)); }),
              1);

    // LinuxCNC: the LOG file, and the PROBEOPEN file with every G38.3's end.
    const std::string id = plan_id(plan);
    const std::vector<RecordedPosition> logged = recorded_touch_positions(
        plan, DialectId::linuxcnc,
        "probecycle plan " + id + " cycle\nprobecycle touch 1 25.030000 0.000000 0.000000\n");
    ASSERT_EQ(logged.size(), 1u);
    EXPECT_EQ(logged[0].line, 2u);
    EXPECT_DOUBLE_EQ(logged[0].xyz[0], 25.03);
    const std::string probe_file =
        "20.000000 0.000000 0.000000 0 0 0 0 0 0\n25.030000 0.000000 0.000000 0 0 0 0 0 0\n"
        "0.000000 0.000000 0.000000 0 0 0 0 0 0\n0.000000 0.000000 -10.000000 0 0 0 0 0 0\n";
    const std::vector<RecordedPosition> probed =
        recorded_touch_positions(plan, DialectId::linuxcnc, probe_file);
    ASSERT_EQ(probed.size(), 1u);
    EXPECT_EQ(probed[0].line, 2u);
    EXPECT_DOUBLE_EQ(probed[0].xyz[0], 25.03);

    // Fanuc-type: the touch, and the obstruction's marker (line 2).
    const std::string letters = id_letters(id);
    const std::vector<RecordedPosition> printed = recorded_touch_positions(
        plan, DialectId::fanuc,
        "PROBECYCLE PLAN " + letters +
            " CYCLE\nTOUCH   1 X  25.0300 Y   0.0000 Z   0.0000\nPROBECYCLE END\n");
    ASSERT_EQ(printed.size(), 1u);
    EXPECT_DOUBLE_EQ(printed[0].xyz[0], 25.03);
    EXPECT_EQ(line_of([&] {
                  recorded_touch_positions(
                      plan, DialectId::fanuc,
                      "PROBECYCLE PLAN " + letters + " CYCLE\nPROBECYCLE OBSTRUCTED\n");
              }),
              2);
}

// The golden bore's plan run on a bore of 50 mm (stylus centre) about X0 Y0:
// every probe triggers at the wall and stops the model's overtravel past it,
// every protected move ends where it was going. Each position as grbl and a
// PROBEOPEN file give it (every probe and protected move, in order), and
// whether it is a recorded touch.
struct BoreRun {
    std::vector<std::array<double, 3>> every_probe;
    std::vector<std::array<double, 3>> recorded;
};
BoreRun run_on_a_bore(const ProbingPlan& plan, const Scenario& scenario) {
    Scenario surface = scenario;
    surface.cycle.feature = Feature::surface;
    const CycleResult model = evaluate(surface);
    const double wall = 0.5 * scenario.cycle.feature_size_mm;
    BoreRun run;
    std::array<double, 3> at{};
    for (const ProgramStep& step : plan.steps) {
        if (step.kind == StepKind::pause) continue;
        const std::size_t axis = static_cast<std::size_t>(step.axis - 'X');
        if (step.kind == StepKind::probe) {
            at[axis] = step.direction * wall;
            run.every_probe.push_back(at);
            if (step.recorded) run.recorded.push_back(at);
            at[axis] += step.direction * (step.recorded ? model.measuring_touch().overtravel_mm
                                                        : model.first_touch().overtravel_mm);
            continue;
        }
        at[axis] += step.direction * step.distance_mm;
        if (step.kind == StepKind::guard) run.every_probe.push_back(at);
    }
    return run;
}

TEST(MachineLog, ABoresRecordedTouchesAreMatchedInALinuxCncLogAndAGrblConsole) {
    const Scenario scenario = program_test::golden_bore();
    const ProbingPlan plan = make_cycle_plan(scenario, CyclePlanOptions{});
    const BoreRun run = run_on_a_bore(plan, scenario);
    // 8 protected moves, 2 probes at each of the 4 touches.
    ASSERT_EQ(run.every_probe.size(), 16u);
    ASSERT_EQ(run.recorded.size(), 4u);
    std::string console = "Grbl 1.1h ['$' for help]\n" + program_test::grbl_signature(plan);
    std::string probe_file;
    std::size_t index = 0;
    for (const ProgramStep& step : plan.steps) {
        if (step.kind != StepKind::probe && step.kind != StepKind::guard) continue;
        const std::array<double, 3>& xyz = run.every_probe[index++];
        console += prb(xyz[0], xyz[1], xyz[2], step.kind == StepKind::probe ? 1 : 0) + "ok\n";
        char line[160];
        std::snprintf(line, sizeof line, "%f %f %f 0 0 0 0 0 0\n", xyz[0], xyz[1], xyz[2]);
        probe_file += line;
    }
    std::string log = "probecycle plan " + plan_id(plan) + " cycle\n";
    for (std::size_t i = 0; i < run.recorded.size(); ++i) {
        char line[160];
        std::snprintf(line, sizeof line, "probecycle touch %zu %.6f %.6f %.6f\n", i + 1,
                      run.recorded[i][0], run.recorded[i][1], run.recorded[i][2]);
        log += line;
    }
    const double expected[4][2] = {{25, 0}, {-25, 0}, {0, 25}, {0, -25}};
    for (const auto& [name, dialect_id, text] :
         {std::tuple{"grbl", DialectId::grbl, console},
          std::tuple{"LinuxCNC LOG", DialectId::linuxcnc, log},
          std::tuple{"LinuxCNC PROBEOPEN", DialectId::linuxcnc, probe_file}}) {
        SCOPED_TRACE(name);
        const std::vector<RecordedPosition> touches =
            recorded_touch_positions(plan, dialect_id, text);
        ASSERT_EQ(touches.size(), 4u);
        for (std::size_t i = 0; i < 4; ++i) {
            EXPECT_NEAR(touches[i].xyz[0], expected[i][0], 1e-6);
            EXPECT_NEAR(touches[i].xyz[1], expected[i][1], 1e-6);
        }
    }
    // The X+ touch's line in the console: after the banner and the signature
    // (lines 2 to 11), the protected move out (line 12) and the first touch
    // (line 14), each answered "ok": line 16.
    EXPECT_EQ(recorded_touch_positions(plan, DialectId::grbl, console)[0].line, 16u);
}

// One probing move on the simulated machine: the surface `surface_mm` along
// the move's axis; the probe triggers after the pretravel, the control
// records the position a total delay later (the interface and controller
// delays and a uniform wait for the next scan), plus the probe's
// repeatability; the axis stops where the cycle model says. nullopt: the
// move ends before the surface. With `noise` false the wait is half a scan
// and the repeatability 0.
class SimulatedProbe {
  public:
    SimulatedProbe(const Scenario& scenario, double surface_mm, unsigned seed, bool noise)
        : scenario_(scenario),
          surface_mm_(surface_mm),
          noise_(noise),
          random_(seed),
          repeatability_(0.0, scenario.probe.repeatability_2sigma_mm / 2) {}

    struct Touch {
        double recorded_mm;
        double stop_mm;
    };
    std::optional<Touch> probe(double position_mm, double move_mm, double feed_mm_min) {
        const Machine& m = scenario_.machine;
        const Probe& p = scenario_.probe;
        const double direction = move_mm > 0 ? 1.0 : -1.0;
        const double room = (surface_mm_ - position_mm) * direction;
        if (room + p.pretravel_mm > std::abs(move_mm)) return std::nullopt;
        Scenario s = scenario_;
        s.cycle.strategy = Strategy::single_touch;
        s.cycle.probe_feed_mm_min = feed_mm_min;
        s.cycle.approach_mm = room;
        const CycleResult touch = evaluate(s);
        const double wait = noise_ ? scan_(random_) : 0.5;
        const double delay = p.interface_delay_s + m.controller_latency_s + wait * m.scan_period_s;
        const double scatter = noise_ ? repeatability_(random_) : 0.0;
        return Touch{
            surface_mm_ + direction * (p.pretravel_mm +
                                       touch.first_touch().trigger_speed_mm_s * delay + scatter),
            surface_mm_ + direction * touch.overtravel_mm()};
    }

  private:
    Scenario scenario_;
    double surface_mm_;
    bool noise_;
    std::mt19937 random_;
    std::uniform_real_distribution<double> scan_{0.0, 1.0};
    std::normal_distribution<double> repeatability_;
};

// A machine running the grbl program's lines (SimulatedProbe); it answers as
// grbl does.
std::string simulate_grbl(const std::string& program, const Scenario& scenario, double surface_mm,
                          double start_mm, unsigned seed, bool noise) {
    SimulatedProbe machine(scenario, surface_mm, seed, noise);
    double position = start_mm;
    std::string console;
    std::istringstream lines(program);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind("G38.2 ", 0) != 0 && line.rfind("G38.3 ", 0) != 0 &&
            line.rfind("G0 ", 0) != 0 && line.rfind("G1 ", 0) != 0) {
            continue;
        }
        const std::size_t word = line.find(' ') + 2;
        const double move = std::stod(line.substr(word));
        if (line.rfind("G38.3 ", 0) == 0) {  // the plan's signature, in free air
            position += move;
            console += prb(0.0, 0.0, position, 0) + "ok\n";
            continue;
        }
        if (line[1] != '3') {
            position += move;
            console += "ok\n";
            continue;
        }
        const double feed = std::stod(line.substr(line.find(" F") + 2));
        const std::optional<SimulatedProbe::Touch> touch = machine.probe(position, move, feed);
        if (!touch) return console + "ALARM:5\n";
        position = touch->stop_mm;
        console += prb(0.0, 0.0, touch->recorded_mm) + "ok\n";
    }
    return console;
}

// A number as DPRNT prints #v[ab] by Haas's rules (96-8000 p.116): b
// decimals, the whole part padded with leading spaces to a places (the sign
// counted in it: how a Fanuc places the sign is not confirmed, and the
// import reads either).
std::string dprnt_number(double value, int whole, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    std::string out = text;
    const std::size_t point = out.find('.');
    const std::size_t whole_chars = point == std::string::npos ? out.size() : point;
    if (whole_chars < static_cast<std::size_t>(whole)) out.insert(0, whole - whole_chars, ' ');
    return out;
}

// A DPRNT line: text, '*' as a space, #v[ab] from `variables`.
std::string dprnt(const std::string& body, const std::map<int, double>& variables) {
    std::string out;
    for (std::size_t i = 0; i < body.size(); ++i) {
        if (body[i] == '*') {
            out += ' ';
        } else if (body[i] == '#') {
            const std::size_t open = body.find('[', i);
            const int variable = std::stoi(body.substr(i + 1, open - i - 1));
            out += dprnt_number(variables.at(variable), body[open + 1] - '0', body[open + 2] - '0');
            i = open + 3;
        } else {
            out += body[i];
        }
    }
    return out;
}

// The Fanuc-type program on the simulated machine of simulate_grbl: G31
// records the skip position (or, without a trigger, the programmed end),
// #101=, IF[...]GOTO9001, #102= and DPRNT run as the control runs them; the
// output goes out as a Haas serial port sends it (DC2 at POPEN, DC4 at PCLOS)
// with `ending` after each line.
// Mitsubishi's program runs here too: its G04 and Haas's ";" and G103 do
// nothing on the simulator, any "#n=" assignment of a number, a variable or
// the current position plus a distance is kept, and an M00 with its reason
// stops; `kept` receives the variables at the end.
std::string simulate_fanuc(const std::string& program, const Scenario& scenario, double surface_mm,
                           double start_mm, unsigned seed, bool noise, const std::string& ending,
                           std::map<int, double>* kept = nullptr) {
    SimulatedProbe machine(scenario, surface_mm, seed, noise);
    std::vector<std::string> lines;
    std::istringstream in(program);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    // Along Z only (the delay plan's axis); X and Y stay at 0.
    double position = start_mm;
    std::map<int, double> variables = {{5061, 0.0}, {5062, 0.0}, {5063, 0.0}};
    std::string output;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& line = lines[i];
        if (line == "POPEN") output += '\x12';
        if (line == "PCLOS") output += '\x14';
        if (line == "M30" || line.rfind("#3000=", 0) == 0 || line.rfind("M00 (", 0) == 0) break;
        if (line.rfind("DPRNT[", 0) == 0) {
            output += dprnt(line.substr(6, line.size() - 7), variables) + ending;
        } else if (line.rfind('#', 0) == 0) {
            const std::size_t eq = line.find('=');
            const std::string value = line.substr(eq + 1);
            double number = 0.0;
            if (value.rfind('#', 0) == 0) {
                std::size_t digits = 0;
                const int source = std::stoi(value.substr(1), &digits);
                number = source == 5043 ? position : variables.at(source);
                if (1 + digits < value.size()) number += std::stod(value.substr(1 + digits));
            } else {
                number = std::stod(value);
            }
            variables[std::stoi(line.substr(1, eq - 1))] = number;
        } else if (line.rfind("IF[ABS[#5063-#101]LT0.050]GOTO9001", 0) == 0) {
            if (std::abs(variables[5063] - variables[101]) < 0.05) {
                while (lines[i] != "N9001") ++i;
            }
        } else if (line.rfind("G0 Z", 0) == 0 || line.rfind("G1 Z", 0) == 0) {
            position += std::stod(line.substr(4));
        } else if (line.rfind("G31 Z", 0) == 0) {
            const double move = std::stod(line.substr(5));
            const double feed = std::stod(line.substr(line.find(" F") + 2));
            const std::optional<SimulatedProbe::Touch> touch = machine.probe(position, move, feed);
            // Without a trigger the skip position is the programmed end.
            position = touch ? touch->stop_mm : position + move;
            variables[5063] = touch ? touch->recorded_mm : position;
        } else if (line.rfind("G31", 0) == 0 || line.rfind("G0 ", 0) == 0 ||
                   line.rfind("G1 ", 0) == 0) {
            ADD_FAILURE() << "the simulator moves Z only: " << line;
        }
    }
    if (kept != nullptr) *kept = variables;
    return output;
}

// The Siemens program on the same simulated machine (along Z): STOPRE,
// R1= from $AA_IW, the absolute MEAS block to R1, the $A_PROBE checks, the
// moves, and WRITE's text (string literals, SPRINT("%12.4F", ...) of
// $AA_MW and $AA_IW) appended to the file it returns, a line each.
std::string simulate_siemens(const std::string& program, const Scenario& scenario,
                             double surface_mm, double start_mm, unsigned seed, bool noise) {
    SimulatedProbe machine(scenario, surface_mm, seed, noise);
    std::vector<std::string> lines;
    std::istringstream in(program);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    double position = start_mm;
    double r1 = 0.0;
    double trip = 0.0;
    bool probe = false;
    const auto value = [&](const std::string& name) {
        if (name == "$AA_MW[Z]") return trip;
        if (name == "$AA_IW[Z]") return position;
        EXPECT_TRUE(name == "$AA_IW[X]" || name == "$AA_IW[Y]") << name;
        return 0.0;
    };
    const auto jump = [&](std::size_t& i, const std::string& label) {
        while (i < lines.size() && lines[i] != label + ":") ++i;
        EXPECT_LT(i, lines.size()) << label;
    };
    std::string file;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& line = lines[i];
        if (line == "M30" || line.rfind("MSG(\"PROBECYCLE:", 0) == 0) break;
        if (line.rfind("R1=$AA_IW[Z]", 0) == 0) {
            r1 = position + std::stod(line.substr(12));
        } else if (line.rfind("MEAS=1 G90 G1 Z=R1 F", 0) == 0) {
            const double feed = std::stod(line.substr(20));
            const std::optional<SimulatedProbe::Touch> touch =
                machine.probe(position, r1 - position, feed);
            probe = touch.has_value();
            position = touch ? touch->stop_mm : r1;
            if (touch) trip = touch->recorded_mm;
        } else if (line == "IF $A_PROBE[1]<>1 GOTOF NO_TRIGGER") {
            if (!probe) jump(i, "NO_TRIGGER");
        } else if (line.rfind("WRITE(PC_ERROR,\"PROBECYCLE_LOG\",", 0) == 0) {
            const std::string text = line.substr(32, line.size() - 33);
            std::string out;
            for (std::size_t at = 0; at < text.size();) {
                if (text[at] == '"') {
                    const std::size_t close = text.find('"', at + 1);
                    out += text.substr(at + 1, close - at - 1);
                    at = close + 1;
                } else if (text.compare(at, 2, "<<") == 0) {
                    at += 2;
                } else {
                    EXPECT_EQ(text.compare(at, 20, "SPRINT(\"%12.4F\",$AA_"), 0) << text.substr(at);
                    const std::size_t close = text.find(')', at);
                    char number[32];
                    std::snprintf(number, sizeof number, "%12.4f",
                                  value(text.substr(at + 16, close - at - 16)));
                    out += number;
                    at = close + 1;
                }
            }
            file += out + "\n";
        } else if (line.rfind("G0 Z", 0) == 0 || line.rfind("G1 Z", 0) == 0) {
            position += std::stod(line.substr(4));
        } else if (line.rfind("MEAS", 0) == 0 || line.rfind("G0 ", 0) == 0 ||
                   line.rfind("G1 ", 0) == 0) {
            ADD_FAILURE() << "the simulator moves Z only: " << line;
        }
    }
    return file;
}

// The common variables #500-#999 a Mitsubishi program kept, as a list of
// "#n = value" lines with 4 decimals, each line ending in `ending`.
std::string variable_list(const std::map<int, double>& variables, const std::string& ending) {
    std::string list;
    for (const auto& [number, value] : variables) {
        if (number < 500 || number > 999) continue;
        char line[64];
        std::snprintf(line, sizeof line, "#%d = %.4f", number, value);
        list += line + ending;
    }
    return list;
}

// The Mitsubishi program of `plan` on the simulated machine: its variable list.
std::string simulate_mitsubishi(const ProbingPlan& plan, const Scenario& scenario,
                                double surface_mm, double start_mm, unsigned seed, bool noise,
                                const std::string& ending) {
    const std::string program = write_program(plan, mitsubishi_dialect(), program_test::kDate);
    std::map<int, double> variables;
    EXPECT_EQ(
        simulate_fanuc(program, scenario, surface_mm, start_mm, seed, noise, ending, &variables),
        "");
    return variable_list(variables, ending);
}

// Plan, program, the simulated machine, import, fit; `ending` ends each
// DPRNT line of the fanuc output.
DelayGroup round_trip(int repeats, bool noise, DialectId dialect_id = DialectId::grbl,
                      const std::string& ending = "\n") {
    const Scenario scenario;  // t_i 2 ms, t_c 2 ms, scan 4 ms: 6 ms on average
    DelayPlanOptions options;
    options.touch = {'Z', -1};
    options.repeats = repeats;
    const ProbingPlan plan = make_delay_plan(scenario, options);
    const std::string program = write_program(plan, dialect(dialect_id), program_test::kDate);
    const std::string log =
        dialect_id == DialectId::fanuc || dialect_id == DialectId::haas
            ? simulate_fanuc(program, scenario, -50.0, -43.0, 42, noise, ending)
        : dialect_id == DialectId::mitsubishi
            ? simulate_mitsubishi(plan, scenario, -50.0, -43.0, 42, noise, ending)
        : dialect_id == DialectId::siemens
            ? simulate_siemens(program, scenario, -50.0, -43.0, 42, noise)
            : simulate_grbl(program, scenario, -50.0, -43.0, 42, noise);
    const std::vector<DelayTouch> touches =
        parse_delay_csv(import_machine_log(plan, dialect_id, log));
    // 30, 100, 300, 1000 and 2000 mm/min (the scenario's feed is among them).
    EXPECT_EQ(touches.size(), static_cast<std::size_t>(5 * repeats));
    const DelayFit fit = fit_delay(touches);
    EXPECT_EQ(fit.groups.size(), 1u);
    return fit.groups.at(0);
}

// The controls that record 4 decimals (0.1 um): the Fanuc-type DPRNT (a
// Haas's too, with its look-ahead limited by empty blocks and G103),
// Mitsubishi's common variables, Siemens's WRITE file. Without noise only
// the 4 decimals stand between the delay and the fit: finer than grbl's
// 1 um, so a tighter bound. The lines end as each control ends them.
TEST(MachineLog, FourDecimalRecordsRoundTripToTheKnownDelay) {
    const Scenario scenario;
    const double delay_s = measurement_delay_s(scenario.machine, scenario.probe);
    const std::tuple<DialectId, const char*, const char*> cases[] = {
        {DialectId::fanuc, "\r", "\n\r\r"},
        {DialectId::haas, "\r\n", "\r"},
        {DialectId::mitsubishi, "\r\n", "\n"},
        {DialectId::siemens, "\n", "\n"}};
    for (const auto& [id, ending, noisy_ending] : cases) {
        SCOPED_TRACE(dialect(id).name);
        const DelayGroup exact = round_trip(5, false, id, ending);
        EXPECT_NEAR(exact.delay_s, delay_s, 5e-6);
        EXPECT_NEAR(exact.zero_speed_position_mm, -50.0 - scenario.probe.pretravel_mm, 0.0001);
        const DelayGroup noisy = round_trip(20, true, id, noisy_ending);
        EXPECT_NEAR(noisy.delay_s, delay_s, 5e-4);
    }
}

// The list as a control outputs it or a user copies it: "#n = v", "#n=v"
// and "n v" lines, other lines, vacant variables, the same line twice: the
// same table. A broken list names its line.
TEST(MachineLog, MitsubishiVariableListsInEveryFormAndBrokenOnes) {
    const Scenario scenario;
    const ProbingPlan plan = small_delay_plan();
    const std::string list = simulate_mitsubishi(plan, scenario, -50.0, -43.0, 42, false, "\n");
    const std::string expected = import_machine_log(plan, DialectId::mitsubishi, list);
    EXPECT_EQ(parse_delay_csv(expected).size(), 4u);
    std::string compact;
    std::string bare;
    std::istringstream lines(list);
    for (std::string line; std::getline(lines, line);) {
        const std::size_t eq = line.find(" = ");
        compact += line.substr(0, eq) + "=" + line.substr(eq + 3) + "\r\n";
        bare += line.substr(1, eq - 1) + "  " + line.substr(eq + 3) + "\n";
    }
    EXPECT_EQ(import_machine_log(plan, DialectId::mitsubishi, compact), expected);
    EXPECT_EQ(import_machine_log(plan, DialectId::mitsubishi, bare), expected);
    const std::string framed = "COMMON VARIABLES\n#100 = 3.0\n#599 =\n#600 = ****\n" + list +
                               list.substr(0, list.find('\n') + 1) + "#1000 = 1\n";
    EXPECT_EQ(import_machine_log(plan, DialectId::mitsubishi, framed), expected);

    const auto line_with = [&](const std::string& text, const std::string& start) {
        std::size_t number = 1;
        for (std::size_t at = 0; at < text.find(start); ++at) number += text[at] == '\n';
        return static_cast<int>(number);
    };
    const auto import = [&plan](const std::string& text) {
        import_machine_log(plan, DialectId::mitsubishi, text);
    };
    // Another plan's id in #500-#503: named at #500.
    std::string other = list;
    const std::size_t units = other.find('.', other.find("#501 = ")) - 1;  // stays 0-65535
    other[units] = other[units] == '0' ? '1' : '0';
    EXPECT_EQ(line_of([&] { import(other); }), line_with(other, "#500 ="));
    // A variable listed twice with two values: the second line.
    const std::string twice = list + "#521 = 7.0000\n";
    EXPECT_EQ(line_of([&] { import(twice); }), line_with(twice, "#521 = 7"));
    // A touch's variable missing.
    std::string missing = list;
    missing.erase(missing.find("#524 ="),
                  missing.find('\n', missing.find("#524 =")) + 1 - missing.find("#524 ="));
    EXPECT_THROW(import(missing), CsvError);
    // The program did not end, or stopped: named at #504.
    for (const char* state : {"0.0000", "101.0000", "102.0000", "7.0000"}) {
        std::string stopped = list;
        const std::size_t at = stopped.find("#504 = ") + 7;
        stopped.replace(at, stopped.find('\n', at) - at, state);
        EXPECT_EQ(line_of([&] { import(stopped); }), line_with(stopped, "#504 =")) << state;
    }
    // Not a variable list at all.
    EXPECT_EQ(line_of([&] { import("PROBECYCLE PLAN ABC DELAY\n"); }), 1);
    EXPECT_THROW(import("nothing here\n"), CsvError);
}

TEST(MachineLog, MitsubishiProbeThatDoesNotTriggerStopsTheProgramAndTheImport) {
    const Scenario scenario;
    const ProbingPlan plan = small_delay_plan();
    // The surface 30 mm away: the locating touch finds nothing, the check
    // jumps to the stop, which keeps 101 in #504.
    const std::string list = simulate_mitsubishi(plan, scenario, -80.0, -50.0, 42, false, "\n");
    EXPECT_NE(list.find("#504 = 101.0000\n"), std::string::npos) << list;
    EXPECT_NE(list.find("#505 = 0.0000\n"), std::string::npos) << list;
    try {
        import_machine_log(plan, DialectId::mitsubishi, list);
        ADD_FAILURE() << "imported";
    } catch (const CsvError& e) {
        EXPECT_NE(std::string(e.what()).find("PROBE DID NOT TRIGGER"), std::string::npos)
            << e.what();
    }
}

// WRITE appends, so the file holds every run: the import reads the last one
// (an earlier run that stopped, or another plan's, changes nothing), and a
// last run that stopped is refused at its line.
TEST(MachineLog, SiemensFileIsReadFromItsLastRun) {
    const Scenario scenario;
    const ProbingPlan plan = small_delay_plan();
    const std::string program = write_program(plan, siemens_dialect(), program_test::kDate);
    const std::string run = simulate_siemens(program, scenario, -50.0, -43.0, 42, false);
    const std::string expected = import_machine_log(plan, DialectId::siemens, run);
    EXPECT_EQ(parse_delay_csv(expected).size(), 4u);
    const std::string stopped = simulate_siemens(program, scenario, -80.0, -50.0, 42, false);
    EXPECT_EQ(stopped.find("TOUCH"), std::string::npos) << stopped;
    EXPECT_NE(stopped.find("PROBECYCLE NO TRIGGER\n"), std::string::npos) << stopped;
    DelayPlanOptions other_options;
    other_options.feeds_mm_min = {100, 1000};
    const std::string other =
        simulate_siemens(write_program(make_delay_plan(scenario, other_options), siemens_dialect(),
                                       program_test::kDate),
                         scenario, -50.0, -43.0, 42, false);
    EXPECT_EQ(import_machine_log(plan, DialectId::siemens, other + stopped + run), expected);
    EXPECT_EQ(line_of([&] { import_machine_log(plan, DialectId::siemens, run + stopped); }),
              static_cast<int>(std::count(run.begin(), run.end(), '\n')) + 2);
    // A DPRNT reader of the same lines reads the whole file and finds two runs.
    EXPECT_THROW(import_machine_log(plan, DialectId::fanuc, stopped + run), CsvError);
}

TEST(MachineLog, FanucProbeThatDoesNotTriggerStopsTheProgramAndTheImport) {
    const Scenario scenario;
    const ProbingPlan plan = small_delay_plan();
    const std::string program = write_program(plan, fanuc_dialect(), program_test::kDate);
    // The surface 30 mm away: the locating touch (10 mm) finds nothing, the
    // check jumps to the alarm branch, which prints the marker.
    const std::string output = simulate_fanuc(program, scenario, -80.0, -50.0, 42, false, "\n");
    EXPECT_NE(output.find("PROBECYCLE NO TRIGGER\n"), std::string::npos) << output;
    EXPECT_EQ(output.find("TOUCH"), std::string::npos);
    EXPECT_EQ(line_of([&] { import_machine_log(plan, DialectId::fanuc, output); }), 2);
}

TEST(MachineLog, RoundTripGivesBackTheKnownDelay) {
    const Scenario scenario;
    const double delay_s = measurement_delay_s(scenario.machine, scenario.probe);
    // Without noise only grbl's 1 µm digits stand between the delay and the fit.
    const DelayGroup exact = round_trip(5, false);
    EXPECT_NEAR(exact.delay_s, delay_s, 2e-5);
    EXPECT_NEAR(exact.zero_speed_position_mm, -50.0 - scenario.probe.pretravel_mm, 0.001);
    // With the scan's uniform wait (a range of v * 4 ms) and the repeatability,
    // seed 42: 20 repeats give the delay to about a quarter of a millisecond.
    const DelayGroup noisy = round_trip(20, true);
    EXPECT_NEAR(noisy.delay_s, delay_s, 5e-4);
}

}  // namespace
}  // namespace probecycle
