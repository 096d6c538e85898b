#pragma once

// Messages in the CLI's JSON: the English text and the arguments' values
// under their names (units in the names), so a script needs no parsing.

#include <nlohmann/json.hpp>

#include <string_view>

#include "core/common/message.h"
#include "core/common/severity.h"

namespace probecycle {

// {"speed_mm_min": 1500.0, "key": "machine.scan_period_s", ...}: numbers as
// numbers, text as strings, a nested message's values merged in. A name
// given twice keeps the first value.
nlohmann::ordered_json message_values(const Message& message);

// {"message": English text, "values": message_values(message)}.
nlohmann::ordered_json message_json(const Message& message);

// A finding as the CLI lists it: {"code", "severity", "message", "values"}.
nlohmann::ordered_json warning_json(std::string_view code, Severity severity,
                                    const Message& message);

}  // namespace probecycle
