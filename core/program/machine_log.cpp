#include "core/program/machine_log.h"

#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "core/common/csv_reader.h"
#include "core/common/input_error.h"
#include "core/common/number_format.h"
#include "core/program/dialect.h"

namespace probecycle {

namespace {

// Between two probes that only one axis moved between, the other axes stay
// put: more than this (a jog, another setup) means the log is not this plan's.
constexpr double kStillAxisTolerance_mm = 0.05;

Message log_message(const char* code, const char* text, std::vector<MessageArg> args = {}) {
    return Message{code, "MachineLog", text, std::move(args)};
}

std::vector<std::pair<std::size_t, std::string_view>> lines_of(std::string_view text) {
    std::vector<std::pair<std::size_t, std::string_view>> lines;
    std::size_t number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.emplace_back(++number, line);
        start = end + 1;
    }
    return lines;
}

std::vector<std::string_view> words_of(std::string_view line, char separator) {
    std::vector<std::string_view> words;
    std::size_t start = 0;
    while (start <= line.size()) {
        std::size_t end = line.find(separator, start);
        if (end == std::string_view::npos) end = line.size();
        std::string_view word = line.substr(start, end - start);
        if (separator != ' ' || !word.empty()) words.push_back(word);
        start = end + 1;
    }
    return words;
}

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
    return text;
}

[[noreturn]] void bad_line(std::size_t line, std::string_view content, const char* expected) {
    throw CsvError(line, "",
                   log_message("log_unreadable_line",
                               QT_TRANSLATE_NOOP("MachineLog", "cannot read '%1'; expected %2"),
                               {text_arg("content", std::string(content.substr(0, 80))),
                                text_arg("expected", expected)}));
}

[[noreturn]] void plan_mismatch(std::size_t line, std::string log_plan, const std::string& plan) {
    throw CsvError(
        line, "",
        log_message("log_plan_mismatch",
                    QT_TRANSLATE_NOOP("MachineLog",
                                      "the log is from plan %1, the plan file is "
                                      "plan %2: give the plan the program was "
                                      "made from; nothing imported"),
                    {text_arg("log_plan", std::move(log_plan)), text_arg("plan", plan)}));
}

[[noreturn]] void touch_out_of_order(std::size_t line, std::string touch, std::size_t due) {
    throw CsvError(line, "",
                   log_message("log_touch_order",
                               QT_TRANSLATE_NOOP("MachineLog",
                                                 "touch %1 where touch %2 was due: the log "
                                                 "holds more than one run; nothing imported"),
                               {text_arg("touch", std::move(touch)),
                                arg("due", ArgKind::integer, static_cast<double>(due))}));
}

// Three coordinates from words; nullopt when one is not a number within reach.
std::optional<std::array<double, 3>> coordinates(const std::vector<std::string_view>& words,
                                                 std::size_t first) {
    if (words.size() < first + 3) return std::nullopt;
    std::array<double, 3> xyz{};
    for (std::size_t i = 0; i < 3; ++i) {
        const std::optional<double> value = parse_decimal(words[first + i]);
        if (!value || std::abs(*value) > kMaxCoordinate_mm) return std::nullopt;
        xyz[i] = *value;
    }
    return xyz;
}

// "S s X x Y y D d T t" from words[first]: the five numbers of a result
// line; nullopt when the words are not that.
std::optional<std::array<double, 5>> result_values(const std::vector<std::string_view>& words,
                                                   std::size_t first) {
    if (words.size() != first + 10) return std::nullopt;
    std::array<double, 5> values{};
    for (std::size_t i = 0; i < 5; ++i) {
        const std::optional<double> value = parse_decimal(words[first + 2 * i + 1]);
        if (words[first + 2 * i] != std::string_view(&"SXYDT"[i], 1) || !value ||
            std::abs(*value) > kMaxCoordinate_mm) {
            return std::nullopt;
        }
        values[i] = *value;
    }
    return values;
}

std::size_t axis_index(char axis) {
    return axis == 'X' ? 0 : axis == 'Y' ? 1 : 2;
}

// Probes in the order the positions stand for: with `every_probe` the
// protected moves too (grbl reports each G38.3, LinuxCNC's PROBEOPEN file
// holds each one's end).
std::vector<const ProgramStep*> probes_of(const ProbingPlan& plan, bool every_probe) {
    std::vector<const ProgramStep*> probes;
    for (const ProgramStep& step : plan.steps) {
        if ((step.kind == StepKind::probe && (every_probe || step.recorded)) ||
            (step.kind == StepKind::guard && every_probe)) {
            probes.push_back(&step);
        }
    }
    return probes;
}

