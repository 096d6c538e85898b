#pragma once

// What a JSON input is checked for before nlohmann parses it, because the
// parser accepts it or fails without saying where:
// - nesting deeper than the format needs (a deep input overflowed the stack
//   of the code that writes the error message);
// - a NUL byte (the bytes after it were ignored);
// - a key given twice in one object (the last won silently), or an empty key;
// - a number no double holds (1e400), named without key or line.
// One pass over the text, no recursion; the first problem is reported with
// the dotted key it belongs to and its line and column.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>

#include "core/common/field_error.h"

namespace probecycle {

// Nothing when the text passes; else the problem, keyed by the dotted path of
// the object keys around it ("machine.time_constant_s"), or "file" at the top.
std::optional<FieldError> check_json_text(std::string_view text, std::size_t max_depth);

// check_json_text, then nlohmann's parse into `root`: nothing when both pass,
// else the problem ("file: malformed JSON: ..." with the parser's words).
std::optional<FieldError> parse_checked_json(std::string_view text, std::size_t max_depth,
                                             nlohmann::ordered_json& root);

}  // namespace probecycle
