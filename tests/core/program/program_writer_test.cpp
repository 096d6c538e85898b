// The programs, byte for byte, against golden files reviewed line by line
// against the dialects' documentation (core/program/dialect.cpp cites it).
// To accept a deliberate change, regenerate them and read the diff:
//   PROBECYCLE_UPDATE_GOLDEN=1 ctest --test-dir build -R ProgramGolden

#include "core/program/program_writer.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/common/input_error.h"

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
        for (const DialectId id : all_dialects()) {
            const Dialect* d = &dialect(id);
            const std::string file = "program_" + name + "_" + d->name + "." + d->extension;
            const std::string text =
                write_program(plan, *d, program_test::kDate, program_test::golden_options());
            if (std::getenv("PROBECYCLE_UPDATE_GOLDEN") != nullptr) {
                std::ofstream(golden_path(file), std::ios::binary) << text;
            }
            EXPECT_EQ(text, read_file(golden_path(file))) << file;
        }
    }
}

// The header says what slows the program down, from its own moves: feed
// override always (every probing, protected and return move runs at a
// feed), rapid override where the program has rapids (retracts, lifts).
TEST(ProgramWriter, TheHeaderNamesTheOverridesItsMovesObey) {
    for (const auto& [name, plan] : program_test::golden_plans()) {
        for (const DialectId id : all_dialects()) {
            const Dialect* d = &dialect(id);
            SCOPED_TRACE(name + " " + d->name);
            std::string text =
                write_program(plan, *d, program_test::kDate, program_test::golden_options());
            bool rapid = false;
            std::istringstream lines(text);
            for (std::string line; std::getline(lines, line);) {
                rapid = rapid || line.rfind(std::string(d->rapid_word) + " ", 0) == 0;
            }
            for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
            // (Comments may break a line between two words.)
            std::string flat;
            for (char c : text) {
                if (c == '\n' || c == ';' || c == '(' || c == ')') continue;
                if (c == ' ' && !flat.empty() && flat.back() == ' ') continue;
                flat += c;
            }
            EXPECT_NE(flat.find("REDUCED FEED OVERRIDE"), std::string::npos);
            EXPECT_EQ(flat.find("REDUCED RAPID OVERRIDE") != std::string::npos, rapid);
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
    EXPECT_NE(text.find("reduced feed override"), std::string::npos);
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

// A protected move in each dialect: LinuxCNC's G38.3 and an abort when #5070
// reads 1 (a trip), grbl's G38.3 alone (grbl cannot branch), the Fanuc-type
// G31 to the move's end and alarm 102 when the skip position is not that end,
// each on the moving axis's own variables; the header says what each does.
TEST(ProgramWriter, ProtectedMovesInEveryDialect) {
    const ProbingPlan plan = program_test::guarded_plan();
    const std::string linuxcnc = write_program(plan, linuxcnc_dialect(), program_test::kDate);
    EXPECT_NE(linuxcnc.find("; out to the X+ start\n"
                            "G38.3 X20.000 F3000\n"
                            "o1001 if [#5070 EQ 1]\n"
                            "(ABORT,probecycle: the probe touched something during a protected "
                            "move: the path is obstructed)\n"
                            "o1001 endif\n"
                            "; touch 1: X+ at 2000 mm/min\n"
                            "G38.2 X6.000 F2000\n"),
              std::string::npos)
        << linuxcnc;
    EXPECT_NE(linuxcnc.find("G38.3 Z-10.000 F3000\no1003 if [#5070 EQ 1]\n"), std::string::npos);
    EXPECT_NE(linuxcnc.find("; Protected moves are G38.3"), std::string::npos);

    const std::string grbl = write_program(plan, grbl_dialect(), program_test::kDate);
    EXPECT_NE(grbl.find("; out to the X+ start\nG38.3 X20.000 F3000\n; touch 1:"),
              std::string::npos)
        << grbl;
    EXPECT_NE(grbl.find("; Protected moves are G38.3, the probe armed: grbl answers"),
              std::string::npos);

    const std::string fanuc = write_program(plan, fanuc_dialect(), program_test::kDate);
    EXPECT_NE(fanuc.find("(OUT TO THE X+ START)\n"
                         "#101=#5041+20.000\n"
                         "G31 X20.000 F3000\n"
                         "IF[ABS[#5061-#101]GE0.050]GOTO9002\n"),
              std::string::npos)
        << fanuc;
    EXPECT_NE(fanuc.find("#101=#5043-10.000\n"
                         "G31 Z-10.000 F3000\n"
                         "IF[ABS[#5063-#101]GE0.050]GOTO9002\n"),
              std::string::npos);
    EXPECT_EQ(
        fanuc.substr(fanuc.find("\nM30\n")),
        "\nM30\nN9001\nDPRNT[PROBECYCLE*NO*TRIGGER]\nPCLOS\n#3000=101(PROBE DID NOT TRIGGER)\n"
        "N9002\nDPRNT[PROBECYCLE*OBSTRUCTED]\nPCLOS\n#3000=102(PROBE PATH OBSTRUCTED)\n%\n");
    EXPECT_NE(fanuc.find("(PROTECTED MOVES ARE G31 TO THE END OF THE MOVE, WHEN"),
              std::string::npos)
        << fanuc;

    // A plan without protected moves has neither the notes nor the branch.
    for (const DialectId id : all_dialects()) {
        const Dialect* d = &dialect(id);
        const std::string text =
            write_program(program_test::golden_plans()[2].plan, *d, program_test::kDate);
        EXPECT_EQ(text.find("rotected moves"), std::string::npos) << d->name;
        EXPECT_EQ(text.find("ROTECTED MOVES"), std::string::npos) << d->name;
        EXPECT_EQ(text.find("9002"), std::string::npos) << d->name;
    }
}

// Fanuc-type: every G31 keeps its programmed end just before and alarms just
// after when the skip position is that end (a probe) or is not (a protected
// move); DPRNT texts are letters and '*' only (Haas); no lower case anywhere
// (comments included).
TEST(ProgramWriter, FanucChecksEveryProbeAndPrintsLettersOnly) {
    std::vector<program_test::NamedPlan> plans = program_test::golden_plans();
    plans.push_back({"guarded", program_test::guarded_plan()});
    for (const auto& [name, plan] : plans) {
        const std::string text = write_program(plan, fanuc_dialect(), program_test::kDate,
                                               program_test::golden_options());
        std::istringstream lines(text);
        std::vector<std::string> all;
        for (std::string line; std::getline(lines, line);) all.push_back(line);
        std::size_t probes = 0;
        for (std::size_t i = 0; i < all.size(); ++i) {
            const std::string& line = all[i];
            for (const char c : line) EXPECT_FALSE(c >= 'a' && c <= 'z') << name << ": " << line;
            if (line.rfind("G31 ", 0) == 0) {
                ++probes;
                const char axis = line[4];
                const std::string n = std::to_string(axis - 'X' + 1);
                ASSERT_GT(i, 0u);
                ASSERT_LT(i + 1, all.size());
                EXPECT_EQ(all[i - 1].rfind("#101=#504" + n, 0), 0u) << all[i - 1];
                // A comparison of the skip position on the same axis: a probe's
                // or a protected move's.
                EXPECT_TRUE(all[i + 1] == "IF[ABS[#506" + n + "-#101]LT0.050]GOTO9001" ||
                            all[i + 1] == "IF[ABS[#506" + n + "-#101]GE0.050]GOTO9002")
                    << all[i + 1];
                // The programmed end is the move's own distance.
                EXPECT_EQ(all[i - 1].substr(10),
                          (line[5] == '-' ? "" : "+") + line.substr(5, line.find(" F") - 5));
                EXPECT_EQ(line.find(" P"), std::string::npos);
            }
            if (line.rfind("DPRNT[", 0) == 0) {
                const std::string body = line.substr(6, line.size() - 7);
                std::string outside_variables;
                bool in_variable = false;
                for (const char c : body) {
                    if (c == '#') in_variable = true;
                    if (!in_variable) outside_variables += c;
                    if (c == ']') in_variable = false;
                }
                for (const char c : outside_variables) {
                    EXPECT_TRUE((c >= 'A' && c <= 'Z') || c == '*') << line;
                }
            }
        }
        std::size_t all_probes = 0;
        for (const ProgramStep& step : plan.steps) {
            all_probes += step.kind == StepKind::probe || step.kind == StepKind::guard;
        }
        EXPECT_EQ(probes, all_probes) << name;
        EXPECT_EQ(text.find("GOTO9002") != std::string::npos, plan.has_guards()) << name;
        EXPECT_EQ(text.find("\nN9002\n") != std::string::npos, plan.has_guards()) << name;
        EXPECT_EQ(text.rfind("%\nO1300 (PROBECYCLE)\n", 0), 0u);
        EXPECT_LT(text.find("\nM30\nN9001\n"), text.find("#3000=101(PROBE DID NOT TRIGGER)"));
        EXPECT_EQ(text.substr(text.size() - 2), "%\n");
    }
}

// Mitsubishi keeps three common variables per touch, #520 to #999: a plan
// with more touches than fit is refused, naming the limit.
TEST(ProgramWriter, MitsubishiRefusesMoreTouchesThanItsVariablesHold) {
    EXPECT_EQ(max_recorded_touches(mitsubishi_dialect()), 160u);
    EXPECT_EQ(max_recorded_touches(fanuc_dialect()), 0u);
    DelayPlanOptions options;
    options.feeds_mm_min = {30, 100, 300, 1000, 2000};
    options.repeats = 32;  // 160 touches: the most
    EXPECT_NO_THROW(write_program(make_delay_plan(Scenario{}, options), mitsubishi_dialect(),
                                  program_test::kDate));
    options.repeats = 33;
    const ProbingPlan plan = make_delay_plan(Scenario{}, options);
    try {
        write_program(plan, mitsubishi_dialect(), program_test::kDate);
        ADD_FAILURE() << "written";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("165 touches"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("#520 to #999"), std::string::npos) << e.what();
    }
    // The other dialects keep no touches in variables.
    EXPECT_NO_THROW(write_program(plan, haas_dialect(), program_test::kDate));
}

// Siemens measures to an absolute target from the start read after STOPRE,
// with the probe input the user gives: MEAS=n and $A_PROBE[|n|].
TEST(ProgramWriter, SiemensMeasuresToAbsoluteTargetsWithTheUsersProbeInput) {
    const ProbingPlan plan = program_test::guarded_plan();
    ProgramOptions options;
    options.probe_input = -2;
    const std::string text = write_program(plan, siemens_dialect(), program_test::kDate, options);
    EXPECT_NE(
        text.find("; touch 1: X+ at 2000 mm/min\n"
                  "STOPRE\n"
                  "R1=$AA_IW[X]+6.000\n"
                  "MEAS=-2 G90 G1 X=R1 F2000\n"
                  "G91\n"
                  "STOPRE\n"
                  "IF $A_PROBE[2]<>1 GOTOF NO_TRIGGER\n"
                  "WRITE(PC_ERROR,\"PROBECYCLE_LOG\",\"TOUCH 1 X\"<<SPRINT(\"%12.4F\",$AA_MW[X])"
                  "<<\" Y\"<<SPRINT(\"%12.4F\",$AA_IW[Y])<<\" Z\"<<SPRINT(\"%12.4F\",$AA_IW[Z]))\n"
                  "IF PC_ERROR<>0 GOTOF WRITE_FAILED\n"),
        std::string::npos)
        << text;
    EXPECT_NE(text.find("MEAS=-2 G90 G1 X=R1 F3000\nG91\nSTOPRE\n"
                        "IF $A_PROBE[2]==1 GOTOF OBSTRUCTED\n"),
              std::string::npos);
    // The definition comes first, before any block that runs.
    EXPECT_EQ(text.rfind("DEF INT PC_ERROR\n", 0), 0u);
    for (const int bad : {0, 3, -3}) {
        options.probe_input = bad;
        EXPECT_THROW(write_program(plan, siemens_dialect(), program_test::kDate, options),
                     InputError);
        // The other dialects have no probe input to check.
        EXPECT_NO_THROW(write_program(plan, fanuc_dialect(), program_test::kDate, options));
    }
}

TEST(ProgramWriter, FanucRingNeedsTheUsersOrientCommand) {
    const ProbingPlan ring = program_test::golden_plans()[1].plan;
    EXPECT_THROW(write_program(ring, fanuc_dialect(), program_test::kDate), InputError);
    EXPECT_THROW(write_program(ring, fanuc_dialect(), program_test::kDate,
                               ProgramOptions{"M19 R180.\nG0 X100."}),
                 InputError);
    EXPECT_THROW(
        write_program(ring, fanuc_dialect(), program_test::kDate, ProgramOptions{"m19 r180."}),
        InputError);
    // The delay and cycle programs turn no spindle; the other dialects leave it
    // to the operator at a pause.
    EXPECT_NO_THROW(
        write_program(program_test::golden_plans()[0].plan, fanuc_dialect(), program_test::kDate));
    EXPECT_NO_THROW(write_program(ring, grbl_dialect(), program_test::kDate));
    try {
        write_program(ring, fanuc_dialect(), program_test::kDate);
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("--orient-180: the ring program turns", 0), 0u)
            << e.what();
    }
}

}  // namespace
}  // namespace probecycle
