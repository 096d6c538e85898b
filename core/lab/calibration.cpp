#include "core/lab/calibration.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/common/csv_reader.h"
#include "core/common/input_error.h"

namespace probecycle {

namespace {

constexpr double kPi = std::numbers::pi;
// An orientation is 0 or 180 deg; allow for a file written with rounding.
constexpr double kOrientationTolerance_deg = 1e-6;

constexpr std::array<double, 2> kOrientations_deg = {0.0, 180.0};

// Lengths in messages: 4 significant digits, "0.003606 mm" (the window
// formats its own).
MessageArg mm(std::string name, double value_mm) {
    return significant_arg(std::move(name), ArgKind::length_mm, value_mm, 4);
}
// A spindle orientation by its index, "0 deg" / "180 deg".
MessageArg orientation_arg(std::string name, std::size_t index) {
    return arg(std::move(name), ArgKind::angle_deg, kOrientations_deg[index], 0);
}

// Templates in context "Calibration", like every text of this file.
Message calibration_message(const char* code, const char* text, std::vector<MessageArg> args) {
    return Message{code, "Calibration", text, std::move(args)};
}

CalibrationWarning warning(CalibrationWarningCode code, Severity severity, const char* text,
                           std::vector<MessageArg> args) {
    return {code, severity, calibration_message(to_string(code), text, std::move(args))};
}

CsvError orientation_not_allowed(std::size_t line, double orientation_deg) {
    return CsvError(
        line, "orientation_deg",
        calibration_message("orientation_not_allowed",
                            QT_TRANSLATE_NOOP("Calibration",
                                              "%1 is not allowed: the spindle "
                                              "orientation is 0 or 180"),
                            {arg("orientation_deg", ArgKind::number, orientation_deg)}));
}

}  // namespace

std::string CalibrationWarning::text() const {
    return render(message);
}

std::optional<std::size_t> orientation_index(double orientation_deg) {
    if (std::abs(orientation_deg) <= kOrientationTolerance_deg) return 0;
    if (std::abs(orientation_deg - 180.0) <= kOrientationTolerance_deg) return 1;
    return std::nullopt;
}

const char* to_string(CalibrationWarningCode code) {
    switch (code) {
        case CalibrationWarningCode::points_one_side:
            return "points_one_side";
        case CalibrationWarningCode::large_runout:
            return "large_runout";
        case CalibrationWarningCode::large_residual:
            return "large_residual";
        case CalibrationWarningCode::single_orientation:
            return "single_orientation";
        case CalibrationWarningCode::exact_fit:
            return "exact_fit";
        case CalibrationWarningCode::length_wear:
            return "length_wear";
    }
    return "?";
}

std::optional<CircleFit> fit_circle(const Eigen::Ref<const Eigen::MatrixX2d>& points_mm) {
    const Eigen::Index n = points_mm.rows();
    if (n < 3) return std::nullopt;
    // Work about the centroid and in units of the spread: machine coordinates
    // (x = -350.123) would otherwise square into an ill-conditioned system.
    const Eigen::RowVector2d centroid = points_mm.colwise().mean();
    Eigen::MatrixX2d q = points_mm.rowwise() - centroid;
    const double scale = q.cwiseAbs().maxCoeff();
    if (!(scale > 0.0)) return std::nullopt;
    q /= scale;

    // Algebraic start (Kasa): x^2 + y^2 + D x + E y + F = 0 is linear in D, E, F.
    Eigen::Matrix<double, Eigen::Dynamic, 3> a(n, 3);
    a << q, Eigen::VectorXd::Ones(n);
    const Eigen::VectorXd b = -q.rowwise().squaredNorm();
    Eigen::ColPivHouseholderQR<Eigen::Matrix<double, Eigen::Dynamic, 3>> qr(a);
    qr.setThreshold(1e-9);
    if (qr.rank() < 3) return std::nullopt;  // on a line, or fewer than 3 distinct points
    const Eigen::Vector3d def = qr.solve(b);
    Eigen::Vector2d center(-def(0) / 2.0, -def(1) / 2.0);
    const double r_squared = center.squaredNorm() - def(2);
    if (!(r_squared > 0.0)) return std::nullopt;
    double radius = std::sqrt(r_squared);

    // Geometric refinement (Gauss-Newton on d_i - r, d_i = |p_i - c|): the
    // least-squares circle of the issue, which Kasa only approximates with noise.
    Eigen::Matrix<double, Eigen::Dynamic, 3> jacobian(n, 3);
    Eigen::VectorXd residual(n);
    for (int iteration = 0; iteration < 50; ++iteration) {
        for (Eigen::Index i = 0; i < n; ++i) {
            const Eigen::Vector2d d = q.row(i).transpose() - center;
            const double distance = d.norm();
            if (!(distance > 0.0)) return std::nullopt;
            residual(i) = distance - radius;
            jacobian.row(i) << -d.x() / distance, -d.y() / distance, -1.0;
        }
        const Eigen::Vector3d step = jacobian.colPivHouseholderQr().solve(-residual);
        center += step.head<2>();
        radius += step(2);
        if (!std::isfinite(radius) || radius <= 0.0) return std::nullopt;
        if (step.norm() <= 1e-15) break;
    }

    double residual_max = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
        const double distance = (q.row(i).transpose() - center).norm();
        residual_max = std::max(residual_max, std::abs(distance - radius));
    }
    return CircleFit{
        centroid(0) + scale * center.x(),
        centroid(1) + scale * center.y(),
        scale * radius,
        scale * residual_max,
    };
}

