// The project file (core/project/project_file.h): a round trip keeps every
// value, the format is pinned by a golden file, and a bad file is refused
// naming each problem by its dotted key.
// To accept a deliberate change of format, regenerate and read the diff:
//   PROBECYCLE_UPDATE_GOLDEN=1 ctest --test-dir build -R Golden
#include "core/project/project_file.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/common/file_io.h"
#include "tests/core/common/line_ends.h"

namespace probecycle {
namespace {

namespace fs = std::filesystem;

// A project with a value other than the default in every key.
Project sample_project() {
    Project p;
    p.scenario.cycle.strategy = Strategy::two_touch;
    p.scenario.cycle.probe_feed_mm_min = 2500.0;
    p.scenario.probe.interface_delay_s = 0.004;
    Scenario baseline;
    baseline.cycle.probe_feed_mm_min = 1200.0;
    p.baseline = baseline;
    p.ring.points_csv = "orientation_deg,x_mm,y_mm\n0,25.001,0\n";
    p.ring.fitted_csv =
        "orientation_deg,x_mm,y_mm\n0,25,0\n0,0,25\n0,-25,0\n180,25.01,0\n180,0,25\n180,-24.99,0\n";
    p.ring.options.gauge_diameter_mm = 50.002;
    p.ring.options.runout_limit_mm = 0.02;
    p.ring.options.residual_limit_mm = 0.003;
    p.ring.magnification = 1000.0;
    p.length.surface_z_mm = -12.5;
    p.length.trigger_z = "-12.4; -12.41";
    p.length.active_length_mm = 100.0;
    p.length.nominal_length_mm = 101.0;
    p.delay.touches_csv = "axis,direction,feed_mm_min,measured_mm\nX,1,500,10.001\n";
    p.delay.fitted_csv =
        "axis,direction,feed_mm_min,measured_mm\nX,1,500,10.001\nX,1,1000,10.002\n"
        "X,1,2000,10.004\n";
    p.delay.interpolation_period_s = 0.002;
    p.delay.applied_group = "X+";
    p.compensation.feed_mm_min = 3000.0;
    p.compensation.interpolation_period_s = 0.004;
    p.compensation.lag_cycles = 10;
    p.compensation.touch = TouchMotion::constant_speed;
    p.compensation.speed_fraction = 0.25;
    p.compensation.compensated_lag_cycles = 9;
    p.comparison.plan = "plan.csv";
    p.comparison.reference_cmm = "data/cmm.csv";
    p.comparison.c_axis_x_mm = 200.0;
    p.comparison.tolerance_mm = 0.02;
    p.report = {"Acme", "VMC 2", "Housing 4711", "J. Engineer", "Probe OMP40.\nAt 21 °C."};
    return p;
}

// Every problem of a refused text, "key: message" per line.
std::string problems(std::string_view text) {
    try {
        (void)parse_project(text);
    } catch (const ProjectError& e) {
        std::string out;
        for (const FieldError& error : e.errors()) out += error.message() + "\n";
        return out;
    }
    return "accepted";
}

std::string with(std::string_view section_and_body) {
    std::string text = R"({"format": "probecycle-project", "version": 1, "scenario": {})";
    if (!section_and_body.empty()) text += std::string(", ") + std::string(section_and_body);
    return text + "}";
}

// A bad project file is a project's error, not a scenario's, even where the
// problem is in its scenario section.
TEST(ProjectFile, ABadFileIsAProjectError) {
    try {
        (void)parse_project(
            R"({"format": "probecycle-project", "version": 1, "scenario": {"machine": 3}})");
        ADD_FAILURE() << "accepted";
    } catch (const ScenarioError&) {
        ADD_FAILURE() << "a project's problem thrown as a scenario's";
    } catch (const FileContentError& e) {
        EXPECT_NE(dynamic_cast<const ProjectError*>(&e), nullptr);
        EXPECT_EQ(e.kind(), FileKind::project);
        ASSERT_FALSE(e.errors().empty());
        EXPECT_EQ(e.errors().front().key.rfind("scenario", 0), 0u) << e.errors().front().key;
    }
}

TEST(ProjectFile, RoundTripKeepsEveryValue) {
    const Project p = sample_project();
    const std::string text = project_json(p);
    const Project back = parse_project(text);
    EXPECT_EQ(project_json(back), text);
    EXPECT_EQ(back.scenario.cycle.probe_feed_mm_min, 2500.0);
    ASSERT_TRUE(back.baseline.has_value());
    EXPECT_EQ(back.baseline->cycle.probe_feed_mm_min, 1200.0);
    EXPECT_EQ(back.ring.fitted_csv, p.ring.fitted_csv);
    EXPECT_EQ(back.ring.options.gauge_diameter_mm, 50.002);
    EXPECT_EQ(back.ring.magnification, 1000.0);
    EXPECT_EQ(back.length.trigger_z, "-12.4; -12.41");
    EXPECT_EQ(back.delay.applied_group, "X+");
    EXPECT_EQ(back.compensation.touch, TouchMotion::constant_speed);
    EXPECT_EQ(back.compensation.compensated_lag_cycles, 9);
    EXPECT_EQ(back.comparison.reference_cmm, "data/cmm.csv");
    EXPECT_EQ(back.comparison.tolerance_mm, 0.02);
    EXPECT_EQ(back.report, p.report);
}

TEST(ProjectFile, WindowsLineEndsReadAsUnixOnes) {
    const std::string text = project_json(sample_project());
    const std::string crlf = test::with_crlf(text);
    ASSERT_NE(crlf, text);
    EXPECT_EQ(project_json(parse_project(crlf)), text);
}

// The report's title block is optional: files from before it open with
// every field empty; a field that is not text is refused by its key.
TEST(ProjectFile, TheReportDetailsAreOptionalTextKeyedUnderReport) {
    EXPECT_EQ(parse_project(with("")).report, ReportDetails{});
    EXPECT_EQ(parse_project(with(R"("report": {"customer": "Acme"})")).report.customer, "Acme");
    const std::string got =
        problems(with(R"("report": {"customer": 3, "notes": ["a"], "colour": "red"})"));
    EXPECT_NE(got.find("report.customer: got 3; allowed: text"), std::string::npos) << got;
    EXPECT_NE(got.find("report.notes: got [\"a\"]; allowed: text"), std::string::npos) << got;
    EXPECT_NE(got.find("report.colour: unknown key; allowed in report: customer, machine, part, "
                       "author, notes"),
              std::string::npos)
        << got;
    EXPECT_EQ(problems(with(R"("report": "Acme")")),
              "report: got \"Acme\"; allowed: an object of keys\n");
}

TEST(ProjectFile, DefaultsRoundTripAndOnlyTheScenarioIsRequired) {
    EXPECT_EQ(project_json(parse_project(project_json(Project{}))), project_json(Project{}));
    const Project minimal = parse_project(with(""));
    EXPECT_EQ(project_json(minimal), project_json(Project{}));
    EXPECT_FALSE(minimal.baseline.has_value());
}

TEST(ProjectFileGolden, MatchesTheGoldenFileByteForByte) {
    const fs::path path = fs::path(PROBECYCLE_TEST_DATA_DIR) / "golden" / "project.probecycle";
    const std::string got = project_json(sample_project());
    if (std::getenv("PROBECYCLE_UPDATE_GOLDEN") != nullptr) {
        std::ofstream(path, std::ios::binary) << got;
        return;
    }
    EXPECT_EQ(read_text_file(path.string()), got);
}

TEST(ProjectFile, TellsAProjectFromAScenarioOrAComparisonProject) {
    EXPECT_TRUE(is_project_text(project_json(Project{})));
    EXPECT_FALSE(is_project_text(scenario_to_json(Scenario{})));
    EXPECT_FALSE(is_project_text(comparison_project_json(ComparisonProject{})));
    // A damaged project is still one, so its own messages say what is wrong.
    EXPECT_TRUE(is_project_text(R"({"format": "probecycle-project", "version": )"));
    // So is one whose format was mistyped: refused for its format alone
    // (before: every section reported unknown to a scenario).
    const std::string mistyped =
        R"({"format": "probecycle-projekt", "version": 1, "scenario": {}, "ring": {}})";
    EXPECT_TRUE(is_project_text(mistyped));
    EXPECT_EQ(problems(mistyped),
              "format: got \"probecycle-projekt\"; allowed: \"probecycle-project\" (a ProbeCycle "
              "project)\n");
}

TEST(ProjectFile, RefusesWhatIsNotAProjectOfThisVersion) {
    EXPECT_EQ(problems(scenario_to_json(Scenario{})),
              "format: \"probecycle-project\" (a ProbeCycle project)\n");
    EXPECT_EQ(problems(R"({"format": "probecycle-project", "version": 2, "scenario": {}})"),
              "version: got 2; allowed: 1 (a newer ProbeCycle wrote this file)\n");
    // Not newer: damaged (before, all three said a newer ProbeCycle wrote them).
    for (const char* version : {"0", "null", "\"1\"", "1.5"}) {
        EXPECT_EQ(problems(std::string(R"({"format": "probecycle-project", "version": )") +
                           version + R"(, "scenario": {}})"),
                  std::string("version: got ") + version +
                      "; allowed: the whole number 1 (this ProbeCycle's project version)\n");
    }
    EXPECT_NE(problems(R"({"format": "probecycle-project", "version": 1,)").find("malformed JSON"),
              std::string::npos);
    EXPECT_EQ(problems(R"({"format": "probecycle-project", "version": 1})"),
              "scenario: missing; a project holds a scenario\n");
}

TEST(ProjectFile, NamesEveryProblemByItsDottedKey) {
    const std::string text = with(R"("ring": {"gauge_diameter_mm": 0, "colour": 1},
                "length": {"trigger_z": 12},
                "compensation": {"lag_cycles": 2.5, "touch": "sliding"},
                "comparison": {"tolerance_mm": -1},
                "baseline": {"machine": {"scan_period_s": -1}},
                "extra": 1)");
    const std::string got = problems(text);
    EXPECT_NE(got.find("ring.gauge_diameter_mm: got 0; allowed: a number from 0.1 to 2000 mm"),
              std::string::npos)
        << got;
    EXPECT_NE(got.find("ring.colour: unknown key; allowed in ring: points_csv, fitted_csv, "
                       "gauge_diameter_mm, runout_limit_mm, residual_limit_mm, magnification"),
              std::string::npos)
        << got;
    EXPECT_NE(got.find("length.trigger_z: got 12; allowed: text"), std::string::npos) << got;
    EXPECT_NE(got.find("compensation.lag_cycles: got 2.5; allowed: a whole number from 0 to 49"),
              std::string::npos)
        << got;
    EXPECT_NE(got.find("compensation.touch: got \"sliding\"; allowed: one of constant_speed, "
                       "braking"),
              std::string::npos)
        << got;
    EXPECT_NE(got.find("comparison.tolerance_mm: got -1"), std::string::npos) << got;
    EXPECT_NE(got.find("baseline.machine.scan_period_s: got -1"), std::string::npos) << got;
    EXPECT_NE(got.find("extra: unknown key; allowed in the project: format, version, scenario"),
              std::string::npos)
        << got;
}

TEST(ProjectFile, ScenarioProblemsAreKeyedUnderScenario) {
    const std::string text =
        R"({"format": "probecycle-project", "version": 1,
            "scenario": {"cycle": {"probe_feed_mm_min": "fast"}, "tool": {}}})";
    const std::string got = problems(text);
    EXPECT_NE(got.find("scenario.cycle.probe_feed_mm_min: got \"fast\""), std::string::npos) << got;
    EXPECT_NE(got.find("scenario.tool:"), std::string::npos) << got;
}