// The one axis every move between two probes runs along (pauses: none, the
// operator may move anything), or nullopt.
std::optional<char> only_axis_between(const ProgramStep* from, const ProgramStep* to) {
    std::optional<char> axis;
    for (const ProgramStep* step = from; step <= to; ++step) {
        if (step->kind == StepKind::pause) return std::nullopt;
        if (axis && *axis != step->axis) return std::nullopt;
        axis = step->axis;
    }
    return axis;
}

void check_matches_plan(const std::vector<const ProgramStep*>& probes,
                        const std::vector<RecordedPosition>& positions) {
    if (positions.size() < probes.size()) {
        const std::size_t last_line = positions.empty() ? 0 : positions.back().line;
        throw CsvError(
            last_line, "",
            log_message("log_missing_touches",
                        QT_TRANSLATE_NOOP("MachineLog",
                                          "the log ends after %1 of the plan's %2 probe "
                                          "positions: the program stopped early, a position was "
                                          "not recorded, or the log is from another plan; "
                                          "nothing imported"),
                        {arg("found", ArgKind::integer, static_cast<double>(positions.size())),
                         arg("expected", ArgKind::integer, static_cast<double>(probes.size()))}));
    }
    if (positions.size() > probes.size()) {
        throw CsvError(
            positions[probes.size()].line, "",
            log_message("log_extra_touch",
                        QT_TRANSLATE_NOOP("MachineLog",
                                          "a probe position more than the plan's %1: the program "
                                          "ran twice into one log, or the log is from another "
                                          "plan; nothing imported"),
                        {arg("expected", ArgKind::integer, static_cast<double>(probes.size()))}));
    }
    for (std::size_t i = 1; i < probes.size(); ++i) {
        const std::optional<char> axis = only_axis_between(probes[i - 1], probes[i]);
        if (!axis) continue;
        for (std::size_t a = 0; a < 3; ++a) {
            if (a == axis_index(*axis)) continue;
            const double moved = positions[i].xyz[a] - positions[i - 1].xyz[a];
            if (std::abs(moved) > kStillAxisTolerance_mm) {
                throw CsvError(
                    positions[i].line, "",
                    log_message(
                        "log_other_plan",
                        QT_TRANSLATE_NOOP("MachineLog",
                                          "%1 moved %2 since line %3, but the plan moves only %4 "
                                          "between these probes: is the log from another plan? "
                                          "Nothing imported"),
                        {text_arg("axis", std::string(1, "XYZ"[a])),
                         significant_arg("moved_mm", ArgKind::length_mm, moved, 4),
                         arg("line", ArgKind::integer, static_cast<double>(positions[i - 1].line)),
                         text_arg("moving_axis", std::string(1, *axis))}));
            }
        }
    }
}

std::string csv_value(double value) {
    return format_exact(value);
}

}  // namespace

std::vector<RecordedPosition> read_linuxcnc_positions(std::string_view text,
                                                      const ProbingPlan& plan,
                                                      LoggedResult* result) {
    std::vector<RecordedPosition> positions;
    bool log_file = false;
    bool probe_file = false;
    for (const auto& [number, raw] : lines_of(text)) {
        const std::string_view line = trimmed(raw);
        if (line.empty()) continue;
        const std::vector<std::string_view> words = words_of(line, ' ');
        if (words[0] == "probecycle") {
            log_file = true;
            if (words.size() >= 3 && words[1] == "plan") {
                const std::string expected = plan_id(plan);
                if (words[2] != expected) {
                    plan_mismatch(number, std::string(words[2]), expected);
                }
                continue;
            }
            if (words.size() == 4 && words[1] == "out" && words[2] == "of" &&
                words[3] == "tolerance") {
                if (result != nullptr) result->out_of_tolerance_line = number;
                continue;
            }
            if (words.size() >= 2 && words[1] == "result") {
                const std::optional<std::array<double, 5>> values = result_values(words, 2);
                if (!values) bad_line(number, line, "'probecycle result S s X x Y y D d T t'");
                if (result != nullptr) {
                    result->line = number;
                    result->values = *values;
                }
                continue;
            }
            const std::optional<std::array<double, 3>> xyz = coordinates(words, 3);
            const std::optional<double> n =
                words.size() == 6 ? parse_decimal(words[2]) : std::nullopt;
            if (words.size() != 6 || words[1] != "touch" || !xyz || !n) {
                bad_line(number, line, "'probecycle touch N X Y Z'");
            }
            if (*n != static_cast<double>(positions.size() + 1)) {
                touch_out_of_order(number, std::string(words[2]), positions.size() + 1);
            }
            positions.push_back({number, *xyz});
            continue;
        }
        const std::optional<std::array<double, 3>> xyz = coordinates(words, 0);
        if (words.size() != 9 || !xyz || log_file) {
            bad_line(number, line,
                     log_file ? "'probecycle touch N X Y Z' (the program's LOG file)"
                              : "9 numbers X Y Z A B C U V W (a PROBEOPEN file) or the "
                                "program's LOG file");
        }
        probe_file = true;
        positions.push_back({number, *xyz});
    }
    if (log_file && probe_file) {
        bad_line(positions.front().line, "", "one file: the LOG file or the PROBEOPEN file");
    }
    return positions;
}

