#include "core/lab/calibration_report.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "core/common/csv_writer.h"

namespace probecycle {

namespace {

// Lengths to 0.1 um (csv_writer.h); the user's inputs exactly as given.
std::string number(double value) {
    return csv_length_mm(value);
}
std::string number(const std::optional<double>& value) {
    return csv_length_mm(value);
}

std::string row(const char* quantity, const std::string& value, const char* unit) {
    return csv_line({quantity, value, unit});
}

constexpr const char* kDirectionNames[] = {"X+", "X-", "Y+", "Y-"};

// A point without a fit for its orientation has no radius or residual.
constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

}  // namespace

std::string calibration_report_csv(const std::optional<RingReportInput>& ring,
                                   const std::optional<LengthReportInput>& length,
                                   const ReportHeader& header, ReportRows rows) {
    std::string csv = report_header_csv("calibration report", "points", header);
    std::vector<CalibrationWarning> warnings;
    if (ring) {
        const RingCalibration& r = ring->result;
        const double gauge_radius_mm = ring->options.gauge_diameter_mm / 2.0;
        csv += "# ring\nquantity,value,unit\n";
        csv += row("gauge_diameter", csv_exact(ring->options.gauge_diameter_mm), "mm");
        csv += row("center_x", number(r.center_x_mm), "mm");
        csv += row("center_y", number(r.center_y_mm), "mm");
        csv += row("runout_x", number(r.runout_x_mm), "mm");
        csv += row("runout_y", number(r.runout_y_mm), "mm");
        std::optional<double> runout;
        if (r.runout_x_mm && r.runout_y_mm) runout = std::hypot(*r.runout_x_mm, *r.runout_y_mm);
        csv += row("runout", number(runout), "mm");
        csv += row("effective_radius", number(r.effective_radius_mm), "mm");
        csv += row("radius_x_plus", number(r.radius_by_direction.x_plus_mm), "mm");
        csv += row("radius_x_minus", number(r.radius_by_direction.x_minus_mm), "mm");
        csv += row("radius_y_plus", number(r.radius_by_direction.y_plus_mm), "mm");
        csv += row("radius_y_minus", number(r.radius_by_direction.y_minus_mm), "mm");
        csv += row("residual_max", number(r.residual_max_mm), "mm");
        csv += row("runout_limit", csv_exact(ring->options.runout_limit_mm), "mm");
        csv += row("residual_limit", csv_exact(ring->options.residual_limit_mm), "mm");

        csv += "\n# fits\norientation_deg,center_x_mm,center_y_mm,radius_mm,residual_max_mm\n";
        for (std::size_t o = 0; o < r.fits.size(); ++o) {
            if (!r.fits[o]) continue;
            const CircleFit& fit = *r.fits[o];
            csv += std::string(o == 0 ? "0" : "180") + ',' + number(fit.center_x_mm) + ',' +
                   number(fit.center_y_mm) + ',' + number(fit.radius_mm) + ',' +
                   number(fit.residual_max_mm) + '\n';
        }

        // Per point: the ball radius there is the gauge radius less the distance
        // from its orientation's centre (the runout cancels), as the core computes it.
        const std::span<const RingPoint> points = ring->points;
        std::vector<double> radius_mm(points.size(), kNoValue);
        std::vector<double> residual_mm(points.size(), kNoValue);
        const auto point_row = [&](std::size_t i) {
            const RingPoint& p = points[i];
            const std::size_t o = orientation_index(p.orientation_deg).value_or(0);
            std::string line = (p.line > 0 ? std::to_string(p.line) : std::string()) + ',' +
                               csv_exact(p.orientation_deg) + ',' + csv_exact(p.x_mm) + ',' +
                               csv_exact(p.y_mm) + ',';
            if (const auto& fit = r.fits[o]) {
                const double dx = p.x_mm - fit->center_x_mm;
                const double dy = p.y_mm - fit->center_y_mm;
                if (const auto sector = touch_direction(dx, dy)) line += kDirectionNames[*sector];
                line += ',' + number(radius_mm[i]) + ',' + number(residual_mm[i]);
            } else {
                line += ",,";
            }
            return line + '\n';
        };
        for (std::size_t i = 0; i < points.size(); ++i) {
            const RingPoint& p = points[i];
            const std::size_t o = orientation_index(p.orientation_deg).value_or(0);
            if (const auto& fit = r.fits[o]) {
                const double distance =
                    std::hypot(p.x_mm - fit->center_x_mm, p.y_mm - fit->center_y_mm);
                radius_mm[i] = gauge_radius_mm - distance;
                residual_mm[i] = distance - fit->radius_mm;
            }
        }
        const char* columns =
            "line,orientation_deg,x_mm,y_mm,direction,effective_radius_mm,residual_mm\n";
        if (summarised(rows, points.size())) {
            csv += "\n# points summary\n" + csv_stats_header();
            csv += csv_stats_row("effective_radius", value_stats(radius_mm));
            csv += csv_stats_row("residual", value_stats(residual_mm));
            const std::vector<std::size_t> largest =
                largest_magnitudes(residual_mm, kReportLargestRows);
            csv +=
                '\n' + csv_largest_heading("points", "residual_mm", largest.size(), points.size());
            csv += columns;
            for (const std::size_t i : largest) csv += point_row(i);
        } else {
            csv += std::string("\n# points\n") + columns;
            for (std::size_t i = 0; i < points.size(); ++i) csv += point_row(i);
        }
        warnings.insert(warnings.end(), r.warnings.begin(), r.warnings.end());
    }
    if (length) {
        const LengthCalibrationInput& in = length->input;
        const LengthCalibration& l = length->result;
        if (ring) csv += '\n';
        csv += "# length\nquantity,value,unit\n";
        csv += row("surface_z", csv_exact(in.surface_z_mm), "mm");
        csv += row("active_length", csv_exact(in.active_length_mm), "mm");
        csv += row("nominal_length",
                   in.nominal_length_mm ? csv_exact(*in.nominal_length_mm) : std::string(), "mm");
        csv += row("touches", std::to_string(l.touches), "");
        csv += row("trigger_z_mean", number(l.trigger_z_mean_mm), "mm");
        csv += row("trigger_z_range", number(l.trigger_z_range_mm), "mm");
        csv += row("effective_length", number(l.effective_length_mm), "mm");
        csv += row("wear", number(l.wear_mm), "mm");
        warnings.insert(warnings.end(), l.warnings.begin(), l.warnings.end());
    }
    if (ring || length) csv += '\n';
    csv += csv_warnings_header();
    for (const CalibrationWarning& w : warnings) {
        csv += csv_warning_row(to_string(w.code), to_string(w.severity), w.text());
    }
    return csv;
}

}  // namespace probecycle
