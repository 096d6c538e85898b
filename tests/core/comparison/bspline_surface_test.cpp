// B-spline surface fit, evaluation and projection: hand cases (a plane, a
// bicubic polynomial, a cylinder section) and the net's density.

#include "core/comparison/bspline_surface.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace probecycle {
namespace {

using Eigen::Vector3d;

std::vector<Vector3d> grid(int nx, int ny, double width, double depth,
                           double (*z)(double, double)) {
    std::vector<Vector3d> points;
    for (int i = 0; i < nx; ++i) {
        for (int j = 0; j < ny; ++j) {
            const double x = width * i / (nx - 1);
            const double y = depth * j / (ny - 1);
            points.emplace_back(x, y, z(x, y));
        }
    }
    return points;
}

// A freeform face of a few millimetres' height over 80 x 60 mm.
double freeform(double x, double y) {
    return 3.0 * std::sin(x / 13.0) * std::cos(y / 11.0) + 0.02 * x * y / 10.0 +
           1.5 * std::exp(-((x - 50) * (x - 50) + (y - 20) * (y - 20)) / 300.0);
}

TEST(BSplineSurfaceTest, ReproducesATiltedPlaneAndMeasuresDistanceAlongItsNormal) {
    // 30 degrees from XY: the best-fit plane parameterises it.
    const Vector3d normal = Vector3d(0.0, -std::sin(0.5236), std::cos(0.5236)).normalized();
    const Vector3d a = Vector3d::UnitX();
    const Vector3d b = normal.cross(a);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> along(-30.0, 30.0);
    std::vector<Vector3d> points;
    for (int k = 0; k < 40; ++k) {
        points.push_back(Vector3d(100, 20, 5) + along(rng) * a + along(rng) * b);
    }
    SurfaceFitOptions options;
    options.facing = normal;
    const BSplineSurface surface = BSplineSurface::fit(points, options);
    EXPECT_LT(surface.residuals().max_mm, 1e-9);
    for (int k = 0; k < 20; ++k) {
        const Vector3d on = Vector3d(100, 20, 5) + 0.5 * along(rng) * a + 0.5 * along(rng) * b;
        const SurfaceProjection hit = surface.project(on + 0.013 * normal);
        EXPECT_TRUE(hit.converged);
        EXPECT_TRUE(hit.inside);
        EXPECT_NEAR(hit.distance_mm, 0.013, 1e-10);
        EXPECT_LT((hit.foot - on).norm(), 1e-9);
        EXPECT_NEAR(hit.normal.dot(normal), 1.0, 1e-12);
    }
}

TEST(BSplineSurfaceTest, ABicubicFitReproducesABicubicPolynomialSurface) {
    // z = sum c_ab x^a y^b, a, b <= 3, from 200 scattered points (no grid).
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
    double c[4][4];
    for (auto& row : c) {
        for (double& value : row) value = coefficient(rng);
    }
    const auto height = [&c](double x, double y) {
        const double s = (x - 40.0) / 40.0;
        const double t = (y - 30.0) / 30.0;
        double z = 0.0;
        for (int a = 0; a < 4; ++a) {
            for (int b = 0; b < 4; ++b) z += c[a][b] * std::pow(s, a) * std::pow(t, b);
        }
        return 2.0 * z;  // a few millimetres of height
    };
    std::uniform_real_distribution<double> x_of(0.0, 80.0);
    std::uniform_real_distribution<double> y_of(0.0, 60.0);
    std::vector<Vector3d> points;
    for (int k = 0; k < 200; ++k) {
        const double x = x_of(rng);
        const double y = y_of(rng);
        points.emplace_back(x, y, height(x, y));
    }
    SurfaceFitOptions options;
    options.facing = Vector3d::UnitZ();
    const BSplineSurface surface = BSplineSurface::fit(points, options);
    EXPECT_LT(surface.residuals().max_mm, 1e-9);
    std::uniform_real_distribution<double> x_in(2.0, 78.0);
    std::uniform_real_distribution<double> y_in(2.0, 58.0);
    for (int k = 0; k < 200; ++k) {
        const double x = x_in(rng);
        const double y = y_in(rng);
        const SurfaceProjection hit = surface.project(Vector3d(x, y, height(x, y)));
        ASSERT_TRUE(hit.converged);
        EXPECT_LT(std::abs(hit.distance_mm), 1e-9) << x << ", " << y;
        EXPECT_LT((hit.foot - Vector3d(x, y, height(x, y))).norm(), 1e-9);
    }
}

TEST(BSplineSurfaceTest, FitsACylinderSectionToBelowAMicrometre) {
    // Radius 40 mm about the X axis, 70 degrees of arc about +Z, 15 x 11.
    constexpr double radius = 40.0;
    std::vector<Vector3d> points;
    for (int i = 0; i < 15; ++i) {
        for (int j = 0; j < 11; ++j) {
            const double phi = (-35.0 + 7.0 * j) * M_PI / 180.0;
            points.emplace_back(60.0 * i / 14, radius * std::sin(phi), radius * std::cos(phi));
        }
    }
    SurfaceFitOptions options;
    options.facing = Vector3d::UnitZ();
    const BSplineSurface surface = BSplineSurface::fit(points, options);
    EXPECT_LT(surface.residuals().max_mm, 1e-4);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> x_of(1.0, 59.0);
    std::uniform_real_distribution<double> phi_of(-33.0 * M_PI / 180, 33.0 * M_PI / 180);
    for (int k = 0; k < 100; ++k) {
        const double phi = phi_of(rng);
        const Vector3d radial(0.0, std::sin(phi), std::cos(phi));
        const Vector3d on = Vector3d(x_of(rng), 0, 0) + radius * radial;
        const SurfaceProjection hit = surface.project(on - 0.020 * radial);
        ASSERT_TRUE(hit.converged);
        EXPECT_NEAR(hit.distance_mm, -0.020, 1e-3);
        EXPECT_GT(hit.normal.dot(radial), 1.0 - 1e-6);
    }
}

TEST(BSplineSurfaceTest, TheControlNetFollowsThePointDensity) {
    // A 17 x 13 plan over a freeform face: an 8 x 8 net cannot follow it, the
    // default net (as dense as the points) can.
    const std::vector<Vector3d> points = grid(17, 13, 80.0, 60.0, freeform);
    SurfaceFitOptions coarse;
    coarse.controls_u = 8;
    coarse.controls_v = 8;
    const BSplineSurface sparse = BSplineSurface::fit(points, coarse);
    const BSplineSurface dense = BSplineSurface::fit(points);
    EXPECT_EQ(dense.controls_u(), 19);
    EXPECT_EQ(dense.controls_v(), 14);
    EXPECT_GT(sparse.residuals().max_mm, 0.002);
    EXPECT_LT(dense.residuals().max_mm, 1e-4);
    EXPECT_EQ(control_counts(221, 80.0, 60.0, 3), std::make_pair(19, 14));
}

TEST(BSplineSurfaceTest, TheFootOfAProjectionIsSquareToTheSurface) {
    const std::vector<Vector3d> points = grid(17, 13, 80.0, 60.0, freeform);
    const BSplineSurface surface = BSplineSurface::fit(points);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> x_of(0.0, 80.0);
    std::uniform_real_distribution<double> y_of(0.0, 60.0);
    std::uniform_real_distribution<double> off(-0.5, 0.5);
    for (int k = 0; k < 200; ++k) {
        const Vector3d p(x_of(rng), y_of(rng), freeform(x_of(rng), y_of(rng)) + off(rng));
        const SurfaceProjection hit = surface.project(p);
        ASSERT_TRUE(hit.converged);
        const SurfacePoint at = surface.evaluate(hit.u, hit.v);
        if (hit.inside) {
            EXPECT_LT(std::abs((p - hit.foot).dot(at.su.normalized())), 1e-9);
            EXPECT_LT(std::abs((p - hit.foot).dot(at.sv.normalized())), 1e-9);
        }
        EXPECT_NEAR(std::abs(hit.distance_mm), (p - hit.foot).norm(), 1e-9);
    }
}

TEST(BSplineSurfaceTest, RefusesTooFewPointsAndPointsOnALine) {
    std::vector<Vector3d> few;
    for (int k = 0; k < 15; ++k) few.emplace_back(k, k % 4, 0.0);
    EXPECT_THROW((void)BSplineSurface::fit(few), std::invalid_argument);
    std::vector<Vector3d> line;
    for (int k = 0; k < 30; ++k) line.emplace_back(k, 2.0 * k, 0.0);
    EXPECT_THROW((void)BSplineSurface::fit(line), std::invalid_argument);
}

}  // namespace
}  // namespace probecycle
