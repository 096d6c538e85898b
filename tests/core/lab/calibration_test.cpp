#include "core/lab/calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <ostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/csv_reader.h"
#include "core/common/input_error.h"
#include "tests/core/common/message_checks.h"

namespace probecycle {
namespace {

constexpr double kExact = 1e-9;  // mm: exact synthetic data, only rounding
constexpr double kPi = std::numbers::pi;

struct RingCaseName {
    template <typename T>
    std::string operator()(const testing::TestParamInfo<T>& case_info) const {
        return case_info.param.name;
    }
};

// A ring-gauge measurement built from the convention of docs/cli.md, "Ring
// gauge": the ball centre touches the bore at gauge radius - ball radius (per
// direction), and the machine records ball centre - runout at 0 deg, ball
// centre + runout at 180 deg.
struct SyntheticRing {
    double center_x_mm{100.0};
    double center_y_mm{-200.0};
    double gauge_diameter_mm{50.0};
    double runout_x_mm{0.003};
    double runout_y_mm{-0.002};
    // Effective ball radius at angle a (rad); constant unless a test lobes it.
    double ball_radius_mm{2.995};
    double lobe_x_mm{0.0};  // added along X, subtracted along Y: a 2-lobe probe
    std::vector<double> angles_deg{0.0, 180.0, 90.0, 270.0};

    double ball_radius_at(double angle_rad) const {
        return ball_radius_mm + lobe_x_mm * std::cos(2.0 * angle_rad);
    }

