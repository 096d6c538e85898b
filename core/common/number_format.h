#pragma once

// Numbers in messages: the shortest text that reads back as the value rounded
// to `significant` digits, C locale, no trailing zeros ("0.004", "1e+09").
// NaN and infinities read "NaN", "inf", "-inf". Files with their own number
// format (the CSV reports) use csv_writer.h.

#include <optional>
#include <string>
#include <string_view>

namespace probecycle {

std::string format_number(double value, int significant = 6);

// `value` rounded to `decimals` decimals, trailing zeros dropped ("0.36",
// "15"), never "-0"; NaN and infinities as format_number(). The reports give
// each quantity the digits the model supports (csv_writer.h).
std::string format_fixed(double value, int decimals);
// `value` with exactly `decimals` decimals, C locale whatever the process's,
// never "-0.000" ("0.4000", "-12.5"): the programs' constants and the
// import's text. NaN and infinities as format_number().
std::string format_decimals(double value, int decimals);
// The shortest text that reads back as exactly `value` ("0.06", "1e-06"): an
// input echoed as the user gave it.
std::string format_exact(double value);

// The whole text as a decimal number, as a user types one: no hex, no inf or
// nan, nothing a double cannot hold; white space around it is ignored. The
// scenario's --set and the CLI's number options read numbers with it.
std::optional<double> parse_decimal(std::string_view text);

// `value` rounded up or down to a multiple of `step` (the digits an editor
// shows). A quotient within 1e-6 of a whole step counts as on it, so a sum's
// last bits (2.1050000000000004 at 0.001) do not move it a whole step.
double round_up_to(double value, double step);
double round_down_to(double value, double step);

}  // namespace probecycle
