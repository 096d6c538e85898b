#pragma once

// What the cycle model warns about: a code, a severity and the figures the
// check found, by name. Each check (cycle_warnings.cpp; the knee's in
// sweep.cpp) fills its own figures type, and that type words its message
// (the code, an English template, named arguments; core/common/message.h).
// The message is built when it is shown, not when the cycle is evaluated: a
// sweep or the optimiser evaluates thousands of candidates and reads only
// their codes.

#include <string>
#include <variant>
#include <vector>

#include "core/common/message.h"
#include "core/common/severity.h"
#include "core/cycle/scenario.h"

namespace probecycle {

enum class WarningCode {
    overtravel_limit,
    backoff_too_small,
    backoff_excess,
    touch_while_accelerating,
    feed_beyond_knee,
    knee_at_range_end,
    uncertainty_over_target,
    calibration_feed_mismatch,
    no_valid_feed,
    feed_over_probe_limit,
    start_inside_uncertainty,
    search_ends_too_soon,
    protected_move_overtravel,
};
const char* to_string(WarningCode code);

// The figures of each warning, in internal units (mm, s, mm/s). A touch is
// numbered from 1: 1 the first touch, 2 the second of two-touch.
namespace warning {

// The worst touch's overtravel, at up to the highest feed override, at or
// near the probe's limit (an error at the limit, a warning from 80 %).
struct OvertravelLimit {
    static constexpr WarningCode code = WarningCode::overtravel_limit;
    double overtravel_mm{0.0};
    double limit_mm{0.0};
    double feed_override{1.0};  // the factor it is at: 1.5 for 150 %
    int touch{1};
    Message message(Severity severity) const;
    bool operator==(const OvertravelLimit&) const = default;
};

// A two-touch backoff under the recommended one: an error.
struct BackoffTooSmall {
    static constexpr WarningCode code = WarningCode::backoff_too_small;
    double backoff_mm{0.0};
    double recommended_mm{0.0};
    BackoffFrom from{BackoffFrom::stop};  // where the backoff is measured from
    Message message(Severity severity) const;
    bool operator==(const BackoffTooSmall&) const = default;
};

// A two-touch backoff well over the recommended one: the time it wastes.
struct BackoffExcess {
    static constexpr WarningCode code = WarningCode::backoff_excess;
    double backoff_mm{0.0};
    double recommended_mm{0.0};
    double wasted_s{0.0};
    Message message(Severity severity) const;
    bool operator==(const BackoffExcess&) const = default;
};

// The measuring touch triggers before it reaches its feed: the speed it
// triggers at and the error against a calibration at full feed.
struct TouchWhileAccelerating {
    static constexpr WarningCode code = WarningCode::touch_while_accelerating;
    double speed_mm_s{0.0};
    double feed_mm_s{0.0};
    double error_mm{0.0};
    int touch{1};
    Message message(Severity severity) const;
    bool operator==(const TouchWhileAccelerating&) const = default;
};

// The probing feed beyond the knee of the cycle time against feed; a
// negative time saved is the time the faster feed loses.
struct FeedBeyondKnee {
    static constexpr WarningCode code = WarningCode::feed_beyond_knee;
    double feed_mm_s{0.0};
    double knee_feed_mm_s{0.0};
    double time_saved_s{0.0};
    double knee_tolerance{0.0};  // a fraction: 0.01 for 1 %
    Message message(Severity severity) const;
    bool operator==(const FeedBeyondKnee&) const = default;
};

// The fastest cycle lies at an end of the feeds searched.
struct KneeAtRangeEnd {
    static constexpr WarningCode code = WarningCode::knee_at_range_end;
    double end_feed_mm_s{0.0};
    double knee_feed_mm_s{0.0};
    bool highest{false};  // the highest feed searched, else the lowest
    Message message(Severity severity) const;
    bool operator==(const KneeAtRangeEnd&) const = default;
};

struct UncertaintyOverTarget {
    static constexpr WarningCode code = WarningCode::uncertainty_over_target;
    double uncertainty_mm{0.0};
    double target_mm{0.0};
    Message message(Severity severity) const;
    bool operator==(const UncertaintyOverTarget&) const = default;
};

// Measuring at another speed than the calibration's: the delay travel's error.
struct CalibrationFeedMismatch {
    static constexpr WarningCode code = WarningCode::calibration_feed_mismatch;
    double speed_mm_s{0.0};
    double calibration_speed_mm_s{0.0};
    double error_mm{0.0};
    Message message(Severity severity) const;
    bool operator==(const CalibrationFeedMismatch&) const = default;
};

// No feed of the range searched counts for the knee (analyse() in sweep.h):
// none gives a valid cycle, or (`unreached`) valid ones are there but the
// first touch reaches none of them.
struct NoValidFeed {
    static constexpr WarningCode code = WarningCode::no_valid_feed;
    double from_feed_mm_s{0.0};
    double to_feed_mm_s{0.0};
    bool unreached{false};
    Message message(Severity severity) const;
    bool operator==(const NoValidFeed&) const = default;
};

// A touch's feed over the probe's rated maximum: an error.
struct FeedOverProbeLimit {
    static constexpr WarningCode code = WarningCode::feed_over_probe_limit;
    double feed_mm_s{0.0};
    double max_feed_mm_s{0.0};
    bool measuring{false};  // the measuring feed, else the probing feed
    Message message(Severity severity) const;
    bool operator==(const FeedOverProbeLimit&) const = default;
};

// The start lies inside the part's position uncertainty (`inside`), or
// outside it but too near to reach the probing feed after it.
struct StartInsideUncertainty {
    static constexpr WarningCode code = WarningCode::start_inside_uncertainty;
    double approach_mm{0.0};
    double part_uncertainty_mm{0.0};
    double reach_mm{0.0};  // the distance to reach the probing feed
    bool inside{false};
    Message message(Severity severity) const;
    bool operator==(const StartInsideUncertainty&) const = default;
};

// A hand-set cycle.search_beyond_mm short of the touch's stop: an error.
struct SearchEndsTooSoon {
    static constexpr WarningCode code = WarningCode::search_ends_too_soon;
    double search_beyond_mm{0.0};
    double stop_mm{0.0};  // past the surface
    int touch{1};
    Message message(Severity severity) const;
    bool operator==(const SearchEndsTooSoon&) const = default;
};

// A protected positioning move that meets an obstruction stops this far past
// it, at or near the probe's limit.
struct ProtectedMoveOvertravel {
    static constexpr WarningCode code = WarningCode::protected_move_overtravel;
    double overtravel_mm{0.0};
    double limit_mm{0.0};
    double position_feed_mm_s{0.0};
    double feed_override{1.0};  // the factor it is at: 1.5 for 150 %
    Message message(Severity severity) const;
    bool operator==(const ProtectedMoveOvertravel&) const = default;
};

}  // namespace warning

using WarningFigures =
    std::variant<warning::OvertravelLimit, warning::BackoffTooSmall, warning::BackoffExcess,
                 warning::TouchWhileAccelerating, warning::FeedBeyondKnee, warning::KneeAtRangeEnd,
                 warning::UncertaintyOverTarget, warning::CalibrationFeedMismatch,
                 warning::NoValidFeed, warning::FeedOverProbeLimit, warning::StartInsideUncertainty,
                 warning::SearchEndsTooSoon, warning::ProtectedMoveOvertravel>;

struct Warning {
    Warning() = default;
    template <typename Figures>
    Warning(Severity severity_, const Figures& figures_)
        : code(Figures::code), severity(severity_), figures(figures_) {}

