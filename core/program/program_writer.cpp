#include "core/program/program_writer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string_view>

#include "core/common/input_error.h"
#include "core/common/number_format.h"
#include "core/program/feature_result.h"

namespace probecycle {

namespace {

std::string replaced(std::string text, std::string_view name, const std::string& value) {
    for (std::size_t at = text.find(name); at != std::string::npos;
         at = text.find(name, at + value.size())) {
        text.replace(at, name.size(), value);
    }
    return text;
}

Message program_message(const char* code, const char* text, std::vector<MessageArg> args = {}) {
    return Message{code, "Program", text, std::move(args)};
}

// Text of a Fanuc-type comment: upper case; letters, digits, spaces and
// . , - + / * = # (":" and ";" read as ","); anything else (parentheses, "%",
// which ends the file, "_", non-ASCII) becomes a space.
std::string plain_comment(std::string_view text) {
    std::string out;
    for (const char c : text) {
        const char upper = c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
        if ((upper >= 'A' && upper <= 'Z') || (upper >= '0' && upper <= '9') ||
            std::string_view(" .,-+/*=#").find(upper) != std::string_view::npos) {
            out += upper;
        } else {
            out += c == ':' || c == ';' ? ',' : ' ';
        }
    }
    return out;
}

// The option that gives the spindle's 180 deg block, as the CLI names it (the
// window shows its own field's label in its place).
constexpr const char* kOrientOption = "--orient-180";
constexpr const char* kProbeInputOption = "--probe-input";

bool is_orient_command_char(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           std::string_view(" .+-#[]=").find(c) != std::string_view::npos;
}

// Text inside a "(...)" comment: no parentheses (they would end or nest it).
std::string comment_safe(std::string text) {
    for (char& c : text) {
        if (c == '(') c = '[';
        if (c == ')') c = ']';
        if (c == '\n' || c == '\r') c = ' ';
    }
    return text;
}

// The tuned cycle on a feature (plan.h, CyclePlanOptions): the plan names the
// feature in its values; a surface's plan does not. nullptr for another word.
const char* feature_description(std::string_view feature) {
    if (feature == "bore") {
        return "the tuned cycle on a bore.\n"
               "X+, X-, Y+ and Y- touched with the scenario's strategy, feeds, backoff and\n"
               "start distance, from the centre at the measuring depth: a protected move\n"
               "out to each touch's start and back to the centre.";
    }
    if (feature == "pocket") {
        return "the tuned cycle on a pocket.\n"
               "Both walls along one axis touched with the scenario's strategy, feeds,\n"
               "backoff and start distance, from the centre at the measuring depth: a\n"
               "protected move out to each touch's start and back to the centre.";
    }
    if (feature == "boss") {
        return "the tuned cycle on a boss.\n"
               "The X+, X-, Y+ and Y- sides touched toward the centre with the scenario's\n"
               "strategy, feeds, backoff and start distance, from above the centre at the\n"
               "clearance height: per side a protected move out over its start, a protected\n"
               "move down by the clearance, the touch, a rapid up by the clearance and a\n"
               "protected move back over the centre.";
    }
    if (feature == "web") {
        return "the tuned cycle on a web.\n"
               "Both sides along one axis touched toward the centre with the scenario's\n"
               "strategy, feeds, backoff and start distance, from above the centre at the\n"
               "clearance height: per side a protected move out over its start, a protected\n"
               "move down by the clearance, the touch, a rapid up by the clearance and a\n"
               "protected move back over the centre.";
    }
    return nullptr;
}

// The header's warning: which overrides slow the program down.
constexpr const char* kProveAtFeed =
    "WARNING: prove this program out first at reduced feed override (every\n"
    "move runs at a feed, none at the rapid), with the probe clear of the\n"
    "part, and check every move against your machine before a touch.\n";
constexpr const char* kProveWithRapids =
    "WARNING: prove this program out first at reduced feed override (its\n"
    "probing and return moves run at a feed) and reduced rapid override\n"
    "(its retracts and lifts are rapids), with the probe clear of the part,\n"
    "and check every move against your machine before a touch.\n";

// How far every probing move searches (plan.h, checked_search_beyond_mm).
constexpr const char* kSearchNote =
    "\nEvery probing move searches past the farthest place its surface can be by\n"
    "more than the touch's stop (cycle.search_beyond_mm), and every later one\n"
    "covers the whole move back before it: the axis is never braking for the\n"
    "move's end when it touches.";

const char* description(ProgramKind kind) {
    switch (kind) {
        case ProgramKind::delay:
            return "the delay-stability test (ISO 230-10).\n"
                   "The same surface touched repeatedly at several feeds along one axis and\n"
                   "direction, each touch from far enough out to be at full speed. The lab fits\n"
                   "the delay from the recorded positions.";
        case ProgramKind::ring:
            return "the ring-gauge calibration.\n"
                   "4 points in the bore with the spindle at 0 deg, the same 4 at 180 deg.\n"
                   "The lab fits the ball radius and the stylus runout.";
        case ProgramKind::cycle:
            return "the tuned cycle.\n"
                   "One surface touched with the scenario's strategy, feeds, backoff and start\n"
                   "distance: a plain skip sequence, no macro call.";
    }
    return "";
}

std::string description(const ProbingPlan& plan) {
    if (plan.kind == ProgramKind::cycle) {
        for (const PlanValue& value : plan.values) {
            const char* text =
                value.key == "cycle.feature" ? feature_description(value.text) : nullptr;
            if (text != nullptr) return std::string(text) + kSearchNote;
        }
    }
    return std::string(description(plan.kind)) + kSearchNote;
}

std::size_t axis_index(char axis) {
    return axis == 'X' ? 0 : axis == 'Y' ? 1 : 2;
}

// The orientation of the next recorded probe after `at` (the plan sets it on
// those), or nullopt.
std::optional<double> next_orientation(const ProbingPlan& plan, std::size_t at) {
    for (std::size_t i = at + 1; i < plan.steps.size(); ++i) {
        const ProgramStep& step = plan.steps[i];
        if (step.kind == StepKind::probe && step.recorded) return step.orientation_deg;
    }
    return std::nullopt;
}

// A cycle's result (feature_result.h) in the variables of a control that
// computes, the same numbers in every such dialect (docs/programs.md, "What
// the cycle program measures"), from the dialect's first result variable on
// (#110, or Siemens's R60): +0 to +3 the mean stylus-centre coordinate of
// each side, +4 the size (a surface: its position), +5 and +6 the centre's X
// and Y, +7 the deviation from the nominal size, +8 1 when out of tolerance.
struct ResultVariables {
    explicit ResultVariables(const Dialect& dialect)
        : d(dialect), size(name(4)), centre{name(5), name(6)}, deviation(name(7)), flag(name(8)) {}
    std::string side(std::size_t s) const { return name(static_cast<int>(s)); }
    // An expression the writer built with [ ] as the dialect groups it.
    std::string grouped(std::string text) const {
        for (char& c : text) {
            if (c == '[') c = d.group_open;
            if (c == ']') c = d.group_close;
        }
        return text;
    }
    std::string name(int offset) const {
        // (Appended: g++ 12 warns falsely of an overlapping memcpy in
        // "#" + std::to_string(n).)
        std::string text(d.variable_prefix);
        text += std::to_string(d.first_result_variable + offset);
        return text;
    }