    std::vector<RingPoint> points(bool with_0 = true, bool with_180 = true) const {
        std::vector<RingPoint> out;
        std::size_t line = 2;
        for (const double orientation : {0.0, 180.0}) {
            if ((orientation == 0.0 && !with_0) || (orientation == 180.0 && !with_180)) continue;
            const double sign = orientation == 0.0 ? -1.0 : 1.0;  // recorded = ball -/+ runout
            for (const double angle_deg : angles_deg) {
                const double a = angle_deg * kPi / 180.0;
                const double rho = gauge_diameter_mm / 2.0 - ball_radius_at(a);
                out.push_back({orientation, center_x_mm + rho * std::cos(a) + sign * runout_x_mm,
                               center_y_mm + rho * std::sin(a) + sign * runout_y_mm, line++});
            }
        }
        return out;
    }
};

RingCalibrationOptions gauge(double diameter_mm) {
    RingCalibrationOptions options;
    options.gauge_diameter_mm = diameter_mm;
    return options;
}

bool has_warning(const std::vector<CalibrationWarning>& warnings, CalibrationWarningCode code) {
    for (const auto& w : warnings) {
        if (w.code == code) return true;
    }
    return false;
}

// ---------------------------------------------------------------------------
// Least-squares circle

struct CircleCase {
    const char* name;
    double cx, cy, r;
    std::vector<double> angles_deg;
};
// Test names in ctest show the case name, not the bytes.
void PrintTo(const CircleCase& c, std::ostream* os) {
    *os << c.name;
}

class CircleFitExact : public testing::TestWithParam<CircleCase> {};

TEST_P(CircleFitExact, RecoversTheCircle) {
    const auto& c = GetParam();
    Eigen::MatrixX2d xy(static_cast<Eigen::Index>(c.angles_deg.size()), 2);
    for (std::size_t i = 0; i < c.angles_deg.size(); ++i) {
        const double a = c.angles_deg[i] * kPi / 180.0;
        xy.row(static_cast<Eigen::Index>(i)) << c.cx + c.r * std::cos(a), c.cy + c.r * std::sin(a);
    }
    const auto fit = fit_circle(xy);
    ASSERT_TRUE(fit);
    EXPECT_NEAR(fit->center_x_mm, c.cx, kExact);
    EXPECT_NEAR(fit->center_y_mm, c.cy, kExact);
    EXPECT_NEAR(fit->radius_mm, c.r, kExact);
    EXPECT_NEAR(fit->residual_max_mm, 0.0, kExact);
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(
    Circles, CircleFitExact,
    testing::Values(
        CircleCase{"FourAxisPoints",     0.0,      0.0,     22.005, {0, 90, 180, 270}},
        CircleCase{"ThreePoints",        12.3,     -45.6,   9.5,    {10, 130, 250}},
        CircleCase{"EightPoints",        1.0,      2.0,     3.0,    {0, 45, 90, 135, 180, 225, 270, 315}},
        CircleCase{"MachineCoordinates", -350.123, 512.701, 22.005, {0, 90, 180, 270}},
        CircleCase{"HalfCircle",         5.0,      5.0,     40.0,   {0, 60, 120, 180}},
        CircleCase{"SmallBore",          -0.5,     0.25,    0.2,    {0, 100, 200, 300}}),
    RingCaseName{});
// clang-format on

TEST(CircleFit, RandomCirclesFixedSeed) {
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> centre(-500.0, 500.0);
    std::uniform_real_distribution<double> radius(0.5, 100.0);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi);
    for (int trial = 0; trial < 2000; ++trial) {
        const double cx = centre(rng), cy = centre(rng), r = radius(rng);
        Eigen::MatrixX2d xy(5, 2);
        for (Eigen::Index i = 0; i < 5; ++i) {
            // Spread the points around the circle so that none is degenerate.
            const double a = angle(rng) * 0.2 + static_cast<double>(i) * 2.0 * kPi / 5.0;
            xy.row(i) << cx + r * std::cos(a), cy + r * std::sin(a);
        }
        const auto fit = fit_circle(xy);
        ASSERT_TRUE(fit) << "trial " << trial;
        EXPECT_NEAR(fit->center_x_mm, cx, 1e-9 * (1.0 + std::abs(cx))) << "trial " << trial;
        EXPECT_NEAR(fit->center_y_mm, cy, 1e-9 * (1.0 + std::abs(cy))) << "trial " << trial;
        EXPECT_NEAR(fit->radius_mm, r, 1e-9 * (1.0 + r)) << "trial " << trial;
    }
}

TEST(CircleFit, NoisyPointsWithinTolerance) {
    // 1 um (1 sigma) noise on 16 points: the centre and radius scatter by about
    // sigma * sqrt(2 / n) = 0.35 um; 2 um is more than five of those.
    std::mt19937 rng(42);
    std::normal_distribution<double> noise(0.0, 0.001);
    const double cx = 10.0, cy = -20.0, r = 22.0;
    Eigen::MatrixX2d xy(16, 2);
    for (Eigen::Index i = 0; i < 16; ++i) {
        const double a = static_cast<double>(i) * 2.0 * kPi / 16.0;
        xy.row(i) << cx + r * std::cos(a) + noise(rng), cy + r * std::sin(a) + noise(rng);
    }
    const auto fit = fit_circle(xy);
    ASSERT_TRUE(fit);
    EXPECT_NEAR(fit->center_x_mm, cx, 0.002);
    EXPECT_NEAR(fit->center_y_mm, cy, 0.002);
    EXPECT_NEAR(fit->radius_mm, r, 0.002);
    EXPECT_GT(fit->residual_max_mm, 0.0);
    EXPECT_LT(fit->residual_max_mm, 0.005);
}

TEST(CircleFit, DegenerateInputHasNoCircle) {
    Eigen::MatrixX2d two(2, 2);
    two << 0, 0, 1, 1;
    EXPECT_FALSE(fit_circle(two));
    Eigen::MatrixX2d line(4, 2);
    line << 0, 0, 1, 1, 2, 2, 3, 3;
    EXPECT_FALSE(fit_circle(line));
    Eigen::MatrixX2d repeated(3, 2);
    repeated << 1, 1, 1, 1, 2, 3;
    EXPECT_FALSE(fit_circle(repeated));
    Eigen::MatrixX2d same(4, 2);
    same.setConstant(5.0);
    EXPECT_FALSE(fit_circle(same));
}

TEST(CircleFit, TakesAnyEigenExpression) {
    // A block of a larger, row-major matrix binds to the Ref without a copy by hand.
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> table(4, 3);
    table << 0, 10, 0, 0, 0, 10, 0, -10, 0, 0, 0, -10;
    const auto fit = fit_circle(table.rightCols<2>());
    ASSERT_TRUE(fit);
    EXPECT_NEAR(fit->radius_mm, 10.0, kExact);
}

TEST(TouchDirection, SectorsOfFortyFiveDegrees) {
    EXPECT_EQ(touch_direction(1.0, 0.0), 0);
    EXPECT_EQ(touch_direction(-1.0, 0.0), 1);
    EXPECT_EQ(touch_direction(0.0, 1.0), 2);
    EXPECT_EQ(touch_direction(0.0, -1.0), 3);
    EXPECT_EQ(touch_direction(1.0, 0.4), 0);    // 21.8 deg
    EXPECT_EQ(touch_direction(-1.0, -0.4), 1);  // wraps through 180 deg
    EXPECT_FALSE(touch_direction(1.0, 1.0));    // the diagonal belongs to none
    EXPECT_FALSE(touch_direction(1.0, 0.5));    // 26.6 deg
}

// ---------------------------------------------------------------------------
// Ring gauge

TEST(RingCalibration, ExactDataGivesCentreRunoutAndRadius) {
    const SyntheticRing ring;
    const auto points = ring.points();
    const auto result = calibrate_ring(points, gauge(ring.gauge_diameter_mm));
    EXPECT_NEAR(result.center_x_mm, ring.center_x_mm, kExact);
    EXPECT_NEAR(result.center_y_mm, ring.center_y_mm, kExact);
    ASSERT_TRUE(result.runout_x_mm && result.runout_y_mm);
    EXPECT_NEAR(*result.runout_x_mm, ring.runout_x_mm, kExact);
    EXPECT_NEAR(*result.runout_y_mm, ring.runout_y_mm, kExact);
    EXPECT_NEAR(result.effective_radius_mm, ring.ball_radius_mm, kExact);
    EXPECT_NEAR(result.residual_max_mm, 0.0, kExact);
    for (const auto& r :
         {result.radius_by_direction.x_plus_mm, result.radius_by_direction.x_minus_mm,
          result.radius_by_direction.y_plus_mm, result.radius_by_direction.y_minus_mm}) {
        ASSERT_TRUE(r);
        EXPECT_NEAR(*r, ring.ball_radius_mm, kExact);
    }
    ASSERT_TRUE(result.fits[0] && result.fits[1]);
    // Recorded circles sit at C - r (0 deg) and C + r (180 deg).
    EXPECT_NEAR(result.fits[0]->center_x_mm, ring.center_x_mm - ring.runout_x_mm, kExact);
    EXPECT_NEAR(result.fits[1]->center_y_mm, ring.center_y_mm + ring.runout_y_mm, kExact);
    EXPECT_TRUE(result.warnings.empty()) << result.warnings.front().text();
}

TEST(RingCalibration, RunoutSignFollowsTheIssueConvention) {
    // Recorded at 0 deg = ball - runout, so a positive runout puts the 0 deg
    // circle at lower X than the 180 deg circle: runout = (c180 - c0) / 2 > 0.
    SyntheticRing ring;
    ring.runout_x_mm = 0.004;
    ring.runout_y_mm = 0.0;
    const auto result = calibrate_ring(ring.points(), gauge(50.0));
    ASSERT_TRUE(result.runout_x_mm);
    EXPECT_GT(*result.runout_x_mm, 0.0);
    EXPECT_LT(result.fits[0]->center_x_mm, result.fits[1]->center_x_mm);
}

TEST(RingCalibration, DirectionalRadiiOfALobedProbe) {
    // Ball radius 2.996 along X, 2.994 along Y: the mean is 2.995, and the
    // fitted circle misses each point by the lobe, 1 um.
    SyntheticRing ring;
    ring.lobe_x_mm = 0.001;
    ring.angles_deg = {0, 45, 90, 135, 180, 225, 270, 315};
    const auto result = calibrate_ring(ring.points(), gauge(50.0));
    EXPECT_NEAR(result.effective_radius_mm, 2.995, kExact);
    EXPECT_NEAR(*result.radius_by_direction.x_plus_mm, 2.996, kExact);
    EXPECT_NEAR(*result.radius_by_direction.x_minus_mm, 2.996, kExact);
    EXPECT_NEAR(*result.radius_by_direction.y_plus_mm, 2.994, kExact);
    EXPECT_NEAR(*result.radius_by_direction.y_minus_mm, 2.994, kExact);
    EXPECT_NEAR(result.residual_max_mm, 0.001, kExact);
    EXPECT_NEAR(result.center_x_mm, ring.center_x_mm, kExact);
}

TEST(RingCalibration, DirectionsOnlyWherePointsExist) {
    SyntheticRing ring;
    ring.angles_deg = {0, 120, 240};  // X+ and two points between the axes
    const auto result = calibrate_ring(ring.points(), gauge(50.0));
    EXPECT_TRUE(result.radius_by_direction.x_plus_mm);
    EXPECT_FALSE(result.radius_by_direction.x_minus_mm);
    EXPECT_FALSE(result.radius_by_direction.y_plus_mm);
    EXPECT_FALSE(result.radius_by_direction.y_minus_mm);
    EXPECT_TRUE(has_warning(result.warnings, CalibrationWarningCode::exact_fit));
}

TEST(RingCalibration, NoisyTouchesWithinTolerance) {
    // 0.5 um (1 sigma) repeatability on 8 points per orientation, 50 trials with
    // a fixed seed: every result within 1.5 um (centre, runout) and 1 um
    // (radius) - about six standard errors (sigma * sqrt(2/n) / sqrt(2) for the
    // mean of two centres, 0.18 um).
    std::mt19937 rng(42);
    std::normal_distribution<double> noise(0.0, 0.0005);
    SyntheticRing ring;
    ring.angles_deg = {0, 45, 90, 135, 180, 225, 270, 315};
    for (int trial = 0; trial < 50; ++trial) {
        auto points = ring.points();
        for (auto& p : points) {
            p.x_mm += noise(rng);
            p.y_mm += noise(rng);
        }
        const auto result = calibrate_ring(points, gauge(50.0));
        EXPECT_NEAR(result.center_x_mm, ring.center_x_mm, 0.0015);
        EXPECT_NEAR(result.center_y_mm, ring.center_y_mm, 0.0015);
        EXPECT_NEAR(*result.runout_x_mm, ring.runout_x_mm, 0.0015);
        EXPECT_NEAR(*result.runout_y_mm, ring.runout_y_mm, 0.0015);
        EXPECT_NEAR(result.effective_radius_mm, ring.ball_radius_mm, 0.001);
        EXPECT_FALSE(has_warning(result.warnings, CalibrationWarningCode::large_residual));
    }
}

TEST(RingCalibration, SingleOrientationHasNoRunoutAndSaysSo) {
    const SyntheticRing ring;
    const auto result = calibrate_ring(ring.points(true, false), gauge(50.0));
    EXPECT_FALSE(result.runout_x_mm);
    EXPECT_FALSE(result.runout_y_mm);
    // The centre is the 0 deg circle's: the gauge centre less the runout.
    EXPECT_NEAR(result.center_x_mm, ring.center_x_mm - ring.runout_x_mm, kExact);
    EXPECT_NEAR(result.effective_radius_mm, ring.ball_radius_mm, kExact);
    ASSERT_TRUE(has_warning(result.warnings, CalibrationWarningCode::single_orientation));
    EXPECT_NE(result.warnings.front().text().find("no runout"), std::string::npos);

    const auto only_180 = calibrate_ring(ring.points(false, true), gauge(50.0));
    EXPECT_NEAR(only_180.center_y_mm, ring.center_y_mm + ring.runout_y_mm, kExact);
    EXPECT_TRUE(has_warning(only_180.warnings, CalibrationWarningCode::single_orientation));
}

TEST(RingCalibration, PointsOnOneSideAreFlagged) {
    SyntheticRing ring;
    ring.angles_deg = {0, 30, 60, 90};
    const auto result = calibrate_ring(ring.points(), gauge(50.0));
    EXPECT_TRUE(has_warning(result.warnings, CalibrationWarningCode::points_one_side));
    // The four axis points span the whole bore.
    EXPECT_FALSE(has_warning(calibrate_ring(SyntheticRing{}.points(), gauge(50.0)).warnings,
                             CalibrationWarningCode::points_one_side));
}

TEST(RingCalibration, LargeRunoutIsFlagged) {
    SyntheticRing ring;
    ring.runout_x_mm = 0.012;
    ring.runout_y_mm = 0.0;
    const auto result = calibrate_ring(ring.points(), gauge(50.0));
    EXPECT_TRUE(has_warning(result.warnings, CalibrationWarningCode::large_runout));
    auto options = gauge(50.0);
    options.runout_limit_mm = 0.02;
    EXPECT_FALSE(has_warning(calibrate_ring(ring.points(), options).warnings,
                             CalibrationWarningCode::large_runout));
}

TEST(RingCalibration, LargeResidualNamesTheLine) {
    SyntheticRing ring;
    ring.angles_deg = {0, 45, 90, 135, 180, 225, 270, 315};
    auto points = ring.points();
    points[3].x_mm += 0.02;  // a chip under the stylus
    const auto result = calibrate_ring(points, gauge(50.0));
    ASSERT_TRUE(has_warning(result.warnings, CalibrationWarningCode::large_residual));
    for (const auto& w : result.warnings) {
        if (w.code == CalibrationWarningCode::large_residual) {
            EXPECT_NE(w.text().find("line " + std::to_string(points[3].line)), std::string::npos)
                << w.text();
        }
    }
}

TEST(RingCalibration, GaugeSmallerThanTheTouchesIsAnError) {
    const SyntheticRing ring;
    // The radius (25) given as the diameter.
    EXPECT_THROW(calibrate_ring(ring.points(), gauge(25.0)), std::invalid_argument);
}

struct BadRingCase {
    const char* name;
    std::vector<RingPoint> points;
    std::size_t line;
    const char* says;
};
// Test names in ctest show the case name, not the bytes.
void PrintTo(const BadRingCase& c, std::ostream* os) {
    *os << c.name;
}

class RingCalibrationErrors : public testing::TestWithParam<BadRingCase> {};

TEST_P(RingCalibrationErrors, NameTheLine) {
    const auto& c = GetParam();
    try {
        calibrate_ring(c.points, gauge(50.0));
        FAIL() << "no error";
    } catch (const CsvError& e) {
        EXPECT_EQ(e.line(), c.line) << e.what();
        EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(
    Points, RingCalibrationErrors,
    testing::Values(
        BadRingCase{"OnePoint",       {{0, 22, 0, 2}},                                                2, "only 1 point"},
        BadRingCase{"TwoPoints",      {{0, 22, 0, 2}, {0, -22, 0, 3}},                                2, "only 2 points (lines 2, 3)"},
        BadRingCase{"OneAt180",       {{0, 22, 0, 2}, {0, -22, 0, 3}, {0, 0, 22, 4}, {180, 1, 1, 5}}, 5, "orientation 180 deg"},
        BadRingCase{"OnALine",        {{0, 1, 1, 2}, {0, 2, 2, 3}, {0, 3, 3, 4}},                     2, "lie on a line"},
        BadRingCase{"BadOrientation", {{90, 1, 1, 7}},                                                7, "0 or 180"},
        BadRingCase{"NoPoints",       {},                                                             0, "no points"}),
    RingCaseName{});
// clang-format on

// ---------------------------------------------------------------------------
// CSV

TEST(RingCsv, ParsesCommentsCrlfBomAndAnyColumnOrder) {
    const std::string text =
        "\xEF\xBB\xBF# ring gauge 50.000, probe T12\r\n"
        "x_mm, y_mm ,orientation_deg,note\r\n"
        "\r\n"
        "22.005,0,0,X+\r\n"
        "+1e-3,-22.0,180,Y-\r\n";
    const auto points = parse_ring_csv(text);
    ASSERT_EQ(points.size(), 2u);
    EXPECT_EQ(points[0].line, 4u);
    EXPECT_DOUBLE_EQ(points[0].x_mm, 22.005);
    EXPECT_DOUBLE_EQ(points[1].orientation_deg, 180.0);
    EXPECT_DOUBLE_EQ(points[1].x_mm, 0.001);
    EXPECT_DOUBLE_EQ(points[1].y_mm, -22.0);
    EXPECT_EQ(points[1].line, 5u);
}

struct BadCsvCase {
    const char* name;
    const char* text;
    std::size_t line;
    const char* column;
    const char* says;
};
// Test names in ctest show the case name, not the bytes.
void PrintTo(const BadCsvCase& c, std::ostream* os) {
    *os << c.name;
}

class RingCsvErrors : public testing::TestWithParam<BadCsvCase> {};

TEST_P(RingCsvErrors, NameTheLineAndColumn) {
    const auto& c = GetParam();
    try {
        parse_ring_csv(c.text);
        FAIL() << "no error";
    } catch (const CsvError& e) {
        EXPECT_EQ(e.line(), c.line) << e.what();
        EXPECT_EQ(e.column(), c.column) << e.what();
        EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
        if (c.line > 0) {
            EXPECT_EQ(std::string(e.what()).rfind("line " + std::to_string(c.line), 0), 0u)
                << e.what();
        }
    }
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(
    Files, RingCsvErrors,
    testing::Values(
        BadCsvCase{"Empty",          "",                                            0, "",                "empty"},
        BadCsvCase{"OnlyComments",   "# nothing\n\n",                               0, "",                "empty"},
        BadCsvCase{"HeaderOnly",     "orientation_deg,x_mm,y_mm\n",                 0, "",                "no data"},
        BadCsvCase{"MissingColumn",  "orientation_deg,x_mm\n0,1\n",                 1, "",                "missing column 'y_mm'"},
        BadCsvCase{"Semicolons",     "orientation_deg;x_mm;y_mm\n0;1;2\n",          1, "",                "comma-separated"},
        BadCsvCase{"RepeatedColumn", "orientation_deg,x_mm,y_mm,x_mm\n0,1,2,3\n",   1, "",                "appears twice"},
        BadCsvCase{"TextInNumber",   "orientation_deg,x_mm,y_mm\n0,1,2\n0,abc,2\n", 3, "x_mm",            "'abc' is not a number"},
        BadCsvCase{"EmptyField",     "orientation_deg,x_mm,y_mm\n0,,2\n",           2, "x_mm",            "empty"},
        BadCsvCase{"UnitInNumber",   "orientation_deg,x_mm,y_mm\n0,1mm,2\n",        2, "x_mm",            "'1mm'"},
        BadCsvCase{"NotFinite",      "orientation_deg,x_mm,y_mm\n0,1,nan\n",        2, "y_mm",            "not a number"},
        BadCsvCase{"MissingField",   "orientation_deg,x_mm,y_mm\n0,1\n",            2, "",                "2 fields"},
        BadCsvCase{"DecimalComma",   "orientation_deg,x_mm,y_mm\n0,1,5,2\n",        2, "",                "4 fields"},
        BadCsvCase{"Orientation90",  "orientation_deg,x_mm,y_mm\n# c\n90,1,2\n",    3, "orientation_deg", "0 or 180"}),
    RingCaseName{});
// clang-format on

// ---------------------------------------------------------------------------
// Length

TEST(LengthCalibration, GaugeLineAboveTheSurface) {
    LengthCalibrationInput input;
    input.surface_z_mm = -400.0;
    input.trigger_z_mm = {-249.75};
    const auto result = calibrate_length(input);
    EXPECT_NEAR(result.effective_length_mm, 150.25, kExact);
    EXPECT_FALSE(result.wear_mm);
    EXPECT_EQ(result.touches, 1u);
}

TEST(LengthCalibration, ActiveOffsetAndWearAgainstTheNominal) {
    // Probing with a 150.000 offset active, the recorded Z is the tip's: it
    // reads 0.030 above the 25.000 surface, so the probe is 0.030 longer.
    LengthCalibrationInput input;
    input.surface_z_mm = 25.0;
    input.trigger_z_mm = {25.029, 25.031, 25.030};
    input.active_length_mm = 150.0;
    input.nominal_length_mm = 150.0;
    const auto result = calibrate_length(input);
    EXPECT_NEAR(result.effective_length_mm, 150.030, kExact);
    ASSERT_TRUE(result.wear_mm);
    EXPECT_NEAR(*result.wear_mm, 0.030, kExact);
    EXPECT_NEAR(result.trigger_z_mean_mm, 25.030, kExact);
    EXPECT_NEAR(result.trigger_z_range_mm, 0.002, kExact);
    EXPECT_TRUE(result.warnings.empty());
}

TEST(LengthCalibration, LargeWearIsFlagged) {
    LengthCalibrationInput input;
    input.surface_z_mm = 0.0;
    input.trigger_z_mm = {151.0};
    input.nominal_length_mm = 150.0;
    const auto result = calibrate_length(input);
    ASSERT_EQ(result.warnings.size(), 1u);
    EXPECT_EQ(result.warnings[0].code, CalibrationWarningCode::length_wear);
}

TEST(LengthCalibration, BadInputIsAnError) {
    LengthCalibrationInput none;
    EXPECT_THROW(calibrate_length(none), std::invalid_argument);
    LengthCalibrationInput below;
    below.surface_z_mm = 10.0;
    below.trigger_z_mm = {5.0};
    EXPECT_THROW(calibrate_length(below), std::invalid_argument);
}

// ---------------------------------------------------------------------------
// The steps of calibrate_ring, alone

TEST(RingSteps, SplitByOrientationKeepsTheOrder) {
    const auto by = split_by_orientation(SyntheticRing{}.points());
    ASSERT_EQ(by[0].size(), 4u);
    ASSERT_EQ(by[1].size(), 4u);
    EXPECT_EQ(by[0][0].line, 2u);
    EXPECT_EQ(by[1][3].line, 9u);
    EXPECT_THROW(split_by_orientation({}), CsvError);
    const std::vector<RingPoint> tilted{{45.0, 1.0, 1.0, 3}};
    EXPECT_THROW(split_by_orientation(tilted), CsvError);
}

TEST(RingSteps, FitOrientationGivesTheCircleTheGapAndTheWorstPoint) {
    SyntheticRing ring;
    ring.runout_x_mm = 0.0;
    ring.runout_y_mm = 0.0;
    ring.angles_deg = {0, 45, 90, 135, 180, 225, 270, 315};
    auto points = ring.points(true, false);
    points[2].y_mm += 0.004;  // Y+ (line 4) lies 4 um outside
    const OrientationFit fit = fit_orientation(points, 0);
    EXPECT_EQ(fit.points, 8u);
    EXPECT_NEAR(fit.largest_gap_rad, kPi / 4.0, 1e-3);
    EXPECT_EQ(fit.worst_line, 4u);
    EXPECT_GT(fit.worst_residual_mm, 0.0005);
    EXPECT_NEAR(fit.circle.radius_mm, 25.0 - ring.ball_radius_mm, 0.002);

    // Three points on one side: a 270 deg gap.
    ring.angles_deg = {0, 45, 90};
    const OrientationFit side = fit_orientation(ring.points(true, false), 0);
    EXPECT_NEAR(side.largest_gap_rad, 1.5 * kPi, 1e-9);

    const std::vector<RingPoint> two{{180, 1, 0, 5}, {180, 2, 0, 6}};
    try {
        (void)fit_orientation(two, 1);
        FAIL() << "two points fitted";
    } catch (const CsvError& e) {
        EXPECT_EQ(e.line(), 5u);
        EXPECT_EQ(std::string(e.what()),
                  "line 5: orientation 180 deg has only 2 points (lines 5, 6); a circle needs 3 "
                  "or more per orientation (typically 4: X+, X-, Y+, Y-)");
        test::expect_translatable(e.problem(), {"orientation_deg", "points", "lines"});
    }
}

TEST(RingSteps, CombineOrientationsAveragesTheCentresAndHalvesTheirDifference) {
    const std::array<std::optional<CircleFit>, 2> both{CircleFit{1.0, 2.0, 20.0, 0.0},
                                                       CircleFit{1.004, 1.998, 20.002, 0.0}};
    const RingCentre centre = combine_orientations(both);
    EXPECT_NEAR(centre.center_x_mm, 1.002, kExact);
    EXPECT_NEAR(centre.center_y_mm, 1.999, kExact);
    EXPECT_NEAR(*centre.runout_x_mm, 0.002, kExact);
    EXPECT_NEAR(*centre.runout_y_mm, -0.001, kExact);
    EXPECT_NEAR(centre.mean_radius_mm, 20.001, kExact);

    const std::array<std::optional<CircleFit>, 2> only_180{std::nullopt,
                                                           CircleFit{5.0, 6.0, 7.0, 0.0}};
    const RingCentre single = combine_orientations(only_180);
    EXPECT_EQ(single.center_x_mm, 5.0);
    EXPECT_FALSE(single.runout_x_mm);
    EXPECT_EQ(single.mean_radius_mm, 7.0);
}

TEST(RingSteps, DirectionalRadiiPerSector) {
    const std::vector<RingPoint> points{{0, 20.0, 0.0, 2}, {0, -19.0, 0.0, 3}, {0, 0.0, 21.0, 4}};
    const std::array<std::optional<CircleFit>, 2> fits{CircleFit{0.0, 0.0, 20.0, 0.0},
                                                       std::nullopt};
    const DirectionalRadius radii = directional_radii(points, fits, 25.0);
    EXPECT_NEAR(*radii.x_plus_mm, 5.0, kExact);
    EXPECT_NEAR(*radii.x_minus_mm, 6.0, kExact);
    EXPECT_NEAR(*radii.y_plus_mm, 4.0, kExact);
    EXPECT_FALSE(radii.y_minus_mm);
}

TEST(RingSteps, WarningsAloneWithTheirNumbers) {
    OrientationFit fit;
    fit.points = 3;
    fit.largest_gap_rad = 1.5 * kPi;
    const auto warnings = orientation_warnings(fit, 1);
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_EQ(warnings[0].code, CalibrationWarningCode::points_one_side);
    EXPECT_EQ(warnings[0].text(),
              "the points at 180 deg cover only 90 deg of the bore (all on one side): the centre "
              "across that side is poorly determined; touch around the whole bore (X+, X-, Y+, "
              "Y-)");
    EXPECT_EQ(warnings[1].code, CalibrationWarningCode::exact_fit);

    EXPECT_FALSE(runout_warning(0.003, 0.004, 0.005));
    const auto runout = runout_warning(0.003, 0.004, 0.001);
    ASSERT_TRUE(runout);
    EXPECT_EQ(runout->text(),
              "stylus runout 0.005 mm (x 0.003 mm, y 0.004 mm) exceeds 0.001 mm: set the stylus on "
              "centre, and check that the spindle orients repeatably");
    EXPECT_NEAR(message_values(runout->message).at("runout_mm").get<double>(), 0.005, kExact);

    EXPECT_FALSE(residual_warning(0.004, 7, 0.005));
    EXPECT_NE(residual_warning(0.006, 7, 0.005)->text().find("the point on line 7 is 0.006 mm"),
              std::string::npos);
    EXPECT_EQ(residual_warning(0.006, 0, 0.005)->text().rfind("a point is 0.006 mm", 0), 0u);

    EXPECT_EQ(single_orientation_warning(0).text(),
              "only orientation 0 deg given: no runout. The centre is that of the 0 deg circle "
              "and is off the gauge centre by the stylus runout; touch the same points at 180 deg "
              "to separate the two");
}

// ---------------------------------------------------------------------------
// Messages: every warning and error a code, a template and its numbers named

TEST(CalibrationMessages, EveryWarningNamesItsNumbers) {
    struct Expected {
        CalibrationWarningCode code;
        std::vector<std::string> values;
    };
    std::vector<CalibrationWarning> all;
    SyntheticRing side;
    side.angles_deg = {0, 45, 90};  // on one side, and 3 points
    side.runout_x_mm = 0.02;        // a large runout
    for (auto& w : calibrate_ring(side.points(), gauge(50.0)).warnings) all.push_back(w);
    for (auto& w : calibrate_ring(SyntheticRing{}.points(true, false), gauge(50.0)).warnings) {
        all.push_back(w);
    }
    SyntheticRing chipped;
    chipped.angles_deg = {0, 45, 90, 135, 180, 225, 270, 315};
    auto points = chipped.points();
    points[3].x_mm += 0.02;
    for (auto& w : calibrate_ring(points, gauge(50.0)).warnings) all.push_back(w);
    LengthCalibrationInput length;
    length.trigger_z_mm = {151.0};
    length.nominal_length_mm = 150.0;
    for (auto& w : calibrate_length(length).warnings) all.push_back(w);

    const std::vector<Expected> expected{
        {CalibrationWarningCode::points_one_side, {"orientation_deg", "covered_deg"}},
        {CalibrationWarningCode::exact_fit, {"orientation_deg"}},
        {CalibrationWarningCode::large_runout,
         {"runout_mm", "runout_x_mm", "runout_y_mm", "limit_mm"}},
        {CalibrationWarningCode::single_orientation,
         {"orientation_deg", "missing_orientation_deg"}},
        {CalibrationWarningCode::large_residual, {"line", "residual_mm", "limit_mm"}},
        {CalibrationWarningCode::length_wear, {"nominal_length_mm", "wear_mm", "limit_mm"}},
    };
    for (const Expected& e : expected) {
        bool found = false;
        for (const CalibrationWarning& w : all) {
            if (w.code != e.code) continue;
            found = true;
            EXPECT_EQ(w.message.code, to_string(w.code));
            EXPECT_STREQ(w.message.context, "Calibration");
            test::expect_translatable(w.message, e.values);
            EXPECT_EQ(w.text(), render(w.message));
        }
        EXPECT_TRUE(found) << to_string(e.code);
    }
    // The wear in its own unit, as a number.
    for (const CalibrationWarning& w : all) {
        if (w.code == CalibrationWarningCode::length_wear) {
            EXPECT_NEAR(message_values(w.message).at("wear_mm").get<double>(), 1.0, 1e-9);
        }
    }
}

TEST(CalibrationMessages, RefusalsAreInputErrorsWithTheirNumbers) {
    try {
        (void)calibrate_ring(SyntheticRing{}.points(), gauge(25.0));
        FAIL() << "a gauge smaller than the touches was accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.to_message().code, "radius_outside_gauge");
        test::expect_translatable(e.to_message(),
                                  {"radius_mm", "gauge_radius_mm", "gauge_diameter_mm"});
        EXPECT_EQ(std::string(e.what()).rfind("the touches lie on a circle of radius 22 mm, not "
                                              "inside the gauge of radius 12.5 mm (diameter 25 mm)",
                                              0),
                  0u)
            << e.what();
    }
    LengthCalibrationInput below;
    below.surface_z_mm = 200.0;
    below.trigger_z_mm = {110.0};
    try {
        (void)calibrate_length(below);
        FAIL() << "a negative length was accepted";
    } catch (const InputError& e) {
        test::expect_translatable(e.to_message(), {"effective_length_mm"});
        EXPECT_EQ(std::string(e.what()).rfind("effective length -90 mm is not positive", 0), 0u);
    }
    try {
        (void)calibrate_length(LengthCalibrationInput{});
        FAIL() << "no touch was accepted";
    } catch (const InputError& e) {
        test::expect_translatable(e.to_message(), {});
    }
}

TEST(CalibrationMessages, FileErrorsNameTheLineAsAnArgument) {
    try {
        (void)parse_ring_csv("orientation_deg,x_mm,y_mm\n90,1,2\n");
        FAIL() << "orientation 90 accepted";
    } catch (const CsvError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "line 2, column orientation_deg: 90 is not allowed: the spindle orientation is 0 "
                  "or 180");
        test::expect_translatable(e.problem(), {"orientation_deg"});
        test::expect_translatable(e.to_message(), {"line", "column", "orientation_deg"});
    }
    const std::vector<RingPoint> line{{0, 1, 1, 2}, {0, 2, 2, 3}, {0, 3, 3, 4}};
    try {
        (void)calibrate_ring(line, gauge(50.0));
        FAIL() << "points on a line accepted";
    } catch (const CsvError& e) {
        test::expect_translatable(e.problem(), {"orientation_deg", "lines"});
    }
}

}  // namespace
}  // namespace probecycle
