#pragma once

// How numbers and text go into the CSV reports: C locale, 9 significant
// digits, quotes doubled. One place, so every report reads the same.

#include <optional>
#include <string>

namespace probecycle {

std::string csv_number_text(double value);
// Empty for an unknown value.
std::string csv_number_text(const std::optional<double>& value);
std::string csv_quote(const std::string& text);

}  // namespace probecycle
