#include "core/comparison/c_axis.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/common/input_error.h"
#include "core/comparison/comparison_message.h"

namespace probecycle {

namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

// Two faces closer than this to parallel give a poorly defined corner.
constexpr double kParallelWarning_deg = 30.0;
// Smallest over largest in-plane spread below this: the touches nearly lie
// on a line, the plane's tilt about that line is poorly known.
constexpr double kCollinearWarning = 0.1;
// Below these the plane or the corner is not defined at all.
constexpr double kCollinearError = 1e-6;
constexpr double kParallelError = 1e-6;

Eigen::Vector3d table_point(const Eigen::Vector3d& machine, const CAxisSetup& setup) {
    return machine - Eigen::Vector3d(setup.x_mm, setup.y_mm, 0.0);
}

Message at_angle(const char* code, const char* text, std::vector<MessageArg> args) {
    return comparison_message(code, text, std::move(args));
}

FacePlane fit_face(BlockFace face, const std::vector<Eigen::Vector3d>& points,
                   const Eigen::Vector3d& block_centroid, double angle_deg) {
    FacePlane plane;
    plane.face = face;
    plane.touches = points.size();
    for (const Eigen::Vector3d& p : points) plane.centroid += p;
    plane.centroid /= static_cast<double>(points.size());
    Eigen::Matrix3Xd centred(3, static_cast<Eigen::Index>(points.size()));
    for (std::size_t k = 0; k < points.size(); ++k) {
        centred.col(static_cast<Eigen::Index>(k)) = points[k] - plane.centroid;
    }
    // Domain: the normal is the singular vector of the smallest singular value.
    const Eigen::JacobiSVD<Eigen::Matrix3Xd> svd(centred, Eigen::ComputeFullU);
    const Eigen::Vector3d singular = svd.singularValues();
    plane.spread_ratio = singular(0) > 0.0 ? singular(1) / singular(0) : 0.0;
    if (!(plane.spread_ratio > kCollinearError)) {
        throw InputError(at_angle(
            "face_on_a_line",
            QT_TRANSLATE_NOOP("Comparison",
                              "face %1 at C = %2: the touches lie on a line and define no "
                              "plane; touch the face at points spread over it"),
            {text_arg("face", to_string(face)), arg("angle_deg", ArgKind::angle_deg, angle_deg)}));
    }
    plane.normal = svd.matrixU().col(2);
    // Away from the centroid of all the block's touches: outward at a convex corner.
    if (plane.normal.dot(plane.centroid - block_centroid) < 0.0) plane.normal = -plane.normal;
    double sum_sq = 0.0;
    for (const Eigen::Vector3d& p : points) {
        const double r = (p - plane.centroid).dot(plane.normal);
        sum_sq += r * r;
        plane.max_mm = std::max(plane.max_mm, std::abs(r));
    }
    plane.rms_mm = std::sqrt(sum_sq / static_cast<double>(points.size()));
    if (points.size() > 3) {
        plane.sigma_mm = std::sqrt(sum_sq / static_cast<double>(points.size() - 3));
    }
    return plane;
}

// The block's pose from its touches (machine coordinates): planes, corner,
// and F in table coordinates. Rotation: the polar factor of [nA nB nC]
// (the nearest orthonormal matrix, by SVD), which turns with the block.
BlockPose block_pose(const std::vector<BlockTouch>& touches, const CAxisSetup& setup,
                     double angle_deg) {
    std::array<std::vector<Eigen::Vector3d>, 3> by_face;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const BlockTouch& t : touches) {
        by_face[static_cast<std::size_t>(t.face)].push_back(t.point);
        centroid += t.point;
    }
    centroid /= static_cast<double>(touches.size());
    BlockPose pose;
    Eigen::Matrix3d normals;
    Eigen::Vector3d offsets;
    for (std::size_t f = 0; f < 3; ++f) {
        pose.faces[f] = fit_face(static_cast<BlockFace>(f), by_face[f], centroid, angle_deg);
        normals.row(static_cast<Eigen::Index>(f)) = pose.faces[f].normal.transpose();
        offsets(static_cast<Eigen::Index>(f)) = pose.faces[f].normal.dot(pose.faces[f].centroid);
    }
    if (!(std::abs(normals.determinant()) > kParallelError)) {
        throw InputError(at_angle(
            "faces_do_not_meet",
            QT_TRANSLATE_NOOP("Comparison",
                              "block at C = %1: the three faces' planes do not meet in one "
                              "point (two of them are parallel); touch three faces of a corner"),
            {arg("angle_deg", ArgKind::angle_deg, angle_deg)}));
    }
    pose.corner = normals.partialPivLu().solve(offsets);
    const Eigen::JacobiSVD<Eigen::Matrix3d> polar(normals.transpose(),
                                                  Eigen::ComputeFullU | Eigen::ComputeFullV);
    pose.pose.topLeftCorner<3, 3>() = polar.matrixU() * polar.matrixV().transpose();
    pose.pose.topRightCorner<3, 1>() = table_point(pose.corner, setup);
    return pose;
}

