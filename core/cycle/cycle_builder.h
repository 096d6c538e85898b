#pragma once

// Inside the cycle model: the timeline of one scenario's cycle, touch by touch
// and move by move (cycle_builder.cpp), and the few solves the figures and the
// warnings take from it. evaluate_into (cycle.cpp) calls build_timeline(),
// then works out the figures and collects the warnings; nothing outside
// core/cycle includes this file.

#include <array>
#include <vector>

#include "core/cycle/cycle.h"
#include "core/cycle/motion_cache.h"

namespace probecycle {

// The parts of a CycleResult a timeline is written into.
struct TimelineBuffers {
    std::vector<PhaseRecord>& phases;
    std::vector<TimedSegment>& segments;
    std::vector<AxisMotion>& motions;
    std::array<double, kPhaseCount>& phase_time_s;
};

// What the figures and the warnings need of a built timeline.
struct CycleTimeline {
    double total_s{0.0};
    // The first touch, with its overtravel at the highest feed override and
    // its search; the same touch at that override (the first touch itself
    // without one); the measuring touch (the second of two-touch, else the
    // first).
    TouchResult first;
    TouchResult first_fast;
    TouchResult measuring;
    // The time the backoff sets in a two-touch cycle (the backoff move and
    // the second approach): after the first touch, and in each repeat.
    double first_backoff_cost_s{0.0};
    double repeat_backoff_cost_s{0.0};
};

// Builds the whole cycle into `buffers` (emptied first): the feature's
// protected moves, the touch sequence (first touch, backoff and second
// touch, the repeats, the return) and its replays for the feature's other
// touches. The cache is bound to the scenario's machine.
CycleTimeline build_timeline(const Scenario& scenario, const TimelineBuffers& buffers,
                             MotionCache& cache, Detail detail);

// The dynamics' kernel when it has any effect, else nullptr (the ideal axis).
const AxisKernel* active_kernel(const AxisKernel& kernel);

// approach_room_mm (cycle.h) for a kernel already built (nullptr: the ideal
// axis), through `cache` when one is given.
double approach_room(const Scenario& scenario, const MotionLimits& limits, const AxisKernel* kernel,
                     double feed_mm_s, MotionCache* cache = nullptr);

// Which of a touch's figures: the worst case, which the checks, the
// recommended backoff and the programs take, or after the mean scan wait,
// which the timeline takes (TouchResult).
enum class TouchCase { worst, mean };

// Where the backoff is measured from, past the surface (cycle.backoff_from):
// where the first touch stopped, or where the control recorded it.
double backoff_reference_mm(const Cycle& cycle, const TouchResult& first, TouchCase which);

// Time for the backoff move and the second approach, the part of a two-touch
// cycle that the backoff changes. The move runs from the stop to
// `backoff_mm` in front of the reference; the second touch starts
// `backoff_mm - reference` in front of the surface.
double backoff_cost_s(const Scenario& scenario, const MotionLimits& limits,
                      const AxisKernel* kernel, double backoff_mm, const TouchResult& first,
                      MotionCache& cache);

}  // namespace probecycle
