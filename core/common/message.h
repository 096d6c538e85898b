#pragma once

// One message system for every text the core shows a user: warnings, errors
// in files and scenarios, the lab's findings. A message is a stable code, an
// English template and typed, named arguments; it is never a finished string
// until someone renders it:
// - the CLI (and every English text) with render(), in this file;
// - the window with ui::translate(), which looks the template up with
//   QCoreApplication::translate(context, text) and formats each argument for
//   the interface's locale and units.
// Templates are marked with QT_TRANSLATE_NOOP(context, text), which core
// defines below without Qt; lupdate finds them in core's sources, so each text
// exists in one place and its translations in the .ts files.
//
// Templates use %1 ... %9 for the arguments in order. An argument also has a
// name with its unit ("speed_mm_min"), under which the CLI's JSON lists its
// value in "values".

#include <string>
#include <string_view>
#include <vector>

#ifndef QT_TRANSLATE_NOOP
#define QT_TRANSLATE_NOOP(context, text) text
#endif

namespace probecycle {

// What an argument holds; decides its unit and how it is written.
enum class ArgKind {
    length_mm,    // a length; English "1.272 mm"
    time_s,       // a duration; English "0.42 s"
    delay_s,      // a delay or another short time, in s; English in ms: "8.5 ms"
    feed_mm_min,  // a feed or speed; English "2000 mm/min"
    angle_deg,    // English "180 deg"
    percent,      // English "25 %"
    number,       // a plain number: a ratio, a count of cycles
    integer,      // a whole number: a count, a line number
    text,         // verbatim and never translated: a key, a file name, a value as given
    message,      // another message, rendered (and translated) in place: "allowed: %3"
};

struct Message;

struct MessageArg {
    std::string name;  // with its unit: "speed_mm_min", "line", "key"
    ArgKind kind{ArgKind::number};
    double number{0.0};           // every kind but text
    std::string text;             // text
    std::vector<Message> nested;  // message: exactly one
    // English digits: decimals after the point, or -1 for up to `significant`
    // significant digits without trailing zeros. The window formats lengths,
    // times and feeds by kind instead, and a plain number to `significant`.
    int decimals{-1};
    int significant{6};
};

struct Message {
    std::string code;         // stable identifier: "calibration_feed_mismatch"
    const char* context{""};  // translation context of the template
    const char* text{""};     // English template, marked with QT_TRANSLATE_NOOP
    std::vector<MessageArg> args;
};

// A message without arguments yet: its code, the template's context and text.
Message make_message(std::string code, const char* context, const char* text);

// Argument builders: number(name, kind, value[, decimals]) and text(name, value).
MessageArg arg(std::string name, ArgKind kind, double value, int decimals = -1);
// A number written in English to `significant` significant digits ("0.0036 mm").
MessageArg significant_arg(std::string name, ArgKind kind, double value, int significant);
MessageArg text_arg(std::string name, std::string value);
MessageArg message_arg(std::string name, Message value);

// The template with %1..%9 replaced by `args` (each already formatted), in
// one pass, so an argument that contains "%2" is not substituted again. A
// placeholder with no argument stays as written.
std::string fill_template(std::string_view text, const std::vector<std::string>& args);

// One argument in English, with its unit: "1.272 mm", "0.42 s", "2000 mm/min".
std::string render_arg(const MessageArg& arg);
// The message in English.
std::string render(const Message& message);

}  // namespace probecycle