    const Dialect& d;
    std::string size;
    std::array<std::string, 2> centre;
    std::string deviation;
    std::string flag;
};

// A constant in a result's expression: 4 decimals (0.1 um), signed.
std::string signed_constant(double value) {
    std::string text = format_decimals(value, 4);
    if (text[0] != '-') text.insert(text.begin(), '+');
    return text;
}

std::string with_result_variables(std::string text, const ResultVariables& v) {
    text = replaced(std::move(text), "{size}", v.size);
    text = replaced(std::move(text), "{centre_x}", v.centre[0]);
    text = replaced(std::move(text), "{centre_y}", v.centre[1]);
    text = replaced(std::move(text), "{deviation}", v.deviation);
    return replaced(std::move(text), "{flag}", v.flag);
}

// The header's lines on the result: what each variable holds.
std::vector<std::string> result_header(const ResultSpec& spec, const Dialect& dialect) {
    const ResultVariables v(dialect);
    std::vector<std::string> lines;
    if (dialect.result_record.empty()) {
        for (const char* note : dialect.result_notes) lines.emplace_back(note);
        return lines;
    }
    std::string sides;
    for (const AxisDirection& side : spec.sides)
        sides += (sides.empty() ? "" : ", ") + to_string(side);
    const std::string ball =
        spec.ball_diameter_mm > 0.0
            ? "with the effective ball diameter " + program_number(spec.ball_diameter_mm) + " mm"
            : std::string("between stylus centres (ball diameter 0)");
    lines.emplace_back("Result, computed by the program from the recorded touches:");
    const std::string side_range =
        spec.sides.size() > 1 ? v.side(0) + "-" + v.side(spec.sides.size() - 1) : v.side(0);
    lines.push_back(side_range + " the mean stylus-centre coordinate of the side" +
                    (spec.sides.size() > 1 ? "s " : " ") + sides + ",");
    lines.push_back(v.size + " the " + size_name(spec.feature) + " " + ball + ",");
    if (spec.feature == Feature::surface) {
        lines.push_back(v.centre[0] + ", " + v.centre[1] + ", " + v.deviation + " and " + v.flag +
                        " 0 (a surface has no size).");
    } else {
        lines.push_back(v.centre[0] + " and " + v.centre[1] +
                        " its centre in X and Y (0 along an axis not measured),");
        lines.push_back(v.deviation + " its deviation from the nominal " +
                        program_number(spec.nominal_size_mm()) + " mm,");
        if (spec.checks_tolerance()) {
            lines.push_back(v.flag + " 1 when that is over +-" +
                            program_number(spec.size_tolerance_mm) + " mm, else 0; out of");
            lines.emplace_back(spec.tolerance_action == ToleranceAction::stop
                                   ? "tolerance the program logs it and stops."
                                   : "tolerance the program logs it and goes on.");
        } else {
            lines.push_back(v.flag + " 0 (no tolerance check).");
        }
    }
    for (const char* note : dialect.result_notes) lines.emplace_back(note);
    return lines;
}

// After the last touch: the sides' means, the result, the tolerance check
// and the log line.
std::vector<std::string> result_lines(const ResultSpec& spec, const Dialect& dialect) {
    const ResultVariables v(dialect);
    std::vector<std::string> lines;
    std::vector<int> count(spec.sides.size(), 0);
    for (const std::size_t side : spec.touch_side) ++count[side];
    for (std::size_t s = 0; s < spec.sides.size(); ++s) {
        if (count[s] > 1) {
            lines.push_back(v.side(s) + "=[" + v.side(s) + "/" + std::to_string(count[s]) + "]");
        }
    }
    const std::string p0 = v.side(0);
    const double ball = spec.ball_diameter_mm;
    // The ball enlarges what is measured inside (a pocket, a bore) and
    // shrinks what is measured outside (a web, a boss).
    const std::string with_ball =
        ball == 0.0 ? std::string()
                    : signed_constant(spec.feature == Feature::surface
                                          ? spec.sides[0].direction * 0.5 * ball
                                          : size_with_ball_mm(spec.feature, 0.0, ball));
    const std::string size = v.size + "=";
    switch (spec.feature) {
        case Feature::surface:
            lines.push_back(size + (ball == 0.0 ? p0 : "[" + p0 + with_ball + "]"));
            lines.push_back(v.centre[0] + "=0");
            lines.push_back(v.centre[1] + "=0");
            break;
        case Feature::pocket:
        case Feature::web: {
            const std::string p1 = v.side(1);
            const std::size_t axis = spec.sides[0].axis == 'X' ? 0 : 1;
            lines.push_back(size + "[" + p0 + "-" + p1 + with_ball + "]");
            lines.push_back(v.centre[axis] + "=[[" + p0 + "+" + p1 + "]/2]");
            lines.push_back(v.centre[1 - axis] + "=0");
            break;
        }
        case Feature::bore:
        case Feature::boss: {
            const std::string p1 = v.side(1);
            const std::string p2 = v.side(2);
            const std::string p3 = v.side(3);
            lines.push_back(size + "[[" + p0 + "-" + p1 + "+" + p2 + "-" + p3 + "]/2" + with_ball +
                            "]");
            lines.push_back(v.centre[0] + "=[[" + p0 + "+" + p1 + "]/2]");
            lines.push_back(v.centre[1] + "=[[" + p2 + "+" + p3 + "]/2]");
            break;
        }
    }
    std::string deviation = v.deviation + "=";
    if (spec.feature == Feature::surface) {
        deviation += "0";
    } else {
        deviation += "[";
        deviation += v.size;
        deviation += signed_constant(-spec.nominal_size_mm());
        deviation += "]";
    }
    lines.push_back(deviation);
    for (std::string& line : lines) line = v.grouped(std::move(line));
    const std::string tolerance = format_decimals(spec.size_tolerance_mm, 4);
    if (spec.checks_tolerance()) {
        for (const char* line : dialect.tolerance_check) {
            lines.push_back(replaced(with_result_variables(line, v), "{tolerance}", tolerance));
        }
    } else {
        lines.push_back(v.flag + "=0");
    }
    for (const char* line : dialect.result_record) lines.push_back(with_result_variables(line, v));
    if (spec.checks_tolerance()) {
        for (const char* line : dialect.out_of_tolerance) {
            if (std::string_view(line) != "{stop}") {
                lines.push_back(with_result_variables(line, v));
            } else if (spec.tolerance_action == ToleranceAction::stop) {
                for (const char* stop : dialect.tolerance_stop) {
                    lines.push_back(with_result_variables(stop, v));
                }
            }
        }
    }
    return lines;
}

class Writer {
  public:
    Writer(const Dialect& dialect, const ProgramOptions& options)
        : d_(dialect), options_(options) {}
    const Dialect& dialect() const { return d_; }