namespace {

// A [PRB:x,y,z:s] report of grbl's console.
struct GrblReport {
    std::size_t line{0};
    std::array<double, 3> xyz{};
    bool triggered{false};
    std::string text;
};

// The plan's signature (plan_signature, plan.h) in the console's first four
// reports: each pair's difference along the signature's axis is its d.
void check_grbl_signature(const std::vector<GrblReport>& reports, const ProbingPlan& plan) {
    const PlanSignature expected = plan_signature(plan);
    const std::size_t axis = axis_index(expected.axis);
    // Not the signature: a console of another plan's or an older ProbeCycle's
    // program, or one whose signature moves touched something (grbl answers
    // such a move with :1, and cannot stop the program on it).
    const auto unsigned_console = [&](std::size_t line) {
        throw CsvError(
            line, "",
            log_message("log_grbl_no_signature",
                        QT_TRANSLATE_NOOP("MachineLog",
                                          "the console does not open with the plan's signature "
                                          "(four [PRB:...:0] answers to the protected moves "
                                          "before the first probe): it is from another plan's "
                                          "or an older ProbeCycle's program (make the program "
                                          "again from this plan), or the probe touched "
                                          "something during those moves (give it free air); "
                                          "nothing imported")));
    };
    if (reports.size() < 4) unsigned_console(reports.empty() ? 0 : reports.back().line);
    std::array<int, 2> codes{};
    for (std::size_t pair = 0; pair < 2; ++pair) {
        const GrblReport& out = reports[2 * pair];
        const GrblReport& back = reports[2 * pair + 1];
        if (out.triggered) unsigned_console(out.line);
        if (back.triggered) unsigned_console(back.line);
        const double d_mm = expected.direction * (out.xyz[axis] - back.xyz[axis]);
        const double code = (d_mm - kSignatureFirst_mm) / kSignatureStep_mm;
        // Within a quarter step of a code (a motor step is far smaller).
        if (!(std::abs(code - std::round(code)) < 0.25) || std::round(code) < 0 ||
            std::round(code) >= kSignatureCodes) {
            unsigned_console(back.line);
        }
        codes[pair] = static_cast<int>(std::round(code));
    }
    if (codes != expected.codes) {
        throw CsvError(
            reports[3].line, "",
            log_message(
                "log_grbl_signature_mismatch",
                QT_TRANSLATE_NOOP("MachineLog",
                                  "the console is from another plan (its signature reads "
                                  "%1, this plan's is %2): give the plan the program was "
                                  "made from; nothing imported"),
                {text_arg("found", std::to_string(codes[0]) + "-" + std::to_string(codes[1])),
                 text_arg("expected", std::to_string(expected.codes[0]) + "-" +
                                          std::to_string(expected.codes[1]))}));
    }
}

}  // namespace

