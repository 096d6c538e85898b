#include "core/cycle/fixes.h"

#include <algorithm>

#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/cycle/motion_cache.h"

namespace probecycle {

const char* to_string(FixKind kind) {
    switch (kind) {
        case FixKind::none:
            return "none";
        case FixKind::backoff_to_recommended:
            return "backoff_to_recommended";
        case FixKind::feed_to_knee:
            return "feed_to_knee";
        case FixKind::feed_for_overtravel:
            return "feed_for_overtravel";
        case FixKind::approach_to_reach_feed:
            return "approach_to_reach_feed";
        case FixKind::search_past_stop:
            return "search_past_stop";
        case FixKind::position_feed_for_overtravel:
            return "position_feed_for_overtravel";
    }
    return "?";
}

namespace {

// The highest probing feed, rounded down, under `feed_mm_min` at which the
// overtravel is under the warning fraction of the limit; nullopt when even
// the slowest feed searched is not. Overtravel grows with the probing feed,
// so bisection on the feed.
std::optional<double> feed_for_overtravel(const Scenario& scenario, double feed_mm_min) {
    const double limit = kOvertravelWarningFraction * scenario.probe.overtravel_limit_mm;
    Scenario s = scenario;
    CycleResult r;
    MotionCache cache;
    const auto under = [&](double feed) {
        s.cycle.probe_feed_mm_min = feed;
        evaluate_into(s, r, cache, Detail::summary);
        return r.checked_overtravel_mm() < limit;
    };
    return highest_feed_where(std::min(kKneeSearchFrom_mm_min, feed_mm_min), feed_mm_min, under);
}

std::optional<Scenario> candidate(const Scenario& scenario, const Analysis& analysis,
                                  FixKind kind) {
    Scenario s = scenario;
    const CycleResult& cycle = analysis.cycle;
    switch (kind) {
        case FixKind::backoff_to_recommended:
            if (s.cycle.strategy != Strategy::two_touch) return std::nullopt;
            // Already on the µm grid (kBackoffStep_mm).
            s.cycle.backoff_mm = cycle.recommended_backoff_mm();
            return s;
        case FixKind::feed_to_knee: {
            const std::optional<double>& knee = analysis.knee_feed_mm_min;
            if (!knee) return std::nullopt;
            s.cycle.probe_feed_mm_min = round_feed_down(*knee);
            return s;
        }
        case FixKind::feed_for_overtravel: {
            const std::optional<double> feed =
                feed_for_overtravel(scenario, scenario.cycle.probe_feed_mm_min);
            if (!feed) return std::nullopt;
            // The knee, when it is slower still, is the better feed.
            const std::optional<double>& knee = analysis.knee_feed_mm_min;
            s.cycle.probe_feed_mm_min = knee ? std::min(*feed, round_feed_down(*knee)) : *feed;
            return s;
        }
        case FixKind::approach_to_reach_feed: {
            const double feed_mm_s = cycle.first_touch().programmed_feed_mm_s;
            // Beyond the part's position uncertainty too: the touch is at full feed
            // wherever the part is.
            s.cycle.approach_mm = round_up_to(
                s.cycle.part_position_uncertainty_mm + approach_room_mm(s, feed_mm_s), 0.01);
            return s;
        }
        case FixKind::search_past_stop: {
            // The stop farthest past its surface (at up to the highest feed
            // override: the overtravel the checks take), rounded up to the
            // editor's 0.01 mm so the value shown clears the error.
            s.cycle.search_beyond_mm = round_up_to(cycle.checked_overtravel_mm(), 0.01);
            return s;
        }
        case FixKind::position_feed_for_overtravel: {
            const std::optional<double> feed = highest_position_feed_mm_min(
                scenario, scenario.cycle.position_feed_mm_min, kOvertravelWarningFraction);
            if (!feed) return std::nullopt;
            s.cycle.position_feed_mm_min = *feed;
            return s;
        }
        case FixKind::none:
            break;
    }
    return std::nullopt;
}

// The fixes to try for a warning, best first.
std::vector<FixKind> kinds_for(const Warning& warning) {
    switch (warning.code) {
        case WarningCode::backoff_too_small:
        case WarningCode::backoff_excess:
            return {FixKind::backoff_to_recommended};
        case WarningCode::feed_beyond_knee:
            return {FixKind::feed_to_knee};
        case WarningCode::overtravel_limit:
            return {FixKind::feed_for_overtravel};
        case WarningCode::touch_while_accelerating:
            // The first touch starts farther out; the second gets the room
            // the recommended backoff includes.
            return {accelerating_touch(warning) == 1 ? FixKind::approach_to_reach_feed
                                                     : FixKind::backoff_to_recommended};
        case WarningCode::start_inside_uncertainty:
            return {FixKind::approach_to_reach_feed};
        case WarningCode::search_ends_too_soon:
            return {FixKind::search_past_stop};
        case WarningCode::protected_move_overtravel:
            return {FixKind::position_feed_for_overtravel};
        default:
            break;
    }
    return {};
}

// The numeric keys whose values differ from `before` to `after`, with the
// new values, in the key table's order.
std::vector<std::pair<std::string, double>> changed_numbers(const Scenario& before,
                                                            const Scenario& after) {
    std::vector<std::pair<std::string, double>> changes;
    for (const KeyInfo& key : numeric_keys()) {
        const double value = *get_number(after, key.key);
        if (value != *get_number(before, key.key)) changes.emplace_back(key.key, value);
    }
    return changes;
}

}  // namespace

bool still_warns(const CycleResult& result, const Warning& warning) {
    return std::any_of(result.warnings().begin(), result.warnings().end(), [&](const Warning& w) {
        // The same code; an acceleration warning about the same touch.
        return w.code == warning.code && accelerating_touch(w) == accelerating_touch(warning);
    });
}

std::optional<Fix> fix_for(const Scenario& scenario, const Analysis& analysis,
                           const Warning& warning) {
    const unsigned errors_before = analysis.cycle.invalid_codes();
    constexpr unsigned kBackoffTooSmall = invalid_code_bit(WarningCode::backoff_too_small);
    for (FixKind kind : kinds_for(warning)) {
        std::optional<Scenario> fixed = candidate(scenario, analysis, kind);
        if (!fixed || !validate(*fixed).empty()) continue;
        // A fix that changes nothing fixes nothing.
        if (changed_numbers(scenario, *fixed).empty()) continue;
        CycleResult result = evaluate(*fixed);
        // The change made the backoff too small (a faster first touch stops
        // farther): the recommended backoff comes with it.
        bool with_backoff = false;
        if (fixed->cycle.strategy == Strategy::two_touch &&
            kind != FixKind::backoff_to_recommended &&
            (result.invalid_codes() & kBackoffTooSmall) != 0 &&
            (errors_before & kBackoffTooSmall) == 0) {
            fixed->cycle.backoff_mm = result.recommended_backoff_mm();
            if (!validate(*fixed).empty()) continue;
            result = evaluate(*fixed);
            with_backoff = true;
        }
        // Never an error the cycle did not have.
        if ((result.invalid_codes() & ~errors_before) != 0) continue;
        if (warning.code == WarningCode::feed_beyond_knee) {
            // At or under the knee by construction while the knee search's
            // range stays the same (it reaches past 10000 mm/min only for a
            // faster feed): then the knee is the same.
            if (scenario.cycle.probe_feed_mm_min > kKneeSearchTo_mm_min &&
                still_warns(analyse(*fixed).cycle, warning)) {
                continue;
            }
            return Fix{kind, *fixed, with_backoff};
        }
        if (still_warns(result, warning)) continue;
        return Fix{kind, *fixed, with_backoff};
    }
    return std::nullopt;
}

std::vector<std::pair<std::string, double>> fix_changes(const Scenario& scenario, const Fix& fix) {
    return changed_numbers(scenario, fix.scenario);
}

}  // namespace probecycle
