// probecycle-cli program and import, run as a user runs them: the programs
// are the core's golden files, the import feeds 'latency fit', and bad input
// is named with what is allowed.

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "core/program/dialect.h"
#include "tests/cli/cli_run.h"

namespace probecycle::cli_test {
namespace {

// On the golden files' day, 2026-01-15 (tests/core/program/program_test_plans.h).
CliRun run_on_golden_day(const std::string& arguments) {
    cli_test::set_env("SOURCE_DATE_EPOCH", "1768435200");
    CliRun result = run(arguments);
    cli_test::set_env("SOURCE_DATE_EPOCH", nullptr);
    return result;
}

TEST(ProgramCli, WritesTheGoldenProgramAndItsPlan) {
    const TempDir dir;
    for (const DialectId id : all_dialects()) {
        const std::string dialect = probecycle::dialect(id).name;
        const std::string suffix = "_" + dialect + "." + probecycle::dialect(id).extension;
        const CliRun r = run_on_golden_day("program delay --dialect " + dialect +
                                           " --axis X+ --feeds 30,300,2000 --repeats 2 --plan " +
                                           quote((dir / "plan.json").string()) + " --out " +
                                           quote((dir / "program").string()));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(read(dir / "program"), read(data("golden/program_delay" + suffix)));
        EXPECT_NE(read(dir / "plan.json").find("\"format\": \"probecycle-probing-plan\""),
                  std::string::npos);
        // The orient command serves the fanuc program; the others ignore it.
        const CliRun ring =
            run_on_golden_day("program ring --dialect " + dialect + " --orient-180 'M19 R180.'");
        EXPECT_EQ(ring.out, read(data("golden/program_ring" + suffix)));
        // The golden cycles are for a known part (program_test_plans.h).
        const std::string known = " --set cycle.part_position_uncertainty_mm=0";
        const CliRun cycle = run_on_golden_day("program cycle --dialect " + dialect + known);
        EXPECT_EQ(cycle.out, read(data("golden/program_cycle" + suffix)));
        // A feature's cycle: the core's golden plans (program_test_plans.h).
        const CliRun bore = run_on_golden_day("program cycle --dialect " + dialect + known +
                                              " --set cycle.feature=bore");
        EXPECT_EQ(bore.out, read(data("golden/program_cycle_bore" + suffix))) << bore.err;
        const CliRun boss =
            run_on_golden_day("program cycle --dialect " + dialect + known +
                              " --set cycle.feature=boss --set cycle.strategy=single_touch --set "
                              "cycle.probe_feed_mm_min=300 --set cycle.repeats=2");
        EXPECT_EQ(boss.out, read(data("golden/program_cycle_boss" + suffix))) << boss.err;
    }
}

TEST(ProgramCli, ImportGivesTheCsvThatLatencyFitReads) {
    const TempDir dir;
    const std::string plan = quote((dir / "plan.json").string());
    ASSERT_EQ(run("program delay --dialect grbl --feeds 100,1000 --repeats 2 --plan " + plan +
                  " --out " + quote((dir / "p.nc").string()))
                  .exit_code,
              0);
    // grbl's answers to the program's signature (its G38.3 moves before the
    // first probe, from Z 0), then the touches.
    std::string console;
    {
        std::istringstream program(read(dir / "p.nc"));
        double z = 0.0;
        for (std::string line; std::getline(program, line) && line.rfind("G38.2", 0) != 0;) {
            if (line.rfind("G38.3 Z", 0) != 0 && line.rfind("G1 Z", 0) != 0) continue;
            z += std::stod(line.substr(line.find('Z') + 1));
            if (line[1] == '3') {
                char report[64];
                std::snprintf(report, sizeof report, "[PRB:0.000,0.000,%.3f:0]\nok\n", z);
                console += report;
            }
        }
    }
    console += "[PRB:0.000,0.000,-20.000:1]\nok\n";
    for (const char* z : {"-20.017", "-20.018", "-20.150", "-20.151"}) {
        console += std::string("[PRB:0.000,0.000,") + z + ":1]\nok\n";
    }
    write(dir / "console.txt", console);
    const CliRun imported =
        run("import --dialect grbl --plan " + plan + " " + quote((dir / "console.txt").string()) +
            " --out " + quote((dir / "touches.csv").string()));
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
    EXPECT_NE(read(dir / "touches.csv").find("Z,-1,1000,-20.151\n"), std::string::npos);
    const CliRun fit = run("latency fit " + quote((dir / "touches.csv").string()));
    EXPECT_EQ(fit.exit_code, 0) << fit.err;
    EXPECT_NE(fit.out.find("\"group\": \"Z-\""), std::string::npos) << fit.out;

    // A touch that did not trigger: the line, and no CSV.
    const std::string signature = console.substr(0, console.find("[PRB:0.000,0.000,-20.000:1]"));
    write(dir / "bad.txt",
          signature + "[PRB:0.000,0.000,-20.000:1]\n[PRB:0.000,0.000,-20.000:0]\n");
    const CliRun bad =
        run("import --dialect grbl --plan " + plan + " " + quote((dir / "bad.txt").string()));
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_EQ(bad.out, "");
    EXPECT_NE(bad.err.find("bad.txt: line 10: the probe did not trigger"), std::string::npos)
        << bad.err;
}

TEST(ProgramCli, FanucImportGivesTheRingCsvThatCalibrateRingReads) {
    const TempDir dir;
    const std::string plan = quote((dir / "plan.json").string());
    const CliRun program = run("program ring --dialect fanuc --orient-180 'M19 R180.' --plan " +
                               plan + " --out " + quote((dir / "ring.nc").string()));
    ASSERT_EQ(program.exit_code, 0) << program.err;
    const std::string text = read(dir / "ring.nc");
    const std::size_t at = text.find("DPRNT[PROBECYCLE*PLAN*") + 22;
    const std::string letters = text.substr(at, 16);
    // The output as a Haas serial port sends it: DC2, CR after every line, DC4.
    std::string output = "\x12PROBECYCLE PLAN " + letters + " RING\r";
    const double r = 21.997;
    const double points[4][2] = {{r, 0}, {-r, 0}, {0, r}, {0, -r}};
    for (int i = 0; i < 8; ++i) {
        char line[128];
        std::snprintf(line, sizeof line, "TOUCH   %d X%9.4f Y%9.4f Z   0.0000\r", i + 1,
                      points[i % 4][0] + (i < 4 ? 0.002 : -0.002), points[i % 4][1]);
        output += line;
    }
    write(dir / "dprnt.txt", output + "PROBECYCLE END\r\x14");
    const CliRun imported =
        run("import --dialect fanuc --plan " + plan + " " + quote((dir / "dprnt.txt").string()) +
            " --out " + quote((dir / "ring.csv").string()));
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
    EXPECT_NE(read(dir / "ring.csv").find("180,21.995,0\n"), std::string::npos)
        << read(dir / "ring.csv");
    const CliRun calibrate =
        run("calibrate ring " + quote((dir / "ring.csv").string()) + " --gauge-diameter 50");
    EXPECT_EQ(calibrate.exit_code, 0) << calibrate.err;

    // The program stopped at a probe that did not trigger: the marker's line.
    write(dir / "stopped.txt", "PROBECYCLE PLAN " + letters + " RING\nPROBECYCLE NO TRIGGER\n");
    const CliRun stopped =
        run("import --dialect fanuc --plan " + plan + " " + quote((dir / "stopped.txt").string()));
    EXPECT_EQ(stopped.exit_code, 2);
    EXPECT_EQ(stopped.out, "");
    EXPECT_NE(stopped.err.find("stopped.txt: line 2: the program printed PROBECYCLE NO TRIGGER"),
              std::string::npos)
        << stopped.err;
}

// A bore's program with the ball and a tolerance; its LinuxCNC log (the plan
// id from the program) gives the feature's result, as text and as JSON.
TEST(ProgramCli, CycleImportGivesTheFeaturesResult) {
    const TempDir dir;
    const std::string plan = quote((dir / "plan.json").string());
    const CliRun program = run(
        "program cycle --dialect linuxcnc --set cycle.feature=bore --set cycle.feature_size_mm=44 "
        "--set cycle.size_tolerance_mm=0.003 --set cycle.tolerance_action=stop "
        "--ball-diameter-mm 6 --plan " +
        plan + " --out " + quote((dir / "bore.ngc").string()));
    ASSERT_EQ(program.exit_code, 0) << program.err;
    const std::string text = read(dir / "bore.ngc");
    const std::size_t at = text.find("(LOG,probecycle plan ") + 21;
    std::string log = "probecycle plan " + text.substr(at, 16) + " cycle\n";
    log += "probecycle touch 1 22.006000 0.000000 0.000000\n";
    log += "probecycle touch 2 -21.998000 0.000000 0.000000\n";
    log += "probecycle touch 3 0.000000 22.010000 0.000000\n";
    log += "probecycle touch 4 0.000000 -21.994000 0.000000\n";
    log += "probecycle result S 50.004000 X 0.004000 Y 0.008000 D 0.004000 T 1.000000\n";
    log += "probecycle out of tolerance\n";
    write(dir / "log.txt", log);
    const std::string import =
        "import --dialect linuxcnc --plan " + plan + " " + quote((dir / "log.txt").string());
    const CliRun imported = run(import);
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
    EXPECT_NE(imported.out.find("bore diameter: 50.0040 mm +- "), std::string::npos)
        << imported.out;
    EXPECT_NE(imported.out.find("OUT OF TOLERANCE (the program stops)"), std::string::npos)
        << imported.out;
    const CliRun json = run(import + " --json");
    ASSERT_EQ(json.exit_code, 0) << json.err;
    EXPECT_NE(json.out.find("\"format\": \"probecycle-feature-result\""), std::string::npos);
    EXPECT_NE(json.out.find("\"out_of_tolerance\": true"), std::string::npos) << json.out;

    // A result line the touches do not give: its line, and no result.
    write(dir / "edited.txt", log.substr(0, log.find("probecycle result")) +
                                  "probecycle result S 50.104000 X 0.004000 Y 0.008000 D "
                                  "0.104000 T 1.000000\n");
    const CliRun edited = run("import --dialect linuxcnc --plan " + plan + " " +
                              quote((dir / "edited.txt").string()));
    EXPECT_EQ(edited.exit_code, 2);
    EXPECT_EQ(edited.out, "");
    EXPECT_NE(edited.err.find("edited.txt: line 6: the program's result line gives S"),
              std::string::npos)
        << edited.err;

    // A plan without the model's uncertainty: the plan file is named.
    std::string old_plan = read(dir / "plan.json");
    const std::size_t value = old_plan.find("    \"point_uncertainty_mm\"");
    ASSERT_NE(value, std::string::npos) << old_plan;
    old_plan.erase(value, old_plan.find('\n', value) + 1 - value);
    write(dir / "old_plan.json", old_plan);
    const CliRun old =
        run("import --dialect linuxcnc --plan " + quote((dir / "old_plan.json").string()) + " " +
            quote((dir / "log.txt").string()));
    EXPECT_EQ(old.exit_code, 2);
    EXPECT_NE(old.err.find("old_plan.json: the cycle plan has no readable value "
                           "point_uncertainty_mm"),
              std::string::npos)
        << old.err;
}

TEST(ProgramCli, BadInputIsNamedWithWhatIsAllowed) {
    const struct {
        std::string arguments;
        std::string message;
    } cases[] = {
        {"program delay --dialect heidenhain",
         "--dialect: got 'heidenhain'; allowed: linuxcnc, grbl, fanuc, haas, mitsubishi, siemens"},
        {"program delay --dialect siemens --probe-input 3",
         "--probe-input: got '3'; allowed: 1, -1, 2, -2"},
        {"program delay --dialect grbl --axis A+", "--axis: got 'A+'; allowed: X+, X-, Y+"},
        {"program delay --dialect grbl --feeds 30,abc",
         "--feeds: got '30,abc'; allowed: numbers separated by commas, each from 1 to 100000 "
         "(item 2, 'abc', is not)"},
        // Before: "got '--repeats'", and "100,,200" ran with two feeds.
        {"program delay --dialect grbl --feeds , --repeats 2",
         "--feeds: got ','; allowed: numbers separated by commas, each from 1 to 100000 (item 1 "
         "is empty)"},
        {"program delay --dialect grbl --feeds 100,,200", "(item 2 is empty)"},
        {"program delay --dialect grbl --feeds 100,100",
         "--feeds: got 100; allowed: from 2 to 20 different feeds"},
        {"program delay --dialect grbl --repeats 0", "--repeats: got '0'; allowed: a whole number"},
        {"program cycle --dialect grbl --set cycle.feature=pocket",
         "--axis: got Z-; allowed: X+, X-, Y+ or Y- for a pocket"},
        {"program cycle --dialect grbl --set cycle.feature=boss --set cycle.clearance_mm=0",
         "cycle.clearance_mm: got 0; allowed: at least 0.001 mm for a boss"},
        {"program ring --dialect grbl --gauge-diameter-mm 6.5",
         "the gauge (6.5 mm) leaves the ball"},
        {"program ring --dialect fanuc",
         "--orient-180: the ring program turns the spindle to 180 deg, and fanuc controls have no "
         "common word for that"},
        {"program ring --dialect fanuc --orient-180 'm19 r180.'",
         "--orient-180: got 'm19 r180.'; allowed: one block of at most 60 upper-case letters"},
        {"program frobnicate", "unknown program 'frobnicate'; allowed: delay, ring, cycle"},
        {"import --dialect grbl LOG", "missing required option --plan"},
    };
    for (const auto& c : cases) {
        const CliRun r = run(c.arguments);
        EXPECT_EQ(r.exit_code, 2) << c.arguments;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.arguments << ":\n" << r.err;
    }
}

}  // namespace
}  // namespace probecycle::cli_test
