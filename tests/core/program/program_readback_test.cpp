// Every dialect's programs read back by a reader of that dialect's own
// syntax, independent of the writer's tables: the moves (probing, protected,
// at a feed, rapid) with their axes, signed distances and feeds are exactly
// the plan's, in order; each probing and protected move's check reads the
// moving axis's own variables with the move's own distance; and the
// recorded touches are recorded once each, numbered 1, 2, ... in order.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "core/program/program_writer.h"
#include "tests/core/program/program_test_plans.h"

namespace probecycle {
namespace {

enum class Motion { probe, guard, feed, rapid };

struct Move {
    Motion motion{Motion::feed};
    char axis{'X'};
    double distance_mm{0.0};  // signed
    double feed_mm_min{0.0};  // 0 for a rapid
};

// The parts appended in order (g++ 12 warns falsely of an overlapping
// memcpy in "literal" + std::string).
std::string joined(std::initializer_list<std::string_view> parts) {
    std::string text;
    for (const std::string_view part : parts) text.append(part);
    return text;
}

std::string describe(const Move& m) {
    static constexpr std::array<const char*, 4> kNames = {"probe", "guard", "feed", "rapid"};
    return joined({kNames[static_cast<std::size_t>(m.motion)], " ", std::string(1, m.axis),
                   std::to_string(m.distance_mm), " F", std::to_string(m.feed_mm_min)});
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// "X-12.500" or "X=R1" and "F30" words of a block, up to its comment.
struct Words {
    std::optional<char> axis;
    std::string value;  // the axis word's text after the letter (and '=')
    std::optional<double> feed;
};

Words words_of(const std::string& block) {
    Words words;
    std::istringstream in(block.substr(0, block.find_first_of(";(")));
    for (std::string word; in >> word;) {
        const char letter = word[0];
        if (letter == 'X' || letter == 'Y' || letter == 'Z') {
            words.axis = letter;
            words.value = word.substr(word[1] == '=' ? 2 : 1);
        } else if (letter == 'F') {
            words.feed = std::stod(word.substr(1));
        }
    }
    return words;
}

std::size_t axis_index(char axis) {
    return axis == 'X' ? 0 : axis == 'Y' ? 1 : 2;
}

// What the reader found: the moves, and the recorded touches' numbers in
// the order the program records them.
struct ReadBack {
    std::vector<Move> moves;
    std::vector<int> recorded;
};

// The first line from `from` on that starts with `prefix`, or lines.size().
std::size_t next_line(const std::vector<std::string>& lines, std::size_t from,
                      const std::string& prefix) {
    while (from < lines.size() && lines[from].rfind(prefix, 0) != 0) ++from;
    return from;
}

// LinuxCNC and grbl: G38.2 probes, G38.3 protected moves, G1 and G0;
// LinuxCNC's LOG line records a touch.
ReadBack read_rs274(const std::vector<std::string>& lines) {
    ReadBack back;
    for (const std::string& line : lines) {
        const Words w = words_of(line);
        Motion motion{};
        if (line.rfind("G38.2 ", 0) == 0) {
            motion = Motion::probe;
        } else if (line.rfind("G38.3 ", 0) == 0) {
            motion = Motion::guard;
        } else if (line.rfind("G1 ", 0) == 0) {
            motion = Motion::feed;
        } else if (line.rfind("G0 ", 0) == 0) {
            motion = Motion::rapid;
        } else {
            if (line.rfind("(LOG,probecycle touch ", 0) == 0) {
                back.recorded.push_back(std::stoi(line.substr(22)));
            }
            continue;
        }
        EXPECT_TRUE(w.axis.has_value()) << line;
        back.moves.push_back({motion, *w.axis, std::stod(w.value), w.feed.value_or(0.0)});
    }
    return back;
}

// Fanuc, Haas, Mitsubishi: G31 to the move's end kept in #101 from the
// axis's current position #5041-#5043; a probe jumps to 9001 when its skip
// position (#5061-#5063) is that end, a protected move to 9002 when it is
// not. A recorded touch: Fanuc and Haas set #102 and print it; Mitsubishi
// counts it in #505 and keeps X Y Z from #520 on.
ReadBack read_macro_b(const std::vector<std::string>& lines) {
    ReadBack back;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& line = lines[i];
        if (line.rfind("#102=", 0) == 0 || line.rfind("#505=", 0) == 0) {
            const int n = std::stoi(line.substr(5));
            if (n > 0) back.recorded.push_back(n);
            if (line.rfind("#102=", 0) == 0) {
                EXPECT_EQ(lines.at(i + 1).rfind("DPRNT[TOUCH#102[40]*X#5061[44]*", 0), 0u);
            } else if (n > 0) {
                // The three variables before the count hold X, Y and Z.
                for (int a = 0; a < 3; ++a) {
                    EXPECT_EQ(lines.at(i - 3 + static_cast<std::size_t>(a)),
                              joined({"#", std::to_string(520 + 3 * (n - 1) + a), "=#506",
                                      std::to_string(a + 1)}));
                }
            }
            continue;
        }
        const Words w = words_of(line);
        if (line.rfind("G31 ", 0) == 0) {
            const std::string var = std::to_string(axis_index(*w.axis) + 1);
            // The end kept just before (past the dialect's waiting blocks).
            std::size_t keep = i;
            while (keep > 0 && lines[keep - 1].rfind("#101=", 0) != 0) --keep;
            EXPECT_GT(keep, 0u) << line;
            if (keep == 0) break;
            const std::string expected_keep =
                joined({"#101=#504", var, w.value[0] == '-' ? "" : "+", w.value});
            EXPECT_EQ(lines[keep - 1], expected_keep);
            const std::size_t check = next_line(lines, i + 1, "IF[");
            EXPECT_LT(check, lines.size()) << line;
            if (check == lines.size()) break;
            const bool probe = lines[check].find("GOTO9001") != std::string::npos;
            EXPECT_EQ(lines[check], joined({"IF[ABS[#506", var, "-#101]",
                                            probe ? "LT0.050]GOTO9001" : "GE0.050]GOTO9002"}));
            back.moves.push_back(
                {probe ? Motion::probe : Motion::guard, *w.axis, std::stod(w.value), *w.feed});
        } else if (line.rfind("G1 ", 0) == 0 || line.rfind("G0 ", 0) == 0) {
            back.moves.push_back({line[1] == '1' ? Motion::feed : Motion::rapid, *w.axis,
                                  std::stod(w.value), w.feed.value_or(0.0)});
        }
    }
    return back;
}

// Siemens: STOPRE, R1 from the axis's $AA_IW plus the move, an absolute
// MEAS block to R1, G91 again; a probe jumps to NO_TRIGGER when $A_PROBE is
// not 1, a protected move to OBSTRUCTED when it is. A recorded touch's WRITE
// line names its number and the probing axis's $AA_MW.
ReadBack read_siemens(const std::vector<std::string>& lines) {
    ReadBack back;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& line = lines[i];
        const Words w = words_of(line);
        if (line.rfind("MEAS=", 0) == 0) {
            const std::string axis(1, *w.axis);
            EXPECT_EQ(w.value, "R1") << line;
            const std::string keep = lines.at(i - 1);
            const std::string prefix = joined({"R1=$AA_IW[", axis, "]"});
            EXPECT_EQ(keep.rfind(prefix, 0), 0u) << keep;
            EXPECT_EQ(lines.at(i - 2), "STOPRE");
            EXPECT_EQ(lines.at(i + 1), "G91");
            EXPECT_EQ(lines.at(i + 2), "STOPRE");
            const std::string& check = lines.at(i + 3);
            const bool probe = check == "IF $A_PROBE[1]<>1 GOTOF NO_TRIGGER";
            if (!probe) {
                EXPECT_EQ(check, "IF $A_PROBE[1]==1 GOTOF OBSTRUCTED");
            }
            back.moves.push_back({probe ? Motion::probe : Motion::guard, *w.axis,
                                  std::stod(keep.substr(prefix.size())), *w.feed});
        } else if (line.rfind("G1 ", 0) == 0 || line.rfind("G0 ", 0) == 0) {
            back.moves.push_back({line[1] == '1' ? Motion::feed : Motion::rapid, *w.axis,
                                  std::stod(w.value), w.feed.value_or(0.0)});
        } else if (line.rfind("WRITE(PC_ERROR,\"PROBECYCLE_LOG\",\"TOUCH ", 0) == 0) {
            const int n = std::stoi(line.substr(39));
            back.recorded.push_back(n);
            // The moving axis's trip: the last MEAS block's axis.
            const std::string& axis = std::string(1, back.moves.back().axis);
            EXPECT_NE(line.find(joined({"SPRINT(\"%12.4F\",$AA_MW[", axis, "])"})),
                      std::string::npos)
                << line;
        }
    }
    return back;
}

ReadBack read_program(const Dialect& d, const std::string& text) {
    const std::vector<std::string> lines = lines_of(text);
    switch (d.id) {
        case DialectId::linuxcnc:
        case DialectId::grbl:
            return read_rs274(lines);
        case DialectId::fanuc:
        case DialectId::haas:
        case DialectId::mitsubishi:
            return read_macro_b(lines);
        case DialectId::siemens:
            return read_siemens(lines);
    }
    return {};
}

// The plan's moves, in order: grbl's program opens with the plan's
// signature (plan.h, plan_signature) before its first move.
std::vector<Move> expected_moves(const ProbingPlan& plan, const Dialect& d) {
    std::vector<Move> moves;
    if (d.id == DialectId::grbl) {
        const PlanSignature s = plan_signature(plan);
        for (const double back : s.back_mm) {
            moves.push_back({Motion::guard, s.axis, s.direction * (kSignatureOut_mm + back),
                             kSignatureFeed_mm_min});
            moves.push_back({Motion::guard, s.axis, -s.direction * back, kSignatureFeed_mm_min});
            moves.push_back(
                {Motion::feed, s.axis, -s.direction * kSignatureOut_mm, kSignatureFeed_mm_min});
        }
    }
    for (const ProgramStep& step : plan.steps) {
        const double distance = step.direction * step.distance_mm;
        switch (step.kind) {
            case StepKind::probe:
                moves.push_back({Motion::probe, step.axis, distance, step.feed_mm_min});
                break;
            case StepKind::guard:
                moves.push_back({Motion::guard, step.axis, distance, step.feed_mm_min});
                break;
            case StepKind::move:
                moves.push_back({step.feed_mm_min > 0.0 ? Motion::feed : Motion::rapid, step.axis,
                                 distance, step.feed_mm_min});
                break;
            case StepKind::pause:
                break;
        }
    }
    return moves;
}

// The first difference between the moves the program holds and the
// plan's, or "" when there is none.
std::string first_difference(const ProbingPlan& plan, const Dialect& d, const std::string& text) {
    const ReadBack back = read_program(d, text);
    const std::vector<Move> expected = expected_moves(plan, d);
    for (std::size_t i = 0; i < std::max(back.moves.size(), expected.size()); ++i) {
        if (i >= back.moves.size()) return "missing: " + describe(expected[i]);
        if (i >= expected.size()) return "extra: " + describe(back.moves[i]);
        const Move& got = back.moves[i];
        const Move& want = expected[i];
        if (got.motion != want.motion || got.axis != want.axis ||
            std::abs(got.distance_mm - want.distance_mm) > 0.0005 ||
            std::abs(got.feed_mm_min - want.feed_mm_min) > 0.05) {
            return joined(
                {"move ", std::to_string(i), ": ", describe(got), ", the plan's ", describe(want)});
        }
    }
    return "";
}

TEST(ProgramReadBack, EveryDialectsProgramHoldsThePlansMovesChecksAndRecords) {
    std::vector<program_test::NamedPlan> plans = program_test::golden_plans();
    plans.push_back({"guarded", program_test::guarded_plan()});
    for (const auto& [name, plan] : plans) {
        for (const DialectId id : all_dialects()) {
            const Dialect& d = dialect(id);
            SCOPED_TRACE(name + " " + d.name);
            const std::string text =
                write_program(plan, d, program_test::kDate, program_test::golden_options());
            EXPECT_FALSE(expected_moves(plan, d).empty());
            EXPECT_EQ(first_difference(plan, d, text), "");
            // Every recorded touch once, numbered in order (grbl records by
            // its console's [PRB:] answers, not in the program).
            if (id != DialectId::grbl) {
                std::vector<int> numbers(plan.recorded().size());
                for (std::size_t n = 0; n < numbers.size(); ++n) {
                    numbers[n] = static_cast<int>(n) + 1;
                }
                EXPECT_EQ(read_program(d, text).recorded, numbers);
            }
        }
    }
}

// The readers see an edit: a distance or a feed changed in the program.
TEST(ProgramReadBack, AnEditedMoveIsFound) {
    const ProbingPlan plan = program_test::guarded_plan();
    const auto edited = [&](const Dialect& d, const std::string& from, const std::string& to) {
        std::string text = write_program(plan, d, program_test::kDate);
        const std::size_t at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return text.replace(at, from.size(), to);
    };
    EXPECT_NE(
        first_difference(plan, linuxcnc_dialect(),
                         edited(linuxcnc_dialect(), "G38.2 X6.000 F2000", "G38.2 X6.100 F2000")),
        "");
    EXPECT_NE(first_difference(plan, fanuc_dialect(),
                               edited(fanuc_dialect(), "G31 X6.000 F2000", "G31 X6.000 F200")),
              "");
    EXPECT_NE(
        first_difference(plan, siemens_dialect(),
                         edited(siemens_dialect(), "R1=$AA_IW[X]+6.000", "R1=$AA_IW[X]+6.500")),
        "");
}

}  // namespace
}  // namespace probecycle
