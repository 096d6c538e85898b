// Every output format of probecycle-cli, byte for byte against a golden file
// in tests/data/golden/, so that a change of format shows in review.
// To accept a deliberate change, regenerate them and read the diff:
//   PROBECYCLE_UPDATE_GOLDEN=1 ctest --test-dir build -R Golden
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_run.h"

namespace {

namespace fs = std::filesystem;

const fs::path kData = PROBECYCLE_TEST_DATA_DIR;
const fs::path kGolden = kData / "golden";

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The first line where the two texts differ, for the failure message.
std::string first_difference(const std::string& want, const std::string& got) {
    std::istringstream a(want);
    std::istringstream b(got);
    std::string la;
    std::string lb;
    for (int line = 1;; ++line) {
        const bool more_a = static_cast<bool>(std::getline(a, la));
        const bool more_b = static_cast<bool>(std::getline(b, lb));
        if (!more_a && !more_b) return "no line differs (line ends?)";
        if (!more_a || !more_b || la != lb) {
            return "line " + std::to_string(line) + ":\n- " + (more_a ? la : "<end>") + "\n+ " +
                   (more_b ? lb : "<end>");
        }
    }
}

#ifdef _WIN32
bool same_json_value(const nlohmann::json& a, const nlohmann::json& b) {
    if (a.is_number_float() || b.is_number_float()) {
        if (!a.is_number() || !b.is_number()) return false;
        const double x = a.get<double>();
        const double y = b.get<double>();
        return std::abs(x - y) <= 1e-9 * std::max(std::abs(x), std::abs(y)) + 1e-12;
    }
    if (a.type() != b.type()) return false;
    if (a.is_object()) {
        if (a.size() != b.size()) return false;
        for (auto it = a.begin(); it != a.end(); ++it) {
            if (!b.contains(it.key()) || !same_json_value(it.value(), b.at(it.key()))) return false;
        }
        return true;
    }
    if (a.is_array()) {
        if (a.size() != b.size()) return false;
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (!same_json_value(a[i], b[i])) return false;
        }
        return true;
    }
    return a == b;
}

bool same_json(const std::string& want, const std::string& got) {
    try {
        return same_json_value(nlohmann::json::parse(want), nlohmann::json::parse(got));
    } catch (const nlohmann::json::exception&) {
        return false;
    }
}
#endif

void expect_golden(const std::string& name, const std::string& got) {
    const fs::path path = kGolden / name;
    if (std::getenv("PROBECYCLE_UPDATE_GOLDEN") != nullptr) {
        std::ofstream(path, std::ios::binary) << got;
        return;
    }
    ASSERT_TRUE(fs::exists(path)) << path << " is missing";
    const std::string want = slurp(path);
#ifdef _WIN32
    // The Windows build's C library rounds the last bit of sin, atan2 ...
    // otherwise than glibc, and a JSON output prints every double in full.
    // A comparison's deviations are differences of positions near 100 mm,
    // whose last bit is 1.4e-14 mm: there the numbers may differ by 1e-9
    // relative plus 1e-12 (mm, rad) absolute, nothing else. (Seen: 1e-13 mm.)
    if (want != got && fs::path(name).extension() == ".json" && same_json(want, got)) return;
#endif
    EXPECT_TRUE(want == got) << name << " differs from its golden file; first difference at "
                             << first_difference(want, got);
}

struct Golden {
    const char* name;  // golden file of stdout; stderr goes to <stem>.stderr.txt when kept
    std::string arguments;
    bool keep_stderr{false};
};

class GoldenOutput : public testing::TestWithParam<Golden> {};