    void line(const std::string& text) { out_ += text + "\n"; }
    std::string comment_text(const std::string& text) const {
        if (d_.plain_comments) {
            return std::string(d_.comment_open) + plain_comment(text) + d_.comment_close;
        }
        return std::string(d_.comment_open) + " " + text + d_.comment_close;
    }
    void comment(const std::string& text) { line(comment_text(text)); }
    void comment_block(const std::string& text) {
        std::size_t start = 0;
        while (start <= text.size()) {
            const std::size_t end = std::min(text.find('\n', start), text.size());
            comment(text.substr(start, end - start));
            start = end + 1;
        }
    }
    // "<word> <axis><distance> F<feed>": a probe, a protected move or a move at a feed.
    std::string move_line(const char* word, const ProgramStep& step) const {
        return std::string(word) + " " + move_words(step) + " F" + program_feed(step.feed_mm_min);
    }
    std::string move_words(const ProgramStep& step) const {
        std::string words = program_number(step.direction * step.distance_mm);
        words.insert(words.begin(), step.axis);
        return words;
    }
    // A probing or protected move: the dialect's probe_move, or move_line.
    void probe_move(const char* word, const ProgramStep& step) {
        if (d_.probe_move == nullptr) {
            line(move_line(word, step));
            return;
        }
        std::string text = replaced(d_.probe_move, "{word}", word);
        text = replaced(std::move(text), "{axis}", std::string(1, step.axis));
        text = replaced(std::move(text), "{feed}", program_feed(step.feed_mm_min));
        line(with_step(std::move(text), step));
    }
    // A probe's or protected move's lines ({current}, {skip}, {distance},
    // {label}, {input}, {probe}, {n}, {x} {y} {z}, {touch_x} {touch_y}
    // {touch_z}), after the dialect's settle lines where one reads a position.
    void probe_lines(const std::vector<const char*>& patterns, const ProgramStep& step,
                     std::size_t label = 0, std::size_t touch = 0) {
        bool settled = false;
        for (const char* pattern : patterns) {
            const std::string_view text_view(pattern);
            if (!settled && (text_view.find("{current}") != std::string_view::npos ||
                             text_view.find("{skip}") != std::string_view::npos)) {
                for (const char* settle : d_.settle) line(settle);
                settled = true;
            }
            std::string text = replaced(pattern, "{label}", std::to_string(label));
            if (touch > 0) text = touch_variables(std::move(text), touch);
            line(with_step(std::move(text), step));
        }
    }
    const std::string& text() const { return out_; }