// E = R(theta)^-1 F_theta F_0^-1, read as six numbers: the skew part's
// angles and the translation.
Vector6d errors_of(const BlockPose& zero, const BlockPose& turned, const CAxisSetup& setup) {
    const Eigen::Matrix4d e =
        table_rotation(setup.angle_deg).inverse() * turned.pose * zero.pose.inverse();
    Vector6d out;
    out << 0.5 * (e(2, 1) - e(1, 2)), 0.5 * (e(0, 2) - e(2, 0)), 0.5 * (e(1, 0) - e(0, 1)), e(0, 3),
        e(1, 3), e(2, 3);
    return out;
}

void add_face_warnings(const BlockPose& pose, double angle_deg,
                       std::vector<CAxisWarning>& warnings) {
    const MessageArg angle = arg("angle_deg", ArgKind::angle_deg, angle_deg);
    for (const FacePlane& face : pose.faces) {
        const MessageArg name = text_arg("face", to_string(face.face));
        if (face.spread_ratio < kCollinearWarning) {
            warnings.push_back(
                {CAxisWarningCode::face_points_collinear, Severity::warning,
                 comparison_message(
                     "face_points_collinear",
                     QT_TRANSLATE_NOOP("Comparison",
                                       "face %1 at C = %2: the touches nearly lie on a line "
                                       "(spread ratio %3); the face's tilt about that line is "
                                       "poorly known"),
                     {name, angle,
                      significant_arg("spread_ratio", ArgKind::number, face.spread_ratio, 2)})});
        }
        if (face.max_mm > kPlaneResidualWarning_mm) {
            warnings.push_back(
                {CAxisWarningCode::large_plane_residual, Severity::warning,
                 comparison_message(
                     "large_plane_residual",
                     QT_TRANSLATE_NOOP("Comparison",
                                       "face %1 at C = %2: a touch lies %3 off the face's "
                                       "plane (above %4); a chip, a burr or a bad touch?"),
                     {name, angle,
                      significant_arg("residual_mm", ArgKind::length_mm, face.max_mm, 3),
                      arg("limit_mm", ArgKind::length_mm, kPlaneResidualWarning_mm)})});
        }
    }
    for (std::size_t a = 0; a < 3; ++a) {
        for (std::size_t b = a + 1; b < 3; ++b) {
            const double cosine = std::abs(pose.faces[a].normal.dot(pose.faces[b].normal));
            const double angle_between =
                std::acos(std::min(1.0, cosine)) * 180.0 / std::numbers::pi;
            if (angle_between < kParallelWarning_deg) {
                warnings.push_back(
                    {CAxisWarningCode::faces_nearly_parallel, Severity::warning,
                     comparison_message(
                         "faces_nearly_parallel",
                         QT_TRANSLATE_NOOP("Comparison",
                                           "faces %1 and %2 at C = %3 meet at %4 (below %5): "
                                           "the corner is poorly defined"),
                         {text_arg("face", to_string(pose.faces[a].face)),
                          text_arg("other_face", to_string(pose.faces[b].face)), angle,
                          arg("between_deg", ArgKind::angle_deg, angle_between, 1),
                          arg("limit_deg", ArgKind::angle_deg, kParallelWarning_deg)})});
            }
        }
    }
}

}  // namespace

Eigen::Matrix<double, 6, 1> CAxisErrors::vector() const {
    Vector6d v;
    v << ex_rad, ey_rad, ez_rad, dx_mm, dy_mm, dz_mm;
    return v;
}

CAxisErrors CAxisErrors::from(const Eigen::Matrix<double, 6, 1>& v) {
    return {v(0), v(1), v(2), v(3), v(4), v(5)};
}

const char* to_string(CAxisWarningCode code) {
    switch (code) {
        case CAxisWarningCode::face_points_collinear:
            return "face_points_collinear";
        case CAxisWarningCode::faces_nearly_parallel:
            return "faces_nearly_parallel";
        case CAxisWarningCode::face_three_touches:
            return "face_three_touches";
        case CAxisWarningCode::large_plane_residual:
            return "large_plane_residual";
    }
    return "unknown";
}

Eigen::Matrix4d error_transform(const CAxisErrors& e) {
    Eigen::Matrix4d m;
    m << 1.0, -e.ez_rad, e.ey_rad, e.dx_mm,  //
        e.ez_rad, 1.0, -e.ex_rad, e.dy_mm,   //
        -e.ey_rad, e.ex_rad, 1.0, e.dz_mm,   //
        0.0, 0.0, 0.0, 1.0;
    return m;
}

