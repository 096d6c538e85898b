// Outputs never lost, half-written or wrong (docs/files.md, "Limits on input
// and output"): a failed write to standard output is an error, a refused
// command writes nothing, and an output of several files (a program and its
// plan, a comparison's set) is written whole or not at all.

#include <gtest/gtest.h>
#ifndef _WIN32
#include <sys/wait.h>
#endif

#include <cstdlib>
#include <string>

#include "tests/cli/cli_run.h"

namespace probecycle::cli_test {
namespace {

#ifndef _WIN32  // /dev/full and a closed stream: a POSIX shell's
// probecycle-cli with `arguments` and the shell redirection `redirect` of its
// standard output; stderr captured.
CliRun run_redirected(const std::string& arguments, const std::string& redirect) {
    const TempDir capture;
    const fs::path err = capture / "stderr";
    const std::string command =
        quote(PROBECYCLE_CLI_PATH) + " " + arguments + " " + redirect + " 2>" + quote(err.string());
    const int status = std::system(command.c_str());
    CliRun result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.err = read(err);
    return result;
}

// Every command that prints, large output and small, and the help.
const char* const kPrinting[] = {"defaults", "evaluate",
                                 "report",   "sweep --from 100 --to 2000 --step 10",
                                 "--help",   "program --help"};

TEST(StandardOutput, AFullDiskIsAnErrorNotSuccess) {
    for (const char* arguments : kPrinting) {
        const CliRun r = run_redirected(arguments, ">/dev/full");
        EXPECT_EQ(r.exit_code, 2) << arguments;
        EXPECT_NE(r.err.find("cannot write the standard output: No space left on device"),
                  std::string::npos)
            << arguments << ": " << r.err;
    }
}

TEST(StandardOutput, AClosedStandardOutputIsAnErrorNotSuccess) {
    for (const char* arguments : kPrinting) {
        const CliRun r = run_redirected(arguments, ">&-");
        EXPECT_EQ(r.exit_code, 2) << arguments;
        EXPECT_NE(r.err.find("cannot write the standard output"), std::string::npos)
            << arguments << ": " << r.err;
    }
}

TEST(StandardOutput, AClosedStandardOutputNeverReachesAFileTheCommandWrites) {
    // With stdout closed, the first file the program opens would take its
    // number and receive what was meant for stdout.
    const TempDir dir;
    const fs::path csv = dir / "sweep.csv";
    const CliRun r =
        run_redirected("sweep --from 100 --to 2000 --step 100 --csv " + quote(csv.string()), ">&-");
    EXPECT_EQ(r.exit_code, 0) << r.err;  // the sweep prints nothing on stdout
    const std::string written = read(csv);
    EXPECT_EQ(written.find("probecycle-cli"), std::string::npos) << written.substr(0, 200);
    EXPECT_EQ(written.rfind("feed_mm_min,", 0), 0u) << written.substr(0, 200);
}

TEST(StandardOutput, ACommandWritingToAFileIgnoresAFullStandardOutput) {
    const TempDir dir;
    const fs::path report = dir / "report.csv";
    const CliRun r = run_redirected("report --csv " + quote(report.string()), ">/dev/full");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(read(report).empty());
}

#endif

std::size_t entries_in(const fs::path& dir) {
    return static_cast<std::size_t>(
        std::distance(fs::directory_iterator(dir), fs::directory_iterator{}));
}

TEST(ProgramAndPlan, ARefusedProgramLeavesNoPlan) {
    // Before, the plan was written, then --out (a folder) refused.
    const TempDir dir;
    fs::create_directory(dir / "folder");
    const CliRun r =
        run("program delay --dialect linuxcnc --plan " + quote((dir / "plan.json").string()) +
            " --out " + quote((dir / "folder").string()));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("it is a directory"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "plan.json"));
    EXPECT_EQ(entries_in(dir.path()), 1u);
}

TEST(ProgramAndPlan, ARefusedPlanLeavesTheOldProgram) {
    const TempDir dir;
    write(dir / "probe.ngc", "old program\n");
    fs::create_directory(dir / "plan.json");
    const CliRun r =
        run("program delay --dialect linuxcnc --plan " + quote((dir / "plan.json").string()) +
            " --out " + quote((dir / "probe.ngc").string()));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(read(dir / "probe.ngc"), "old program\n");
    EXPECT_EQ(entries_in(dir.path()), 2u);
}

TEST(ProgramAndPlan, OneFileForBothIsRefused) {
    const TempDir dir;
    const std::string same = quote((dir / "probe.ngc").string());
    const CliRun r = run("program delay --dialect linuxcnc --plan " + same + " --out " + same);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("give each output a file of its own"), std::string::npos) << r.err;
    EXPECT_EQ(entries_in(dir.path()), 0u);
}

#ifndef _WIN32
TEST(ProgramAndPlan, AProgramLostOnStandardOutputLeavesNoPlan) {
    const TempDir dir;
    const CliRun r = run_redirected(
        "program delay --dialect linuxcnc --plan " + quote((dir / "plan.json").string()),
        ">/dev/full");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_FALSE(fs::exists(dir / "plan.json"));
}
#endif

TEST(SimulatedSet, ARefusalLeavesNoFileAndTheOldSetWhole) {
    // Before, a refusal at the seventh file left six new files beside two old.
    const TempDir dir;
    const std::string set = (dir / "set").string();
    ASSERT_EQ(run("compare simulate --seed 1 --out " + quote(set)).exit_code, 0);
    const std::string old_plan = read(dir / "set" / "plan.csv");
    fs::remove(dir / "set" / "truth.csv");
    fs::create_directory(dir / "set" / "truth.csv");
    const CliRun r = run("compare simulate --seed 2 --out " + quote(set));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("truth.csv"), std::string::npos) << r.err;
    EXPECT_EQ(read(dir / "set" / "plan.csv"), old_plan);
    EXPECT_EQ(entries_in(dir.path()), 1u);  // no temporary folder beside it
}

TEST(SimulatedSet, ASecondSeedReplacesTheWholeSet) {
    const TempDir dir;
    const std::string set = (dir / "set").string();
    ASSERT_EQ(run("compare simulate --seed 1 --noise-mm 0.001 --out " + quote(set)).exit_code, 0);
    const std::string first = read(dir / "set" / "test_omm.csv");
    ASSERT_EQ(run("compare simulate --seed 2 --noise-mm 0.001 --out " + quote(set)).exit_code, 0);
    EXPECT_NE(read(dir / "set" / "test_omm.csv"), first);
    EXPECT_NE(read(dir / "set" / "simulation.json").find("\"seed\": 2"), std::string::npos);
    EXPECT_EQ(entries_in(dir / "set"), 8u);
    EXPECT_EQ(entries_in(dir.path()), 1u);
}

TEST(SimulatedSet, AFolderWithTheUsersFilesIsRefusedAndKept) {
    const TempDir dir;
    fs::create_directory(dir / "work");
    write(dir / "work" / "notes.txt", "mine\n");
    const CliRun r = run("compare simulate --out " + quote((dir / "work").string()));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("notes.txt"), std::string::npos) << r.err;
    EXPECT_EQ(entries_in(dir / "work"), 1u);
}

}  // namespace
}  // namespace probecycle::cli_test
