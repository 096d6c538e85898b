#include "core/common/field_error.h"

namespace probecycle {

Message FieldError::to_message() const {
    Message m;
    m.code = allowed.code;
    m.context = "FieldError";
    if (value.empty()) {
        m.text = QT_TRANSLATE_NOOP("FieldError", "%1: %2");
        m.args = {text_arg("key", key), message_arg("allowed", allowed)};
    } else {
        m.text = QT_TRANSLATE_NOOP("FieldError", "%1: got %2; allowed: %3");
        m.args = {text_arg("key", key), text_arg("value", value), message_arg("allowed", allowed)};
    }
    return m;
}

std::string FieldError::message() const {
    return render(to_message());
}

Message allowed_text(const char* code, const char* text) {
    Message m;
    m.code = code;
    m.context = "FieldError";
    m.text = text;
    return m;
}

}  // namespace probecycle
