// probecycle-cli's generated --help, and the CLI reference in docs/cli.md, name
// the same options; integers are integers and numbers decimal.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_run.h"

namespace {

using probecycle::cli_test::CliRun;

// Runs the CLI with `arguments` (shell words); with `with_stderr`, stderr
// follows stdout in `out`.
CliRun run_cli(const std::string& arguments, bool with_stderr = false) {
    CliRun run = probecycle::cli_test::run(arguments + " </dev/null");
    if (with_stderr) run.out += run.err;
    return run;
}

std::set<std::string> options_in(const std::string& text) {
    static const std::regex option(R"(--[a-z][a-z0-9-]*[a-z0-9])");
    std::set<std::string> found;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), option);
         it != std::sregex_iterator(); ++it) {
        found.insert(it->str());
    }
    found.erase("--help");
    return found;
}

const std::vector<std::string> kCommands = {"",
                                            "defaults",
                                            "evaluate",
                                            "move",
                                            "sweep",
                                            "report",
                                            "montecarlo",
                                            "optimise",
                                            "calibrate",
                                            "calibrate ring",
                                            "calibrate length",
                                            "latency",
                                            "latency fit",
                                            "latency compensate",
                                            "compare",
                                            "compare run",
                                            "compare cerrors",
                                            "compare simulate",
                                            "program",
                                            "program delay",
                                            "program ring",
                                            "program cycle",
                                            "import",
                                            "machine",
                                            "machine linuxcnc"};

TEST(CliHelp, EveryCommandHasHelpOnStdoutAndExitsZero) {
    for (const std::string& command : kCommands) {
        SCOPED_TRACE(command);
        const CliRun run = run_cli(command + " --help");
        EXPECT_EQ(run.exit_code, 0);
        EXPECT_NE(run.out.find("usage: probecycle-cli"), std::string::npos) << run.out;
    }
    // "help" as a word does the same.
    EXPECT_EQ(run_cli("latency help").exit_code, 0);
    EXPECT_EQ(run_cli("help").exit_code, 0);
}

// The version the window prints (probecycle --version) and the package
// carries: the project's.
TEST(CliHelp, VersionIsThePackagesOnStdout) {
    const CliRun run = run_cli("--version");
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(run.out, "ProbeCycle " PROBECYCLE_VERSION "\n");
    EXPECT_EQ(run.err, "");
}

// A page of docs/, up to the line `stop` (the whole page when `stop` is empty or
// not there).
std::string doc_page(const char* path, const std::string& stop = "") {
    std::ifstream in(path);
    std::string line;
    std::string page;
    while (std::getline(in, line) && (stop.empty() || line != stop)) page += line + '\n';
    return page;
}

TEST(CliHelp, TheCliReferenceNamesEveryOptionAndNoOther) {
    std::set<std::string> in_help;
    for (const std::string& command : kCommands) {
        for (const std::string& option : options_in(run_cli(command + " --help").out)) {
            in_help.insert(option);
        }
    }
    ASSERT_GT(in_help.size(), 20u);
    const std::string reference = doc_page(PROBECYCLE_CLI_DOC_PATH);
    ASSERT_NE(reference.find("# probecycle-cli"), std::string::npos)
        << PROBECYCLE_CLI_DOC_PATH << " is not the CLI reference";
    const std::set<std::string> in_reference = options_in(reference);
    for (const std::string& option : in_help) {
        EXPECT_TRUE(in_reference.count(option)) << option << " is in --help but not in docs/cli.md";
    }
    for (const std::string& option : in_reference) {
        EXPECT_TRUE(in_help.count(option)) << option << " is in docs/cli.md but no command has it";
    }
    // The page on programs explains `program` and `import` at length: it names
    // no option they lack either (its last section, on the LinuxCNC rig, runs
    // ctest, whose options are not ours).
    const std::string programs =
        doc_page(PROBECYCLE_PROGRAMS_DOC_PATH, "## Checked on a real controller");
    ASSERT_NE(programs.find("# Programs for your control"), std::string::npos)
        << PROBECYCLE_PROGRAMS_DOC_PATH << " is not the page on programs";
    for (const std::string& option : options_in(programs)) {
        EXPECT_TRUE(in_help.count(option))
            << option << " is in docs/programs.md but no command has it";
    }
}

struct Coercion {
    const char* arguments;
    const char* says;  // empty: accepted
};

class CliNumbers : public testing::TestWithParam<Coercion> {};

TEST_P(CliNumbers, IntegersAreIntegersAndNumbersDecimal) {
    const Coercion& c = GetParam();
    const CliRun run = run_cli(c.arguments, true);
    if (std::string(c.says).empty()) {
        EXPECT_EQ(run.exit_code, 0) << run.out;
    } else {
        EXPECT_EQ(run.exit_code, 2) << run.out;
        EXPECT_NE(run.out.find(c.says), std::string::npos) << run.out;
    }
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(Cli, CliNumbers, testing::Values(
    Coercion{"montecarlo --samples 3.7 --bins 10",            "--samples: got '3.7'; allowed: a whole number"},
    Coercion{"montecarlo --samples 100 --bins 2.9",           "--bins: got '2.9'"},
    Coercion{"montecarlo --samples 100 --seed 1.5",           "--seed: got '1.5'"},
    Coercion{"montecarlo --samples 100 --seed 0x10",          "--seed: got '0x10'"},
    Coercion{"montecarlo --samples 100 --seed 12",            ""},
    Coercion{"evaluate --set cycle.probe_feed_mm_min=0x10",   "cycle.probe_feed_mm_min: got 0x10"},
    Coercion{"evaluate --set 'cycle.probe_feed_mm_min= 1500'", ""},
    Coercion{"evaluate --set 'cycle.probe_feed_mm_min=1500 '", ""},
    Coercion{"move --distance 0x10 --feed 600",               "--distance: got '0x10'"},
    Coercion{"move --distance 1e3 --feed 600",                ""},
    Coercion{"latency compensate --lag-cycles 8.5",           "--lag-cycles: got '8.5'"},
    Coercion{"evaluate --bogus",                              "--bogus"},
    Coercion{"evaluate a.json b.json",                        "b.json"}));
// clang-format on

}  // namespace
