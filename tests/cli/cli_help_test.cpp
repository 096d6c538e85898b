// probecycle-cli's generated --help, and the README's CLI reference, name the
// same options; integers are integers and numbers decimal.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct CliRun {
    int exit_code{-1};
    std::string out;
};

// Runs the CLI with `arguments` (shell words), stdout captured, stderr
// appended to it when `with_stderr`.
CliRun run_cli(const std::string& arguments, bool with_stderr = false) {
    const std::string command = std::string("'") + PROBECYCLE_CLI_PATH + "' " + arguments +
                                (with_stderr ? " 2>&1" : " 2>/dev/null") + " </dev/null";
    CliRun run;
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) return run;
    char buffer[4096];
    std::size_t n = 0;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) run.out.append(buffer, n);
    const int status = pclose(pipe);
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
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

// The README's reference: from "## probecycle-cli" to the next "## " heading.
std::string readme_cli_reference() {
    std::ifstream in(PROBECYCLE_README_PATH);
    std::string line;
    std::string section;
    bool inside = false;
    while (std::getline(in, line)) {
        if (line.rfind("## ", 0) == 0) inside = line == "## probecycle-cli";
        if (inside) section += line + '\n';
    }
    return section;
}

TEST(CliHelp, TheReadmeNamesEveryOptionAndNoOther) {
    std::set<std::string> in_help;
    for (const std::string& command : kCommands) {
        for (const std::string& option : options_in(run_cli(command + " --help").out)) {
            in_help.insert(option);
        }
    }
    ASSERT_GT(in_help.size(), 20u);
    const std::string readme = readme_cli_reference();
    ASSERT_FALSE(readme.empty()) << "README.md has no '## probecycle-cli' section";
    const std::set<std::string> in_readme = options_in(readme);
    for (const std::string& option : in_help) {
        EXPECT_TRUE(in_readme.count(option)) << option << " is in --help but not in the README";
    }
    for (const std::string& option : in_readme) {
        EXPECT_TRUE(in_help.count(option)) << option << " is in the README but no command has it";
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
