#pragma once

// Numbers in messages: the shortest text that reads back as the value rounded
// to `significant` digits, C locale, no trailing zeros ("0.004", "1e+09").
// NaN and infinities read "NaN", "inf", "-inf". Files with their own number
// format (the CSV reports) use csv_number_text() in csv_writer.h.

#include <optional>
#include <string>
#include <string_view>

namespace probecycle {

std::string format_number(double value, int significant = 6);

// The whole text as a decimal number, as a user types one: no hex, no inf or
// nan, nothing a double cannot hold; white space around it is ignored. The
// scenario's --set and the CLI's number options read numbers with it.
std::optional<double> parse_decimal(std::string_view text);

}  // namespace probecycle
