#pragma once

// A whole comparison data set with a known truth (docs/comparison.md, "The
// simulated example"): a freeform design face of a few millimetres' height over
// 80 x 60 mm, 100 mm beside the C axis; a test part and a reference part
// with smooth machining errors along the normal; the C axis's six errors; a
// smooth systematic OMM error (axis scale and squareness, a thermal Z
// offset, a Z tilt, probe lobing by direction); noise. Every touch is the
// exact intersection of the probe's approach line (the plan point along its
// normal) with the part's real surface, as the part sits on the machine.
// The block is touched with the C axis's errors and the noise, not with the
// machine's error field: the identification assumes its two touches see the
// same machine.

#include <cstdint>
#include <vector>

#include "core/comparison/c_axis.h"
#include "core/comparison/comparison.h"

namespace probecycle {

struct ComparisonSimulationOptions {
    std::uint64_t seed{1};
    double omm_noise_mm{0.0};  // per axis, on every OMM touch and the block's
    double cmm_noise_mm{0.0};  // per axis, on the reference's CMM points
    bool c_axis_errors{true};  // false: an exact C axis
    bool machine_error{true};  // false: no systematic OMM error
    bool grid{false};          // true: a regular grid; false: jittered points
    int columns{16};           // plan points along X and Y
    int rows{12};
};

struct ComparisonDataSet {
    ComparisonInput input;  // every file's content, the C axis, the angle
    CAxisErrors true_c_axis;
    std::vector<double> truth_mm;           // the test part's deviation per plan point
    std::vector<double> reference_form_mm;  // the reference part's, per plan point
};

// The C-axis errors the simulator applies (zeros without c_axis_errors).
CAxisErrors simulated_c_axis_errors();
ComparisonDataSet simulate_comparison(const ComparisonSimulationOptions& options);

}  // namespace probecycle
