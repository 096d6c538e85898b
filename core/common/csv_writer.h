#pragma once

// How numbers and text go into the CSV reports: C locale, quotes doubled. One
// place, so every report reads the same.
//
// Each quantity gets the digits the model supports, not the 9 to 17 a double
// carries: the rest is arithmetic, not the machine.
// - Times to 1 us: the inputs are delays and scan periods of tenths of a
//   millisecond, and the smallest difference worth reading (the knee's
//   rounding, a scan period's share) is 0.01 ms of cycle time.
// - Lengths to 0.1 um: a probe repeats to 0.25-1 um, a control resolves
//   0.1-1 um, and the smallest in-position width the scenario allows is 0.1 um.
// - Feeds and speeds to 0.1 mm/min: a control takes feeds in 0.1 or 1 mm/min;
//   a knee feed finer than that cannot be programmed.
// - Inputs (the scenario's values, the user's data) exactly as given.

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace probecycle {

inline constexpr int kReportTimeDecimals = 6;    // s: 1 us
inline constexpr int kReportLengthDecimals = 4;  // mm: 0.1 um
inline constexpr int kReportFeedDecimals = 1;    // mm/min: 0.1 mm/min

std::string csv_time_s(double value);
std::string csv_length_mm(double value);
std::string csv_feed_mm_min(double value);
// An input echoed: the shortest text that reads back as the value.
std::string csv_exact(double value);
// Empty for an unknown value.
std::string csv_time_s(const std::optional<double>& value);
std::string csv_length_mm(const std::optional<double>& value);

std::string csv_quote(const std::string& text);
// The fields joined by commas, and a line end (fields as given: quote them first).
std::string csv_line(std::initializer_list<std::string> fields);
// The "# warnings" section's title and column names: code,severity,message,
// with a group column before the message when the warnings belong to groups.
std::string csv_warnings_header(bool with_group = false);
// One row of it, the message quoted.
std::string csv_warning_row(std::string_view code, std::string_view severity,
                            const std::string& message);
std::string csv_warning_row(std::string_view code, std::string_view severity,
                            const std::string& group, const std::string& message);
// The text as one CSV field: as it is, or quoted when it holds a comma, a
// quote or a line break.
std::string csv_field(const std::string& text);

}  // namespace probecycle
