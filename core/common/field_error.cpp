#include "core/common/field_error.h"

#include <utility>

namespace probecycle {

Message FieldError::to_message() const {
    Message m;
    m.code = allowed.code;
    m.context = "FieldError";
    if (value.empty()) {
        m.text = QT_TRANSLATE_NOOP("FieldError", "%1: %2");
        m.args = {text_arg("key", key), message_arg("allowed", allowed)};
    } else if (value.size() <= kMaxShownValueChars) {
        m.text = QT_TRANSLATE_NOOP("FieldError", "%1: got %2; allowed: %3");
        m.args = {text_arg("key", key), text_arg("value", value), message_arg("allowed", allowed)};
    } else {
        // A value of megabytes is not echoed whole: its start and its length.
        std::size_t cut = kShownStartChars;
        while (cut > 0 && (static_cast<unsigned char>(value[cut]) & 0xC0) == 0x80) --cut;  // UTF-8
        m.text = QT_TRANSLATE_NOOP("FieldError", "%1: got %2... (%4 characters); allowed: %3");
        m.args = {text_arg("key", key), text_arg("value", value.substr(0, cut)),
                  message_arg("allowed", allowed),
                  arg("value_length", ArgKind::integer, static_cast<double>(value.size()))};
    }
    return m;
}

std::string FieldError::message() const {
    return render(to_message());
}

Message allowed_text(const char* code, const char* text) {
    return make_message(code, "FieldError", text);
}

Message range_allowed(double min, double max, const char* unit) {
    if (unit == nullptr || *unit == '\0') {  // a fraction or a count: no unit to name
        Message m =
            allowed_text("out_of_range", QT_TRANSLATE_NOOP("FieldError", "a number from %1 to %2"));
        m.args = {arg("min", ArgKind::number, min), arg("max", ArgKind::number, max)};
        return m;
    }
    Message m =
        allowed_text("out_of_range", QT_TRANSLATE_NOOP("FieldError", "a number from %1 to %2 %3"));
    m.args = {arg("min", ArgKind::number, min), arg("max", ArgKind::number, max),
              text_arg("unit", unit)};
    return m;
}

const char* to_string(FileKind kind) {
    switch (kind) {
        case FileKind::scenario:
            return "scenario";
        case FileKind::plan:
            return "plan";
        case FileKind::project:
            return "project";
    }
    return "?";
}

namespace {
std::string join_messages(const std::vector<FieldError>& errors) {
    std::string text;
    for (const FieldError& e : errors) {
        if (!text.empty()) text += '\n';
        text += e.message();
    }
    return text;
}
}  // namespace

FileContentError::FileContentError(FileKind kind, std::vector<FieldError> errors)
    : std::runtime_error(join_messages(errors)), kind_(kind), errors_(std::move(errors)) {}

}  // namespace probecycle
