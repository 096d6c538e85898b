// compare run, compare cerrors, compare simulate as a user runs them: the
// JSON contract's keys, the simulator's data against its truth, and every
// refusal naming the file, the line and the column with nothing written.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/cli/cli_run.h"

namespace probecycle::cli_test {
namespace {

using Json = nlohmann::json;

const std::string kSet = data("comparison") + "/";

std::string run_args(const std::string& dir) {
    return "compare run --plan " + quote(dir + "plan.csv") + " --reference-cmm " +
           quote(dir + "reference_cmm.csv") + " --test-omm " + quote(dir + "test_omm.csv") +
           " --reference-omm " + quote(dir + "reference_omm.csv") + " --c-axis 200,100";
}

std::string block_args(const std::string& dir) {
    return " --block-c0 " + quote(dir + "block_c0.csv") + " --block-c180 " +
           quote(dir + "block_c180.csv");
}

std::vector<double> truth_of(const std::string& path) {
    std::vector<double> truth;
    std::istringstream in(read(path));
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) truth.push_back(std::stod(line.substr(line.rfind(',') + 1)));
    return truth;
}

TEST(CompareCli, RunPrintsTheDocumentedKeys) {
    const CliRun r = run(run_args(kSet) + block_args(kSet) + " --tolerance 0.01");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json j = Json::parse(r.out);
    for (const char* key : {"ex_rad", "ey_rad", "ez_rad", "dx_mm", "dy_mm", "dz_mm"}) {
        EXPECT_TRUE(j.at("c_axis").at(key).is_number()) << key;
        EXPECT_TRUE(j.at("c_axis").at("uncertainty").at(key).is_number()) << key;
    }
    ASSERT_EQ(j.at("points").size(), 192u);
    for (const char* key :
         {"x_mm", "y_mm", "z_mm", "deviation_mm", "direct_deviation_mm", "system_error_mm"}) {
        EXPECT_TRUE(j.at("points")[0].at(key).is_number()) << key;
    }
    for (const char* group : {"deviation", "direct", "system_error"}) {
        for (const char* key : {"min_mm", "max_mm", "mean_mm", "rms_mm"}) {
            EXPECT_TRUE(j.at("summary").at(group).at(key).is_number()) << group << key;
        }
    }
    EXPECT_TRUE(j.at("summary").at("out_of_tolerance").is_number_integer());
    EXPECT_TRUE(j.at("warnings").is_array());
}

TEST(CompareCli, SimulatedDataAgreeWithTheirTruth) {
    const TempDir dir;
    const std::string d = dir.path().string() + "/";
    const CliRun sim = run("compare simulate --out " + quote(d + "set") + " --seed 4");
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
    const Json made = Json::parse(sim.out);
    EXPECT_EQ(made.at("files").size(), 8u);
    EXPECT_TRUE(made.at("true_c_axis").at("ez_rad").is_number());
    const CliRun r = run(run_args(d + "set/") + block_args(d + "set/"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json j = Json::parse(r.out);
    const std::vector<double> truth = truth_of(d + "set/truth.csv");
    ASSERT_EQ(truth.size(), j.at("points").size());
    double sum_sq = 0.0;
    double direct_sq = 0.0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        const double e = j["points"][i]["deviation_mm"].get<double>() - truth[i];
        const double de = j["points"][i]["direct_deviation_mm"].get<double>() - truth[i];
        sum_sq += e * e;
        direct_sq += de * de;
    }
    EXPECT_LT(std::sqrt(sum_sq / static_cast<double>(truth.size())), 0.0005);
    EXPECT_GT(std::sqrt(direct_sq / static_cast<double>(truth.size())), 0.010);
    EXPECT_NEAR(j["c_axis"]["ez_rad"].get<double>(), made["true_c_axis"]["ez_rad"].get<double>(),
                1e-7);
}

TEST(CompareCli, CerrorsPrintsTheErrorsCornersAndPlanes) {
    const CliRun r =
        run("compare cerrors" + block_args(kSet) + " --c-axis 200,100 --angle-deg 180");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json j = Json::parse(r.out);
    EXPECT_TRUE(j.at("c_axis").at("uncertainty").at("ex_rad").is_number());
    ASSERT_EQ(j.at("blocks").size(), 2u);
    EXPECT_EQ(j["blocks"][0]["planes"].size(), 3u);
    EXPECT_EQ(j["blocks"][1]["corner_mm"].size(), 3u);
}

TEST(CompareCli, TheReportIsTheTabsCsv) {
    const TempDir dir;
    const std::string report = (dir / "report.csv").string();
    const CliRun r = run(run_args(kSet) + block_args(kSet) + " --report " + quote(report));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string text = read(report);
    // The header of every report, the test part's file as its subject.
    EXPECT_EQ(text.rfind("# ProbeCycle comparison report\n# date,", 0), 0u) << text;
    EXPECT_NE(text.find("\n# test_omm,test_omm.csv\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\n# c_axis\n"), std::string::npos);
    EXPECT_NE(text.find("\n# points\npoint,x_mm,y_mm,z_mm,i,j,k,deviation_mm"), std::string::npos);
}

struct BadInput {
    const char* name;
    const char* file;      // which input to replace
    std::string content;   // its text
    std::string expected;  // part of the message
};

TEST(CompareCli, BadInputNamesTheFileLineAndColumnAndWritesNothing) {
    const std::string plan = read(kSet + "plan.csv");
    std::string short_points = read(kSet + "test_omm.csv");
    short_points.erase(short_points.rfind('\n', short_points.size() - 2) + 1);
    const std::vector<BadInput> cases = {
        {"count", "test_omm.csv", short_points,
         "test_omm.csv: line 192: the file ends after 191 points; the plan has 192"},
        {"normal", "plan.csv", plan + "300,90,21,0,0,0.5\n",
         "plan.csv: line 194, column i: the normal (i, j, k) has length 0.5"},
        {"zero normal", "plan.csv", plan + "300,90,21,0,0,0\n", "length 0;"},
        {"nan", "reference_cmm.csv", "x_mm,y_mm,z_mm\nnan,1,2\n",
         "reference_cmm.csv: line 2, column x_mm: 'nan' is not a number"},
        {"column", "reference_omm.csv", "x_mm,y_mm\n1,2\n", "reference_omm.csv"},
        {"few", "plan.csv", "x_mm,y_mm,z_mm,i,j,k\n1,2,3,0,0,1\n",
         "plan.csv: line 2: a comparison needs 16 points or more; got 1"},
        {"face", "block_c0.csv",
         "face,x_mm,y_mm,z_mm\nA,1,2,3\nA,2,2,3\nA,1,5,3\nB,1,2,3\nB,2,2,3\n",
         "block_c0.csv: line 6, column face: touches on face B: 2"},
    };
    for (const BadInput& c : cases) {
        const TempDir dir;
        for (const char* name : {"plan.csv", "reference_cmm.csv", "test_omm.csv",
                                 "reference_omm.csv", "block_c0.csv", "block_c180.csv"}) {
            write(dir / name, name == std::string(c.file) ? c.content : read(kSet + name));
        }
        const std::string d = dir.path().string() + "/";
        const CliRun r = run(run_args(d) + block_args(d) + " --report " + quote(d + "report.csv"));
        EXPECT_EQ(r.exit_code, 2) << c.name;
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.name << ": " << r.err;
        EXPECT_TRUE(r.out.empty()) << c.name;
        EXPECT_FALSE(fs::exists(dir / "report.csv")) << c.name;
    }
}

TEST(CompareCli, BadOptionsSayWhatIsAllowed) {
    const CliRun half = run(run_args(kSet) + " --block-c0 " + quote(kSet + "block_c0.csv"));
    EXPECT_EQ(half.exit_code, 2);
    EXPECT_NE(half.err.find("--block-c0 and --block-c180 together"), std::string::npos) << half.err;
    const CliRun axis = run("compare cerrors" + block_args(kSet) + " --c-axis 200");
    EXPECT_EQ(axis.exit_code, 2);
    EXPECT_NE(axis.err.find("expected two coordinates X,Y"), std::string::npos) << axis.err;
    const CliRun angle =
        run("compare cerrors" + block_args(kSet) + " --c-axis 200,100 --angle-deg 0");
    EXPECT_EQ(angle.exit_code, 2);
    EXPECT_NE(angle.err.find("--angle-deg"), std::string::npos) << angle.err;
    const CliRun verb = run("compare frobnicate");
    EXPECT_EQ(verb.exit_code, 2);
    EXPECT_NE(verb.err.find("allowed: run, cerrors, simulate"), std::string::npos) << verb.err;
    const CliRun noise = run("compare simulate --out /tmp/never --noise-mm -1");
    EXPECT_EQ(noise.exit_code, 2);
    EXPECT_NE(noise.err.find("--noise-mm"), std::string::npos) << noise.err;
}

}  // namespace
}  // namespace probecycle::cli_test
