// LinuxCNC's own interpreter checks the LinuxCNC programs (docs/programs.md,
// "What is verified"): rs274, the stand-alone interpreter of the Debian
// package linuxcnc-uspace, runs every program the tests write
// (`rs274 -g FILE`: batch mode, the canonical calls on stdout). It must read
// every line without an error, and its STRAIGHT_PROBE calls must be the
// plan's probes and protected moves (G38.3 prints as STRAIGHT_PROBE too): the
// axis, the signed incremental distance from the position before it, and the
// feed. rs274 simulates every probe as tripping at its end and backing off
// 0.254 mm toward where it started (STRAIGHT_PROBE, src/emc/sai/saicanon.cc),
// so the next move starts there; the plain moves are not compared. With
// #5070 read as 1 (a trip), the abort branch after a protected move stops the
// program.
//
// Without rs274 the test is skipped with a message; CI installs the package
// (.ci/install-deps.sh) and sets PROBECYCLE_REQUIRE_RS274=1, which makes a
// missing rs274 a failure.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
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

// How far rs274's simulated probe backs off after the trip, in mm
// (saicanon.cc: 0.254 mm, 0.01 inch).
constexpr double kRs274Backoff_mm = 0.254;

// `rs274 -g FILE` in `dir`, with HOME there too: LinuxCNC 2.9's rs274 opens
// $HOME/.tool.mmap with O_TRUNC and maps it shared (tool_mmap_creator,
// src/emc/tooldata/tooldata_mmap.cc), so two runs at once under one HOME
// (ctest -j) truncate each other's map and die with a bus error, and a run
// would empty the tool table of a LinuxCNC running under that HOME. Later
// versions give rs274 a file of its own (src/emc/sai/driver.cc).
Rs274Run run_rs274(const std::string& rs274, const fs::path& dir, const fs::path& file) {
    return run("cd '" + dir.string() + "' && HOME='" + dir.string() + "' " + rs274 + " -g '" +
               file.string() + "' </dev/null 2>&1");
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
            std::size_t axis = 0;
            for (std::size_t a = 0; a < 3; ++a) {
                const double d = args.at(a) - position[a];
                if (std::abs(d) > 1e-9) {
                    probe.axis = "XYZ"[a];
                    probe.distance_mm = d;
                    axis = a;
                    ++moved;
                }
            }
            if (moved != 1) probe.axis = '?';
            probe.feed_mm_min = feed;
            probes.push_back(probe);
            position = {args.at(0), args.at(1), args.at(2)};
            // saicanon.cc: the probe trips at the end and backs off 0.254 mm
            // (in mm) toward where it came from.
            if (moved == 1) position[axis] -= std::copysign(kRs274Backoff_mm, probe.distance_mm);
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
    std::vector<program_test::NamedPlan> plans = program_test::golden_plans();
    plans.push_back({"guarded", program_test::guarded_plan()});
    for (const auto& [name, plan] : plans) {
        const fs::path file = dir / ("program_" + name + ".ngc");
        std::ofstream(file) << write_program(plan, linuxcnc_dialect(), program_test::kDate);
        const Rs274Run result = run_rs274(rs274, dir, file);
        EXPECT_EQ(result.exit_code, 0) << name << ":\n" << result.output;
        std::size_t logs = 0;
        const std::vector<CanonProbe> probes = probes_of(result.output, logs);
        std::vector<const ProgramStep*> planned;
        for (const ProgramStep& step : plan.steps) {
            if (step.kind == StepKind::probe || step.kind == StepKind::guard) {
                planned.push_back(&step);
            }
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

// A protected move that trips (#5070 read as 1, which rs274's simulation
// never gives) stops the program at once with the abort's message.
TEST(Rs274Check, AProtectedMoveThatTripsAbortsTheProgram) {
    const std::string rs274 = find_rs274();
    if (rs274.empty()) GTEST_SKIP() << "rs274 is not installed (apt-get install linuxcnc-uspace)";
    std::string text =
        write_program(program_test::guarded_plan(), linuxcnc_dialect(), program_test::kDate);
    const std::size_t test = text.find("[#5070 EQ 1]");
    ASSERT_NE(test, std::string::npos) << text;
    text.replace(test, 12, "[1 EQ 1]");
    std::random_device seed;
    const fs::path dir =
        fs::temp_directory_path() / ("probecycle_rs274_abort_" + std::to_string(seed()));
    fs::create_directories(dir);
    const fs::path file = dir / "guarded.ngc";
    std::ofstream(file) << text;
    const Rs274Run result = run_rs274(rs274, dir, file);
    EXPECT_NE(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("the path is obstructed"), std::string::npos) << result.output;
    std::size_t logs = 0;
    EXPECT_EQ(probes_of(result.output, logs).size(), 1u) << result.output;
    fs::remove_all(dir);
}

// A size out of tolerance with cycle.tolerance_action stop: under the task
// (#<_task> read as 1, which rs274 never gives) the program writes the line
// and aborts after every probe; rs274's probes trip at their searches' ends,
// so the pocket measures far off its nominal size. In a preview (rs274 as it
// is) the same program runs to its end (EveryLinuxCncProgram... above).
TEST(Rs274Check, ASizeOutOfToleranceStopsTheProgramUnderTheTask) {
    const std::string rs274 = find_rs274();
    if (rs274.empty()) GTEST_SKIP() << "rs274 is not installed (apt-get install linuxcnc-uspace)";
    const ProbingPlan pocket =
        make_cycle_plan(program_test::golden_pocket(), CyclePlanOptions{{'Y', 1}, 4.0});
    std::string text = write_program(pocket, linuxcnc_dialect(), program_test::kDate);
    const std::size_t test = text.find("[#<_task> EQ 1]");
    ASSERT_NE(test, std::string::npos) << text;
    text.replace(test, 15, "[1 EQ 1]");
    std::random_device seed;
    const fs::path dir =
        fs::temp_directory_path() / ("probecycle_rs274_tolerance_" + std::to_string(seed()));
    fs::create_directories(dir);
    const fs::path file = dir / "pocket.ngc";
    std::ofstream(file) << text;
    const Rs274Run result = run_rs274(rs274, dir, file);
    EXPECT_NE(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("the measured size is out of tolerance"), std::string::npos)
        << result.output;
    std::size_t logs = 0;
    EXPECT_EQ(probes_of(result.output, logs).size(),
              static_cast<std::size_t>(std::count_if(pocket.steps.begin(), pocket.steps.end(),
                                                     [](const ProgramStep& step) {
                                                         return step.kind == StepKind::probe ||
                                                                step.kind == StepKind::guard;
                                                     })))
        << result.output;
    fs::remove_all(dir);
}

TEST(Rs274Check, AnInterpreterErrorFailsTheCheck) {
    const std::string rs274 = find_rs274();
    if (rs274.empty()) GTEST_SKIP() << "rs274 is not installed (apt-get install linuxcnc-uspace)";
    std::random_device seed;
    const fs::path dir =
        fs::temp_directory_path() / ("probecycle_rs274_bad_" + std::to_string(seed()));
    fs::create_directories(dir);
    const fs::path file = dir / "bad.ngc";
    std::ofstream(file) << "G21 G91\nG38.2 F30\nM2\n";  // a probe without an axis word
    const Rs274Run result = run_rs274(rs274, dir, file);
    EXPECT_NE(result.exit_code, 0) << result.output;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace probecycle
