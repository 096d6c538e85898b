#pragma once

// One-click fixes for a cycle's warnings: the scenario after the
// change a warning suggests, rounded to the digits the editors show in the
// direction that clears it. A fix is offered only when the scenario it makes
// passes validation, no longer carries the warning it fixes and carries no
// error the current cycle did not: the window's buttons and the CLI never
// propose a change that leaves its own warning behind or breaks the cycle.
// Where the change alone would make a two-touch backoff too small (a start
// farther out reaches a faster, longer first touch), the fix sets the
// recommended backoff with it, as one change.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/cycle/cycle.h"
#include "core/cycle/scenario.h"
#include "core/cycle/sweep.h"

namespace probecycle {

enum class FixKind {
    none,
    backoff_to_recommended,  // the backoff the cycle recommends
    feed_to_knee,            // the probing feed down to the knee
    feed_for_overtravel,     // the probing feed down to overtravel under 80 % of the limit
    approach_to_reach_feed,  // start far enough out to touch at full feed
    search_past_stop,        // every search reaches past its touch's stop
    // The positioning feed down to an obstruction's overtravel under 80 % of
    // the limit.
    position_feed_for_overtravel,
};
const char* to_string(FixKind kind);

struct Fix {
    FixKind kind{FixKind::none};
    Scenario scenario;  // the scenario with the fix applied
    // The fix also sets the backoff to the one the fixed cycle recommends.
    bool with_backoff{false};
};

// The scenario keys a fix changes and their new values, in the key table's
// order ({"cycle.backoff_mm", 4.455}, ...).
std::vector<std::pair<std::string, double>> fix_changes(const Scenario& scenario, const Fix& fix);

// The fix for `warning`, one of `analysis`'s (of `scenario`), or nullopt when
// no fix clears it.
std::optional<Fix> fix_for(const Scenario& scenario, const Analysis& analysis,
                           const Warning& warning);

// Whether `result` still carries `warning` (the same code; for
// touch_while_accelerating, the same touch).
bool still_warns(const CycleResult& result, const Warning& warning);

}  // namespace probecycle