Eigen::Matrix4d table_rotation(double angle_deg) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() =
        Eigen::AngleAxisd(angle_deg * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ())
            .toRotationMatrix();
    return m;
}

Eigen::Vector3d correct_turned_point(const Eigen::Vector3d& machine_point,
                                     const CAxisErrors& errors, const CAxisSetup& setup) {
    const Eigen::Matrix4d r = table_rotation(setup.angle_deg);
    const Eigen::Matrix4d correction = r * error_transform(errors).inverse() * r.inverse();
    const Eigen::Vector4d p = table_point(machine_point, setup).homogeneous();
    return (correction * p).head<3>() + Eigen::Vector3d(setup.x_mm, setup.y_mm, 0.0);
}

Eigen::Matrix<double, 1, 6> correction_sensitivity(const Eigen::Vector3d& machine_point,
                                                   const Eigen::Vector3d& direction,
                                                   const CAxisSetup& setup) {
    // d(R E^-1 R^-1 P')/d(errors) at E = I is -R (eps x y + delta), with
    // y = R^-1 P' (table coordinates); along n: -(y x m) . eps - m . delta,
    // m = R^T n.
    const Eigen::Matrix3d r = table_rotation(setup.angle_deg).topLeftCorner<3, 3>();
    const Eigen::Vector3d y = r.transpose() * table_point(machine_point, setup);
    const Eigen::Vector3d m = r.transpose() * direction;
    Eigen::Matrix<double, 1, 6> row;
    row.head<3>() = -y.cross(m).transpose();
    row.tail<3>() = -m.transpose();
    return row;
}

CAxisIdentification identify_c_axis(const std::vector<BlockTouch>& at_zero,
                                    const std::vector<BlockTouch>& turned,
                                    const CAxisSetup& setup) {
    CAxisIdentification out;
    out.at_zero = block_pose(at_zero, setup, 0.0);
    out.turned = block_pose(turned, setup, setup.angle_deg);
    out.errors = CAxisErrors::from(errors_of(out.at_zero, out.turned, setup));
    add_face_warnings(out.at_zero, 0.0, out.warnings);
    add_face_warnings(out.turned, setup.angle_deg, out.warnings);

    // Uncertainty: each touch moved along its face's normal by its face's
    // standard deviation, independently; the errors' covariance is
    // sum_k sigma_k^2 J_k J_k^T with J_k by central differences (the map is
    // smooth and nearly linear over micrometres).
    bool known = true;
    for (const BlockPose* pose : {&out.at_zero, &out.turned}) {
        for (const FacePlane& face : pose->faces) known = known && face.sigma_mm.has_value();
    }
    if (!known) {
        out.warnings.push_back(
            {CAxisWarningCode::face_three_touches, Severity::info,
             comparison_message("face_three_touches",
                                QT_TRANSLATE_NOOP("Comparison",
                                                  "a face has only 3 touches: its plane passes "
                                                  "through them, so the C-axis errors' "
                                                  "uncertainty is unknown; touch each face 6 "
                                                  "times"),
                                {})});
        return out;
    }
    constexpr double kStep_mm = 1e-4;
    const auto jacobian_pass = [&](const std::vector<BlockTouch>& touches, const BlockPose& pose,
                                   bool is_turned) {
        const double angle = is_turned ? setup.angle_deg : 0.0;
        const auto errors_with = [&](const std::vector<BlockTouch>& moved) {
            const BlockPose moved_pose = block_pose(moved, setup, angle);
            return is_turned ? errors_of(out.at_zero, moved_pose, setup)
                             : errors_of(moved_pose, out.turned, setup);
        };
        std::vector<BlockTouch> moved = touches;
        for (std::size_t k = 0; k < touches.size(); ++k) {
            const FacePlane& face = pose.faces[static_cast<std::size_t>(touches[k].face)];
            moved[k].point = touches[k].point + kStep_mm * face.normal;
            const Vector6d plus = errors_with(moved);
            moved[k].point = touches[k].point - kStep_mm * face.normal;
            const Vector6d minus = errors_with(moved);
            moved[k].point = touches[k].point;
            const Vector6d j = (plus - minus) / (2.0 * kStep_mm);
            const double sigma = *face.sigma_mm;
            out.covariance += sigma * sigma * j * j.transpose();
        }
    };
    jacobian_pass(at_zero, out.at_zero, false);
    jacobian_pass(turned, out.turned, true);
    out.uncertainty = CAxisErrors::from(out.covariance.diagonal().cwiseSqrt());
    return out;
}

}  // namespace probecycle
