#pragma once

// Numbers in messages: the shortest text that reads back as the value rounded
// to `significant` digits, C locale, no trailing zeros ("0.004", "1e+09").
// NaN and infinities read "NaN", "inf", "-inf". Files with their own number
// format (the CSV reports) use csv_number_text() in csv_writer.h.

#include <string>

namespace probecycle {

std::string format_number(double value, int significant = 6);

}  // namespace probecycle