std::optional<int> touch_direction(double dx_mm, double dy_mm) {
    // Four sectors of +-22.5 deg, half the step to the diagonals, so that a
    // diagonal touch is counted in none.
    constexpr double kHalfSector = kPi / 8.0;
    const double angle = std::atan2(dy_mm, dx_mm);
    constexpr std::array<double, 4> kAxisAngles = {0.0, kPi, kPi / 2.0, -kPi / 2.0};
    for (std::size_t i = 0; i < kAxisAngles.size(); ++i) {
        double difference = std::abs(angle - kAxisAngles[i]);
        difference = std::min(difference, 2.0 * kPi - difference);
        if (difference < kHalfSector) return static_cast<int>(i);
    }
    return std::nullopt;
}

std::vector<RingPoint> parse_ring_csv(std::string_view text) {
    const auto rows = read_csv_rows(text, {"orientation_deg", "x_mm", "y_mm"});
    std::vector<RingPoint> points;
    points.reserve(rows.size());
    for (const auto& row : rows) {
        RingPoint point;
        point.orientation_deg = csv_number(row, 0, "orientation_deg");
        point.x_mm = csv_coordinate(row, 1, "x_mm");
        point.y_mm = csv_coordinate(row, 2, "y_mm");
        point.line = row.line;
        if (!orientation_index(point.orientation_deg)) {
            throw orientation_not_allowed(row.line, point.orientation_deg);
        }
        points.push_back(point);
    }
    return points;
}

std::array<std::vector<RingPoint>, 2> split_by_orientation(std::span<const RingPoint> points) {
    if (points.empty()) {
        throw CsvError(0, {},
                       calibration_message("no_points",
                                           QT_TRANSLATE_NOOP("Calibration",
                                                             "no points; a ring needs 3 or more "
                                                             "per orientation"),
                                           {}));
    }
    std::array<std::vector<RingPoint>, 2> by_orientation;
    for (const auto& point : points) {
        const auto index = orientation_index(point.orientation_deg);
        if (!index) throw orientation_not_allowed(point.line, point.orientation_deg);
        by_orientation[*index].push_back(point);
    }
    return by_orientation;
}

