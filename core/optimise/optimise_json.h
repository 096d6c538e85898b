#pragma once

// The optimiser's result as `probecycle-cli optimise` prints it (JSON).

#include <string>

#include "core/optimise/optimiser.h"

namespace probecycle {

// {"best", "current", "current_meets_requirements", "uncertainty_bound_mm",
//  "saved_s", "binding", "advice", "savings", "pareto"}; a setting as
// {"strategy", "probe_feed_mm_min", "measure_feed_mm_min", "backoff_mm",
//  "approach_mm", "repeats", "position_feed_mm_min", "cycle_time_s", "uncertainty_mm",
//  "checked_overtravel_mm"}
// (the overtravel at up to the highest feed override, as the requirement
// holds it: evaluate's checked_overtravel_mm).
std::string optimise_to_json(const OptimiseResult& result);

}  // namespace probecycle