TEST_P(GoldenOutput, MatchesTheGoldenFileByteForByte) {
    const Golden& g = GetParam();
    const fs::path dir = fs::temp_directory_path() / ("probecycle-golden-" + std::string(g.name));
    fs::create_directories(dir);
    std::string arguments = g.arguments;
    const std::string report_marker = "REPORT";
    const std::size_t at = arguments.find(report_marker);
    if (at != std::string::npos) {
        arguments.replace(at, report_marker.size(),
                          probecycle::cli_test::quote((dir / "report.csv").string()));
    }
    // Run from tests/data so that relative input paths are the same everywhere,
    // on a fixed day: the reports' date is SOURCE_DATE_EPOCH's (2025-11-26).
    const fs::path before = fs::current_path();
    fs::current_path(kData);
    probecycle::cli_test::set_env("SOURCE_DATE_EPOCH", "1764115200");
    const probecycle::cli_test::CliRun run = probecycle::cli_test::run(arguments);
    probecycle::cli_test::set_env("SOURCE_DATE_EPOCH", nullptr);
    fs::current_path(before);
    ASSERT_TRUE(run.exited);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    const std::string out = run.out;
    const std::string err = run.err;
    expect_golden(g.name, out);
    if (g.keep_stderr) {
        const std::string stem = fs::path(g.name).stem().string();
        expect_golden(stem + ".stderr.txt", err);
    }
    if (at != std::string::npos) {
        const std::string stem = fs::path(g.name).stem().string();
        expect_golden(stem + "_report.csv", slurp(dir / "report.csv"));
    }
    fs::remove_all(dir);
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(Cli, GoldenOutput, testing::Values(
    Golden{"evaluate_default.json",   "evaluate"},
    Golden{"evaluate_bore.json",      "evaluate ../../resources/examples/bore_two_touch.json"},
    Golden{"evaluate_warnings.json",  "evaluate --set cycle.strategy=single_touch --set probe.calibration_feed_mm_min=500 --set cycle.approach_mm=0.5"},
    Golden{"move_jerk.json",          "move --distance 10 --feed 6000 --set machine.accel_model=jerk_limited"},
    Golden{"sweep_default.csv",       "sweep --from 100 --to 3000 --step 100", true},
    Golden{"sweep_recommended.csv",   "sweep --from 100 --to 3000 --step 100 --recommended-backoff", true},
    Golden{"report_default.csv",      "report"},
    Golden{"report_bore.csv",         "report ../../resources/examples/bore_two_touch.json"},
    Golden{"report_feature_bore.csv", "report --set cycle.feature=bore"},
    Golden{"optimise_bore.json",      "optimise ../../resources/examples/bore_two_touch.json --set cycle.parts_per_year=50000 --set cycle.cycles_per_part=2 --set cycle.machine_rate_per_hour=80 --pareto-points 6"},
    Golden{"montecarlo.json",         "montecarlo --samples 2000 --seed 7 --bins 20"},
    Golden{"calibrate_ring.json",     "calibrate ring lab_ring.csv --gauge-diameter 50 --report REPORT"},
    Golden{"calibrate_length.json",   "calibrate length --surface-z 10 --trigger-z 112.3456 --trigger-z 112.3461 --active-length 0 --nominal-length 102.34"},
    Golden{"latency_fit.json",        "latency fit lab_delay.csv --interpolation-period-s 0.001"},
    Golden{"latency_fit_scatter.json", "latency fit lab_delay_report.csv --interpolation-period-s 0.001 --report REPORT"},
    Golden{"latency_compensate.json", "latency compensate --touch braking --speed-fraction 0.3 --sweep 4"},
    Golden{"compare_run.json",        "compare run --plan comparison/plan.csv --reference-cmm comparison/reference_cmm.csv --test-omm comparison/test_omm.csv --reference-omm comparison/reference_omm.csv --c-axis 200,100 --block-c0 comparison/block_c0.csv --block-c180 comparison/block_c180.csv --tolerance 0.01 --report REPORT"},
    Golden{"machine_linuxcnc.json",   "machine linuxcnc linuxcnc/mill_inch.ini"},
    Golden{"compare_cerrors.json",    "compare cerrors --block-c0 comparison/block_c0.csv --block-c180 comparison/block_c180.csv --c-axis 200,100"}),
    [](const testing::TestParamInfo<Golden>& case_info) {
        std::string name = fs::path(case_info.param.name).stem().string();
        for (char& c : name) if (c == '.' || c == '-') c = '_';
        return name;
    });
// clang-format on

}  // namespace
