#include "core/program/program_writer.h"

#include <charconv>
#include <cmath>
#include <string_view>

namespace probecycle {

namespace {

std::string to_chars_fixed(double value, int decimals) {
    char buffer[64];
    const auto result =
        std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
    std::string text(buffer, result.ptr);
    if (text.find_first_not_of("-0.") == std::string::npos) text = text.substr(text[0] == '-');
    return text;
}

std::string replaced(std::string text, std::string_view name, const std::string& value) {
    for (std::size_t at = text.find(name); at != std::string::npos;
         at = text.find(name, at + value.size())) {
        text.replace(at, name.size(), value);
    }
    return text;
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

class Writer {
  public:
    explicit Writer(const Dialect& dialect) : d_(dialect) {}

    void line(const std::string& text) { out_ += text + "\n"; }
    void comment(const std::string& text) { line(std::string(d_.comment) + " " + text); }
    void comment_block(const std::string& text) {
        std::size_t start = 0;
        while (start <= text.size()) {
            const std::size_t end = std::min(text.find('\n', start), text.size());
            comment(text.substr(start, end - start));
            start = end + 1;
        }
    }
    std::string move_words(const ProgramStep& step) const {
        std::string words = program_number(step.direction * step.distance_mm);
        words.insert(words.begin(), step.axis);
        return words;
    }
    const std::string& text() const { return out_; }

  private:
    const Dialect& d_;
    std::string out_;
};

}  // namespace

std::string program_number(double value) {
    return to_chars_fixed(value, 3);
}

std::string program_feed(double feed_mm_min) {
    std::string text = to_chars_fixed(feed_mm_min, 1);
    if (text.size() > 2 && text.compare(text.size() - 2, 2, ".0") == 0)
        text.resize(text.size() - 2);
    return text;
}

std::string write_program(const ProbingPlan& plan, const Dialect& dialect,
                          const std::string& date) {
    Writer w(dialect);
    const std::string id = plan_id(plan);
    w.comment_block(std::string("ProbeCycle program for ") + dialect.title + ": " +
                    description(plan.kind));
    w.comment("Plan " + id + " (keep the plan file: the import matches the positions to it).");
    w.comment("Date " + date + ".");
    w.comment("Scenario values and options used:");
    for (const PlanValue& v : plan.values) w.comment("  " + v.key + " = " + v.text);
    w.comment_block(
        "WARNING: prove this program out first at reduced rapid override, with the probe\n"
        "clear of the part, and check every move against your machine before a touch.\n"
        "Every move is incremental (G91) from where the probe stands when the program\n"
        "starts or a pause ends. A probing move that does not trigger stops the program\n"
        "with an alarm.");
    for (const char* note : dialect.record_notes) w.comment(note);
    w.line(dialect.modes);
    for (const char* open : dialect.open_record) {
        w.line(replaced(replaced(open, "{id}", id), "{kind}", to_string(plan.kind)));
    }
    std::size_t recorded = 0;
    for (const ProgramStep& step : plan.steps) {
        switch (step.kind) {
            case StepKind::pause:
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
                w.line(std::string(dialect.probe_word) + " " + w.move_words(step) + " F" +
                       program_feed(step.feed_mm_min));
                if (step.recorded && *dialect.after_recorded_probe != '\0') {
                    w.line(replaced(dialect.after_recorded_probe, "{n}", std::to_string(recorded)));
                }
                break;
            case StepKind::move:
                if (step.feed_mm_min > 0.0) {
                    w.line(std::string(dialect.feed_word) + " " + w.move_words(step) + " F" +
                           program_feed(step.feed_mm_min) + " " + dialect.comment + " " +
                           step.text);
                } else {
                    w.line(std::string(dialect.rapid_word) + " " + w.move_words(step) + " " +
                           dialect.comment + " " + step.text);
                }
                break;
        }
    }
    for (const char* close : dialect.close_record) w.line(close);
    for (const char* end : dialect.end) w.line(end);
    return w.text();
}

}  // namespace probecycle
