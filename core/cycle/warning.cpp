#include "core/cycle/warning.h"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace probecycle {

namespace {

// The figures types in WarningCode order: a warning's code is its figures'.
template <std::size_t... I>
constexpr bool codes_in_order(std::index_sequence<I...> /*unused*/) {
    return ((std::variant_alternative_t<I, WarningFigures>::code == static_cast<WarningCode>(I)) &&
            ...);
}
static_assert(codes_in_order(std::make_index_sequence<std::variant_size_v<WarningFigures>>{}));

}  // namespace

const char* to_string(WarningCode code) {
    switch (code) {
        case WarningCode::overtravel_limit:
            return "overtravel_limit";
        case WarningCode::backoff_too_small:
            return "backoff_too_small";
        case WarningCode::backoff_excess:
            return "backoff_excess";
        case WarningCode::touch_while_accelerating:
            return "touch_while_accelerating";
        case WarningCode::feed_beyond_knee:
            return "feed_beyond_knee";
        case WarningCode::knee_at_range_end:
            return "knee_at_range_end";
        case WarningCode::uncertainty_over_target:
            return "uncertainty_over_target";
        case WarningCode::calibration_feed_mismatch:
            return "calibration_feed_mismatch";
        case WarningCode::no_valid_feed:
            return "no_valid_feed";
        case WarningCode::feed_over_probe_limit:
            return "feed_over_probe_limit";
        case WarningCode::start_inside_uncertainty:
            return "start_inside_uncertainty";
        case WarningCode::search_ends_too_soon:
            return "search_ends_too_soon";
        case WarningCode::protected_move_overtravel:
            return "protected_move_overtravel";
    }
    return "?";
}

void order_by_severity(std::vector<Warning>& warnings) {
    // An insertion sort, stable and without the buffer std::stable_sort
    // allocates: it runs in every evaluation, on a handful of warnings.
    const auto before = [](const Warning& x, const Warning& y) {
        return static_cast<int>(x.severity) > static_cast<int>(y.severity);
    };
    for (auto it = warnings.begin(); it != warnings.end(); ++it) {
        std::rotate(std::upper_bound(warnings.begin(), it, *it, before), it, it + 1);
    }
}

std::string invalid_codes_text(unsigned codes, const char* separator) {
    std::string text;
    for (unsigned k = 0; k < 32; ++k) {
        if ((codes & (1u << k)) == 0) continue;
        if (!text.empty()) text += separator;
        text += to_string(static_cast<WarningCode>(k));
    }
    return text;
}

Message warning_message(WarningCode code, const char* text, std::vector<MessageArg> args) {
    Message m;
    m.code = to_string(code);
    m.context = "Warning";
    m.text = text;
    m.args = std::move(args);
    return m;
}

int accelerating_touch(const Warning& warning) {
    const auto* figures = warning.as<warning::TouchWhileAccelerating>();
    return figures != nullptr ? figures->touch : 0;
}

Message Warning::to_message() const {
    return std::visit([this](const auto& f) { return f.message(severity); }, figures);
}

std::string Warning::message() const {
    return render(to_message());
}

}  // namespace probecycle
