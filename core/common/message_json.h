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

// The findings of a list whose items hold a code, a severity and a message
// (the lab's, the comparison's), each by warning_json(); `code_name` gives a
// code's text.
template <typename Warnings, typename CodeName>
nlohmann::ordered_json warnings_json(const Warnings& warnings, CodeName code_name) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const auto& w : warnings) {
        out.push_back(warning_json(code_name(w.code), w.severity, w.message));
    }
    return out;
}

}  // namespace probecycle