std::vector<RecordedPosition> read_grbl_positions(std::string_view text, const ProbingPlan& plan) {
    const std::vector<const ProgramStep*> probes = probes_of(plan, true);
    std::vector<GrblReport> reports;
    for (const auto& [number, line] : lines_of(text)) {
        if (const std::size_t alarm = line.find("ALARM:"); alarm != std::string_view::npos) {
            throw CsvError(
                number, "",
                log_message("log_alarm",
                            QT_TRANSLATE_NOOP("MachineLog",
                                              "grbl raised '%1' (ALARM:5: the probe did not "
                                              "touch; ALARM:4: it was triggered before the move): "
                                              "the program stopped there; nothing imported"),
                            {text_arg("alarm", std::string(trimmed(line.substr(alarm, 12))))}));
        }
        const std::size_t at = line.find("[PRB:");
        if (at == std::string_view::npos) continue;
        const std::size_t end = line.find(']', at);
        if (end == std::string_view::npos) bad_line(number, line, "[PRB:x,y,z:1]");
        const std::string_view body = line.substr(at + 5, end - at - 5);
        const std::size_t colon = body.rfind(':');
        if (colon == std::string_view::npos) bad_line(number, line, "[PRB:x,y,z:1]");
        const std::optional<std::array<double, 3>> xyz =
            coordinates(words_of(body.substr(0, colon), ','), 0);
        const std::string_view success = body.substr(colon + 1);
        if (!xyz || (success != "0" && success != "1")) {
            bad_line(number, line, "[PRB:x,y,z:1]");
        }
        reports.push_back(
            {number, *xyz, success == "1", std::string(line.substr(at, end - at + 1))});
    }
    // The signature first: the console names no plan otherwise.
    check_grbl_signature(reports, plan);
    std::vector<RecordedPosition> positions;
    for (std::size_t r = 4; r < reports.size(); ++r) {
        const GrblReport& report = reports[r];
        // A report past the plan's probes is left to the count's check.
        const bool guard =
            positions.size() < probes.size() && probes[positions.size()]->kind == StepKind::guard;
        if (!report.triggered && !guard) {
            throw CsvError(report.line, "",
                           log_message("log_no_trigger",
                                       QT_TRANSLATE_NOOP("MachineLog",
                                                         "the probe did not trigger (%1); "
                                                         "nothing imported"),
                                       {text_arg("report", report.text)}));
        }
        if (report.triggered && guard) {
            throw CsvError(
                report.line, "",
                log_message("log_obstructed",
                            QT_TRANSLATE_NOOP("MachineLog",
                                              "the probe touched something during a protected "
                                              "move (%1): its path is obstructed, and grbl, which "
                                              "cannot stop a program on it, went on; check the "
                                              "machine; nothing imported"),
                            {text_arg("report", report.text)}));
        }
        positions.push_back({report.line, report.xyz});
    }
    return positions;
}

namespace {

// Lines ending with LF, CR, CR LF or LF CR CR (Fanuc's NCR output): a LF
// takes the CRs that follow it, a CR the LF that follows it.
std::vector<std::pair<std::size_t, std::string_view>> dprnt_lines_of(std::string_view text) {
    std::vector<std::pair<std::size_t, std::string_view>> lines;
    std::size_t number = 0;
    std::size_t start = 0;
    std::size_t at = 0;
    while (at < text.size()) {
        const char c = text[at];
        if (c != '\n' && c != '\r') {
            ++at;
            continue;
        }
        lines.emplace_back(++number, text.substr(start, at - start));
        ++at;
        if (c == '\n') {
            while (at < text.size() && text[at] == '\r') ++at;
        } else if (at < text.size() && text[at] == '\n') {
            ++at;
            while (at < text.size() && text[at] == '\r') ++at;
        }
        start = at;
    }
    if (start < text.size()) lines.emplace_back(++number, text.substr(start));
    return lines;
}

// The line without control bytes (DC2, DC4, NUL, tabs ...) and '%', trimmed.
std::string dprnt_text(std::string_view line) {
    std::string text;
    for (const char c : line) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte != 0x7f && c != '%') text += c;
    }
    return std::string(trimmed(text));
}

// Reads "<sign><spaces><digits>[.<digits>]" after spaces from `at`.
std::optional<double> dprnt_number(std::string_view text, std::size_t& at) {
    while (at < text.size() && text[at] == ' ') ++at;
    std::string number;
    if (at < text.size() && (text[at] == '-' || text[at] == '+')) {
        if (text[at] == '-') number += '-';
        ++at;
        while (at < text.size() && text[at] == ' ') ++at;
    }
    const std::size_t digits = at;
    while (at < text.size() && ((text[at] >= '0' && text[at] <= '9') || text[at] == '.')) ++at;
    if (at == digits) return std::nullopt;
    number += text.substr(digits, at - digits);
    const std::optional<double> value = parse_decimal(number);
    if (!value || std::abs(*value) > kMaxCoordinate_mm) return std::nullopt;
    return value;
}

bool dprnt_word(std::string_view text, std::size_t& at, char letter) {
    while (at < text.size() && text[at] == ' ') ++at;
    if (at >= text.size() || text[at] != letter) return false;
    ++at;
    return true;
}

// The plan id that letters stand for (id_letters() backwards), or the letters.
std::string plan_from_letters(std::string_view letters) {
    std::string hex;
    for (const char c : letters) {
        if (c < 'A' || c > 'P') return std::string(letters);
        hex += "0123456789abcdef"[c - 'A'];
    }
    return hex;
}

}  // namespace

