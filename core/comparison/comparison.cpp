#include "core/comparison/comparison.h"

#include <algorithm>
#include <cmath>

#include "core/common/input_error.h"
#include "core/comparison/comparison_message.h"

namespace probecycle {

namespace {

// A point's C-axis uncertainty above this deserves a look.
constexpr double kCAxisUncertaintyWarning_mm = 0.001;
// At most this many points are named in a warning.
constexpr std::size_t kNamedPoints = 5;

void check_counts(const ComparisonInput& input) {
    const std::size_t n = input.plan.size();
    if (n < kMinComparisonPoints) throw InputError(too_few_points(n));
    for (const auto* points : {&input.reference_cmm, &input.test_omm, &input.reference_omm}) {
        if (points->size() != n) {
            throw InputError(comparison_message(
                "point_count_differs",
                QT_TRANSLATE_NOOP("Comparison",
                                  "%1 measured points for %2 plan points; one measured point "
                                  "per plan point is needed"),
                {arg("points", ArgKind::integer, static_cast<double>(points->size())),
                 arg("plan_points", ArgKind::integer, static_cast<double>(n))}));
        }
    }
    if (input.block_at_zero.empty() != input.block_turned.empty()) {
        throw InputError(comparison_message(
            "block_half_given",
            QT_TRANSLATE_NOOP("Comparison",
                              "the block is needed at C = 0 and after the turn; only one is "
                              "given"),
            {}));
    }
}

// The plan's mean outward normal: the side every fitted surface faces.
Eigen::Vector3d mean_normal(const std::vector<PlanPoint>& plan) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const PlanPoint& p : plan) sum += p.normal;
    return sum.norm() > 1e-9 ? Eigen::Vector3d(sum.normalized()) : Eigen::Vector3d::Zero();
}

// "3, 17, 40" for the first kNamedPoints 1-based point numbers.
std::string point_list(const std::vector<std::size_t>& indices) {
    std::string out;
    for (std::size_t k = 0; k < indices.size() && k < kNamedPoints; ++k) {
        out += (k == 0 ? "" : ", ") + std::to_string(indices[k] + 1);
    }
    if (indices.size() > kNamedPoints) out += ", ...";
    return out;
}

void warn(std::vector<ComparisonWarning>& warnings, ComparisonWarningCode code, Severity severity,
          const char* text, std::vector<MessageArg> args) {
    warnings.push_back(
        {to_string(code), severity, comparison_message(to_string(code), text, std::move(args))});
}

void fit_warning(const Message& which, const SurfaceFitResiduals& fit,
                 std::vector<ComparisonWarning>& warnings) {
    if (fit.max_mm <= kFitResidualWarning_mm) return;
    warn(warnings, ComparisonWarningCode::surface_fit_residual, Severity::warning,
         QT_TRANSLATE_NOOP("Comparison",
                           "the surface through the %1 leaves residuals up to %2 (RMS %3, "
                           "above %4): the plan may be too sparse for the part's form, or "
                           "a point is wrong"),
         {message_arg("surface", which),
          significant_arg("max_mm", ArgKind::length_mm, fit.max_mm, 3),
          significant_arg("rms_mm", ArgKind::length_mm, fit.rms_mm, 3),
          arg("limit_mm", ArgKind::length_mm, kFitResidualWarning_mm)});
}

std::optional<std::size_t> count_beyond(const std::vector<double>& values,
                                        const std::optional<double>& tolerance) {
    if (!tolerance) return std::nullopt;
    return static_cast<std::size_t>(std::count_if(
        values.begin(), values.end(), [&](double v) { return std::abs(v) > *tolerance; }));
}

}  // namespace

const char* to_string(ComparisonWarningCode code) {
    switch (code) {
        case ComparisonWarningCode::c_axis_not_identified:
            return "c_axis_not_identified";
        case ComparisonWarningCode::surface_fit_residual:
            return "surface_fit_residual";
        case ComparisonWarningCode::point_off_surface:
            return "point_off_surface";
        case ComparisonWarningCode::point_far_from_plan:
            return "point_far_from_plan";
        case ComparisonWarningCode::first_order_disagreement:
            return "first_order_disagreement";
        case ComparisonWarningCode::c_axis_uncertainty_large:
            return "c_axis_uncertainty_large";
    }
    return "unknown";
}

DeviationSummary summarize(const std::vector<double>& values) {
    DeviationSummary s;
    if (values.empty()) return s;
    s.min_mm = *std::min_element(values.begin(), values.end());
    s.max_mm = *std::max_element(values.begin(), values.end());
    double sum = 0.0;
    double sum_sq = 0.0;
    for (const double v : values) {
        sum += v;
        sum_sq += v * v;
    }
    const double n = static_cast<double>(values.size());
    s.mean_mm = sum / n;
    s.rms_mm = std::sqrt(sum_sq / n);
    return s;
}

