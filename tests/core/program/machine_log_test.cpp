// Reading back what the control recorded: LinuxCNC's LOG and PROBEOPEN files
// and a grbl sender's console, written here in each format, good and broken;
// and the round trip: plan, program, a machine simulated by the cycle model
// running the program's lines, the import, the fit: the known delay returns.

#include "core/program/machine_log.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <sstream>

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
    // A touch that did not trigger: ":0" (line 6), or the alarm grbl raises.
    const std::string no_trigger = good.substr(0, good.find("[PRB:0.000,0.000,-20.018:1]")) +
                                   "[PRB:0.000,0.000,-20.018:0]\nALARM:5\n";
    EXPECT_EQ(line_of([&] { import_machine_log(plan, DialectId::grbl, no_trigger); }), 7);
    EXPECT_EQ(line_of([&] { import_machine_log(plan, DialectId::grbl, "ok\nALARM:5\n"); }), 2);
    // A missing touch: the log ends early (its last position named).
    const std::string missing = good.substr(0, good.rfind("[PRB:"));
    EXPECT_EQ(line_of([&] { import_machine_log(plan, DialectId::grbl, missing); }), 9);
    // An extra touch: a "$#" printout after the run repeats the last probe.
    EXPECT_EQ(
        line_of([&] { import_machine_log(plan, DialectId::grbl, good + prb(0, 0, -20.151)); }), 13);
    // Another plan: Y moved between two touches this plan makes along Z alone.
    std::string other = good;
    other.replace(other.find("[PRB:0.000,0.000,-20.150:1]"), 27, "[PRB:0.000,5.000,-20.150:1]");
    EXPECT_EQ(line_of([&] { import_machine_log(plan, DialectId::grbl, other); }), 9);
    // An unreadable report.
    EXPECT_EQ(line_of([&] { import_machine_log(plan, DialectId::grbl, "[PRB:1,2:1]\n"); }), 1);
}

using program_test::linuxcnc_log;

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

// A machine running the program's lines: a surface `surface_mm` along the
// plan's axis; each probe triggers after the pretravel, the control records
// the position a total delay later (the interface and controller delays and a
// uniform wait for the next scan), plus the probe's repeatability; the axis
// stops where the cycle model says. It answers as grbl does.
// With `noise` false the wait is half a scan and the repeatability 0.
std::string simulate_grbl(const std::string& program, const Scenario& scenario, double surface_mm,
                          double start_mm, unsigned seed, bool noise) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> scan(0.0, 1.0);
    std::normal_distribution<double> repeatability(0.0, scenario.probe.repeatability_2sigma_mm / 2);
    const Machine& m = scenario.machine;
    const Probe& p = scenario.probe;
    double position = start_mm;
    std::string console;
    std::istringstream lines(program);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind("G38.2 ", 0) != 0 && line.rfind("G0 ", 0) != 0 &&
            line.rfind("G1 ", 0) != 0) {
            continue;
        }
        const std::size_t word = line.find(' ') + 2;
        const double move = std::stod(line.substr(word));
        if (line[1] != '3') {
            position += move;
            console += "ok\n";
            continue;
        }
        const double feed = std::stod(line.substr(line.find(" F") + 2));
        const double direction = move > 0 ? 1.0 : -1.0;
        const double room = (surface_mm - position) * direction;
        if (room + p.pretravel_mm > std::abs(move)) {
            return console + "ALARM:5\n";
        }
        Scenario s = scenario;
        s.cycle.strategy = Strategy::single_touch;
        s.cycle.probe_feed_mm_min = feed;
        s.cycle.approach_mm = room;
        const CycleResult touch = evaluate(s);
        const double wait = noise ? scan(random) : 0.5;
        const double delay = p.interface_delay_s + m.controller_latency_s + wait * m.scan_period_s;
        const double scatter = noise ? repeatability(random) : 0.0;
        const double recorded =
            surface_mm +
            direction * (p.pretravel_mm + touch.first_touch().trigger_speed_mm_s * delay + scatter);
        position = surface_mm + direction * touch.overtravel_mm();
        console += prb(0.0, 0.0, recorded) + "ok\n";
    }
    return console;
}

DelayGroup round_trip(int repeats, bool noise) {
    const Scenario scenario;  // t_i 2 ms, t_c 2 ms, scan 4 ms: 6 ms on average
    DelayPlanOptions options;
    options.touch = {'Z', -1};
    options.repeats = repeats;
    const ProbingPlan plan = make_delay_plan(scenario, options);
    const std::string program = write_program(plan, grbl_dialect(), program_test::kDate);
    const std::string console = simulate_grbl(program, scenario, -50.0, -43.0, 42, noise);
    const std::string csv = import_machine_log(plan, DialectId::grbl, console);
    const std::vector<DelayTouch> touches = parse_delay_csv(csv);
    // 30, 100, 300, 1000 and 2000 mm/min (the scenario's feed is among them).
    EXPECT_EQ(touches.size(), static_cast<std::size_t>(5 * repeats));
    const DelayFit fit = fit_delay(touches);
    EXPECT_EQ(fit.groups.size(), 1u);
    return fit.groups.at(0);
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