TEST(ProjectFile, AFitsCsvMustReadAsTheLabReadsIt) {
    const std::string got = problems(with(
        R"("ring": {"fitted_csv": "orientation_deg,x_mm,y_mm\n0,1,2\n90,1,2\n"},
           "delay": {"fitted_csv": "axis,direction,feed_mm_min,measured_mm\nX,2,100,1\n"})"));
    EXPECT_NE(got.find("ring.fitted_csv: line 3"), std::string::npos) << got;
    EXPECT_NE(got.find("delay.fitted_csv: line 2, column direction"), std::string::npos) << got;
}

TEST(ProjectFile, MagnificationIsOneOfTheDrawingsFactors) {
    EXPECT_EQ(problems(with(R"("ring": {"magnification": 50})")),
              "ring.magnification: got 50; allowed: one of 0, 1, 10, 100, 1000, 10000\n");
    EXPECT_EQ(parse_project(with(R"("ring": {"magnification": 100})")).ring.magnification, 100.0);
}

TEST(ProjectFile, RefusesNestingBeyondTheFormat) {
    const std::string got = problems(with(R"("ring": {"points_csv": {"a": {"b": 1}}})"));
    EXPECT_NE(got.find("ring.points_csv"), std::string::npos) << got;
}

}  // namespace
}  // namespace probecycle
