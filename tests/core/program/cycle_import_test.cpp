// The import of a cycle program's log: synthetic logs of each dialect for
// each feature give the hand-computed result; the program's own result line
// must agree with the touches; broken logs name the line.

#include "core/program/cycle_import.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/common/csv_reader.h"
#include "core/common/input_error.h"
#include "tests/core/program/program_test_plans.h"

namespace probecycle {
namespace {

using Touches = std::vector<std::array<double, 3>>;

ProbingPlan bore_plan(double tolerance_mm = 0.0, ToleranceAction action = ToleranceAction::flag) {
    Scenario bore;
    bore.cycle.feature = Feature::bore;
    bore.cycle.feature_size_mm = 44.0;
    bore.cycle.strategy = Strategy::single_touch;
    bore.cycle.probe_feed_mm_min = 300.0;
    bore.cycle.size_tolerance_mm = tolerance_mm;
    bore.cycle.tolerance_action = action;
    return make_cycle_plan(bore, CyclePlanOptions{{'Z', -1}, 6.0});
}

// 50.004 mm with the 6 mm ball, centre (0.004, 0.008).
const Touches kBore{{22.006, 0, 0}, {-21.998, 0, 0}, {0, 22.010, 0}, {0, -21.994, 0}};

std::string linuxcnc_log(const ProbingPlan& plan, const Touches& touches,
                         const std::string& tail = "") {
    return program_test::linuxcnc_touch_log(plan, touches) + tail;
}

std::string fanuc_log(const ProbingPlan& plan, const Touches& touches,
                      const std::string& tail = "") {
    std::string log = "%\nPROBECYCLE PLAN " + id_letters(plan_id(plan)) + " CYCLE\n";
    for (std::size_t i = 0; i < touches.size(); ++i) {
        char line[160];
        std::snprintf(line, sizeof line, "TOUCH%4zu X%10.4f Y%10.4f Z%10.4f\n", i + 1,
                      touches[i][0], touches[i][1], touches[i][2]);
        log += line;
    }
    return log + tail;
}

std::size_t line_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const CsvError& e) {
        return e.line();
    }
    ADD_FAILURE() << "no CsvError";
    return 0;
}

TEST(CycleImport, LinuxCncLogWithTheProgramsResult) {
    const ProbingPlan plan = bore_plan();
    const std::string log = linuxcnc_log(
        plan, kBore, "probecycle result S 50.004000 X 0.004000 Y 0.008000 D 0.004000 T 0.000000\n");
    const CycleImport import = import_cycle_log(plan, DialectId::linuxcnc, log);
    EXPECT_NEAR(import.result.size_mm, 50.004, 1e-9);
    EXPECT_NEAR(*import.result.centre_mm[0], 0.004, 1e-9);
    EXPECT_NEAR(*import.result.centre_mm[1], 0.008, 1e-9);
    EXPECT_EQ(import.logged.line, 6u);
    const std::string text = cycle_import_text(import);
    EXPECT_NE(text.find("bore diameter: 50.0040 mm +- "), std::string::npos) << text;
    EXPECT_NE(text.find("centre X: 0.0040 mm"), std::string::npos) << text;
    EXPECT_NE(text.find("the program's own result (line 6) agrees"), std::string::npos) << text;
    const nlohmann::json json = nlohmann::json::parse(cycle_import_json(import));
    EXPECT_EQ(json["feature"], "bore");
    EXPECT_NEAR(json["size_mm"].get<double>(), 50.004, 1e-9);
    EXPECT_NEAR(json["centre_y_mm"].get<double>(), 0.008, 1e-9);
    EXPECT_DOUBLE_EQ(json["size_uncertainty_mm"].get<double>(), size_uncertainty_mm(import.spec));
    EXPECT_TRUE(json["tolerance"].is_null());
    EXPECT_EQ(json["program_result_line"], 6);
}

TEST(CycleImport, AResultLineTheTouchesDoNotGiveIsRefusedAtItsLine) {
    const ProbingPlan plan = bore_plan();
    const std::string log = linuxcnc_log(
        plan, kBore, "probecycle result S 50.014000 X 0.004000 Y 0.008000 D 0.014000 T 0.000000\n");
    EXPECT_EQ(line_of([&] { import_cycle_log(plan, DialectId::linuxcnc, log); }), 6u);
    const std::string broken = linuxcnc_log(plan, kBore, "probecycle result S 50.004 X\n");
    EXPECT_EQ(line_of([&] { import_cycle_log(plan, DialectId::linuxcnc, broken); }), 6u);
    // All or nothing: a touch missing.
    const Touches three(kBore.begin(), kBore.begin() + 3);
    EXPECT_EQ(
        line_of([&] { import_cycle_log(plan, DialectId::linuxcnc, linuxcnc_log(plan, three)); }),
        4u);
    EXPECT_THROW(
        import_cycle_log(make_ring_plan(Scenario{}, RingPlanOptions{}), DialectId::linuxcnc, ""),
        InputError);
}