std::vector<RecordedPosition> read_fanuc_positions(std::string_view text, const ProbingPlan& plan,
                                                   LoggedResult* result, bool last_run) {
    constexpr const char* kTouchLine = "'TOUCH n X x Y y Z z'";
    // Each line's text once, for the scan below and the reading.
    std::vector<std::pair<std::size_t, std::string>> lines;
    for (const auto& [number, raw] : dprnt_lines_of(text))
        lines.emplace_back(number, dprnt_text(raw));
    // A file the program appends to holds every run: the last PLAN line on.
    std::size_t first_line = 0;
    if (last_run) {
        for (const auto& [number, line] : lines) {
            const std::vector<std::string_view> words = words_of(line, ' ');
            if (words.size() >= 2 && words[0] == "PROBECYCLE" && words[1] == "PLAN") {
                first_line = number;
            }
        }
    }
    std::vector<RecordedPosition> positions;
    bool plan_line = false;
    for (const auto& [number, line] : lines) {
        if (number < first_line) continue;
        const std::vector<std::string_view> words = words_of(line, ' ');
        if (words.empty()) continue;
        if (words[0] == "PROBECYCLE") {
            if (words.size() >= 3 && words[1] == "PLAN") {
                const std::string expected = plan_id(plan);
                if (words[2] != id_letters(expected)) {
                    plan_mismatch(number, plan_from_letters(words[2]), expected);
                }
                plan_line = true;
            } else if (words.size() == 2 && words[1] == "OBSTRUCTED") {
                throw CsvError(
                    number, "",
                    log_message("log_dprnt_obstructed",
                                QT_TRANSLATE_NOOP("MachineLog",
                                                  "the program printed PROBECYCLE OBSTRUCTED: the "
                                                  "probe touched something during a protected "
                                                  "move and the control stopped with alarm 102; "
                                                  "nothing imported")));
            } else if (words.size() == 3 && words[1] == "NO" && words[2] == "TRIGGER") {
                throw CsvError(
                    number, "",
                    log_message("log_dprnt_no_trigger",
                                QT_TRANSLATE_NOOP("MachineLog",
                                                  "the program printed PROBECYCLE NO TRIGGER: a "
                                                  "probe did not trigger and the control stopped "
                                                  "with alarm 101; nothing imported")));
            } else if (words.size() == 4 && words[1] == "OUT" && words[2] == "OF" &&
                       words[3] == "TOLERANCE") {
                if (result != nullptr) result->out_of_tolerance_line = number;
            } else if (words.size() != 2 || words[1] != "END") {
                bad_line(number, line,
                         "'PROBECYCLE PLAN ...', 'PROBECYCLE END', 'PROBECYCLE NO TRIGGER' or "
                         "'PROBECYCLE OBSTRUCTED'");
            }
            continue;
        }
        if (words[0].substr(0, 6) == "RESULT" && plan_line) {
            // "RESULT S s X x Y y D d T t", a number's sign and digits
            // perhaps apart (as a touch's); before our PLAN line, another
            // program's output.
            std::size_t at = 6;
            std::array<double, 5> values{};
            bool readable = true;
            for (std::size_t i = 0; i < 5 && readable; ++i) {
                const std::optional<double> value =
                    dprnt_word(line, at, "SXYDT"[i]) ? dprnt_number(line, at) : std::nullopt;
                readable = value.has_value();
                values[i] = value.value_or(0.0);
            }
            if (!readable || trimmed(std::string_view(line).substr(at)).size() != 0) {
                bad_line(number, line, "'RESULT S s X x Y y D d T t'");
            }
            if (result != nullptr) {
                result->line = number;
                result->values = values;
            }
            continue;
        }
        if (words[0].substr(0, 5) != "TOUCH") continue;
        if (!plan_line) {
            throw CsvError(
                number, "",
                log_message("log_dprnt_no_plan",
                            QT_TRANSLATE_NOOP("MachineLog",
                                              "a touch before the line PROBECYCLE PLAN that the "
                                              "program prints first: capture its output from the "
                                              "start; nothing imported")));
        }
        std::size_t at = 5;
        const std::optional<double> n = dprnt_number(line, at);
        std::array<double, 3> xyz{};
        bool readable = n && *n == std::floor(*n);
        for (std::size_t a = 0; a < 3 && readable; ++a) {
            const std::optional<double> value =
                dprnt_word(line, at, "XYZ"[a]) ? dprnt_number(line, at) : std::nullopt;
            readable = value.has_value();
            xyz[a] = value.value_or(0.0);
        }
        if (!readable || trimmed(std::string_view(line).substr(at)).size() != 0) {
            bad_line(number, line, kTouchLine);
        }
        if (*n != static_cast<double>(positions.size() + 1)) {
            touch_out_of_order(number, format_number(*n), positions.size() + 1);
        }
        positions.push_back({number, xyz});
    }
    if (!plan_line) {
        throw CsvError(
            0, "",
            log_message("log_dprnt_no_plan_line",
                        QT_TRANSLATE_NOOP("MachineLog",
                                          "no line PROBECYCLE PLAN: is this the DPRNT output of a "
                                          "ProbeCycle program? Nothing imported")));
    }
    return positions;
}

