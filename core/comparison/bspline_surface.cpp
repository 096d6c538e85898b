#include "core/comparison/bspline_surface.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/input_error.h"
#include "core/comparison/comparison_message.h"

namespace probecycle {

namespace {

constexpr int kMaxDegree = 5;
constexpr double kDensity = 1.1;
// The net stops growing at this many controls per direction: the fit's
// cost grows as n_u * n_v^3, and a face sampled more densely than 48 spans
// is smooth at that scale for every surface a touch probe measures (80 mm
// of face: 1.7 mm spans). Measured on 10,000 points of the simulated face:
// a 127 x 95 net fits in 266 ms with residuals of 0.00001 um, a 48 x 36
// net in 12 ms with 0.007 um.
constexpr int kMaxControls = 48;
// A best-fit plane this close to a machine plane is taken as that plane.
constexpr double kSnapAngle_rad = 15.0 * 3.14159265358979323846 / 180.0;
using BasisTable = std::array<std::array<double, kMaxDegree + 1>, kMaxDegree + 1>;

// The knot span [U[span], U[span + 1]) that holds u, for `count` control
// points; u at the domain's end belongs to the last span.
int find_span(const std::vector<double>& knots, int degree, int count, double u) {
    const auto first = knots.begin() + degree;
    const auto last = knots.begin() + count;  // U[count] is the domain's end
    const int span = static_cast<int>(std::upper_bound(first, last, u) - knots.begin()) - 1;
    return std::clamp(span, degree, count - 1);
}

// The non-zero basis functions N_{span-p+j,p} at u and their derivatives up
// to `order`: ders[k][j] (The NURBS Book, A2.3).
void basis_derivatives(const std::vector<double>& knots, int span, double u, int p, int order,
                       BasisTable& ders) {
    BasisTable ndu{};
    std::array<double, kMaxDegree + 1> left{};
    std::array<double, kMaxDegree + 1> right{};
    ndu[0][0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = u - knots[span + 1 - j];
        right[j] = knots[span + j] - u;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            ndu[j][r] = right[r + 1] + left[j - r];
            const double temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    for (int j = 0; j <= p; ++j) ders[0][j] = ndu[j][p];
    std::array<std::array<double, kMaxDegree + 1>, 2> a{};
    for (int r = 0; r <= p; ++r) {
        int s1 = 0;
        int s2 = 1;
        a[0][0] = 1.0;
        for (int k = 1; k <= order; ++k) {
            double d = 0.0;
            const int rk = r - k;
            const int pk = p - k;
            if (r >= k) {
                a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
                d = a[s2][0] * ndu[rk][pk];
            }
            const int j1 = rk >= -1 ? 1 : -rk;
            const int j2 = r - 1 <= pk ? k - 1 : p - r;
            for (int j = j1; j <= j2; ++j) {
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
                d += a[s2][j] * ndu[rk + j][pk];
            }
            if (r <= pk) {
                a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
                d += a[s2][k] * ndu[r][pk];
            }
            ders[k][r] = d;
            std::swap(s1, s2);
        }
    }
    double factor = p;
    for (int k = 1; k <= order; ++k) {
        for (int j = 0; j <= p; ++j) ders[k][j] *= factor;
        factor *= p - k;
    }
}

// Clamped knots, evenly spaced over [0, 1]. The parameters are plane
// coordinates in millimetres, so these are the knots that averaging
// (The NURBS Book, eq. 9.68) gives for points spread evenly over the plane.
// Averaging the points' own parameters was measured worse: on a 17 x 13 grid
// every averaged knot falls on a column of points (a column's parameters are
// equal), the Schoenberg-Whitney condition fails at the edge, and the
// interpolating surface swings 0.6 mm between the columns; even knots keep
// it within 2 um of the sampled freeform face.
std::vector<double> uniform_knots(int count, int degree) {
    std::vector<double> knots(static_cast<std::size_t>(degree) + 1, 0.0);
    const int spans = count - degree;
    for (int j = 1; j < spans; ++j) knots.push_back(static_cast<double>(j) / spans);
    knots.insert(knots.end(), static_cast<std::size_t>(degree) + 1, 1.0);
    return knots;
}

int count_of(const std::vector<double>& knots, int degree) {
    return static_cast<int>(knots.size()) - degree - 1;
}

// Rows of the smoothing term in one direction: per interior knot, the jump of
// the p-th derivative of each basis function across it, scaled by the local
// knot spacing to the p-th power (a dimensionless difference of the control
// points). Each entry is (basis index, jump).
std::vector<std::vector<std::pair<int, double>>> jump_rows(const std::vector<double>& knots,
                                                           int degree) {
    const int count = count_of(knots, degree);
    std::vector<std::vector<std::pair<int, double>>> rows;
    BasisTable left{};
    BasisTable right{};
    for (int r = degree + 1; r < count; ++r) {
        // Knot U[r] separates span r - 1 from span r.
        basis_derivatives(knots, r - 1, 0.5 * (knots[r - 1] + knots[r]), degree, degree, left);
        basis_derivatives(knots, r, 0.5 * (knots[r] + knots[r + 1]), degree, degree, right);
        const double h = 0.5 * (knots[r + 1] - knots[r - 1]);
        const double scale = std::pow(h, degree);
        std::vector<std::pair<int, double>> row;
        for (int i = r - 1 - degree; i <= r; ++i) {
            double jump = 0.0;
            if (i >= r - degree) jump += right[degree][i - (r - degree)];
            if (i <= r - 1) jump -= left[degree][i - (r - 1 - degree)];
            row.emplace_back(i, jump * scale);
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

// A symmetric positive definite band matrix, Cholesky-factorised in place:
// the normal matrix of a tensor-product fit couples a control point only with
// its neighbours, which lie within (p + 1) * n_v of it in row-major order
// (the storage of LAPACK's dpbtrf). Measured on 10,000 points and a 48 x 36
// net: Eigen's SimplicialLDLT took 16 ms for the factorisation (AMD or
// natural ordering alike), this 4 ms.
class BandCholesky {
  public:
    BandCholesky(int size, int half_width)
        : n_(size), w_(half_width), l_(static_cast<std::size_t>(size) * (half_width + 1), 0.0) {}
    // Entry (i, j), j <= i <= j + half_width, of the matrix before factorize().
    double& at(int i, int j) { return l_[index(i, j)]; }
    bool factorize() {
        for (int i = 0; i < n_; ++i) {
            const int first = std::max(0, i - w_);
            for (int j = first; j <= i; ++j) {
                const int len = j - first;
                const double dot =
                    len > 0 ? Eigen::Map<const Eigen::VectorXd>(&l_[index(i, first)], len)
                                  .dot(Eigen::Map<const Eigen::VectorXd>(&l_[index(j, first)], len))
                            : 0.0;
                const double value = l_[index(i, j)] - dot;
                if (j < i) {
                    l_[index(i, j)] = value / l_[index(j, j)];
                } else {
                    if (!(value > 0.0)) return false;
                    l_[index(i, i)] = std::sqrt(value);
                }
            }
        }
        return true;
    }
    // Solves L L^T x = b for each column of b, in place.
    void solve(Eigen::MatrixX3d& b) const {
        for (int i = 0; i < n_; ++i) {
            for (int k = std::max(0, i - w_); k < i; ++k) b.row(i) -= l_[index(i, k)] * b.row(k);
            b.row(i) /= l_[index(i, i)];
        }
        for (int i = n_ - 1; i >= 0; --i) {
            for (int k = i + 1; k <= std::min(n_ - 1, i + w_); ++k) {
                b.row(i) -= l_[index(k, i)] * b.row(k);
            }
            b.row(i) /= l_[index(i, i)];
        }
    }

  private:
    std::size_t index(int i, int j) const {
        return static_cast<std::size_t>(i) * static_cast<std::size_t>(w_ + 1) +
               static_cast<std::size_t>(j - i + w_);
    }
    int n_;
    int w_;
    std::vector<double> l_;
};

}  // namespace

std::pair<int, int> control_counts(std::size_t count, double extent_u, double extent_v,
                                   int degree) {
    const double n = static_cast<double>(count);
    const double aspect = extent_v > 0.0 ? extent_u / extent_v : 1.0;
    // A tenth more than the points per direction: a net exactly as dense as
    // scattered points leaves some spans nearly empty; the smoothing term
    // keeps the extra freedom in check (measured on a jittered 16 x 12 plan
    // over a freeform face: largest residual 0.47 um as dense, 0.13 um so).
    const double per_u = std::sqrt(n * aspect);
    const auto clamp = [degree](double wanted) {
        return std::clamp(static_cast<int>(std::lround(wanted)), degree + 1, kMaxControls);
    };
    return {clamp(kDensity * per_u), clamp(kDensity * n / per_u)};
}

Eigen::Vector3d SurfacePoint::normal() const {
    const Eigen::Vector3d n = su.cross(sv);
    const double length = n.norm();
    return length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
}

BSplineSurface BSplineSurface::fit(const std::vector<Eigen::Vector3d>& points,
                                   const SurfaceFitOptions& options) {
    const int p = options.degree;
    if (p < 1 || p > kMaxDegree) {
        throw std::invalid_argument("surface degree out of range; allowed: 1 to 5");
    }
    const std::size_t n_points = points.size();
    const auto needed = static_cast<std::size_t>(p + 1) * static_cast<std::size_t>(p + 1);
    if (n_points < needed) {
        throw InputError(comparison_message(
            "surface_too_few_points",
            QT_TRANSLATE_NOOP("Comparison", "a surface needs %1 points or more; got %2"),
            {arg("required", ArgKind::integer, (p + 1) * (p + 1)),
             arg("points", ArgKind::integer, static_cast<double>(n_points))}));
    }
    BSplineSurface surface;
    surface.degree_ = p;

    // The best-fit plane: centroid and principal axes.
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& q : points) centroid += q;
    centroid /= static_cast<double>(n_points);
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const Eigen::Vector3d& q : points) scatter += (q - centroid) * (q - centroid).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
    const Eigen::Vector3d& values = eigen.eigenvalues();  // ascending
    if (!(values(2) > 0.0) || values(1) <= 1e-12 * values(2)) {
        throw InputError(comparison_message(
            "surface_points_on_a_line",
            QT_TRANSLATE_NOOP("Comparison", "the points lie on a line: they span no surface"), {}));
    }
    Eigen::Vector3d normal = eigen.eigenvectors().col(0);
    if (options.facing.squaredNorm() > 0.0 && normal.dot(options.facing) < 0.0) normal = -normal;
    surface.origin_ = centroid;
    Eigen::Index axis = 0;
    if (normal.cwiseAbs().maxCoeff(&axis) >= std::cos(kSnapAngle_rad)) {
        // Within kSnapAngle of a machine plane: that plane, machine axes as
        // u and v, so a surface z = f(x, y) keeps f's form in (u, v).
        normal = Eigen::Vector3d::Unit(axis) * (normal(axis) < 0.0 ? -1.0 : 1.0);
        surface.axis_u_ = Eigen::Vector3d::Unit((axis + 1) % 3);
    } else {
        surface.axis_u_ = eigen.eigenvectors().col(2);
    }
    surface.axis_v_ = normal.cross(surface.axis_u_);

    // Parameters: plane coordinates mapped to [0, 1] with the margin.
    std::vector<double> s(n_points);
    std::vector<double> t(n_points);
    for (std::size_t k = 0; k < n_points; ++k) {
        s[k] = (points[k] - centroid).dot(surface.axis_u_);
        t[k] = (points[k] - centroid).dot(surface.axis_v_);
    }
    const auto [s_min, s_max] = std::minmax_element(s.begin(), s.end());
    const auto [t_min, t_max] = std::minmax_element(t.begin(), t.end());
    const double extent_u = *s_max - *s_min;
    const double extent_v = *t_max - *t_min;
    surface.u_scale_ = 1.0 / (extent_u * (1.0 + 2.0 * options.margin));
    surface.u_offset_ = *s_min - options.margin * extent_u;
    surface.v_scale_ = 1.0 / (extent_v * (1.0 + 2.0 * options.margin));
    surface.v_offset_ = *t_min - options.margin * extent_v;
    std::vector<double> u(n_points);
    std::vector<double> v(n_points);
    for (std::size_t k = 0; k < n_points; ++k) {
        u[k] = (s[k] - surface.u_offset_) * surface.u_scale_;
        v[k] = (t[k] - surface.v_offset_) * surface.v_scale_;
    }

    const auto [auto_u, auto_v] = control_counts(n_points, extent_u, extent_v, p);
    surface.knots_u_ = uniform_knots(std::max(p + 1, options.controls_u.value_or(auto_u)), p);
    surface.knots_v_ = uniform_knots(std::max(p + 1, options.controls_v.value_or(auto_v)), p);
    const int nu = surface.controls_u();
    const int nv = surface.controls_v();
    const int unknowns = nu * nv;

    // Normal equations (A^T A + w P^T P) C = A^T (P - centroid), assembled
    // straight into the band.
    BandCholesky normal_matrix(unknowns, (p + 1) * nv);
    Eigen::MatrixX3d controls = Eigen::MatrixX3d::Zero(unknowns, 3);
    BasisTable bu{};
    BasisTable bv{};
    const int per_point = (p + 1) * (p + 1);
    constexpr std::size_t kMaxPerPoint = std::size_t{kMaxDegree + 1} * (kMaxDegree + 1);
    std::array<int, kMaxPerPoint> index{};
    std::array<double, kMaxPerPoint> weight{};
    for (std::size_t k = 0; k < n_points; ++k) {
        const int span_u = find_span(surface.knots_u_, p, nu, u[k]);
        const int span_v = find_span(surface.knots_v_, p, nv, v[k]);
        basis_derivatives(surface.knots_u_, span_u, u[k], p, 0, bu);
        basis_derivatives(surface.knots_v_, span_v, v[k], p, 0, bv);
        const Eigen::RowVector3d rhs = (points[k] - centroid).transpose();
        for (int a = 0; a <= p; ++a) {
            for (int b = 0; b <= p; ++b) {
                index[a * (p + 1) + b] = (span_u - p + a) * nv + (span_v - p + b);
                weight[a * (p + 1) + b] = bu[0][a] * bv[0][b];
            }
        }
        // Indices grow with (a, b), so entry r >= c keeps the lower band.
        for (int r = 0; r < per_point; ++r) {
            controls.row(index[r]) += weight[r] * rhs;
            for (int c = 0; c <= r; ++c)
                normal_matrix.at(index[r], index[c]) += weight[r] * weight[c];
        }
    }
    std::vector<std::vector<std::pair<int, double>>> penalty;
    for (const auto& row : jump_rows(surface.knots_u_, p)) {
        for (int j = 0; j < nv; ++j) {
            std::vector<std::pair<int, double>> entries;
            entries.reserve(row.size());
            for (const auto& [i, value] : row) entries.emplace_back(i * nv + j, value);
            penalty.push_back(std::move(entries));
        }
    }
    for (const auto& row : jump_rows(surface.knots_v_, p)) {
        for (int i = 0; i < nu; ++i) {
            std::vector<std::pair<int, double>> entries;
            entries.reserve(row.size());
            for (const auto& [j, value] : row) entries.emplace_back(i * nv + j, value);
            penalty.push_back(std::move(entries));
        }
    }
    if (!penalty.empty()) {
        const double w =
            options.smoothing * static_cast<double>(n_points) / static_cast<double>(penalty.size());
        for (const auto& entries : penalty) {
            for (const auto& [r, vr] : entries) {
                for (const auto& [c, vc] : entries) {
                    if (c <= r) normal_matrix.at(r, c) += w * vr * vc;
                }
            }
        }
    }
    if (!normal_matrix.factorize()) {
        throw InputError(comparison_message(
            "surface_fit_singular",
            QT_TRANSLATE_NOOP("Comparison",
                              "the surface fit has no unique solution for these points"),
            {}));
    }
    normal_matrix.solve(controls);
    if (!controls.allFinite()) {
        throw InputError(comparison_message(
            "surface_fit_singular",
            QT_TRANSLATE_NOOP("Comparison",
                              "the surface fit has no unique solution for these points"),
            {}));
    }
    surface.controls_.resize(static_cast<std::size_t>(unknowns));
    for (int c = 0; c < unknowns; ++c) {
        surface.controls_[static_cast<std::size_t>(c)] = controls.row(c).transpose() + centroid;
    }

    double sum_sq = 0.0;
    for (std::size_t k = 0; k < n_points; ++k) {
        const SurfacePoint at = surface.evaluate(u[k], v[k]);
        const double r = (points[k] - at.s).dot(at.normal());
        sum_sq += r * r;
        surface.residuals_.max_mm = std::max(surface.residuals_.max_mm, std::abs(r));
    }
    surface.residuals_.rms_mm = std::sqrt(sum_sq / static_cast<double>(n_points));
    return surface;
}

SurfacePoint BSplineSurface::evaluate(double u, double v) const {
    const int p = degree_;
    const int nu = controls_u();
    const int nv = controls_v();
    const int order = std::min(2, p);
    const int span_u = find_span(knots_u_, p, nu, u);
    const int span_v = find_span(knots_v_, p, nv, v);
    BasisTable bu{};
    BasisTable bv{};
    basis_derivatives(knots_u_, span_u, u, p, order, bu);
    basis_derivatives(knots_v_, span_v, v, p, order, bv);
    SurfacePoint out;
    for (int a = 0; a <= p; ++a) {
        // Sum over v first: the row's point and its v-derivatives.
        Eigen::Vector3d row0 = Eigen::Vector3d::Zero();
        Eigen::Vector3d row1 = Eigen::Vector3d::Zero();
        Eigen::Vector3d row2 = Eigen::Vector3d::Zero();
        const std::size_t base =
            static_cast<std::size_t>(span_u - p + a) * static_cast<std::size_t>(nv) +
            static_cast<std::size_t>(span_v - p);
        for (int b = 0; b <= p; ++b) {
            const Eigen::Vector3d& c = controls_[base + static_cast<std::size_t>(b)];
            row0 += bv[0][b] * c;
            row1 += bv[1][b] * c;
            if (order >= 2) row2 += bv[2][b] * c;
        }
        out.s += bu[0][a] * row0;
        out.sv += bu[0][a] * row1;
        out.svv += bu[0][a] * row2;
        out.su += bu[1][a] * row0;
        out.suv += bu[1][a] * row1;
        if (order >= 2) out.suu += bu[2][a] * row0;
    }
    return out;
}

Eigen::Vector3d BSplineSurface::point(double u, double v) const {
    return evaluate(u, v).s;
}

Eigen::Vector2d BSplineSurface::plane_parameters(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d d = p - origin_;
    return {(d.dot(axis_u_) - u_offset_) * u_scale_, (d.dot(axis_v_) - v_offset_) * v_scale_};
}

SurfaceProjection BSplineSurface::project(const Eigen::Vector3d& p) const {
    const Eigen::Vector2d start = plane_parameters(p);
    double u = std::clamp(start(0), 0.0, 1.0);
    double v = std::clamp(start(1), 0.0, 1.0);
    SurfaceProjection out;
    out.converged = false;
    constexpr int kMaxIterations = 30;
    constexpr double kStep_mm = 1e-10;
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        const SurfacePoint at = evaluate(u, v);
        const Eigen::Vector3d r = at.s - p;
        const Eigen::Vector2d f(r.dot(at.su), r.dot(at.sv));
        Eigen::Matrix2d j;
        j << at.su.dot(at.su) + r.dot(at.suu), at.su.dot(at.sv) + r.dot(at.suv),
            at.su.dot(at.sv) + r.dot(at.suv), at.sv.dot(at.sv) + r.dot(at.svv);
        if (!(j.determinant() > 0.0 && j(0, 0) > 0.0)) {
            // Far from the surface Newton's matrix may not be positive
            // definite; the Gauss-Newton part always is.
            j << at.su.dot(at.su), at.su.dot(at.sv), at.su.dot(at.sv), at.sv.dot(at.sv);
        }
        const Eigen::Vector2d step = -j.ldlt().solve(f);
        const double u_next = std::clamp(u + step(0), 0.0, 1.0);
        const double v_next = std::clamp(v + step(1), 0.0, 1.0);
        const double moved_mm = ((u_next - u) * at.su + (v_next - v) * at.sv).norm();
        u = u_next;
        v = v_next;
        if (!std::isfinite(moved_mm)) break;
        if (moved_mm < kStep_mm) {
            out.converged = true;
            break;
        }
    }
    const SurfacePoint at = evaluate(u, v);
    out.u = u;
    out.v = v;
    out.foot = at.s;
    out.normal = at.normal();
    out.distance_mm = (p - at.s).dot(out.normal);
    out.inside = u > 0.0 && u < 1.0 && v > 0.0 && v < 1.0;
    return out;
}

}  // namespace probecycle
