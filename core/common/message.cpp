#include "core/common/message.h"

#include <cmath>
#include <cstdio>

#include "core/common/number_format.h"

namespace probecycle {

Message make_message(std::string code, const char* context, const char* text) {
    Message m;
    m.code = std::move(code);
    m.context = context;
    m.text = text;
    return m;
}

MessageArg arg(std::string name, ArgKind kind, double value, int decimals) {
    MessageArg a;
    a.name = std::move(name);
    a.kind = kind;
    a.number = value;
    a.decimals = decimals;
    return a;
}

MessageArg significant_arg(std::string name, ArgKind kind, double value, int significant) {
    MessageArg a = arg(std::move(name), kind, value);
    a.significant = significant;
    return a;
}

MessageArg text_arg(std::string name, std::string value) {
    MessageArg a;
    a.name = std::move(name);
    a.kind = ArgKind::text;
    a.text = std::move(value);
    return a;
}

MessageArg message_arg(std::string name, Message value) {
    MessageArg a;
    a.name = std::move(name);
    a.kind = ArgKind::message;
    a.nested.push_back(std::move(value));
    return a;
}

std::string fill_template(std::string_view text, const std::vector<std::string>& args) {
    std::string out;
    out.reserve(text.size() + 16 * args.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char ch = text[i];
        if (ch == '%' && i + 1 < text.size() && text[i + 1] >= '1' && text[i + 1] <= '9') {
            const std::size_t index = static_cast<std::size_t>(text[i + 1] - '1');
            if (index < args.size()) {
                out += args[index];
                ++i;
                continue;
            }
        }
        out += ch;
    }
    return out;
}

namespace {

std::string plain_number(double value, int decimals, int significant) {
    if (decimals < 0 || !std::isfinite(value)) return format_number(value, significant);
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    std::string text = buffer;
    if (text == "-0" || text.rfind("-0.", 0) == 0) {
        // A value that rounds to zero reads as 0, not -0.
        if (text.find_first_not_of("-0.") == std::string::npos) text.erase(0, 1);
    }
    return text;
}

const char* unit_of(ArgKind kind) {
    switch (kind) {
        case ArgKind::length_mm:
            return " mm";
        case ArgKind::time_s:
            return " s";
        case ArgKind::delay_s:
            return " ms";
        case ArgKind::feed_mm_min:
            return " mm/min";
        case ArgKind::angle_deg:
            return " deg";
        case ArgKind::percent:
            return " %";
        case ArgKind::number:
        case ArgKind::integer:
        case ArgKind::text:
        case ArgKind::message:
            break;
    }
    return "";
}

}  // namespace

std::string render_arg(const MessageArg& a) {
    switch (a.kind) {
        case ArgKind::text:
            return a.text;
        case ArgKind::message:
            return a.nested.empty() ? std::string() : render(a.nested.front());
        case ArgKind::integer:
            return plain_number(a.number, 0, a.significant);
        case ArgKind::delay_s:
            return plain_number(a.number * 1000.0, a.decimals, a.significant) + unit_of(a.kind);
        default:
            return plain_number(a.number, a.decimals, a.significant) + unit_of(a.kind);
    }
}

std::string render(const Message& message) {
    std::vector<std::string> args;
    args.reserve(message.args.size());
    for (const MessageArg& a : message.args) args.push_back(render_arg(a));
    return fill_template(message.text, args);
}

}  // namespace probecycle