ComparisonResult run_comparison(const ComparisonInput& input) {
    check_counts(input);
    ComparisonResult result;
    const std::size_t n = input.plan.size();

    // The C axis: identified from the block, or taken as exact.
    if (!input.block_at_zero.empty()) {
        result.c_axis = identify_c_axis(input.block_at_zero, input.block_turned, input.c_axis);
        result.c_axis_identified = true;
        for (const CAxisWarning& w : result.c_axis.warnings) {
            result.warnings.push_back({to_string(w.code), w.severity, w.message});
        }
    } else {
        result.c_axis.uncertainty = CAxisErrors{};
        double radius_mm = 0.0;
        for (const PlanPoint& p : input.plan) {
            radius_mm +=
                (p.nominal.head<2>() - Eigen::Vector2d(input.c_axis.x_mm, input.c_axis.y_mm))
                    .norm();
        }
        radius_mm /= static_cast<double>(input.plan.size());
        warn(result.warnings, ComparisonWarningCode::c_axis_not_identified, Severity::info,
             QT_TRANSLATE_NOOP("Comparison",
                               "no block touched: the C axis is taken as exact and its errors "
                               "stay in the result; %1 from the axis, every 10 µrad of tilt "
                               "or turn moves a point by %2"),
             {significant_arg("radius_mm", ArgKind::length_mm, radius_mm, 3),
              significant_arg("per_10_urad_mm", ArgKind::length_mm, radius_mm * 1e-5, 2)});
    }
    const CAxisErrors& errors = result.c_axis.errors;

    SurfaceFitOptions options;
    options.facing = mean_normal(input.plan);
    std::vector<Eigen::Vector3d> nominal(n);
    std::vector<Eigen::Vector3d> reference(n);
    for (std::size_t i = 0; i < n; ++i) {
        nominal[i] = input.plan[i].nominal;
        reference[i] = result.c_axis_identified
                           ? correct_turned_point(input.reference_omm[i], errors, input.c_axis)
                           : input.reference_omm[i];
    }
    // S_c: the reference's real form; S_d: the design.
    const BSplineSurface cmm_surface = BSplineSurface::fit(input.reference_cmm, options);
    const BSplineSurface design_surface = BSplineSurface::fit(nominal, options);

    // System error delta_i = p_i - q_i, q_i the foot of p_i on S_c; the
    // calibrated point q_r = q'_i + delta_i, q'_i the foot of q_i on S_d.
    std::vector<Eigen::Vector3d> system(n);
    std::vector<Eigen::Vector3d> calibrated(n);
    std::vector<std::size_t> off_surface;
    for (std::size_t i = 0; i < n; ++i) {
        const SurfaceProjection on_cmm = cmm_surface.project(reference[i]);
        const SurfaceProjection on_design = design_surface.project(on_cmm.foot);
        if (!on_cmm.inside || !on_cmm.converged || !on_design.converged) off_surface.push_back(i);
        system[i] = reference[i] - on_cmm.foot;
        calibrated[i] = on_design.foot + system[i];
    }
    // S_r: the design as this machine measures it.
    const BSplineSurface calibrated_surface = BSplineSurface::fit(calibrated, options);
    result.cmm_fit = cmm_surface.residuals();
    result.design_fit = design_surface.residuals();
    result.calibrated_fit = calibrated_surface.residuals();

    const Eigen::Matrix<double, 6, 6>& covariance = result.c_axis.covariance;
    const bool uncertainty_known = result.c_axis.uncertainty.has_value();
    std::vector<double> deviation(n);
    std::vector<double> direct(n);
    std::vector<double> system_error(n);
    std::vector<std::size_t> far;
    std::vector<std::size_t> disagree;
    double largest_uncertainty = 0.0;
    result.points.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const PlanPoint& plan = input.plan[i];
        ComparisonPoint& out = result.points[i];
        out.nominal = plan.nominal;
        out.normal = plan.normal;
        const SurfaceProjection hit = calibrated_surface.project(input.test_omm[i]);
        if (!hit.inside || !hit.converged) off_surface.push_back(i);
        // Signed along the plan's outward normal (the surface's own normal
        // faces the plan's mean normal, which one point's may not).
        out.deviation_mm = hit.normal.dot(plan.normal) < 0.0 ? -hit.distance_mm : hit.distance_mm;
        out.direct_deviation_mm = (input.test_omm[i] - plan.nominal).dot(plan.normal);
        out.system_error_mm = system[i].dot(plan.normal);
        out.first_order_mm = out.direct_deviation_mm -
                             (reference[i] - plan.nominal).dot(plan.normal) +
                             (input.reference_cmm[i] - plan.nominal).dot(plan.normal);
        if (!result.c_axis_identified) {
            out.c_axis_uncertainty_mm = 0.0;
        } else if (uncertainty_known) {
            // The deviation moves opposite to the corrected reference point.
            const Eigen::Matrix<double, 1, 6> g =
                -correction_sensitivity(input.reference_omm[i], plan.normal, input.c_axis);
            out.c_axis_uncertainty_mm =
                std::sqrt(std::max(0.0, (g * covariance * g.transpose())(0)));
            largest_uncertainty = std::max(largest_uncertainty, *out.c_axis_uncertainty_mm);
        }
        if (std::max((input.test_omm[i] - plan.nominal).norm(),
                     (reference[i] - plan.nominal).norm()) > kFarFromPlanWarning_mm) {
            far.push_back(i);
        }
        if (std::abs(out.deviation_mm - out.first_order_mm) > kFirstOrderWarning_mm) {
            disagree.push_back(i);
        }
        deviation[i] = out.deviation_mm;
        direct[i] = out.direct_deviation_mm;
        system_error[i] = out.system_error_mm;
    }
    result.deviation = summarize(deviation);
    result.direct = summarize(direct);
    result.system_error = summarize(system_error);
    result.out_of_tolerance = count_beyond(deviation, input.tolerance_mm);
    result.direct_out_of_tolerance = count_beyond(direct, input.tolerance_mm);

    fit_warning(comparison_message("cmm_points",
                                   QT_TRANSLATE_NOOP("Comparison", "reference's CMM points"), {}),
                result.cmm_fit, result.warnings);
    fit_warning(comparison_message("plan_points",
                                   QT_TRANSLATE_NOOP("Comparison", "plan's nominal points"), {}),
                result.design_fit, result.warnings);
    fit_warning(
        comparison_message("calibrated_points",
                           QT_TRANSLATE_NOOP("Comparison", "calibrated reference points"), {}),
        result.calibrated_fit, result.warnings);
    std::sort(off_surface.begin(), off_surface.end());
    off_surface.erase(std::unique(off_surface.begin(), off_surface.end()), off_surface.end());
    if (!off_surface.empty()) {
        warn(result.warnings, ComparisonWarningCode::point_off_surface, Severity::warning,
             QT_TRANSLATE_NOOP("Comparison",
                               "%1 points project onto the edge of a fitted surface, not "
                               "square onto it (points %2): their results are less sure"),
             {arg("points", ArgKind::integer, static_cast<double>(off_surface.size())),
              text_arg("point_numbers", point_list(off_surface))});
    }
    if (!far.empty()) {
        warn(result.warnings, ComparisonWarningCode::point_far_from_plan, Severity::warning,
             QT_TRANSLATE_NOOP("Comparison",
                               "%1 measured points lie more than %2 from their plan points "
                               "(points %3): are the files in the plan's order, and the C "
                               "axis's position and angle right?"),
             {arg("points", ArgKind::integer, static_cast<double>(far.size())),
              arg("limit_mm", ArgKind::length_mm, kFarFromPlanWarning_mm),
              text_arg("point_numbers", point_list(far))});
    }
    if (!disagree.empty()) {
        warn(result.warnings, ComparisonWarningCode::first_order_disagreement, Severity::warning,
             QT_TRANSLATE_NOOP("Comparison",
                               "at %1 points the result differs from its first-order "
                               "estimate by more than %2 (points %3): the surfaces do not "
                               "follow the points there"),
             {arg("points", ArgKind::integer, static_cast<double>(disagree.size())),
              arg("limit_mm", ArgKind::length_mm, kFirstOrderWarning_mm),
              text_arg("point_numbers", point_list(disagree))});
    }
    if (largest_uncertainty > kCAxisUncertaintyWarning_mm) {
        warn(result.warnings, ComparisonWarningCode::c_axis_uncertainty_large, Severity::warning,
             QT_TRANSLATE_NOOP("Comparison",
                               "the C-axis errors' uncertainty reaches %1 on the part "
                               "(above %2): touch the block more often or on larger faces, "
                               "or judge whether the correction helps"),
             {significant_arg("uncertainty_mm", ArgKind::length_mm, largest_uncertainty, 2),
              arg("limit_mm", ArgKind::length_mm, kCAxisUncertaintyWarning_mm)});
    }
    return result;
}

}  // namespace probecycle