OrientationFit fit_orientation(std::span<const RingPoint> points, std::size_t orientation) {
    std::vector<std::size_t> lines;
    for (const auto& point : points) lines.push_back(point.line);
    const std::size_t first_line = lines.empty() ? 0 : lines.front();
    if (points.size() < 3) {
        throw CsvError(
            first_line, {},
            calibration_message(
                "too_few_points",
                points.size() == 1
                    ? QT_TRANSLATE_NOOP("Calibration",
                                        "orientation %1 has only %2 point (%3); a circle needs 3 "
                                        "or more per orientation (typically 4: X+, X-, Y+, Y-)")
                    : QT_TRANSLATE_NOOP("Calibration",
                                        "orientation %1 has only %2 points (%3); a circle needs "
                                        "3 or more per orientation (typically 4: X+, X-, Y+, Y-)"),
                {orientation_arg("orientation_deg", orientation),
                 arg("points", ArgKind::integer, static_cast<double>(points.size())),
                 message_arg("lines", describe_lines(lines))}));
    }
    Eigen::MatrixX2d xy(static_cast<Eigen::Index>(points.size()), 2);
    for (std::size_t i = 0; i < points.size(); ++i) {
        xy(static_cast<Eigen::Index>(i), 0) = points[i].x_mm;
        xy(static_cast<Eigen::Index>(i), 1) = points[i].y_mm;
    }
    const auto circle = fit_circle(xy);
    if (!circle) {
        throw CsvError(
            first_line, {},
            calibration_message("no_circle",
                                QT_TRANSLATE_NOOP("Calibration",
                                                  "the points at orientation %1 (%2) lie on a line "
                                                  "or repeat: no circle through them; touch 3 or "
                                                  "more distinct points around the bore"),
                                {orientation_arg("orientation_deg", orientation),
                                 message_arg("lines", describe_lines(lines))}));
    }

    OrientationFit fit;
    fit.circle = *circle;
    fit.points = points.size();
    fit.worst_residual_mm = -1.0;
    std::vector<double> angles(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const RingPoint& point = points[i];
        const double dx = point.x_mm - circle->center_x_mm;
        const double dy = point.y_mm - circle->center_y_mm;
        angles[i] = std::atan2(dy, dx);
        const double residual = std::abs(std::hypot(dx, dy) - circle->radius_mm);
        if (residual > fit.worst_residual_mm) {
            fit.worst_residual_mm = residual;
            fit.worst_line = point.line;
        }
    }
    std::sort(angles.begin(), angles.end());
    double largest_gap = angles.front() + 2.0 * kPi - angles.back();
    for (std::size_t i = 1; i < angles.size(); ++i) {
        largest_gap = std::max(largest_gap, angles[i] - angles[i - 1]);
    }
    fit.largest_gap_rad = largest_gap;
    return fit;
}

RingCentre combine_orientations(const std::array<std::optional<CircleFit>, 2>& fits) {
    const auto& fit0 = fits[0];
    const auto& fit180 = fits[1];
    RingCentre centre;
    if (fit0 && fit180) {
        // The convention of docs/cli.md, "Ring gauge": ball centre = recorded +
        // runout at 0 deg, recorded - runout at 180 deg. The recorded circles are
        // then centred at C - r and C + r: the gauge centre C is their mean, the
        // runout r half of (180 - 0).
        centre.center_x_mm = 0.5 * (fit0->center_x_mm + fit180->center_x_mm);
        centre.center_y_mm = 0.5 * (fit0->center_y_mm + fit180->center_y_mm);
        centre.runout_x_mm = 0.5 * (fit180->center_x_mm - fit0->center_x_mm);
        centre.runout_y_mm = 0.5 * (fit180->center_y_mm - fit0->center_y_mm);
        centre.mean_radius_mm = 0.5 * (fit0->radius_mm + fit180->radius_mm);
    } else {
        const CircleFit& fit = fit0 ? *fit0 : *fit180;
        centre.center_x_mm = fit.center_x_mm;
        centre.center_y_mm = fit.center_y_mm;
        centre.mean_radius_mm = fit.radius_mm;
    }
    return centre;
}

DirectionalRadius directional_radii(std::span<const RingPoint> points,
                                    const std::array<std::optional<CircleFit>, 2>& fits,
                                    double gauge_radius_mm) {
    std::array<double, 4> sum{};
    std::array<int, 4> count{};
    // Orientation by orientation, as the fits were made.
    for (std::size_t o = 0; o < fits.size(); ++o) {
        if (!fits[o]) continue;
        for (const auto& point : points) {
            if (orientation_index(point.orientation_deg) != o) continue;
            const double dx = point.x_mm - fits[o]->center_x_mm;
            const double dy = point.y_mm - fits[o]->center_y_mm;
            // The recorded point less its orientation's centre is the ball centre
            // less the gauge centre (the runout cancels); the effective radius is
            // the gauge radius less that distance (docs/cli.md, "Ring gauge").
            if (const auto sector = touch_direction(dx, dy)) {
                sum[static_cast<std::size_t>(*sector)] += gauge_radius_mm - std::hypot(dx, dy);
                ++count[static_cast<std::size_t>(*sector)];
            }
        }
    }
    constexpr std::array<std::optional<double> DirectionalRadius::*, 4> kSlots = {
        &DirectionalRadius::x_plus_mm, &DirectionalRadius::x_minus_mm,
        &DirectionalRadius::y_plus_mm, &DirectionalRadius::y_minus_mm};
    DirectionalRadius radii;
    for (std::size_t i = 0; i < kSlots.size(); ++i) {
        if (count[i] > 0) radii.*kSlots[i] = sum[i] / count[i];
    }
    return radii;
}