  private:
    // {current}, {skip}, {distance}, {input}, {probe}, and {x} {y} {z}: the
    // probing axis's skip position, the other axes' current positions.
    std::string with_step(std::string text, const ProgramStep& step) const {
        const std::size_t axis = axis_index(step.axis);
        std::string distance = program_number(step.direction * step.distance_mm);
        if (distance[0] != '-') distance.insert(distance.begin(), '+');
        const auto position = [&](std::size_t a) {
            return std::string(a == axis ? d_.skip_position.at(a) : d_.current_position.at(a));
        };
        for (std::size_t a = 0; a < 3; ++a) {
            std::string name("{");
            name += "xyz"[a];
            name += '}';
            if (text.find(name) != std::string::npos) text = replaced(text, name, position(a));
        }
        if (text.find("{current}") != std::string::npos) {
            text = replaced(text, "{current}", d_.current_position.at(axis));
        }
        if (text.find("{skip}") != std::string::npos) {
            text = replaced(text, "{skip}", d_.skip_position.at(axis));
        }
        text = replaced(std::move(text), "{input}", std::to_string(options_.probe_input));
        text = replaced(std::move(text), "{probe}", std::to_string(std::abs(options_.probe_input)));
        return replaced(std::move(text), "{distance}", distance);
    }
    // {n}: the recorded touch's number; {touch_x} {touch_y} {touch_z}: the
    // variables it is kept in.
    std::string touch_variables(std::string text, std::size_t n) const {
        text = replaced(std::move(text), "{n}", std::to_string(n));
        if (d_.first_touch_variable == 0) return text;
        const int first = d_.first_touch_variable + 3 * (static_cast<int>(n) - 1);
        for (int axis = 0; axis < 3; ++axis) {
            std::string name("{touch_");
            name += "xyz"[axis];
            name += '}';
            std::string variable("#");  // (appended: see ResultVariables::name)
            variable += std::to_string(first + axis);
            text = replaced(std::move(text), name, variable);
        }
        return text;
    }