TEST(CycleImport, ToleranceBothWaysAndTheProgramsFlagAgrees) {
    // 0.004 over nominal: in a tolerance of 0.005, out of 0.003.
    const ProbingPlan in = bore_plan(0.005);
    const CycleImport ok = import_cycle_log(
        in, DialectId::linuxcnc,
        linuxcnc_log(
            in, kBore,
            "probecycle result S 50.004000 X 0.004000 Y 0.008000 D 0.004000 T 0.000000\n"));
    EXPECT_TRUE(ok.result.checked);
    EXPECT_FALSE(ok.result.out_of_tolerance);
    EXPECT_NE(cycle_import_text(ok).find("deviation +0.0040 mm: in tolerance"), std::string::npos)
        << cycle_import_text(ok);

    const ProbingPlan out = bore_plan(0.003, ToleranceAction::stop);
    const CycleImport flagged = import_cycle_log(
        out, DialectId::linuxcnc,
        linuxcnc_log(out, kBore,
                     "probecycle result S 50.004000 X 0.004000 Y 0.008000 D 0.004000 T 1.000000\n"
                     "probecycle out of tolerance\n"));
    EXPECT_TRUE(flagged.result.out_of_tolerance);
    EXPECT_EQ(flagged.logged.out_of_tolerance_line, 7u);
    EXPECT_NE(cycle_import_text(flagged).find("OUT OF TOLERANCE (the program stops)"),
              std::string::npos);
    const nlohmann::json json = nlohmann::json::parse(cycle_import_json(flagged));
    EXPECT_EQ(json["tolerance"]["out_of_tolerance"], true);
    EXPECT_EQ(json["tolerance"]["action"], "stop");
    // A program whose flag says otherwise is not this plan's.
    EXPECT_EQ(line_of([&] {
                  import_cycle_log(out, DialectId::linuxcnc,
                                   linuxcnc_log(out, kBore,
                                                "probecycle result S 50.004000 X 0.004000 Y "
                                                "0.008000 D 0.004000 T 0.000000\n"));
              }),
              6u);
}

TEST(CycleImport, FanucDprntResultIsReadAndChecked) {
    const ProbingPlan plan = bore_plan(0.003);
    const std::string log = fanuc_log(plan, kBore,
                                      "RESULT S  50.0040 X   0.0040 Y   0.0080 D   0.0040 T1.\n"
                                      "PROBECYCLE OUT OF TOLERANCE\nPROBECYCLE END\n%\n");
    const CycleImport import = import_cycle_log(plan, DialectId::fanuc, log);
    EXPECT_NEAR(import.result.size_mm, 50.004, 1e-9);
    EXPECT_TRUE(import.result.out_of_tolerance);
    EXPECT_EQ(import.logged.line, 7u);
    EXPECT_EQ(import.logged.out_of_tolerance_line, 8u);
    // Another program's RESULT line before ours is not read.
    const CycleImport after = import_cycle_log(
        plan, DialectId::fanuc, "RESULT OF PROGRAM 12\n" + log.substr(log.find("PROBECYCLE PLAN")));
    EXPECT_EQ(after.logged.line, 7u);
    const std::string wrong =
        fanuc_log(plan, kBore, "RESULT S  50.0140 X 0.0040 Y 0.0080 D 0.0140 T1.\n");
    EXPECT_EQ(line_of([&] { import_cycle_log(plan, DialectId::fanuc, wrong); }), 7u);
}

// Mitsubishi's common variables: the plan, the state, the touches and the
// program's own result in #506-#510, read and checked.
std::string mitsubishi_list(const ProbingPlan& plan, const Touches& touches, double state,
                            const std::array<double, 5>& result) {
    const std::string id = plan_id(plan);
    std::string list;
    const auto add = [&list](int variable, double value) {
        char line[64];
        std::snprintf(line, sizeof line, "#%d = %.4f\n", variable, value);
        list += line;
    };
    for (int part = 0; part < 4; ++part) {
        add(500 + part, static_cast<double>(std::stoul(id.substr(4 * part, 4), nullptr, 16)));
    }
    add(504, state);
    add(505, static_cast<double>(touches.size()));
    for (int i = 0; i < 5; ++i) add(506 + i, result[static_cast<std::size_t>(i)]);
    for (std::size_t t = 0; t < touches.size(); ++t) {
        for (std::size_t axis = 0; axis < 3; ++axis) {
            add(520 + static_cast<int>(3 * t + axis), touches[t][axis]);
        }
    }
    return list;
}

