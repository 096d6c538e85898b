// The result a cycle program computes is the one the import computes: the
// programs' own lines (assignments, IF/GOTO, o-word if, the stop) run by a
// small interpreter of the macro arithmetic they use, on touches around each
// golden feature's nominal geometry, give #114-#118 as feature_result does;
// out of tolerance with the stop action the program stops. LinuxCNC itself
// runs them in tests/linuxcnc; no Fanuc-type control runs here, so this is
// where its arithmetic is checked.

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/program/feature_result.h"
#include "core/program/program_writer.h"
#include "tests/core/program/program_test_plans.h"

namespace probecycle {
namespace {

// Expressions of #n, numbers, + - * /, [ ], ABS[ ] and one comparison (EQ,
// NE, GT, GE, LT, LE), spaces removed; #<_task> reads as 1 (the task).
// The probes' own checks (Fanuc-type's jumps to 9001 and 9002, LinuxCNC's
// #5070) are not run: every probe here triggers and no move is obstructed.
class Macro {
  public:
    std::map<int, double> vars;
    std::array<double, 3> skip{};

    double eval(const std::string& text) {
        text_ = text;
        at_ = 0;
        const double value = comparison();
        EXPECT_EQ(at_, text_.size()) << "unread: " << text_.substr(at_);
        return value;
    }

  private:
    std::string text_;
    std::size_t at_{0};

