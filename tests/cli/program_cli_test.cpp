// probecycle-cli program and import, run as a user runs them: the programs
// are the core's golden files, the import feeds 'latency fit', and bad input
// is named with what is allowed.

#include <gtest/gtest.h>

#include <cstdlib>

#include "tests/cli/cli_run.h"

namespace probecycle::cli_test {
namespace {

// On the golden files' day, 2026-01-15 (tests/core/program/program_test_plans.h).
CliRun run_on_golden_day(const std::string& arguments) {
    ::setenv("SOURCE_DATE_EPOCH", "1768435200", 1);
    CliRun result = run(arguments);
    ::unsetenv("SOURCE_DATE_EPOCH");
    return result;
}

TEST(ProgramCli, WritesTheGoldenProgramAndItsPlan) {
    const TempDir dir;
    for (const std::string dialect : {"linuxcnc", "grbl"}) {
        const std::string suffix = "_" + dialect + (dialect == "grbl" ? ".nc" : ".ngc");
        const CliRun r = run_on_golden_day("program delay --dialect " + dialect +
                                           " --axis X+ --feeds 30,300,2000 --repeats 2 --plan " +
                                           quote((dir / "plan.json").string()) + " --out " +
                                           quote((dir / "program").string()));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(read(dir / "program"), read(data("golden/program_delay" + suffix)));
        EXPECT_NE(read(dir / "plan.json").find("\"format\": \"probecycle-probing-plan\""),
                  std::string::npos);
        const CliRun ring = run_on_golden_day("program ring --dialect " + dialect);
        EXPECT_EQ(ring.out, read(data("golden/program_ring" + suffix)));
        const CliRun cycle = run_on_golden_day("program cycle --dialect " + dialect);
        EXPECT_EQ(cycle.out, read(data("golden/program_cycle" + suffix)));
    }
}

TEST(ProgramCli, ImportGivesTheCsvThatLatencyFitReads) {
    const TempDir dir;
    const std::string plan = quote((dir / "plan.json").string());
    ASSERT_EQ(run("program delay --dialect grbl --feeds 100,1000 --repeats 2 --plan " + plan +
                  " --out " + quote((dir / "p.nc").string()))
                  .exit_code,
              0);
    std::string console = "[PRB:0.000,0.000,-20.000:1]\nok\n";
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
    write(dir / "bad.txt", "[PRB:0.000,0.000,-20.000:1]\n[PRB:0.000,0.000,-20.000:0]\n");
    const CliRun bad =
        run("import --dialect grbl --plan " + plan + " " + quote((dir / "bad.txt").string()));
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_EQ(bad.out, "");
    EXPECT_NE(bad.err.find("bad.txt: line 2: the probe did not trigger"), std::string::npos)
        << bad.err;
}

TEST(ProgramCli, BadInputIsNamedWithWhatIsAllowed) {
    const struct {
        std::string arguments;
        std::string message;
    } cases[] = {
        {"program delay --dialect siemens",
         "--dialect: got 'siemens'; allowed: linuxcnc, grbl, fanuc"},
        {"program delay --dialect grbl --axis A+", "--axis: got 'A+'; allowed: X+, X-, Y+"},
        {"program delay --dialect grbl --feeds 30,abc", "--feeds: got 'abc'; allowed: a number"},
        {"program delay --dialect grbl --feeds 100,100",
         "--feeds: got 100; allowed: from 2 to 20 different feeds"},
        {"program delay --dialect grbl --repeats 0", "--repeats: got '0'; allowed: a whole number"},
        {"program cycle --dialect grbl --set cycle.feature=bore",
         "cycle.feature: got bore; allowed: surface"},
        {"program ring --dialect grbl --gauge-diameter-mm 6.5",
         "the gauge (6.5 mm) leaves the ball"},
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