namespace {

// "#n value", "#n=value" or "n value": a common variable's number and its
// text; nullopt for any other line.
std::optional<std::pair<int, std::string_view>> variable_line(std::string_view line) {
    std::size_t at = 0;
    if (at < line.size() && line[at] == '#') ++at;
    const std::size_t digits = at;
    while (at < line.size() && line[at] >= '0' && line[at] <= '9') ++at;
    if (at == digits || at - digits > 5) return std::nullopt;
    const int number = std::stoi(std::string(line.substr(digits, at - digits)));
    const std::size_t after = at;
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
    if (at < line.size() && line[at] == '=') ++at;
    if (at == after) return std::nullopt;  // "#5201" is not "#520 1"
    return std::pair{number, trimmed(line.substr(at))};
}

}  // namespace

std::vector<RecordedPosition> read_variable_positions(std::string_view text,
                                                      const ProbingPlan& plan,
                                                      const Dialect& dialect,
                                                      LoggedResult* result) {
    // The record's variables (dialect.cpp, mitsubishi_dialect): the plan in
    // #500-#503, the state in #504, the count in #505, a cycle's result in
    // #506-#510, the touches from first_touch_variable.
    constexpr int kPlan = 500;
    constexpr int kState = 504;
    constexpr int kCount = 505;
    constexpr int kResult = 506;
    std::map<int, std::pair<std::size_t, double>> values;
    for (const auto& [number, raw] : dprnt_lines_of(text)) {
        const std::optional<std::pair<int, std::string_view>> variable =
            variable_line(trimmed(raw));
        if (!variable || variable->first < kPlan || variable->first > dialect.last_variable) {
            continue;
        }
        // A vacant variable (no number after it) is as if not listed.
        const std::optional<double> value = parse_decimal(variable->second);
        if (!value || std::abs(*value) > kMaxCoordinate_mm) continue;
        const auto [it, added] = values.emplace(variable->first, std::pair{number, *value});
        if (!added && it->second.second != *value) {
            throw CsvError(
                number, "",
                log_message(
                    "log_variable_twice",
                    QT_TRANSLATE_NOOP("MachineLog",
                                      "#%1 is listed again with another value (first on "
                                      "line %2): the list holds more than one output; "
                                      "nothing imported"),
                    {arg("variable", ArgKind::integer, variable->first),
                     arg("line", ArgKind::integer, static_cast<double>(it->second.first))}));
        }
    }
    const auto missing = [&](int variable, std::size_t line) {
        throw CsvError(
            line, "",
            log_message("log_variable_missing",
                        QT_TRANSLATE_NOOP("MachineLog",
                                          "no value of #%1 in the list: list every common "
                                          "variable from #500 to #%2 that the program set; "
                                          "nothing imported"),
                        {arg("variable", ArgKind::integer, variable),
                         arg("last", ArgKind::integer, dialect.last_variable)}));
    };
    std::string id;
    for (int part = 0; part < 4; ++part) {
        const auto it = values.find(kPlan + part);
        if (it == values.end()) {
            throw CsvError(0, "",
                           log_message("log_variables_no_plan",
                                       QT_TRANSLATE_NOOP(
                                           "MachineLog",
                                           "no values of #500 to #503, where the program keeps its "
                                           "plan: is this the list of common variables after a "
                                           "ProbeCycle program? Nothing imported")));
        }
        const double group = it->second.second;
        if (group < 0.0 || group > 65535.0 || group != std::floor(group)) {
            bad_line(it->second.first, format_number(group), "a whole number from 0 to 65535");
        }
        static constexpr const char* kHex = "0123456789abcdef";
        const auto bits = static_cast<unsigned>(group);
        for (int shift = 12; shift >= 0; shift -= 4) id += kHex[(bits >> shift) & 0xfU];
    }
    if (id != plan_id(plan)) plan_mismatch(values.at(kPlan).first, id, plan_id(plan));
    const auto state = values.find(kState);
    if (state == values.end()) missing(kState, values.at(kPlan).first);
    const std::size_t state_line = state->second.first;
    const double state_value = state->second.second;
    if (state_value == 101.0 || state_value == 102.0) {
        throw CsvError(
            state_line, "",
            state_value == 101.0
                ? log_message("log_variables_no_trigger",
                              QT_TRANSLATE_NOOP("MachineLog",
                                                "#504 is 101: a probe did not trigger and the "
                                                "program stopped at PROBE DID NOT TRIGGER; "
                                                "nothing imported"))
                : log_message("log_variables_obstructed",
                              QT_TRANSLATE_NOOP("MachineLog",
                                                "#504 is 102: the probe touched something during "
                                                "a protected move and the program stopped at "
                                                "PROBE PATH OBSTRUCTED; nothing imported")));
    }
    if (state_value != 1.0 && state_value != 103.0) {
        throw CsvError(
            state_line, "",
            log_message("log_variables_unfinished",
                        QT_TRANSLATE_NOOP("MachineLog",
                                          "#504 is %1: the program did not end (1 when it ends, "
                                          "103 when it stops out of tolerance); nothing imported"),
                        {text_arg("state", format_number(state_value))}));
    }
    const auto count = values.find(kCount);
    if (count == values.end()) missing(kCount, state_line);
    const double touches = count->second.second;
    if (touches < 0.0 || touches != std::floor(touches) ||
        touches > static_cast<double>(max_recorded_touches(dialect))) {
        bad_line(count->second.first, format_number(touches),
                 "the number of touches the program kept");
    }
    std::vector<RecordedPosition> positions;
    for (int n = 0; n < static_cast<int>(touches); ++n) {
        RecordedPosition position;
        for (int axis = 0; axis < 3; ++axis) {
            const int variable = dialect.first_touch_variable + 3 * n + axis;
            const auto it = values.find(variable);
            if (it == values.end()) missing(variable, count->second.first);
            if (axis == 0) position.line = it->second.first;
            position.xyz[static_cast<std::size_t>(axis)] = it->second.second;
        }
        positions.push_back(position);
    }
    if (result != nullptr && plan.kind == ProgramKind::cycle) {
        for (int i = 0; i < 5; ++i) {
            const auto it = values.find(kResult + i);
            if (it == values.end()) missing(kResult + i, state_line);
            result->values[static_cast<std::size_t>(i)] = it->second.second;
        }
        result->line = values.at(kResult).first;
        if (state_value == 103.0) {
            result->out_of_tolerance_line = state_line;
        } else if (result->values[4] == 1.0) {
            result->out_of_tolerance_line = values.at(kResult + 4).first;
        }
    }
    return positions;
}