    WarningCode code{};
    Severity severity{};
    WarningFigures figures;

    // The figures when they are of type `Figures` (the code's), else nullptr.
    template <typename Figures>
    const Figures* as() const {
        return std::get_if<Figures>(&figures);
    }
    // The message: code, template and the figures as named arguments.
    Message to_message() const;
    std::string message() const;  // in English: render(to_message())
};

// Which touch a touch_while_accelerating warning is about (1 the first, 2 the
// second); 0 for any other warning.
int accelerating_touch(const Warning& warning);

// Errors first, then warnings, then notes; in the order computed within each
// (a stable sort): what makes a cycle invalid is read first.
void order_by_severity(std::vector<Warning>& warnings);

constexpr unsigned invalid_code_bit(WarningCode code) {
    return 1u << static_cast<unsigned>(code);
}
// Errors that no probing feed changes (a feature's protected moves, at the
// positioning feed): the knee and a sweep's fastest cycle look past them, so
// the curve still tells where the probing feed is best, while the cycle
// itself stays invalid.
constexpr unsigned kFeedIndependentErrors =
    invalid_code_bit(WarningCode::protected_move_overtravel);
// Whether the invalid codes leave a feed that counts for the knee.
constexpr bool valid_for_knee(unsigned invalid_codes) {
    return (invalid_codes & ~kFeedIndependentErrors) == 0;
}

// The codes of invalid_codes() by name, in WarningCode order, joined by
// `separator` ("backoff_too_small;overtravel_limit"); "" for none.
std::string invalid_codes_text(unsigned codes, const char* separator);

// A warning's message with its code and template (context "Warning"); the
// figures types build theirs with it.
Message warning_message(WarningCode code, const char* text, std::vector<MessageArg> args);

}  // namespace probecycle