std::vector<CalibrationWarning> orientation_warnings(const OrientationFit& fit,
                                                     std::size_t orientation) {
    std::vector<CalibrationWarning> warnings;
    if (fit.largest_gap_rad > kPi) {
        warnings.push_back(warning(
            CalibrationWarningCode::points_one_side, Severity::warning,
            QT_TRANSLATE_NOOP("Calibration",
                              "the points at %1 cover only %2 of the bore (all on one side): the "
                              "centre across that side is poorly determined; touch around the "
                              "whole bore (X+, X-, Y+, Y-)"),
            {orientation_arg("orientation_deg", orientation),
             significant_arg("covered_deg", ArgKind::angle_deg,
                             (2.0 * kPi - fit.largest_gap_rad) * 180.0 / kPi, 3)}));
    }
    if (fit.points == 3) {
        warnings.push_back(warning(
            CalibrationWarningCode::exact_fit, Severity::info,
            QT_TRANSLATE_NOOP("Calibration",
                              "3 points at %1: the circle passes through them exactly, so the "
                              "residual shows nothing; a fourth point checks the touches"),
            {orientation_arg("orientation_deg", orientation)}));
    }
    return warnings;
}

std::optional<CalibrationWarning> runout_warning(double runout_x_mm, double runout_y_mm,
                                                 double limit_mm) {
    const double runout_mm = std::hypot(runout_x_mm, runout_y_mm);
    if (!(runout_mm > limit_mm)) return std::nullopt;
    return warning(CalibrationWarningCode::large_runout, Severity::warning,
                   QT_TRANSLATE_NOOP("Calibration",
                                     "stylus runout %1 (x %2, y %3) exceeds %4: set the stylus on "
                                     "centre, and check that the spindle orients repeatably"),
                   {mm("runout_mm", runout_mm), mm("runout_x_mm", runout_x_mm),
                    mm("runout_y_mm", runout_y_mm), mm("limit_mm", limit_mm)});
}

CalibrationWarning single_orientation_warning(std::size_t given_orientation) {
    return warning(CalibrationWarningCode::single_orientation, Severity::warning,
                   QT_TRANSLATE_NOOP("Calibration",
                                     "only orientation %1 given: no runout. The centre is that of "
                                     "the %1 circle and is off the gauge centre by the stylus "
                                     "runout; touch the same points at %2 to separate the two"),
                   {orientation_arg("orientation_deg", given_orientation),
                    orientation_arg("missing_orientation_deg", 1 - given_orientation)});
}

std::optional<CalibrationWarning> residual_warning(double residual_mm, std::size_t line,
                                                   double limit_mm) {
    if (!(residual_mm > limit_mm)) return std::nullopt;
    if (line == 0) {
        return warning(CalibrationWarningCode::large_residual, Severity::warning,
                       QT_TRANSLATE_NOOP("Calibration",
                                         "a point is %1 off the fitted circle (limit %2): clean "
                                         "the gauge and the stylus, check the gauge is clamped, "
                                         "and repeat the touch"),
                       {mm("residual_mm", residual_mm), mm("limit_mm", limit_mm)});
    }
    return warning(CalibrationWarningCode::large_residual, Severity::warning,
                   QT_TRANSLATE_NOOP("Calibration",
                                     "the point on line %1 is %2 off the fitted circle (limit %3): "
                                     "clean the gauge and the stylus, check the gauge is clamped, "
                                     "and repeat the touch"),
                   {arg("line", ArgKind::integer, static_cast<double>(line)),
                    mm("residual_mm", residual_mm), mm("limit_mm", limit_mm)});
}

