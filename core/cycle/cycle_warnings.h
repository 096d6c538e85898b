#pragma once

// Inside the cycle model: the warnings an evaluated cycle carries, each check
// a function of its own (cycle_warnings.cpp). evaluate_into (cycle.cpp) calls
// collect_warnings() last; the knee's warnings need a sweep and are analyse()'s
// (sweep.h).

#include <vector>

#include "core/cycle/cycle.h"
#include "core/cycle/cycle_builder.h"
#include "core/cycle/motion_cache.h"

namespace probecycle {

// Appends the cycle's warnings to `warnings`, errors first (order_by_severity).
// `result` holds the cycle's figures already; with Detail::summary, the
// warnings that take solves of their own (backoff_excess,
// touch_while_accelerating) are left out.
void collect_warnings(const Scenario& scenario, const CycleTimeline& timeline,
                      const CycleResult& result, MotionCache& cache, Detail detail,
                      std::vector<Warning>& warnings);

}  // namespace probecycle
