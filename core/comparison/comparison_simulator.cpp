#include "core/comparison/comparison_simulator.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <random>

namespace probecycle {

namespace {

// The layout: C axis at (200, 100); the test part's 80 x 60 mm face from
// (260, 70) at C = 0, its centre 100 mm from the axis; the reference part
// opposite it, so that the turn puts it where the test part was.
constexpr double kAxisX_mm = 200.0;
constexpr double kAxisY_mm = 100.0;
constexpr double kPartX_mm = 260.0;
constexpr double kPartY_mm = 70.0;
constexpr double kPartZ_mm = 20.0;
constexpr double kWidth_mm = 80.0;
constexpr double kDepth_mm = 60.0;

// The design face: z over the part's own x, y (a few millimetres of form).
double design_height(double u, double v) {
    return 3.0 * std::sin(u / 13.0) * std::cos(v / 11.0) + 0.02 * u * v / 10.0 +
           1.5 * std::exp(-((u - 50.0) * (u - 50.0) + (v - 20.0) * (v - 20.0)) / 300.0);
}

// Machining errors along the normal, in mm: the test part's (up to about
// 15 um) and the reference part's own form error (a few um).
double test_error(double u, double v) {
    return 0.008 * std::sin(u / 17.0 + 0.4) * std::cos(v / 23.0) + 0.006 * (u / kWidth_mm) -
           0.004 * std::exp(-((u - 20.0) * (u - 20.0) + (v - 40.0) * (v - 40.0)) / 150.0);
}
double reference_error(double u, double v) {
    return 0.003 * std::cos(u / 19.0) * std::sin(v / 15.0 + 0.3) - 0.002 * (v / kDepth_mm);
}

struct Face {
    double (*error)(double, double);  // nullptr: the design itself
};

// A point of the part's real face over machine (x, y) at its measuring place.
Eigen::Vector3d design_point(double x, double y) {
    return {x, y, kPartZ_mm + design_height(x - kPartX_mm, y - kPartY_mm)};
}
Eigen::Vector3d design_normal(double x, double y) {
    constexpr double h = 1e-5;
    const double fx = (design_height(x - kPartX_mm + h, y - kPartY_mm) -
                       design_height(x - kPartX_mm - h, y - kPartY_mm)) /
                      (2.0 * h);
    const double fy = (design_height(x - kPartX_mm, y - kPartY_mm + h) -
                       design_height(x - kPartX_mm, y - kPartY_mm - h)) /
                      (2.0 * h);
    return Eigen::Vector3d(-fx, -fy, 1.0).normalized();
}
Eigen::Vector3d real_point(const Face& face, double x, double y) {
    const double e = face.error ? face.error(x - kPartX_mm, y - kPartY_mm) : 0.0;
    return design_point(x, y) + e * design_normal(x, y);
}

// The machine's systematic OMM error at a touch at `p` approached along -n
// (the probe comes from the side n points to), mm: scale and squareness of
// the axes, a thermal Z growth, a Z tilt across X, and probe lobing (a
// trigger later by direction, along -n).
Eigen::Vector3d machine_error(const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
    const double x = p.x() - kAxisX_mm;
    const double y = p.y() - kAxisY_mm;
    const double z = p.z();
    Eigen::Vector3d e(30e-6 * x + 40e-6 * z, -25e-6 * y + 20e-6 * x,
                      0.012 + 15e-6 * z + 20e-6 * (x - 100.0) - 15e-6 * y);
    const double lobing = 0.003 * (1.0 - n.z() * n.z()) - 0.001;
    return e - lobing * n;
}

// Where the approach line p0 + t n0 meets the face carried by `motion`
// (a rigid map of the face at its measuring place): Newton on (x, y, t).
Eigen::Vector3d touch(const Face& face, const Eigen::Matrix4d& motion, const Eigen::Vector3d& p0,
                      const Eigen::Vector3d& n0) {
    const auto carried = [&](double x, double y) {
        return Eigen::Vector3d((motion * real_point(face, x, y).homogeneous()).head<3>());
    };
    Eigen::Vector3d unknown(p0.x(), p0.y(), 0.0);
    for (int iteration = 0; iteration < 20; ++iteration) {
        const Eigen::Vector3d g = carried(unknown(0), unknown(1)) - p0 - unknown(2) * n0;
        if (g.norm() < 1e-13) break;
        constexpr double h = 1e-6;
        Eigen::Matrix3d j;
        j.col(0) =
            (carried(unknown(0) + h, unknown(1)) - carried(unknown(0) - h, unknown(1))) / (2.0 * h);
        j.col(1) =
            (carried(unknown(0), unknown(1) + h) - carried(unknown(0), unknown(1) - h)) / (2.0 * h);
        j.col(2) = -n0;
        unknown -= j.partialPivLu().solve(g);
    }
    return p0 + unknown(2) * n0;
}

// The block: a corner at table (-50, 60, 10) with faces A (+X), B (+Y),
// C (+Z), touched 6 times each within 4-24 mm of the corner.
std::vector<BlockTouch> block_at_place() {
    const Eigen::Vector3d corner(kAxisX_mm - 50.0, kAxisY_mm + 60.0, 10.0);
    std::vector<BlockTouch> touches;
    const double a[3] = {4.0, 14.0, 24.0};
    const double b[2] = {5.0, 18.0};
    for (const double s : a) {
        for (const double t : b) {
            touches.push_back({BlockFace::a, corner + Eigen::Vector3d(0.0, -s, -t), 0});
            touches.push_back({BlockFace::b, corner + Eigen::Vector3d(-s, 0.0, -t), 0});
            touches.push_back({BlockFace::c, corner + Eigen::Vector3d(-s, -t, 0.0), 0});
        }
    }
    return touches;
}

Eigen::Vector3d noisy(const Eigen::Vector3d& p, double sigma, std::mt19937_64& rng) {
    if (!(sigma > 0.0)) return p;
    std::normal_distribution<double> noise(0.0, sigma);
    return p + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
}

}  // namespace

CAxisErrors simulated_c_axis_errors() {
    return {20e-6, -25e-6, 30e-6, 0.004, -0.003, 0.002};
}

ComparisonDataSet simulate_comparison(const ComparisonSimulationOptions& options) {
    ComparisonDataSet out;
    ComparisonInput& in = out.input;
    in.c_axis = {kAxisX_mm, kAxisY_mm, 180.0};
    out.true_c_axis = options.c_axis_errors ? simulated_c_axis_errors() : CAxisErrors{};
    std::mt19937_64 rng(options.seed);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);

