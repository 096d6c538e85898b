#pragma once

// Runs the core for the window: one analysis of the scenario and the sweeps
// the charts draw, into buffers kept across calls. No formulas live here;
// every number comes from core/.

#include <QString>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "core/cycle/cycle.h"
#include "core/cycle/scenario.h"
#include "core/cycle/sweep.h"

namespace probecycle::ui {

struct Computed {
    Scenario scenario;
    // Non-empty when the scenario fails validation; nothing below is then valid.
    std::vector<FieldError> errors;
    Analysis analysis;
    // Cycle time, overtravel and uncertainty against the probing feed, for
    // each strategy with everything else as in the scenario, except that the
    // two-touch backoff is the recommended one at each feed: the optimised
    // cycle, the curve the knee is found on (core analyse()).
    SweepResult single_touch;
    SweepResult two_touch;

    bool valid() const { return errors.empty(); }
    const CycleResult& cycle() const { return analysis.cycle; }
    // The sweep of the scenario's own strategy.
    const SweepResult& own_sweep() const {
        return scenario.cycle.strategy == Strategy::single_touch ? single_touch : two_touch;
    }
};

class Computation {
  public:
    explicit Computation(std::size_t points_per_curve = 500);

    const Computed& run(const Scenario& scenario);
    const Computed& result() const { return result_; }
    std::span<const double> feeds() const { return feeds_; }

  private:
    std::vector<double> feeds_;
    Computed result_;
    Scenario variant_;
};

}  // namespace probecycle::ui