namespace {

void refuse_cycle_plan(const ProbingPlan& plan) {
    if (plan.kind == ProgramKind::cycle) {
        throw InputError(log_message(
            "log_cycle_plan",
            QT_TRANSLATE_NOOP("MachineLog",
                              "a cycle plan's positions have no table in the lab; import the log "
                              "of a delay or a ring program")));
    }
}

// Whether a line is one that `id`'s log holds and no other dialect's does:
// LinuxCNC's "probecycle ..." LOG lines, grbl's "[PRB:" reports, the
// Fanuc-type DPRNT's "PROBECYCLE ..." lines (upper case).
bool is_signature_line(DialectId id, std::string_view line) {
    switch (dialect(id).log_format) {
        case LogFormat::linuxcnc_log:
            return line.substr(0, 11) == "probecycle ";
        case LogFormat::grbl_console:
            return line.find("[PRB:") != std::string_view::npos;
        case LogFormat::dprnt:
        case LogFormat::write_file:
            return line.find("PROBECYCLE ") != std::string_view::npos;
        case LogFormat::common_variables: {
            const std::optional<std::pair<int, std::string_view>> variable = variable_line(line);
            return variable && variable->first == 500;
        }
    }
    return false;
}

// A log of another control given as this one's (a grbl console read as a
// LinuxCNC log once said only "the log ends after 0 of the plan's 26 probe
// positions"): when no line is the chosen dialect's and one is another's,
// say which, at that line.
void check_dialect(DialectId chosen, std::string_view text) {
    std::optional<std::pair<std::size_t, DialectId>> other;
    for (const auto& [number, raw] : lines_of(text)) {
        const std::string_view line = trimmed(raw);
        if (is_signature_line(chosen, line)) return;
        for (const DialectId id : all_dialects()) {
            // (Haas writes the Fanuc-type DPRNT: a log of either reads as both.)
            if (dialect(id).log_format != dialect(chosen).log_format && !other &&
                is_signature_line(id, line)) {
                other = {number, id};
            }
        }
    }
    if (!other) return;
    throw CsvError(other->first, "",
                   log_message("log_other_dialect",
                               QT_TRANSLATE_NOOP("MachineLog",
                                                 "this line is from a %1 log, and no line is "
                                                 "from a %2 log: import it as %1 (--dialect %1); "
                                                 "nothing imported"),
                               {text_arg("found", dialect(other->second).name),
                                text_arg("chosen", dialect(chosen).name)}));
}

// The positions in the dialect's file, and whether they stand for every probe
// (and protected move) or the recorded touches only.
std::vector<RecordedPosition> read_positions(const ProbingPlan& plan, DialectId dialect,
                                             std::string_view text, bool& every_probe,
                                             LoggedResult* result = nullptr) {
    check_dialect(dialect, text);
    const Dialect& d = probecycle::dialect(dialect);
    switch (d.log_format) {
        case LogFormat::grbl_console:
            every_probe = true;
            return read_grbl_positions(text, plan);
        case LogFormat::dprnt:
        case LogFormat::write_file:
            every_probe = false;
            return read_fanuc_positions(text, plan, result, d.log_format == LogFormat::write_file);
        case LogFormat::common_variables:
            every_probe = false;
            return read_variable_positions(text, plan, d, result);
        case LogFormat::linuxcnc_log:
            break;
    }
    std::vector<RecordedPosition> positions = read_linuxcnc_positions(text, plan, result);
    // The LOG file's first line that is not blank opens with "probecycle";
    // otherwise it is the PROBEOPEN file.
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    every_probe = first == std::string_view::npos || text.substr(first, 10) != "probecycle";
    return positions;
}

}  // namespace

