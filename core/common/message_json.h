#pragma once

// Messages in the CLI's JSON: the English text and the arguments' values
// under their names (units in the names), so a script needs no parsing.

#include <nlohmann/json.hpp>

#include "core/common/message.h"

namespace probecycle {

// {"speed_mm_min": 1500.0, "key": "machine.scan_period_s", ...}: numbers as
// numbers, text as strings, a nested message's values merged in. A name
// given twice keeps the first value.
nlohmann::ordered_json message_values(const Message& message);

}  // namespace probecycle
