#include "core/common/message_json.h"

#include <cmath>

namespace probecycle {

nlohmann::ordered_json message_values(const Message& message) {
    nlohmann::ordered_json values = nlohmann::ordered_json::object();
    for (const MessageArg& a : message.args) {
        if (values.contains(a.name)) continue;
        if (a.kind == ArgKind::text) {
            values[a.name] = a.text;
        } else if (a.kind == ArgKind::message) {
            // A nested message contributes its own values, under their names.
            for (const Message& inner : a.nested) {
                const nlohmann::ordered_json inner_values = message_values(inner);
                for (auto it = inner_values.begin(); it != inner_values.end(); ++it) {
                    if (!values.contains(it.key())) values[it.key()] = it.value();
                }
            }
        } else if (a.kind == ArgKind::integer && std::isfinite(a.number) &&
                   a.number == std::floor(a.number) && std::abs(a.number) < 9e15) {
            // A count or a touch's number: a whole number, not 1.0.
            values[a.name] = static_cast<long long>(a.number);
        } else {
            values[a.name] = a.number;
        }
    }
    return values;
}

nlohmann::ordered_json message_json(const Message& message) {
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    out["message"] = render(message);
    out["values"] = message_values(message);
    return out;
}

nlohmann::ordered_json warning_json(std::string_view code, Severity severity,
                                    const Message& message) {
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    out["code"] = code;
    out["severity"] = to_string(severity);
    out.update(message_json(message));
    return out;
}

}  // namespace probecycle