    const Dialect& d_;
    const ProgramOptions& options_;
    std::string out_;
};

}  // namespace

std::string program_number(double value) {
    return format_decimals(value, 3);
}

std::string program_feed(double feed_mm_min) {
    std::string text = format_decimals(feed_mm_min, 1);
    if (text.size() > 2 && text.compare(text.size() - 2, 2, ".0") == 0)
        text.resize(text.size() - 2);
    return text;
}

void check_program_options(const ProbingPlan& plan, const Dialect& dialect,
                           const ProgramOptions& options) {
    const std::size_t most = max_recorded_touches(dialect);
    if (most > 0 && plan.recorded().size() > most) {
        throw InputError(program_message(
            "program_too_many_touches",
            QT_TRANSLATE_NOOP("Program",
                              "the plan records %1 touches; a %2 program keeps at most %3 (three "
                              "common variables each, #%4 to #%5): use fewer feeds or repeats"),
            {arg("touches", ArgKind::integer, static_cast<double>(plan.recorded().size())),
             text_arg("dialect", dialect.name),
             arg("most", ArgKind::integer, static_cast<double>(most)),
             arg("first", ArgKind::integer, dialect.first_touch_variable),
             arg("last", ArgKind::integer, dialect.last_variable)}));
    }
    if (names_probe_input(dialect) && options.probe_input != 1 && options.probe_input != -1 &&
        options.probe_input != 2 && options.probe_input != -2) {
        throw InputError(program_message(
            "program_probe_input",
            QT_TRANSLATE_NOOP("Program",
                              "%1: got %2; allowed: 1 or 2 (the probe's input), negative for a "
                              "probe whose signal falls when it triggers: 1, -1, 2, -2"),
            {text_arg("key", kProbeInputOption),
             text_arg("input", std::to_string(options.probe_input))}));
    }
    if (!dialect.orient_from_user) return;
    double orientation = 0.0;
    bool turns = false;
    for (const ProgramStep* step_ptr : plan.recorded()) {
        const ProgramStep& step = *step_ptr;
        if (step.orientation_deg == orientation) continue;
        if (step.orientation_deg != 180.0) {
            throw InputError(program_message(
                "program_orient_angle",
                QT_TRANSLATE_NOOP("Program",
                                  "the plan turns the spindle to %1 deg; a %2 program turns it "
                                  "to 180 deg only, with the command given as --orient-180"),
                {text_arg("angle", format_number(step.orientation_deg)),
                 text_arg("dialect", dialect.name)}));
        }
        orientation = step.orientation_deg;
        turns = true;
    }
    const std::string& command = options.orient_180_command;
    if (turns && command.empty()) {
        throw InputError(program_message(
            "program_orient_missing",
            QT_TRANSLATE_NOOP("Program",
                              "%1: the ring program turns the spindle to 180 deg, and "
                              "%2 controls have no common word for that (M19 with an angle "
                              "differs by maker and machine): give your control's command, e.g. "
                              "\"M19 R180.\" if your manual says so; ProbeCycle does not guess "
                              "it"),
            {text_arg("key", kOrientOption), text_arg("dialect", dialect.name)}));
    }
    if (turns && (command.size() > 60 || command.find_first_not_of(' ') == std::string::npos ||
                  !std::all_of(command.begin(), command.end(), is_orient_command_char))) {
        throw InputError(program_message(
            "program_orient_text",
            QT_TRANSLATE_NOOP("Program",
                              "%1: got '%2'; allowed: one block of at most 60 upper-case "
                              "letters, digits, spaces and . + - # [ ] ="),
            {text_arg("key", kOrientOption), text_arg("command", command.substr(0, 80))}));
    }
}

// The plan's signature in grbl's own reports (plan_signature, plan.h),
// before the first move: the import reads it back from the [PRB:] lines.
void write_grbl_signature(Writer& w, const ProbingPlan& plan, const std::string& id) {
    const PlanSignature signature = plan_signature(plan);
    const std::string way = std::string(1, signature.axis) + (signature.direction > 0 ? "+" : "-");
    w.comment("Plan signature (plan " + id + "): twice, G38.3 out along " + way +
              " and back; grbl's");
    const double reach_mm = kSignatureOut_mm + std::max(signature.back_mm[0], signature.back_mm[1]);
    w.comment("[PRB:...:0] answers tell the import which plan ran. Free air needed: " +
              program_number(reach_mm) + " mm along " + way + ".");
    // Each move at the signature's feed (the way back too, not a rapid: the
    // header's override advice stays true).
    const auto move = [&](int direction, double distance) {
        ProgramStep step;
        step.axis = signature.axis;
        step.direction = direction * signature.direction;
        step.distance_mm = distance;
        step.feed_mm_min = kSignatureFeed_mm_min;
        return step;
    };
    for (const double back : signature.back_mm) {
        w.line(w.move_line(w.dialect().guard_word, move(1, kSignatureOut_mm + back)));
        w.line(w.move_line(w.dialect().guard_word, move(-1, back)));
        w.line(w.move_line(w.dialect().feed_word, move(-1, kSignatureOut_mm)));
    }
}

std::string write_program(const ProbingPlan& plan, const Dialect& dialect, const std::string& date,
                          const ProgramOptions& options) {
    check_program_options(plan, dialect, options);
    Writer w(dialect, options);
    const std::string id = plan_id(plan);
    for (const char* start : dialect.program_start) w.line(start);
    w.comment_block(std::string("ProbeCycle program for ") + dialect.title + ": " +
                    description(plan));
    w.comment("Plan " + id + " (keep the plan file: the import matches the positions to it).");
    w.comment("Date " + date + ".");
    w.comment("Scenario values and options used:");
    for (const PlanValue& v : plan.values) w.comment("  " + v.key + " = " + v.text);
    // What slows the program down is what its moves obey: the probing,
    // protected and return moves run at a feed (feed override), retracts and
    // lifts at the rapid (rapid override).
    const bool rapids = std::any_of(plan.steps.begin(), plan.steps.end(), [](const ProgramStep& s) {
        return s.kind == StepKind::move && s.feed_mm_min == 0.0;
    });
    w.comment_block(std::string(rapids ? kProveWithRapids : kProveAtFeed) +
                    "Every move is incremental (G91) from where the probe stands when the program\n"
                    "starts or a pause ends. A probing move that does not trigger stops the\n"
                    "program.");
    for (const char* note : dialect.record_notes) w.comment(note);
    const bool guards = plan.has_guards();
    if (guards) {
        for (const char* note : dialect.guard_notes) w.comment(note);
    }
    const std::optional<ResultSpec> spec = result_spec(plan);
    const bool computes = spec && !dialect.result_record.empty();
    const ResultVariables results(dialect);
    std::vector<bool> side_started(spec ? spec->sides.size() : 0, false);
    if (spec) {
        for (const std::string& note : result_header(*spec, dialect)) w.comment(note);
    }
    w.line(dialect.modes);
    std::string kind_upper = to_string(plan.kind);
    for (char& c : kind_upper) c = static_cast<char>(c - 'a' + 'A');
    for (const char* open : dialect.open_record) {
        std::string text = replaced(open, "{id}", id);
        text = replaced(std::move(text), "{id_letters}", id_letters(id));
        for (std::size_t part = 0; part < 4; ++part) {
            // The id in four numbers of 4 hex digits each (0-65535).
            text = replaced(std::move(text), "{id_" + std::to_string(part + 1) + "}",
                            std::to_string(std::stoul(id.substr(4 * part, 4), nullptr, 16)));
        }
        text = replaced(std::move(text), "{kind}", to_string(plan.kind));
        w.line(replaced(std::move(text), "{KIND}", kind_upper));
    }
    std::size_t recorded = 0;
    std::size_t guard_count = 0;
    double orientation = 0.0;
    bool signed_plan = dialect.id != DialectId::grbl;
    for (std::size_t i = 0; i < plan.steps.size(); ++i) {
        const ProgramStep& step = plan.steps[i];
        if (!signed_plan && step.kind != StepKind::pause) {
            write_grbl_signature(w, plan, id);
            signed_plan = true;
        }
        switch (step.kind) {
            case StepKind::pause:
                if (const std::optional<double> next = next_orientation(plan, i);
                    dialect.orient_from_user && next && *next != orientation) {
                    // The program turns the spindle (check_program_options).
                    orientation = *next;
                    w.comment(
                        "orient the spindle to 180 deg, the probe at the gauge centre: the "
                        "command given with --orient-180");
                    w.line(options.orient_180_command);
                    break;
                }
                w.comment(step.text);
                if (*dialect.pause_message != '\0') {
                    w.line(replaced(dialect.pause_message, "{text}", comment_safe(step.text)));
                }
                w.line(dialect.pause_word);
                break;
            case StepKind::probe:
                if (step.recorded) {
                    ++recorded;
                    w.comment("touch " + std::to_string(recorded) + ": " + step.text);
                } else {
                    w.comment(step.text);
                }
                w.probe_lines(dialect.before_probe, step);
                w.probe_move(dialect.probe_word, step);
                w.probe_lines(dialect.after_probe, step);
                if (step.recorded) w.probe_lines(dialect.after_recorded_probe, step, 0, recorded);
                if (step.recorded && computes) {
                    // The side's sum of its touches' skip positions.
                    const std::size_t side = spec->touch_side[recorded - 1];
                    const std::string skip = dialect.skip_position.at(axis_index(step.axis));
                    const std::string variable = results.side(side);
                    std::string sum = variable + "=";
                    if (side_started[side]) {
                        sum += dialect.group_open;
                        sum += variable;
                        sum += "+";
                        sum += skip;
                        sum += dialect.group_close;
                    } else {
                        sum += skip;
                    }
                    w.line(sum);
                    side_started[side] = true;
                }
                break;
            case StepKind::guard: {
                // A number of the move's own: LinuxCNC's o-word of its branch.
                const std::size_t label = 1000 + ++guard_count;
                w.comment(step.text);
                w.probe_lines(dialect.before_guard, step, label);
                w.probe_move(dialect.guard_word, step);
                w.probe_lines(dialect.after_guard, step, label);
                break;
            }
            case StepKind::move:
                if (step.feed_mm_min > 0.0) {
                    w.line(w.move_line(dialect.feed_word, step) + " " + w.comment_text(step.text));
                } else {
                    w.line(std::string(dialect.rapid_word) + " " + w.move_words(step) + " " +
                           w.comment_text(step.text));
                }
                break;
        }
    }
    if (computes) {
        w.comment("the " + size_name(spec->feature) + " from the recorded touches");
        for (const std::string& line : result_lines(*spec, dialect)) w.line(line);
    }
    for (const char* close : dialect.close_record) w.line(close);
    for (const char* end : dialect.end) w.line(end);
    for (const char* after : dialect.after_end) w.line(after);
    if (guards) {
        for (const char* line : dialect.guard_alarm) w.line(line);
    }
    for (const char* line : dialect.file_end) w.line(line);
    return w.text();
}

}  // namespace probecycle
