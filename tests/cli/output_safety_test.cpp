// Outputs never lost, half-written or wrong (issue 29): a failed write to
// standard output is an error, a refused command writes nothing, and an
// output of several files (a program and its plan, a comparison's set) is
// written whole or not at all.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "tests/cli/cli_run.h"

namespace probecycle::cli_test {
namespace {

// probecycle-cli with `arguments` and the shell redirection `redirect` of its
// standard output; stderr captured.
CliRun run_redirected(const std::string& arguments, const std::string& redirect) {
    const TempDir capture;
    const fs::path err = capture / "stderr";
    const std::string command = quote(PROBECYCLE_CLI_PATH) + " " + arguments + " " + redirect +
                                " 2>" + quote(err.string());
    const int status = std::system(command.c_str());
    CliRun result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.err = read(err);
    return result;
}

// Every command that prints, large output and small, and the help.
const char* const kPrinting[] = {"defaults", "evaluate", "report",
                                 "sweep --from 100 --to 2000 --step 10", "--help",
                                 "program --help"};

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
    const CliRun r = run_redirected(
        "sweep --from 100 --to 2000 --step 100 --csv " + quote(csv.string()), ">&-");
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

}  // namespace
}  // namespace probecycle::cli_test
