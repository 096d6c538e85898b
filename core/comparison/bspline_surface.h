#pragma once

// Tensor-product B-spline surfaces fitted to scattered points (The NURBS Book,
// Piegl and Tiller, 2nd ed.: basis functions and derivatives A2.2-A2.3,
// evenly spaced knots (see uniform_knots()), least-squares surface approximation
// section 9.4; point projection by Newton iteration, section 6.1):
//   S(u, v) = sum_i sum_j N_i,p(u) N_j,q(v) C_ij,   (u, v) in [0, 1]^2.
// The points' parameters are their projections onto their best-fit plane, so
// the surface is a graph over that plane (every comparison surface is: a
// part's face seen from the side the probe comes from). A best-fit plane
// within 15 degrees of a machine plane (XY, YZ, ZX) is replaced by that plane
// with the machine axes as u and v: the parameters are then machine
// coordinates, and a polynomial surface z = f(x, y) of degree (3, 3) is
// reproduced exactly by a bicubic fit (a tilted plane would make the height
// over it a non-polynomial function of the parameters).
//
// The fit minimises sum_k |S(u_k, v_k) - P_k|^2 + lambda * J, where J sums
// the squared jumps of the p-th derivative across the interior knots, row by
// row of the control net (and of the q-th across the columns). J is zero for
// every polynomial surface of degree (p, q), so a bicubic fit reproduces any
// bicubic polynomial surface exactly, while J keeps the system regular where
// a knot span holds no point.

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace probecycle {

struct SurfaceFitOptions {
    int degree{3};  // p = q
    // Control points per direction; by default as many as the data have
    // points per direction (the net follows the point density; see
    // control_counts()).
    std::optional<int> controls_u;
    std::optional<int> controls_v;
    // lambda, relative: the jump rows are scaled to the data rows' size.
    double smoothing{1e-6};
    // The parameter domain reaches this fraction of the points' extent
    // beyond them on each side, so a point a few micrometres outside the
    // outermost sample still projects square onto the surface.
    double margin{0.02};
    // The side the surface's normal faces (S_u x S_v points this way): the
    // plan's mean outward normal. Zero: the best-fit plane's normal as found.
    Eigen::Vector3d facing{Eigen::Vector3d::Zero()};
};

// The control net for `count` points spread over an extent of
// `extent_u` x `extent_v`: a tenth more per direction than the points have
// there, at least degree + 1 and at most 48 each (a 17 x 13 grid gives
// 19 x 14; 10,000 points over 80 x 60 mm give 48 x 48).
std::pair<int, int> control_counts(std::size_t count, double extent_u, double extent_v, int degree);

// A point, its first and second partial derivatives at (u, v).
struct SurfacePoint {
    Eigen::Vector3d s{Eigen::Vector3d::Zero()};
    Eigen::Vector3d su{Eigen::Vector3d::Zero()};
    Eigen::Vector3d sv{Eigen::Vector3d::Zero()};
    Eigen::Vector3d suu{Eigen::Vector3d::Zero()};
    Eigen::Vector3d suv{Eigen::Vector3d::Zero()};
    Eigen::Vector3d svv{Eigen::Vector3d::Zero()};
    // Unit normal S_u x S_v / |S_u x S_v|.
    Eigen::Vector3d normal() const;
};

// The closest point of the surface to a point.
struct SurfaceProjection {
    double u{0.0};
    double v{0.0};
    Eigen::Vector3d foot{Eigen::Vector3d::Zero()};
    Eigen::Vector3d normal{Eigen::Vector3d::Zero()};  // unit, at the foot
    double distance_mm{0.0};                          // signed: (P - foot) . normal
    bool inside{true};                                // false: the foot is on the domain's edge
    bool converged{true};
};

struct SurfaceFitResiduals {
    double rms_mm{0.0};
    double max_mm{0.0};  // largest |normal distance| of a point from the surface
};

class BSplineSurface {
  public:
    // Fits the surface; InputError for fewer than (degree + 1)^2 points,
    // points that do not span a plane, or a system that cannot be solved.
    static BSplineSurface fit(const std::vector<Eigen::Vector3d>& points,
                              const SurfaceFitOptions& options = {});

    Eigen::Vector3d point(double u, double v) const;
    // Derivatives up to second order (the normal needs the first only).
    SurfacePoint evaluate(double u, double v) const;
    // (u, v) of a point's projection onto the best-fit plane of the fitted
    // points: the parameterisation the fit used.
    Eigen::Vector2d plane_parameters(const Eigen::Vector3d& p) const;
    // Newton iteration on (S - P) . S_u = 0, (S - P) . S_v = 0 from the
    // point's plane parameters, kept in the domain.
    SurfaceProjection project(const Eigen::Vector3d& p) const;

    int degree() const { return degree_; }
    int controls_u() const { return static_cast<int>(knots_u_.size()) - degree_ - 1; }
    int controls_v() const { return static_cast<int>(knots_v_.size()) - degree_ - 1; }
    const std::vector<double>& knots_u() const { return knots_u_; }
    const std::vector<double>& knots_v() const { return knots_v_; }
    // Distances of the fitted points from the surface, along its normal at
    // their parameters.
    const SurfaceFitResiduals& residuals() const { return residuals_; }

  private:
    int degree_{3};
    std::vector<double> knots_u_;
    std::vector<double> knots_v_;
    // Control points, row i (u) major: controls_(i * controls_v() + j).
    std::vector<Eigen::Vector3d> controls_;
    // The parameter plane: origin, axes, and the affine map to [0, 1].
    Eigen::Vector3d origin_{Eigen::Vector3d::Zero()};
    Eigen::Vector3d axis_u_{Eigen::Vector3d::UnitX()};
    Eigen::Vector3d axis_v_{Eigen::Vector3d::UnitY()};
    double u_offset_{0.0};
    double u_scale_{1.0};
    double v_offset_{0.0};
    double v_scale_{1.0};
    SurfaceFitResiduals residuals_;
};

}  // namespace probecycle