TEST(CycleImport, MitsubishiVariablesResultIsReadAndChecked) {
    const ProbingPlan plan = bore_plan(0.003, ToleranceAction::stop);
    const std::array<double, 5> result = {50.004, 0.004, 0.008, 0.004, 1.0};
    const CycleImport stopped =
        import_cycle_log(plan, DialectId::mitsubishi, mitsubishi_list(plan, kBore, 103, result));
    EXPECT_NEAR(stopped.result.size_mm, 50.004, 1e-9);
    EXPECT_TRUE(stopped.result.out_of_tolerance);
    EXPECT_EQ(stopped.logged.line, 7u);                   // #506
    EXPECT_EQ(stopped.logged.out_of_tolerance_line, 5u);  // #504 = 103
    // The flag alone (the program went on): named at #510.
    const CycleImport flagged =
        import_cycle_log(plan, DialectId::mitsubishi, mitsubishi_list(plan, kBore, 1, result));
    EXPECT_EQ(flagged.logged.out_of_tolerance_line, 11u);
    // A result the touches do not give: named at #506.
    EXPECT_EQ(line_of([&] {
                  import_cycle_log(
                      plan, DialectId::mitsubishi,
                      mitsubishi_list(plan, kBore, 1, {50.014, 0.004, 0.008, 0.014, 1}));
              }),
              7u);
}

// Siemens's WRITE file: the DPRNT lines' words, SPRINT's padded numbers,
// the last run of the file.
TEST(CycleImport, SiemensWriteFileResultIsReadAndChecked) {
    const ProbingPlan plan = bore_plan(0.003);
    std::string run = "PROBECYCLE PLAN " + id_letters(plan_id(plan)) + " CYCLE\n";
    for (std::size_t i = 0; i < kBore.size(); ++i) {
        char line[160];
        std::snprintf(line, sizeof line, "TOUCH %zu X%12.4f Y%12.4f Z%12.4f\n", i + 1, kBore[i][0],
                      kBore[i][1], kBore[i][2]);
        run += line;
    }
    run +=
        "RESULT S     50.0040 X      0.0040 Y      0.0080 D      0.0040 T      1.0000\n"
        "PROBECYCLE OUT OF TOLERANCE\nPROBECYCLE END\n";
    const std::string earlier =
        "PROBECYCLE PLAN " + id_letters(plan_id(plan)) + " CYCLE\nPROBECYCLE NO TRIGGER\n";
    const CycleImport import = import_cycle_log(plan, DialectId::siemens, earlier + run);
    EXPECT_NEAR(import.result.size_mm, 50.004, 1e-9);
    EXPECT_TRUE(import.result.out_of_tolerance);
    EXPECT_EQ(import.logged.line, 8u);
    EXPECT_EQ(import.logged.out_of_tolerance_line, 9u);
}

TEST(CycleImport, GrblConsoleGivesTheResultTheProgramCannotCompute) {
    // A web along X, 10 mm with a 2 mm ball: the console reports every probe
    // and protected move, in the plan's order.
    const ProbingPlan plan =
        make_cycle_plan(program_test::golden_web(), CyclePlanOptions{{'X', 1}, 2.0});
    std::string console = "Grbl 1.1h ['$' for help]\n" + program_test::grbl_signature(plan);
    for (const ProgramStep& step : plan.steps) {
        if (step.kind == StepKind::guard) console += program_test::prb(0, 0, 0, 0) + "ok\n";
        if (step.kind != StepKind::probe) continue;
        // Touched toward the centre: the X+ side moving X-, at 6.02, the X-
        // side at -5.95 (11.97 between stylus centres).
        const double x = step.direction < 0 ? 6.02 : -5.95;
        console += program_test::prb(x, 0, 0) + "ok\n";
    }
    // The protected moves' reports say where each ended; the import takes the touches.
    const CycleImport import = import_cycle_log(plan, DialectId::grbl, console);
    EXPECT_NEAR(import.result.size_mm, 9.97, 1e-9);
    EXPECT_NEAR(*import.result.centre_mm[0], 0.035, 1e-9);
    EXPECT_TRUE(import.result.out_of_tolerance);  // 0.03 under, tolerance 0.02
    EXPECT_EQ(import.logged.line, 0u);
    EXPECT_NE(cycle_import_text(import).find("OUT OF TOLERANCE (the program flags it)"),
              std::string::npos);
}

TEST(CycleImport, SurfacePositionFromALinuxCncLog) {
    Scenario surface;
    const ProbingPlan plan = make_cycle_plan(surface, CyclePlanOptions{{'Z', -1}, 6.0});
    const std::string log = linuxcnc_log(
        plan, {{1.0, 2.0, -10.003}},
        "probecycle result S -13.003000 X 0.000000 Y 0.000000 D 0.000000 T 0.000000\n");
    const CycleImport import = import_cycle_log(plan, DialectId::linuxcnc, log);
    EXPECT_NEAR(import.result.size_mm, -13.003, 1e-9);
    EXPECT_NE(cycle_import_text(import).find("surface position along Z-: -13.0030 mm"),
              std::string::npos)
        << cycle_import_text(import);
    const nlohmann::json json = nlohmann::json::parse(cycle_import_json(import));
    EXPECT_NEAR(json["position_mm"].get<double>(), -13.003, 1e-9);
    EXPECT_EQ(json["axis"], "Z-");
}

}  // namespace
}  // namespace probecycle
