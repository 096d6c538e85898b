// LinuxCNC's own interpreter checks the LinuxCNC programs (issue 13, "A real
// interpreter checks us"): rs274, the stand-alone interpreter of the Debian
// package linuxcnc-uspace, runs every program the tests write
// (`rs274 -g FILE`: batch mode, the canonical calls on stdout). It must read
// every line without an error, and its STRAIGHT_PROBE calls must be the
// plan's probes: the axis, the signed incremental distance from the position
// before the probe (the plans precede every probe by a plain move or the
// start), and the feed. The probing moves' ends in rs274 are its simulation,
// so the moves after them are not compared.
//
// Without rs274 the test is skipped with a message; CI installs the package
// (.ci/install-deps.sh) and sets PROBECYCLE_REQUIRE_RS274=1, which makes a
// missing rs274 a failure.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "core/program/program_writer.h"
#include "tests/core/program/program_test_plans.h"

namespace probecycle {
namespace {

namespace fs = std::filesystem;

std::string find_rs274() {
    for (const char* dir : {"/usr/bin", "/usr/local/bin"}) {
        const fs::path path = fs::path(dir) / "rs274";
        if (fs::exists(path)) return path.string();
    }
    return {};
}

struct Rs274Run {
    int exit_code{-1};
    std::string output;
};

Rs274Run run(const std::string& command) {
    Rs274Run result;
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) return result;
    std::array<char, 4096> buffer{};
    std::size_t n = 0;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
        result.output.append(buffer.data(), n);
    }
    const int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

struct CanonProbe {
    char axis{'?'};
    double distance_mm{0.0};
    double feed_mm_min{0.0};
};

// The probes rs274 printed, each as an incremental move along one axis.
std::vector<CanonProbe> probes_of(const std::string& output, std::size_t& logs) {
    static const std::regex call(R"(N\.+\s+(\w+)\((.*)\))");
    std::vector<CanonProbe> probes;
    std::array<double, 3> position{};
    double feed = 0.0;
    logs = 0;
    std::size_t start = 0;
    while (start < output.size()) {
        std::size_t end = output.find('\n', start);
        if (end == std::string::npos) end = output.size();
        const std::string line = output.substr(start, end - start);
        start = end + 1;
        std::smatch m;
        if (!std::regex_search(line, m, call)) continue;
        const std::string name = m[1];
        std::vector<double> args;
        std::string list = m[2];
        for (std::size_t at = 0; at <= list.size();) {
            std::size_t comma = list.find(',', at);
            if (comma == std::string::npos) comma = list.size();
            args.push_back(std::atof(list.substr(at, comma - at).c_str()));
            at = comma + 1;
        }
        if (name == "SET_FEED_RATE") feed = args.at(0);
        if (name == "LOG" && list.find("probecycle touch") != std::string::npos) ++logs;
        if (name == "STRAIGHT_TRAVERSE" || name == "STRAIGHT_FEED") {
            position = {args.at(0), args.at(1), args.at(2)};
        }
        if (name == "STRAIGHT_PROBE") {
            CanonProbe probe;
            int moved = 0;
            for (int a = 0; a < 3; ++a) {
                const double d =
                    args.at(static_cast<std::size_t>(a)) - position[static_cast<std::size_t>(a)];
                if (std::abs(d) > 1e-9) {
                    probe.axis = "XYZ"[a];
                    probe.distance_mm = d;
                    ++moved;
                }
            }
            if (moved != 1) probe.axis = '?';
            probe.feed_mm_min = feed;
            probes.push_back(probe);
            position = {args.at(0), args.at(1), args.at(2)};
        }
    }
    return probes;
}

TEST(Rs274Check, EveryLinuxCncProgramReadsAndProbesAsPlanned) {
    const std::string rs274 = find_rs274();
    if (rs274.empty()) {
        if (std::getenv("PROBECYCLE_REQUIRE_RS274") != nullptr) {
            FAIL() << "rs274 is missing, and PROBECYCLE_REQUIRE_RS274 is set (CI installs "
                      "linuxcnc-uspace)";
        }
        GTEST_SKIP() << "rs274 (LinuxCNC's stand-alone interpreter) is not installed: "
                        "apt-get install linuxcnc-uspace to run this check";
    }
    std::random_device seed;
    const fs::path dir = fs::temp_directory_path() / ("probecycle_rs274_" + std::to_string(seed()));
    fs::create_directories(dir);
    for (const auto& [name, plan] : program_test::golden_plans()) {
        const fs::path file = dir / ("program_" + name + ".ngc");
        std::ofstream(file) << write_program(plan, linuxcnc_dialect(), program_test::kDate);
        const Rs274Run result = run("cd '" + dir.string() + "' && " + rs274 + " -g '" +
                                    file.string() + "' </dev/null 2>&1");
        EXPECT_EQ(result.exit_code, 0) << name << ":\n" << result.output;
        std::size_t logs = 0;
        const std::vector<CanonProbe> probes = probes_of(result.output, logs);
        std::vector<const ProgramStep*> planned;
        for (const ProgramStep& step : plan.steps) {
            if (step.kind == StepKind::probe) planned.push_back(&step);
        }
        ASSERT_EQ(probes.size(), planned.size()) << name << ":\n" << result.output;
        for (std::size_t i = 0; i < probes.size(); ++i) {
            SCOPED_TRACE(name + ", probe " + std::to_string(i + 1));
            EXPECT_EQ(probes[i].axis, planned[i]->axis);
            EXPECT_NEAR(probes[i].distance_mm, planned[i]->direction * planned[i]->distance_mm,
                        1e-4);
            EXPECT_DOUBLE_EQ(probes[i].feed_mm_min, planned[i]->feed_mm_min);
        }
        EXPECT_EQ(logs, plan.recorded().size()) << name;
    }
    fs::remove_all(dir);
}

TEST(Rs274Check, AnInterpreterErrorFailsTheCheck) {
    const std::string rs274 = find_rs274();
    if (rs274.empty()) GTEST_SKIP() << "rs274 is not installed (apt-get install linuxcnc-uspace)";
    std::random_device seed;
    const fs::path file =
        fs::temp_directory_path() / ("probecycle_rs274_bad_" + std::to_string(seed()) + ".ngc");
    std::ofstream(file) << "G21 G91\nG38.2 F30\nM2\n";  // a probe without an axis word
    const Rs274Run result = run(rs274 + " -g '" + file.string() + "' </dev/null 2>&1");
    EXPECT_NE(result.exit_code, 0) << result.output;
    fs::remove(file);
}

}  // namespace
}  // namespace probecycle