std::vector<RecordedPosition> match_recorded_touches(const ProbingPlan& plan,
                                                     const std::vector<RecordedPosition>& positions,
                                                     bool every_probe) {
    const std::vector<const ProgramStep*> probes = probes_of(plan, every_probe);
    check_matches_plan(probes, positions);
    std::vector<RecordedPosition> recorded;
    for (std::size_t i = 0; i < probes.size(); ++i) {
        if (probes[i]->kind == StepKind::probe && probes[i]->recorded) {
            recorded.push_back(positions[i]);
        }
    }
    return recorded;
}

std::string lab_csv_from_positions(const ProbingPlan& plan,
                                   const std::vector<RecordedPosition>& positions,
                                   bool every_probe) {
    refuse_cycle_plan(plan);
    const std::vector<RecordedPosition> matched =
        match_recorded_touches(plan, positions, every_probe);
    const std::vector<const ProgramStep*> touches = plan.recorded();
    std::string csv =
        "# ProbeCycle: imported for plan " + plan_id(plan) + " (" + to_string(plan.kind) + ")\n";
    csv += plan.kind == ProgramKind::delay ? "axis,direction,feed_mm_min,measured_mm\n"
                                           : "orientation_deg,x_mm,y_mm\n";
    for (std::size_t i = 0; i < touches.size(); ++i) {
        const ProgramStep& probe = *touches[i];
        const std::array<double, 3>& xyz = matched[i].xyz;
        if (plan.kind == ProgramKind::delay) {
            csv += std::string(1, probe.axis) + "," + (probe.direction > 0 ? "+1" : "-1") + "," +
                   csv_value(probe.feed_mm_min) + "," + csv_value(xyz[axis_index(probe.axis)]) +
                   "\n";
        } else {
            csv += csv_value(probe.orientation_deg) + "," + csv_value(xyz[0]) + "," +
                   csv_value(xyz[1]) + "\n";
        }
    }
    return csv;
}

std::vector<RecordedPosition> recorded_touch_positions(const ProbingPlan& plan, DialectId dialect,
                                                       std::string_view text) {
    bool every_probe = false;
    const std::vector<RecordedPosition> positions =
        read_positions(plan, dialect, text, every_probe);
    return match_recorded_touches(plan, positions, every_probe);
}

std::vector<RecordedPosition> recorded_touch_positions(const ProbingPlan& plan, DialectId dialect,
                                                       std::string_view text,
                                                       LoggedResult& result) {
    bool every_probe = false;
    const std::vector<RecordedPosition> positions =
        read_positions(plan, dialect, text, every_probe, &result);
    return match_recorded_touches(plan, positions, every_probe);
}

std::string import_machine_log(const ProbingPlan& plan, DialectId dialect, std::string_view text) {
    refuse_cycle_plan(plan);
    bool every_probe = false;
    const std::vector<RecordedPosition> positions =
        read_positions(plan, dialect, text, every_probe);
    return lab_csv_from_positions(plan, positions, every_probe);
}

}  // namespace probecycle
