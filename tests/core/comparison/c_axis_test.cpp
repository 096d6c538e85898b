// C-axis identification on exact poses, the correction, and bad blocks.

#include "core/comparison/c_axis.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/common/input_error.h"

namespace probecycle {
namespace {

// A block's corner at `corner` (machine), faces +X, +Y, +Z, 6 touches each.
std::vector<BlockTouch> block(const Eigen::Vector3d& corner, int per_face = 6) {
    std::vector<BlockTouch> touches;
    for (int k = 0; k < per_face; ++k) {
        const double s = 3.0 + 7.0 * (k % 3);
        const double t = 4.0 + 9.0 * (k % 2) + 6.0 * (k / 3);
        touches.push_back({BlockFace::a, corner + Eigen::Vector3d(0, -s, -t), 0});
        touches.push_back({BlockFace::b, corner + Eigen::Vector3d(-s, 0, -t), 0});
        touches.push_back({BlockFace::c, corner + Eigen::Vector3d(-s, -t, 0), 0});
    }
    return touches;
}

// Moves touches (machine) as the real turn does: table R(theta) E.
std::vector<BlockTouch> turned(std::vector<BlockTouch> touches, const CAxisErrors& errors,
                               const CAxisSetup& setup) {
    const Eigen::Vector3d axis(setup.x_mm, setup.y_mm, 0.0);
    const Eigen::Matrix4d m = table_rotation(setup.angle_deg) * error_transform(errors);
    for (BlockTouch& t : touches) {
        t.point = (m * (t.point - axis).homogeneous()).head<3>() + axis;
    }
    return touches;
}

TEST(CAxisTest, ExactPosesGiveTheSixErrorsBack) {
    const CAxisSetup setup{150.0, -40.0, 180.0};
    const CAxisErrors truth{12e-6, -7e-6, 31e-6, 0.0042, -0.0013, 0.0027};
    const std::vector<BlockTouch> zero = block({110.0, 20.0, 15.0});
    const CAxisIdentification found = identify_c_axis(zero, turned(zero, truth, setup), setup);
    const Eigen::Matrix<double, 6, 1> error = found.errors.vector() - truth.vector();
    for (int k = 0; k < 3; ++k) EXPECT_LT(std::abs(error(k)), 1e-7) << k;  // 0.1 urad
    for (int k = 3; k < 6; ++k) EXPECT_LT(std::abs(error(k)), 1e-4) << k;  // 0.1 um
    EXPECT_TRUE(found.warnings.empty());
    ASSERT_TRUE(found.uncertainty.has_value());
    EXPECT_LT(found.uncertainty->vector().maxCoeff(), 1e-9);
    // The corner where the faces meet, normals outward.
    EXPECT_LT((found.at_zero.corner - Eigen::Vector3d(110.0, 20.0, 15.0)).norm(), 1e-9);
    EXPECT_NEAR(found.at_zero.faces[0].normal.x(), 1.0, 1e-12);
    EXPECT_NEAR(found.at_zero.faces[2].normal.z(), 1.0, 1e-12);
}

TEST(CAxisTest, AnotherAngleAndAnExactAxis) {
    const CAxisSetup setup{0.0, 0.0, 90.0};
    const std::vector<BlockTouch> zero = block({-60.0, 35.0, 5.0});
    const CAxisIdentification found = identify_c_axis(zero, turned(zero, {}, setup), setup);
    EXPECT_LT(found.errors.vector().cwiseAbs().maxCoeff(), 1e-10);
}

TEST(CAxisTest, TheCorrectionUndoesTheRealTurn) {
    const CAxisSetup setup{200.0, 100.0, 180.0};
    const CAxisErrors errors{20e-6, -25e-6, 30e-6, 0.004, -0.003, 0.002};
    const Eigen::Vector3d at_zero(120.0, 90.0, 22.0);  // on the table at C = 0
    const Eigen::Vector3d axis(200.0, 100.0, 0.0);
    const Eigen::Matrix4d ideal = table_rotation(180.0);
    const Eigen::Matrix4d real = ideal * error_transform(errors);
    const Eigen::Vector3d measured = (real * (at_zero - axis).homogeneous()).head<3>() + axis;
    const Eigen::Vector3d expected = (ideal * (at_zero - axis).homogeneous()).head<3>() + axis;
    EXPECT_LT((correct_turned_point(measured, errors, setup) - expected).norm(), 1e-12);
    // The sensitivity is the derivative of the correction along a direction.
    const Eigen::Vector3d n = Eigen::Vector3d(0.2, -0.1, 1.0).normalized();
    const auto row = correction_sensitivity(measured, n, setup);
    for (int k = 0; k < 6; ++k) {
        Eigen::Matrix<double, 6, 1> step = Eigen::Matrix<double, 6, 1>::Zero();
        step(k) = 1e-6;
        const double plus = correct_turned_point(measured, CAxisErrors::from(step), setup).dot(n);
        const double minus = correct_turned_point(measured, CAxisErrors::from(-step), setup).dot(n);
        EXPECT_NEAR(row(k), (plus - minus) / 2e-6, 1e-6) << k;
    }
}

TEST(CAxisTest, ThreeTouchesAFaceLeaveTheUncertaintyUnknown) {
    const CAxisSetup setup{0.0, 0.0, 180.0};
    const std::vector<BlockTouch> zero = block({50.0, 50.0, 0.0}, 3);
    const CAxisIdentification found = identify_c_axis(zero, turned(zero, {}, setup), setup);
    EXPECT_FALSE(found.uncertainty.has_value());
    ASSERT_EQ(found.warnings.size(), 1u);
    EXPECT_EQ(found.warnings[0].code, CAxisWarningCode::face_three_touches);
}

TEST(CAxisTest, WarnsOfCollinearTouchesAndNearlyParallelFaces) {
    const CAxisSetup setup{0.0, 0.0, 180.0};
    std::vector<BlockTouch> zero = block({50.0, 50.0, 0.0});
    // Face C's touches nearly on a line along X.
    int k = 0;
    for (BlockTouch& t : zero) {
        if (t.face == BlockFace::c) t.point = {40.0 - 3.0 * k, 45.0 + 0.05 * (k % 2), 0.0}, ++k;
    }
    CAxisIdentification found = identify_c_axis(zero, turned(zero, {}, setup), setup);
    bool collinear = false;
    for (const auto& w : found.warnings) {
        collinear = collinear || w.code == CAxisWarningCode::face_points_collinear;
    }
    EXPECT_TRUE(collinear);

    // Face B tilted 20 degrees from face A.
    std::vector<BlockTouch> wedge = block({50.0, 50.0, 0.0});
    const Eigen::Matrix3d tilt =
        Eigen::AngleAxisd(70.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    for (BlockTouch& t : wedge) {
        if (t.face == BlockFace::b) {
            t.point = Eigen::Vector3d(50, 50, 0) + tilt * (t.point - Eigen::Vector3d(50, 50, 0));
        }
    }
    found = identify_c_axis(wedge, turned(wedge, {}, setup), setup);
    bool parallel = false;
    for (const auto& w : found.warnings) {
        parallel = parallel || w.code == CAxisWarningCode::faces_nearly_parallel;
    }
    EXPECT_TRUE(parallel);
}

TEST(CAxisTest, RefusesTouchesOnALineAndFacesThatDoNotMeet) {
    const CAxisSetup setup{0.0, 0.0, 180.0};
    std::vector<BlockTouch> line = block({50.0, 50.0, 0.0});
    int k = 0;
    for (BlockTouch& t : line) {
        if (t.face == BlockFace::a) t.point = {50.0, 40.0 - 2.0 * k++, -5.0};
    }
    EXPECT_THROW((void)identify_c_axis(line, line, setup), InputError);
    std::vector<BlockTouch> parallel = block({50.0, 50.0, 0.0});
    for (BlockTouch& t : parallel) {
        if (t.face == BlockFace::b) t.point = {t.point.y(), t.point.x() - 20.0, t.point.z()};
    }
    EXPECT_THROW((void)identify_c_axis(parallel, parallel, setup), InputError);
}

}  // namespace
}  // namespace probecycle
