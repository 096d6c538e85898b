#pragma once

// Probe calibration (docs/cli.md, "The calibration and latency lab"): the
// effective ball radius and the stylus runout from touches in a ring gauge,
// and the effective length from a surface of known Z.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/message.h"
#include "core/common/severity.h"

namespace probecycle {

// --- Least-squares circle ---

struct CircleFit {
    double center_x_mm{0.0};
    double center_y_mm{0.0};
    double radius_mm{0.0};
    double residual_max_mm{0.0};  // largest |distance to centre - radius|
};

// Geometric least-squares circle through the rows (x, y) of `points_mm`
// (minimises the sum of squared radial distances; exact through 3 points).
// Returns nullopt with fewer than 3 distinct points or points on a line.
std::optional<CircleFit> fit_circle(const Eigen::Ref<const Eigen::MatrixX2d>& points_mm);

// --- Ring gauge ---

// One recorded trigger position (the spindle centre the machine recorded).
struct RingPoint {
    double orientation_deg{0.0};  // spindle orientation: 0 or 180
    double x_mm{0.0};
    double y_mm{0.0};
    std::size_t line{0};  // line in the input file, for messages; 0 when typed in
};

enum class CalibrationWarningCode {
    points_one_side,     // all points of an orientation within half the circle
    large_runout,        // stylus runout above the limit
    large_residual,      // a point off the fitted circle by more than the limit
    single_orientation,  // only one orientation: no runout
    exact_fit,           // 3 points: the circle passes through them, nothing to check
    length_wear,         // length differs from the nominal by more than the limit
};
const char* to_string(CalibrationWarningCode code);

struct CalibrationWarning {
    CalibrationWarningCode code{};
    Severity severity{};
    // Code, template (context "Calibration") and the numbers as named
    // arguments; the window translates it, the CLI renders it.
    Message message;
    std::string text() const;  // in English: render(message)
};

struct RingCalibrationOptions {
    double gauge_diameter_mm{50.0};
    // Warning limits. A stylus is set up on centre to a few micrometres; a
    // residual above a few micrometres is dirt, a bad touch or a loose gauge.
    double runout_limit_mm{0.010};
    double residual_limit_mm{0.005};
};

// Effective ball radius at a touch direction, where touches exist there.
struct DirectionalRadius {
    std::optional<double> x_plus_mm;
    std::optional<double> x_minus_mm;
    std::optional<double> y_plus_mm;
    std::optional<double> y_minus_mm;
};

struct RingCalibration {
    // The gauge centre: the mean of the two fitted centres (the runout cancels);
    // with one orientation, that orientation's centre (runout included).
    double center_x_mm{0.0};
    double center_y_mm{0.0};
    // Stylus runout, (centre at 180 - centre at 0) / 2; nullopt with one orientation.
    std::optional<double> runout_x_mm;
    std::optional<double> runout_y_mm;
    // Gauge radius minus the mean fitted radius.
    double effective_radius_mm{0.0};
    DirectionalRadius radius_by_direction;
    double residual_max_mm{0.0};
    // The fitted circles of the recorded points, [0] at 0 deg, [1] at 180 deg
    // (for drawing).
    std::array<std::optional<CircleFit>, 2> fits;
    std::vector<CalibrationWarning> warnings;
};

// Parses `orientation_deg,x_mm,y_mm`. Throws CsvError naming the line
// and column: not a number, an orientation other than 0 or 180.
std::vector<RingPoint> parse_ring_csv(std::string_view text);

// Fits and evaluates, by the steps below. Throws CsvError (naming the lines)
// when an orientation has fewer than 3 points, or its points lie on a line, and
// InputError (a std::invalid_argument) when the fitted radius is not inside the
// gauge (effective radius not positive).
RingCalibration calibrate_ring(std::span<const RingPoint> points,
                               const RingCalibrationOptions& options);

// --- The steps of calibrate_ring, each usable alone ---

// The points of each orientation, [0] at 0 deg and [1] at 180 deg, in their
// order. Throws CsvError with no points, or an orientation other than 0 or 180.
std::array<std::vector<RingPoint>, 2> split_by_orientation(std::span<const RingPoint> points);

// One orientation's circle and how its points sit on it.
struct OrientationFit {
    CircleFit circle;
    std::size_t points{0};
    // The largest angle between neighbouring points about the centre; above
    // pi the points lie on one side of the bore.
    double largest_gap_rad{0.0};
    double worst_residual_mm{0.0};  // the largest |distance to centre - radius|
    std::size_t worst_line{0};      // that point's line (0 when typed in)
};
// Fits the points of orientation `orientation` (0 for 0 deg, 1 for 180 deg).
// Throws CsvError naming their lines with fewer than 3 points, or no circle
// through them.
OrientationFit fit_orientation(std::span<const RingPoint> points, std::size_t orientation);

// The gauge centre and the runout from the fits present (at least one).
struct RingCentre {
    double center_x_mm{0.0};
    double center_y_mm{0.0};
    std::optional<double> runout_x_mm;  // nullopt with one orientation
    std::optional<double> runout_y_mm;
    double mean_radius_mm{0.0};  // of the fitted circles
};
RingCentre combine_orientations(const std::array<std::optional<CircleFit>, 2>& fits);

// The effective ball radius per touch direction: the gauge radius less each
// point's distance from its orientation's centre (the runout cancels), averaged
// over the points in a direction's sector (touch_direction).
DirectionalRadius directional_radii(std::span<const RingPoint> points,
                                    const std::array<std::optional<CircleFit>, 2>& fits,
                                    double gauge_radius_mm);

// The warnings, each with its numbers: points on one side and an exact fit
// (per orientation), a runout over the limit, one orientation only, a point
// off its circle by more than the limit (line 0: "a point").
std::vector<CalibrationWarning> orientation_warnings(const OrientationFit& fit,
                                                     std::size_t orientation);
std::optional<CalibrationWarning> runout_warning(double runout_x_mm, double runout_y_mm,
                                                 double limit_mm);
CalibrationWarning single_orientation_warning(std::size_t given_orientation);
std::optional<CalibrationWarning> residual_warning(double residual_mm, std::size_t line,
                                                   double limit_mm);

// Index into RingCalibration::fits of a spindle orientation: 0 for 0 deg,
// 1 for 180 deg (within a small tolerance), nullopt otherwise.
std::optional<std::size_t> orientation_index(double orientation_deg);

// The sector (within +-22.5 deg) a touch direction falls in, measured from the
// fitted centre: 0 X+, 1 X-, 2 Y+, 3 Y-; nullopt between them.
std::optional<int> touch_direction(double dx_mm, double dy_mm);

// --- Length ---

// Z is positive up, away from the table. The machine records the Z of the
// spindle gauge line at the trigger, less the length offset active while
// probing (0 when none). The probe's effective length is then the recorded
// gauge-line height above the known surface:
//   length = active_length + trigger_z - surface_z
// (the difference between the trigger position and the known surface
// position, taken along the tool axis, so with Z up the trigger is the larger;
// docs/cli.md, "Length"). It includes pretravel and the delay travel at the
// calibration feed, which is why it is "effective".
struct LengthCalibrationInput {
    double surface_z_mm{0.0};
    std::vector<double> trigger_z_mm;  // one or more touches
    double active_length_mm{0.0};
    std::optional<double> nominal_length_mm;  // for the wear
    double wear_limit_mm{0.5};                // warn beyond: wrong nominal, bent stylus
};

struct LengthCalibration {
    double effective_length_mm{0.0};
    std::optional<double> wear_mm;  // effective - nominal, as a wear offset adds to it
    double trigger_z_mean_mm{0.0};
    double trigger_z_range_mm{0.0};  // max - min over the touches
    std::size_t touches{0};
    std::vector<CalibrationWarning> warnings;
};

// Throws InputError (a std::invalid_argument) with no touch, or when the length is
// not positive.
LengthCalibration calibrate_length(const LengthCalibrationInput& input);

}  // namespace probecycle