    bool take(const char* word) {
        const std::string w(word);
        if (text_.compare(at_, w.size(), w) != 0) return false;
        at_ += w.size();
        return true;
    }
    double comparison() {
        const double left = sum();
        // Macro B's words, Siemens's signs (the two-character ones first).
        for (const char* op :
             {"EQ", "NE", "GT", "GE", "LT", "LE", "==", "<>", ">=", "<=", ">", "<"}) {
            if (!take(op)) continue;
            const double right = sum();
            const std::string o(op);
            if (o == "EQ" || o == "==") return left == right;
            if (o == "NE" || o == "<>") return left != right;
            if (o == "GT" || o == ">") return left > right;
            if (o == "GE" || o == ">=") return left >= right;
            if (o == "LT" || o == "<") return left < right;
            return left <= right;
        }
        return left;
    }
    double sum() {
        double value = product();
        while (at_ < text_.size() && (text_[at_] == '+' || text_[at_] == '-')) {
            const char op = text_[at_++];
            const double right = product();
            value = op == '+' ? value + right : value - right;
        }
        return value;
    }
    double product() {
        double value = factor();
        while (at_ < text_.size() && (text_[at_] == '*' || text_[at_] == '/')) {
            const char op = text_[at_++];
            const double right = factor();
            value = op == '*' ? value * right : value / right;
        }
        return value;
    }
    double factor() {
        if (take("-")) return -factor();
        if (take("+")) return factor();
        if (take("ABS[")) {
            const double value = comparison();
            EXPECT_TRUE(take("]"));
            return std::abs(value);
        }
        if (take("ABS(")) {
            const double value = comparison();
            EXPECT_TRUE(take(")"));
            return std::abs(value);
        }
        if (take("[")) {
            const double value = comparison();
            EXPECT_TRUE(take("]"));
            return value;
        }
        if (take("(")) {
            const double value = comparison();
            EXPECT_TRUE(take(")"));
            return value;
        }
        // Siemens: the trip ($AA_MW) and the current position ($AA_IW).
        static constexpr std::array<const char*, 3> kTrip = {"$AA_MW[X]", "$AA_MW[Y]", "$AA_MW[Z]"};
        static constexpr std::array<const char*, 3> kAt = {"$AA_IW[X]", "$AA_IW[Y]", "$AA_IW[Z]"};
        for (std::size_t axis = 0; axis < 3; ++axis) {
            if (take(kTrip[axis])) return skip.at(axis);
            if (take(kAt[axis])) return 0.0;
        }
        if (at_ + 1 < text_.size() && text_[at_] == 'R' &&
            std::isdigit(static_cast<unsigned char>(text_[at_ + 1]))) {
            ++at_;
            const int n = static_cast<int>(number());
            EXPECT_TRUE(vars.count(n)) << "R" << n << " read before it is set";
            return vars[n];
        }
        if (take("#<_task>")) return 1.0;
        if (take("#")) {
            const int n = static_cast<int>(number());
            if (n >= 5061 && n <= 5063) return skip.at(static_cast<std::size_t>(n - 5061));
            // The current position and LinuxCNC's probe-tripped flag: the
            // probes' own checks, not what this test runs.
            if ((n >= 5041 && n <= 5043) || n == 5070) return 0.0;
            EXPECT_TRUE(vars.count(n)) << "#" << n << " read before it is set";
            return vars[n];
        }
        return number();
    }
    double number() {
        const std::size_t start = at_;
        while (at_ < text_.size() &&
               (std::isdigit(static_cast<unsigned char>(text_[at_])) || text_[at_] == '.')) {
            ++at_;
        }
        EXPECT_GT(at_, start) << "a number at " << text_.substr(start);
        return std::stod(text_.substr(start, at_ - start));
    }
};

std::string without_spaces(const std::string& line) {
    std::string out;
    for (char c : line) {
        if (c != ' ') out += c;
    }
    return out;
}

struct ProgramRun {
    Macro macro;
    bool stopped{false};
};

// Runs the program's macro lines; the recorded touches' skip positions are
// `touches`, in order (a touch's number from the LinuxCNC LOG line, the
// Fanuc-type #102 or Mitsubishi's #505, 0 before the first). A stop is an abort, an alarm or a
// Mitsubishi M00 with its reason.
ProgramRun run_program(const std::string& program,
                       const std::vector<std::array<double, 3>>& touches) {
    std::vector<std::string> lines;
    std::istringstream in(program);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    ProgramRun run;
    for (std::size_t i = 0; i < lines.size() && !run.stopped; ++i) {
        const std::string& raw = lines[i];
        const std::string line = without_spaces(raw);
        if (raw.rfind("(LOG,probecycle touch ", 0) == 0) {
            run.macro.skip = touches.at(std::stoul(raw.substr(22)) - 1);
        } else if (line.rfind("WRITE(", 0) == 0 && line.find("\"TOUCH") != std::string::npos) {
            // Siemens: the touch's WRITE line names its number.
            run.macro.skip = touches.at(std::stoul(line.substr(line.find("\"TOUCH") + 6)) - 1);
        } else if (line.rfind("(ABORT,", 0) == 0 || line.rfind("#3000=", 0) == 0 ||
                   line.rfind("M00(", 0) == 0 || line.rfind("MSG(\"PROBECYCLE:", 0) == 0 ||
                   line == "M2" || line == "M30") {
            run.stopped = line != "M2" && line != "M30";
            if (!run.stopped) break;
        } else if (line.rfind("IF", 0) == 0 && line.find("GOTOF") != std::string::npos) {
            // Siemens: "IF condition GOTOF LABEL" to "LABEL:" further down;
            // the probes' and WRITE's own checks are not run (as above).
            const std::size_t go = line.find("GOTOF");
            const std::string label = line.substr(go + 5);
            if (label == "NO_TRIGGER" || label == "OBSTRUCTED" || label == "WRITE_FAILED") {
                continue;
            }
            if (run.macro.eval(line.substr(2, go - 2)) != 0.0) {
                std::size_t j = i + 1;
                while (j < lines.size() && without_spaces(lines[j]) != label + ":") ++j;
                EXPECT_LT(j, lines.size()) << label;
                i = j;
            }
        } else if ((line.rfind('#', 0) == 0 ||
                    (line.size() > 1 && line[0] == 'R' &&
                     std::isdigit(static_cast<unsigned char>(line[1])))) &&
                   line.find('=') != std::string::npos) {
            const std::size_t eq = line.find('=');
            const int n = std::stoi(line.substr(1, eq - 1));
            const double value = run.macro.eval(line.substr(eq + 1));
            run.macro.vars[n] = value;
            // The touch's number: the Fanuc-type #102, Mitsubishi's count #505.
            if ((n == 102 || n == 505) && value > 0.0) {
                run.macro.skip = touches.at(static_cast<std::size_t>(value) - 1);
            }
        } else if (line.rfind("IF[", 0) == 0) {
            const std::size_t go = line.rfind("GOTO");
            const std::string target = line.substr(go + 4);
            if (target == "9001" || target == "9002") continue;
            if (run.macro.eval(line.substr(2, go - 2)) != 0.0) {
                std::string label("N");  // (appended: g++ 12 warns falsely of "N" + ...)
                label += target;
                std::size_t j = i + 1;
                while (j < lines.size() && without_spaces(lines[j]) != label) ++j;
                EXPECT_LT(j, lines.size()) << label;
                i = j;
            }
        } else if (line.size() > 1 && line[0] == 'o' && line.find("if[") != std::string::npos) {
            const std::string label = line.substr(0, line.find("if["));
            const std::size_t open = line.find("if[") + 2;
            if (run.macro.eval(line.substr(open)) == 0.0) {
                std::size_t j = i + 1;
                while (j < lines.size() && without_spaces(lines[j]) != label + "endif") ++j;
                EXPECT_LT(j, lines.size()) << label;
                i = j;
            }
        }
    }
    return run;
}

// Touches of a plan about its nominal geometry: each side's stylus centre at
// the nominal distance plus up to +-`spread_mm`, the centre off by `offset`.
std::vector<std::array<double, 3>> touches_about(const ResultSpec& spec, double spread_mm,
                                                 double offset_mm, std::mt19937& random) {
    std::uniform_real_distribution<double> noise(-spread_mm, spread_mm);
    std::vector<std::array<double, 3>> touches;
    for (const std::size_t side : spec.touch_side) {
        const AxisDirection& s = spec.sides[side];
        const std::size_t axis = s.axis == 'X' ? 0 : s.axis == 'Y' ? 1 : 2;
        std::array<double, 3> xyz{0.3, -0.2, -5.0};
        const double half = spec.feature == Feature::surface ? -12.5 : spec.nominal_mm / 2;
        xyz[axis] = offset_mm + s.direction * half + noise(random);
        touches.push_back(xyz);
    }
    return touches;
}

TEST(ProgramResult, EveryComputingDialectComputesWhatTheImportComputes) {
    std::mt19937 random(42);
    int stops = 0;
    int flags = 0;
    for (const auto& [name, plan] : program_test::golden_plans()) {
        const std::optional<ResultSpec> spec = result_spec(plan);
        if (!spec) continue;
        for (const DialectId id : all_dialects()) {
            const Dialect* d = &dialect(id);
            if (d->result_record.empty()) continue;  // grbl computes nothing
            const std::string program =
                write_program(plan, *d, program_test::kDate, program_test::golden_options());
            for (int k = 0; k < 50; ++k) {
                SCOPED_TRACE(name + " " + d->name + " " + std::to_string(k));
                // Half the runs spread over a few tolerances, to go out of it too.
                const double spread = k % 2 == 0 ? 0.001 : 0.05;
                const std::vector<std::array<double, 3>> touches =
                    touches_about(*spec, spread, 0.01 * (k % 5), random);
                const FeatureResult expected = feature_result(*spec, touches);
                const ProgramRun run = run_program(program, touches);
                const std::map<int, double>& v = run.macro.vars;
                // #114-#118, or Siemens's R64-R68.
                const int size = d->first_result_variable + 4;
                ASSERT_TRUE(v.count(size) && v.count(size + 4));
                EXPECT_NEAR(v.at(size), expected.size_mm, 1e-9);
                EXPECT_NEAR(v.at(size + 1), expected.centre_mm[0].value_or(0.0), 1e-9);
                EXPECT_NEAR(v.at(size + 2), expected.centre_mm[1].value_or(0.0), 1e-9);
                EXPECT_NEAR(v.at(size + 3), expected.deviation_mm, 1e-9);
                EXPECT_EQ(v.at(size + 4), expected.out_of_tolerance ? 1.0 : 0.0);
                const bool stops_here =
                    expected.out_of_tolerance && spec->tolerance_action == ToleranceAction::stop;
                EXPECT_EQ(run.stopped, stops_here);
                stops += stops_here ? 1 : 0;
                flags += expected.out_of_tolerance && !stops_here ? 1 : 0;
            }
        }
    }
    // Both ways were taken: a stop (the pocket) and a flag that goes on (the web).
    EXPECT_GT(stops, 0);
    EXPECT_GT(flags, 0);
}

}  // namespace
}  // namespace probecycle