    // Carrying a point of the table at C = 0 to where the real turn puts
    // it, in machine coordinates: shift, R(theta) E, shift back.
    Eigen::Matrix4d to_table = Eigen::Matrix4d::Identity();
    to_table.topRightCorner<3, 1>() = Eigen::Vector3d(-kAxisX_mm, -kAxisY_mm, 0.0);
    const Eigen::Matrix4d turn = table_rotation(in.c_axis.angle_deg);
    const Eigen::Matrix4d real_turn =
        to_table.inverse() * turn * error_transform(out.true_c_axis) * to_table;
    // The reference part sits at the ideal turn's inverse of the measuring
    // place; the real turn brings it back with E's error: R E R^-1.
    const Eigen::Matrix4d reference_motion =
        real_turn * (to_table.inverse() * turn * to_table).inverse();

    const Face test{test_error};
    const Face reference{reference_error};
    for (int i = 0; i < options.columns; ++i) {
        for (int j = 0; j < options.rows; ++j) {
            double u = kWidth_mm * i / (options.columns - 1);
            double v = kDepth_mm * j / (options.rows - 1);
            if (!options.grid) {
                u = std::clamp(u + jitter(rng) * kWidth_mm / (options.columns - 1), 0.0, kWidth_mm);
                v = std::clamp(v + jitter(rng) * kDepth_mm / (options.rows - 1), 0.0, kDepth_mm);
            }
            const double x = kPartX_mm + u;
            const double y = kPartY_mm + v;
            PlanPoint plan;
            plan.nominal = design_point(x, y);
            plan.normal = design_normal(x, y);
            in.plan.push_back(plan);
            out.truth_mm.push_back(test_error(u, v));
            out.reference_form_mm.push_back(reference_error(u, v));

            const auto omm = [&](const Eigen::Vector3d& hit) {
                const Eigen::Vector3d systematic = options.machine_error
                                                       ? machine_error(hit, plan.normal)
                                                       : Eigen::Vector3d::Zero();
                return noisy(hit + systematic, options.omm_noise_mm, rng);
            };
            in.reference_cmm.push_back(
                noisy(real_point(reference, x, y), options.cmm_noise_mm, rng));
            in.test_omm.push_back(omm(real_point(test, x, y)));
            in.reference_omm.push_back(
                omm(touch(reference, reference_motion, plan.nominal, plan.normal)));
        }
    }
    for (BlockTouch t : block_at_place()) {
        BlockTouch turned = t;
        turned.point = (real_turn * t.point.homogeneous()).head<3>();
        t.point = noisy(t.point, options.omm_noise_mm, rng);
        turned.point = noisy(turned.point, options.omm_noise_mm, rng);
        in.block_at_zero.push_back(t);
        in.block_turned.push_back(turned);
    }
    return out;
}

}  // namespace probecycle
