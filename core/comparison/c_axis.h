#pragma once

// The C axis's six errors from a block's corner touched at C = 0 and after the
// turn (domain: "Identifying the C-axis errors"), and the correction of a
// point measured after the turn (P_ideal = R(theta) E^-1 R(theta)^-1 P').
// Frames: machine coordinates in the files; table coordinates are machine
// coordinates minus (c_x, c_y, 0); R(theta) turns about Z by theta.
// R'(theta) = R(theta) E with the small-angle transform
//   E = [ 1 -ez ey dx ; ez 1 -ex dy ; -ey ex 1 dz ; 0 0 0 1 ].

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/common/message.h"
#include "core/common/severity.h"
#include "core/comparison/comparison_input.h"

namespace probecycle {

struct CAxisSetup {
    double x_mm{0.0};  // the C axis's position in machine X, Y
    double y_mm{0.0};
    double angle_deg{180.0};  // the comparison angle
};

// The six errors (ISO 230-1 EAC, EBC, ECC, EXC, EYC, EZC), or their
// standard uncertainties.
struct CAxisErrors {
    double ex_rad{0.0};
    double ey_rad{0.0};
    double ez_rad{0.0};
    double dx_mm{0.0};
    double dy_mm{0.0};
    double dz_mm{0.0};
    Eigen::Matrix<double, 6, 1> vector() const;
    static CAxisErrors from(const Eigen::Matrix<double, 6, 1>& v);
};

// E as a 4 x 4 homogeneous matrix.
Eigen::Matrix4d error_transform(const CAxisErrors& errors);
// R(theta) as a 4 x 4 homogeneous matrix.
Eigen::Matrix4d table_rotation(double angle_deg);

// A point (machine coordinates) measured after the turn, moved to where an
// ideal C axis would have put it: R E^-1 R^-1 in table coordinates.
Eigen::Vector3d correct_turned_point(const Eigen::Vector3d& machine_point,
                                     const CAxisErrors& errors, const CAxisSetup& setup);
// The derivative of correct_turned_point() with respect to the six errors at
// E = I, projected on `direction`: how a point's deviation along it moves per
// unit of each error (a 1 x 6 row; the columns in CAxisErrors' order).
Eigen::Matrix<double, 1, 6> correction_sensitivity(const Eigen::Vector3d& machine_point,
                                                   const Eigen::Vector3d& direction,
                                                   const CAxisSetup& setup);

struct FacePlane {
    BlockFace face{BlockFace::a};
    Eigen::Vector3d normal{Eigen::Vector3d::Zero()};  // unit, away from the block's centroid
    Eigen::Vector3d centroid{Eigen::Vector3d::Zero()};
    std::size_t touches{0};
    double rms_mm{0.0};  // residuals' RMS
    double max_mm{0.0};  // largest |residual|
    // Standard deviation of a touch about the plane, sqrt(SSR / (n - 3));
    // unknown with 3 touches (the plane passes through them).
    std::optional<double> sigma_mm;
    // Smallest over largest in-plane spread of the touches (0: on a line).
    double spread_ratio{0.0};
};

struct BlockPose {
    std::array<FacePlane, 3> faces;                     // A, B, C
    Eigen::Vector3d corner{Eigen::Vector3d::Zero()};    // machine coordinates
    Eigen::Matrix4d pose{Eigen::Matrix4d::Identity()};  // table coordinates
};

enum class CAxisWarningCode {
    face_points_collinear,
    faces_nearly_parallel,
    face_three_touches,
    large_plane_residual,
};
const char* to_string(CAxisWarningCode code);

struct CAxisWarning {
    CAxisWarningCode code{};
    Severity severity{};
    Message message;  // context "Comparison"
};

struct CAxisIdentification {
    CAxisErrors errors;
    // Standard uncertainties; unknown when a face has only 3 touches.
    std::optional<CAxisErrors> uncertainty;
    Eigen::Matrix<double, 6, 6> covariance{Eigen::Matrix<double, 6, 6>::Zero()};
    BlockPose at_zero;
    BlockPose turned;
    std::vector<CAxisWarning> warnings;
};

// A face whose plane fit leaves residuals above this is worth a look.
constexpr double kPlaneResidualWarning_mm = 0.005;

// Identifies E from the block at C = 0 and after the turn. InputError when a
// face's touches lie on a line or the three planes do not meet in a point.
CAxisIdentification identify_c_axis(const std::vector<BlockTouch>& at_zero,
                                    const std::vector<BlockTouch>& turned, const CAxisSetup& setup);

}  // namespace probecycle
