#pragma once

// The comparison pipeline (domain: "The pipeline"): the reference part's OMM
// points, corrected for the C axis, against the surface through its CMM
// points give the machine's systematic error per point; added to the design
// surface it gives the design as this machine measures it (S_r), and the
// test part's OMM points' signed distances from S_r are its machining error
// without the machine's. Signs: > 0 is excess material, outside the nominal
// surface along the plan's outward normal.

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

#include "core/common/message.h"
#include "core/common/severity.h"
#include "core/comparison/bspline_surface.h"
#include "core/comparison/c_axis.h"
#include "core/comparison/comparison_input.h"

namespace probecycle {

struct ComparisonInput {
    std::vector<PlanPoint> plan;
    std::vector<Eigen::Vector3d> reference_cmm;  // plan coordinates, plan order
    std::vector<Eigen::Vector3d> test_omm;       // at C = 0
    std::vector<Eigen::Vector3d> reference_omm;  // after the turn
    CAxisSetup c_axis;
    // The block at C = 0 and after the turn; both or neither.
    std::vector<BlockTouch> block_at_zero;
    std::vector<BlockTouch> block_turned;
    std::optional<double> tolerance_mm;  // half-width of the band about nominal
};

struct ComparisonPoint {
    Eigen::Vector3d nominal{Eigen::Vector3d::Zero()};
    Eigen::Vector3d normal{Eigen::Vector3d::UnitZ()};
    double deviation_mm{0.0};         // the comparison's result
    double direct_deviation_mm{0.0};  // (test OMM - nominal) . normal: plain OMM
    double system_error_mm{0.0};      // the machine's error found, along the normal
    // The first-order estimate (domain): test OMM deviation - reference OMM
    // deviation + reference CMM deviation, along the normal.
    double first_order_mm{0.0};
    // Standard uncertainty of deviation_mm from the C-axis errors'
    // uncertainty; 0 without a block, unknown if the block's is.
    std::optional<double> c_axis_uncertainty_mm;
};

struct DeviationSummary {
    double min_mm{0.0};
    double max_mm{0.0};
    double mean_mm{0.0};
    double rms_mm{0.0};
};
DeviationSummary summarize(const std::vector<double>& values);

enum class ComparisonWarningCode {
    c_axis_not_identified,
    surface_fit_residual,
    point_off_surface,
    point_far_from_plan,
    first_order_disagreement,
    c_axis_uncertainty_large,
};
const char* to_string(ComparisonWarningCode code);

struct ComparisonWarning {
    std::string code;  // a ComparisonWarningCode or a CAxisWarningCode
    Severity severity{};
    Message message;  // context "Comparison"
};

struct ComparisonResult {
    bool c_axis_identified{false};
    CAxisIdentification c_axis;           // zeros without a block
    std::vector<ComparisonPoint> points;  // plan order
    DeviationSummary deviation;
    DeviationSummary direct;
    DeviationSummary system_error;
    std::optional<std::size_t> out_of_tolerance;         // |deviation| > tolerance
    std::optional<std::size_t> direct_out_of_tolerance;  // |direct| > tolerance
    SurfaceFitResiduals cmm_fit;                         // S_c through the reference's CMM points
    SurfaceFitResiduals design_fit;                      // S_d through the plan's nominal points
    SurfaceFitResiduals calibrated_fit;                  // S_r through the calibrated points
    std::vector<ComparisonWarning> warnings;
};

// Residuals of a surface fit above this make the result doubtful.
constexpr double kFitResidualWarning_mm = 0.001;
// An OMM point further than this from its plan point is probably another
// point (files out of order) or a wrong C-axis position.
constexpr double kFarFromPlanWarning_mm = 1.0;
// The comparison and its first-order estimate differ by more than this.
constexpr double kFirstOrderWarning_mm = 0.002;

// InputError when the counts differ or fewer than kMinComparisonPoints;
// InputError from the block (see identify_c_axis()) or a surface fit.
ComparisonResult run_comparison(const ComparisonInput& input);

}  // namespace probecycle
