#pragma once

// The lab's results as the CLI prints them (JSON). Key names carry their
// units; a value the fit could not give is null. Warnings list code,
// severity, English message and their numbers under "values".

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/lab/calibration.h"
#include "core/lab/compensation.h"
#include "core/lab/delay_fit.h"

namespace probecycle {

nlohmann::ordered_json ring_calibration_json(const RingCalibration& result,
                                             const RingCalibrationOptions& options);
nlohmann::ordered_json length_calibration_json(const LengthCalibrationInput& input,
                                               const LengthCalibration& result);
// The groups and their warnings; with a period, the lag in cycles too.
nlohmann::ordered_json delay_fit_json(const DelayFit& fit, const DelayFitOptions& options);
// What --apply-to wrote into `file`.
nlohmann::ordered_json applied_delay_json(const AppliedDelay& applied, const std::string& file);
// The setup, the trigger, what was recorded and each method's error; the
// braking sweep, the per-cycle trace and the compensated-lag sweep when given.
nlohmann::ordered_json compensation_json(const CompensationSetup& setup,
                                         const CompensationComparison& result,
                                         const std::vector<BrakingRow>& braking_sweep,
                                         bool with_trace,
                                         const std::vector<LagRow>& lag_sweep = {});

}  // namespace probecycle
