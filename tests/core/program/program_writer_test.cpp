// The programs, byte for byte, against golden files reviewed line by line
// against the dialects' documentation (core/program/dialect.cpp cites it).
// To accept a deliberate change, regenerate them and read the diff:
//   PROBECYCLE_UPDATE_GOLDEN=1 ctest --test-dir build -R ProgramGolden

#include "core/program/program_writer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "tests/core/program/program_test_plans.h"

namespace probecycle {
namespace {

std::string golden_path(const std::string& name) {
    return std::string(PROBECYCLE_TEST_DATA_DIR) + "/golden/" + name;
}

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(ProgramGolden, EveryProgramInEveryDialect) {
    for (const auto& [name, plan] : program_test::golden_plans()) {
        for (const Dialect* d : {&linuxcnc_dialect(), &grbl_dialect()}) {
            const std::string file = "program_" + name + "_" + d->name + "." + d->extension;
            const std::string text = write_program(plan, *d, program_test::kDate);
            if (std::getenv("PROBECYCLE_UPDATE_GOLDEN") != nullptr) {
                std::ofstream(golden_path(file), std::ios::binary) << text;
            }
            EXPECT_EQ(text, read_file(golden_path(file))) << file;
        }
    }
}

TEST(ProgramWriter, NumbersIgnoreTheLocaleAndNeverReadMinusZero) {
    EXPECT_EQ(program_number(-10.5), "-10.500");
    EXPECT_EQ(program_number(-0.0001), "0.000");
    EXPECT_EQ(program_feed(30.0), "30");
    EXPECT_EQ(program_feed(1500.5), "1500.5");
}

TEST(ProgramWriter, EveryProbeIsIncrementalAndEveryRecordedTouchIsLogged) {
    const ProbingPlan plan = program_test::golden_plans()[0].plan;
    const std::string text = write_program(plan, linuxcnc_dialect(), program_test::kDate);
    // G91 comes before the first move.
    EXPECT_LT(text.find("G21 G91 G94"), text.find("G38.2"));
    std::size_t probes = 0;
    std::size_t logs = 0;
    for (std::size_t at = text.find("\nG38.2 "); at != std::string::npos;
         at = text.find("\nG38.2 ", at + 1)) {
        ++probes;
    }
    for (std::size_t at = text.find("(LOG,probecycle touch "); at != std::string::npos;
         at = text.find("(LOG,probecycle touch ", at + 1)) {
        ++logs;
    }
    std::size_t all_probes = 0;
    for (const ProgramStep& step : plan.steps) all_probes += step.kind == StepKind::probe;
    EXPECT_EQ(probes, all_probes);
    EXPECT_EQ(logs, plan.recorded().size());
    EXPECT_NE(text.find("; Plan " + plan_id(plan)), std::string::npos);
    EXPECT_NE(text.find("reduced rapid override"), std::string::npos);
    EXPECT_NE(text.find("Date 2026-01-15."), std::string::npos);
}

TEST(ProgramWriter, GrblHasNoActiveCommentsAndNoParameters) {
    for (const auto& [name, plan] : program_test::golden_plans()) {
        const std::string text = write_program(plan, grbl_dialect(), program_test::kDate);
        EXPECT_EQ(text.find('#'), std::string::npos) << name;
        EXPECT_EQ(text.find("(MSG"), std::string::npos) << name;
        EXPECT_EQ(text.find("(LOG"), std::string::npos) << name;
    }
}

}  // namespace
}  // namespace probecycle