RingCalibration calibrate_ring(std::span<const RingPoint> points,
                               const RingCalibrationOptions& options) {
    const auto by_orientation = split_by_orientation(points);
    RingCalibration result;
    auto& warnings = result.warnings;
    double worst_residual_mm = -1.0;
    std::size_t worst_line = 0;
    for (std::size_t o = 0; o < by_orientation.size(); ++o) {
        if (by_orientation[o].empty()) continue;
        const OrientationFit fit = fit_orientation(by_orientation[o], o);
        result.fits[o] = fit.circle;
        if (fit.worst_residual_mm > worst_residual_mm) {
            worst_residual_mm = fit.worst_residual_mm;
            worst_line = fit.worst_line;
        }
        for (auto& w : orientation_warnings(fit, o)) warnings.push_back(std::move(w));
    }

    const RingCentre centre = combine_orientations(result.fits);
    result.center_x_mm = centre.center_x_mm;
    result.center_y_mm = centre.center_y_mm;
    result.runout_x_mm = centre.runout_x_mm;
    result.runout_y_mm = centre.runout_y_mm;
    if (centre.runout_x_mm && centre.runout_y_mm) {
        if (auto w =
                runout_warning(*centre.runout_x_mm, *centre.runout_y_mm, options.runout_limit_mm)) {
            warnings.push_back(std::move(*w));
        }
    } else {
        warnings.push_back(single_orientation_warning(result.fits[0] ? 0 : 1));
    }

    // Domain.md, "Calibration": effective ball radius = gauge radius minus the
    // distance from the centre to the trigger points (the trigger points of a bore
    // lie inside it, by the ball radius plus the pretravel and delay travel).
    const double gauge_radius_mm = options.gauge_diameter_mm / 2.0;
    result.effective_radius_mm = gauge_radius_mm - centre.mean_radius_mm;
    if (!(result.effective_radius_mm > 0.0)) {
        throw InputError(calibration_message(
            "radius_outside_gauge",
            QT_TRANSLATE_NOOP("Calibration",
                              "the touches lie on a circle of radius %1, not inside the gauge of "
                              "radius %2 (diameter %3): the effective ball radius would not be "
                              "positive; check the gauge diameter"),
            {mm("radius_mm", centre.mean_radius_mm), mm("gauge_radius_mm", gauge_radius_mm),
             mm("gauge_diameter_mm", options.gauge_diameter_mm)}));
    }
    result.radius_by_direction = directional_radii(points, result.fits, gauge_radius_mm);

    result.residual_max_mm = std::max(worst_residual_mm, 0.0);
    if (auto w = residual_warning(result.residual_max_mm, worst_line, options.residual_limit_mm)) {
        warnings.push_back(std::move(*w));
    }
    return result;
}

LengthCalibration calibrate_length(const LengthCalibrationInput& input) {
    if (input.trigger_z_mm.empty()) {
        throw InputError(calibration_message(
            "no_trigger_z",
            QT_TRANSLATE_NOOP("Calibration", "no trigger Z given; touch the surface at least once"),
            {}));
    }
    LengthCalibration result;
    result.touches = input.trigger_z_mm.size();
    const auto [low, high] =
        std::minmax_element(input.trigger_z_mm.begin(), input.trigger_z_mm.end());
    result.trigger_z_range_mm = *high - *low;
    double sum = 0.0;
    for (const double z : input.trigger_z_mm) sum += z;
    result.trigger_z_mean_mm = sum / static_cast<double>(result.touches);

    // Domain.md, "Calibration", "Length" (sign: Z up, see the header).
    result.effective_length_mm =
        input.active_length_mm + result.trigger_z_mean_mm - input.surface_z_mm;
    if (!(result.effective_length_mm > 0.0)) {
        throw InputError(calibration_message(
            "length_not_positive",
            QT_TRANSLATE_NOOP("Calibration",
                              "effective length %1 is not positive: with Z up, the trigger Z plus "
                              "the active length offset must lie above the surface Z"),
            {mm("effective_length_mm", result.effective_length_mm)}));
    }
    if (input.nominal_length_mm) {
        // A wear offset adds to the nominal (geometry) length.
        result.wear_mm = result.effective_length_mm - *input.nominal_length_mm;
        if (std::abs(*result.wear_mm) > input.wear_limit_mm) {
            result.warnings.push_back(warning(
                CalibrationWarningCode::length_wear, Severity::warning,
                QT_TRANSLATE_NOOP("Calibration",
                                  "the effective length differs from the nominal %1 by %2 (limit "
                                  "%3): check the nominal, the surface Z and the stylus"),
                {mm("nominal_length_mm", *input.nominal_length_mm), mm("wear_mm", *result.wear_mm),
                 mm("limit_mm", input.wear_limit_mm)}));
        }
    }
    return result;
}

}  // namespace probecycle
