#include "core/lab/calibration.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/common/csv_reader.h"
#include "core/common/number_format.h"

namespace probecycle {

namespace {

constexpr double kPi = std::numbers::pi;
// An orientation is 0 or 180 deg; allow for a file written with rounding.
constexpr double kOrientationTolerance_deg = 1e-6;

std::string mm(double value_mm) {
    return format_number(value_mm, 4) + " mm";
}

constexpr std::array<const char*, 2> kOrientationNames = {"0 deg", "180 deg"};

}  // namespace

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
            throw CsvError(row.line, "orientation_deg",
                           format_number(point.orientation_deg) +
                               " is not allowed: the spindle orientation is 0 or 180");
        }
        points.push_back(point);
    }
    return points;
}

RingCalibration calibrate_ring(std::span<const RingPoint> points,
                               const RingCalibrationOptions& options) {
    if (points.empty()) throw CsvError(0, {}, "no points; a ring needs 3 or more per orientation");
    std::array<std::vector<const RingPoint*>, 2> by_orientation;
    for (const auto& point : points) {
        const auto index = orientation_index(point.orientation_deg);
        if (!index) {
            throw CsvError(point.line, "orientation_deg",
                           format_number(point.orientation_deg) +
                               " is not allowed: the spindle orientation is 0 or 180");
        }
        by_orientation[*index].push_back(&point);
    }

    RingCalibration result;
    auto& warnings = result.warnings;
    const double gauge_radius_mm = options.gauge_diameter_mm / 2.0;

    struct WorstPoint {
        double residual_mm{-1.0};
        std::size_t line{0};
    } worst;
    std::array<double, 4> radius_sum{};
    std::array<int, 4> radius_count{};

    for (std::size_t o = 0; o < 2; ++o) {
        const auto& group = by_orientation[o];
        if (group.empty()) continue;
        std::vector<std::size_t> lines;
        for (const auto* point : group) lines.push_back(point->line);
        if (group.size() < 3) {
            throw CsvError(lines.front(), {},
                           "orientation " + std::string(kOrientationNames[o]) + " has only " +
                               std::to_string(group.size()) +
                               (group.size() == 1 ? " point" : " points") + " (" +
                               describe_lines(lines) +
                               "); a circle needs 3 or more per orientation (typically 4: X+, X-, "
                               "Y+, Y-)");
        }
        Eigen::MatrixX2d xy(static_cast<Eigen::Index>(group.size()), 2);
        for (std::size_t i = 0; i < group.size(); ++i) {
            xy(static_cast<Eigen::Index>(i), 0) = group[i]->x_mm;
            xy(static_cast<Eigen::Index>(i), 1) = group[i]->y_mm;
        }
        const auto fit = fit_circle(xy);
        if (!fit) {
            throw CsvError(lines.front(), {},
                           "the points at orientation " + std::string(kOrientationNames[o]) + " (" +
                               describe_lines(lines) +
                               ") lie on a line or repeat: no circle through them; touch 3 or "
                               "more distinct points around the bore");
        }
        result.fits[o] = fit;

        // Angles about the fitted centre: spread, direction sectors, worst residual.
        std::vector<double> angles;
        for (const auto* point : group) {
            const double dx = point->x_mm - fit->center_x_mm;
            const double dy = point->y_mm - fit->center_y_mm;
            const double distance = std::hypot(dx, dy);
            angles.push_back(std::atan2(dy, dx));
            const double residual = std::abs(distance - fit->radius_mm);
            if (residual > worst.residual_mm) worst = {residual, point->line};
            // The recorded point less its orientation's centre is the ball centre
            // less the gauge centre (the runout cancels): domain.md, "Calibration",
            // "effective ball radius ... gauge radius minus the distance from
            // centre to trigger point".
            if (const auto sector = touch_direction(dx, dy)) {
                radius_sum[static_cast<std::size_t>(*sector)] += gauge_radius_mm - distance;
                ++radius_count[static_cast<std::size_t>(*sector)];
            }
        }
        std::sort(angles.begin(), angles.end());
        double largest_gap = angles.front() + 2.0 * kPi - angles.back();
        for (std::size_t i = 1; i < angles.size(); ++i) {
            largest_gap = std::max(largest_gap, angles[i] - angles[i - 1]);
        }
        if (largest_gap > kPi) {
            warnings.push_back(
                {CalibrationWarningCode::points_one_side, Severity::warning,
                 "the points at " + std::string(kOrientationNames[o]) + " cover only " +
                     format_number((2.0 * kPi - largest_gap) * 180.0 / kPi, 3) +
                     " deg of the bore (all on one side): the centre across that side is poorly "
                     "determined; touch around the whole bore (X+, X-, Y+, Y-)"});
        }
        if (group.size() == 3) {
            warnings.push_back(
                {CalibrationWarningCode::exact_fit, Severity::info,
                 "3 points at " + std::string(kOrientationNames[o]) +
                     ": the circle passes through them exactly, so the residual shows nothing; "
                     "a fourth point checks the touches"});
        }
    }

    const auto& fit0 = result.fits[0];
    const auto& fit180 = result.fits[1];
    double mean_radius_mm = 0.0;
    if (fit0 && fit180) {
        // Issue 4: ball centre = recorded + runout at 0 deg, recorded - runout at
        // 180 deg. The recorded circles are then centred at C - r and C + r: the
        // gauge centre C is their mean, the runout r half of (180 - 0).
        result.center_x_mm = 0.5 * (fit0->center_x_mm + fit180->center_x_mm);
        result.center_y_mm = 0.5 * (fit0->center_y_mm + fit180->center_y_mm);
        result.runout_x_mm = 0.5 * (fit180->center_x_mm - fit0->center_x_mm);
        result.runout_y_mm = 0.5 * (fit180->center_y_mm - fit0->center_y_mm);
        mean_radius_mm = 0.5 * (fit0->radius_mm + fit180->radius_mm);
        const double runout_mm = std::hypot(*result.runout_x_mm, *result.runout_y_mm);
        if (runout_mm > options.runout_limit_mm) {
            warnings.push_back(
                {CalibrationWarningCode::large_runout, Severity::warning,
                 "stylus runout " + mm(runout_mm) + " (x " + mm(*result.runout_x_mm) + ", y " +
                     mm(*result.runout_y_mm) + ") exceeds " + mm(options.runout_limit_mm) +
                     ": set the stylus on centre, and check that the spindle orients "
                     "repeatably"});
        }
    } else {
        const std::size_t given = fit0 ? 0 : 1;
        const auto& fit = fit0 ? fit0 : fit180;
        result.center_x_mm = fit->center_x_mm;
        result.center_y_mm = fit->center_y_mm;
        mean_radius_mm = fit->radius_mm;
        warnings.push_back(
            {CalibrationWarningCode::single_orientation, Severity::warning,
             "only orientation " + std::string(kOrientationNames[given]) +
                 " given: no runout. The centre is that of the " + kOrientationNames[given] +
                 " circle and is off the gauge centre by the stylus runout; touch the same points "
                 "at " +
                 kOrientationNames[1 - given] + " to separate the two"});
    }

    // Domain.md, "Calibration": effective ball radius = gauge radius minus the
    // distance from the centre to the trigger points (the trigger points of a bore
    // lie inside it, by the ball radius plus the pretravel and delay travel).
    result.effective_radius_mm = gauge_radius_mm - mean_radius_mm;
    if (!(result.effective_radius_mm > 0.0)) {
        throw std::invalid_argument(
            "the touches lie on a circle of radius " + mm(mean_radius_mm) +
            ", not inside the gauge of radius " + mm(gauge_radius_mm) + " (diameter " +
            mm(options.gauge_diameter_mm) +
            "): the effective ball radius would not be positive; check the gauge diameter");
    }
    constexpr std::array<std::optional<double> DirectionalRadius::*, 4> kSlots = {
        &DirectionalRadius::x_plus_mm, &DirectionalRadius::x_minus_mm,
        &DirectionalRadius::y_plus_mm, &DirectionalRadius::y_minus_mm};
    for (std::size_t i = 0; i < kSlots.size(); ++i) {
        if (radius_count[i] > 0) {
            result.radius_by_direction.*kSlots[i] = radius_sum[i] / radius_count[i];
        }
    }

    result.residual_max_mm = std::max(worst.residual_mm, 0.0);
    if (result.residual_max_mm > options.residual_limit_mm) {
        warnings.push_back({CalibrationWarningCode::large_residual, Severity::warning,
                            (worst.line > 0 ? "the point on line " + std::to_string(worst.line)
                                            : std::string("a point")) +
                                " is " + mm(result.residual_max_mm) +
                                " off the fitted circle (limit " + mm(options.residual_limit_mm) +
                                "): clean the gauge and the stylus, check the gauge is clamped, "
                                "and repeat the touch"});
    }
    return result;
}

LengthCalibration calibrate_length(const LengthCalibrationInput& input) {
    if (input.trigger_z_mm.empty()) {
        throw std::invalid_argument("no trigger Z given; touch the surface at least once");
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
        throw std::invalid_argument(
            "effective length " + mm(result.effective_length_mm) +
            " is not positive: with Z up, the trigger Z plus the active length offset must lie "
            "above the surface Z");
    }
    if (input.nominal_length_mm) {
        // A wear offset adds to the nominal (geometry) length.
        result.wear_mm = result.effective_length_mm - *input.nominal_length_mm;
        if (std::abs(*result.wear_mm) > input.wear_limit_mm) {
            result.warnings.push_back(
                {CalibrationWarningCode::length_wear, Severity::warning,
                 "the effective length differs from the nominal " + mm(*input.nominal_length_mm) +
                     " by " + mm(*result.wear_mm) + " (limit " + mm(input.wear_limit_mm) +
                     "): check the nominal, the surface Z and the stylus"});
        }
    }
    return result;
}

}  // namespace probecycle
