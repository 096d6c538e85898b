// The comparison pipeline against the simulator's truth, and hand cases.

#include "core/comparison/comparison.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/input_error.h"
#include "core/comparison/comparison_simulator.h"

namespace probecycle {
namespace {

struct Errors {
    double rms_mm{0.0};
    double max_mm{0.0};
};

Errors against_truth(const ComparisonResult& result, const std::vector<double>& truth,
                     double ComparisonPoint::*member) {
    Errors e;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        const double d = result.points[i].*member - truth[i];
        e.rms_mm += d * d;
        e.max_mm = std::max(e.max_mm, std::abs(d));
    }
    e.rms_mm = std::sqrt(e.rms_mm / static_cast<double>(truth.size()));
    return e;
}

TEST(ComparisonTest, NoiseFreeDataRecoverTheTruthWhilePlainOmmIsOffByTheMachine) {
    ComparisonSimulationOptions options;  // jittered plan, C-axis errors, machine error
    const ComparisonDataSet data = simulate_comparison(options);
    ASSERT_GE(data.input.plan.size(), 190u);
    const ComparisonResult result = run_comparison(data.input);
    const Errors method = against_truth(result, data.truth_mm, &ComparisonPoint::deviation_mm);
    EXPECT_LT(method.rms_mm, 0.0005);
    EXPECT_LT(method.max_mm, 0.0015);
    const Errors direct =
        against_truth(result, data.truth_mm, &ComparisonPoint::direct_deviation_mm);
    EXPECT_GT(direct.rms_mm, 0.010);
    EXPECT_LT(direct.max_mm, 0.020);
    // What the method removed is the machine's error: direct - deviation.
    for (const ComparisonPoint& p : result.points) {
        EXPECT_NEAR(p.direct_deviation_mm - p.deviation_mm, p.system_error_mm, 0.0005);
    }
    const auto found = result.c_axis.errors.vector();
    const auto truth = data.true_c_axis.vector();
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(found(k), truth(k), 1e-7) << k;
    for (int k = 3; k < 6; ++k) EXPECT_NEAR(found(k), truth(k), 1e-4) << k;
}

TEST(ComparisonTest, OnAGridTheResultIsExactToATenthOfAMicrometre) {
    ComparisonSimulationOptions options;
    options.grid = true;
    const ComparisonDataSet data = simulate_comparison(options);
    const ComparisonResult result = run_comparison(data.input);
    const Errors method = against_truth(result, data.truth_mm, &ComparisonPoint::deviation_mm);
    EXPECT_LT(method.max_mm, 0.0001);
}

TEST(ComparisonTest, NoisyMeasurementsStayWithinAMicrometreRms) {
    ComparisonSimulationOptions options;
    options.c_axis_errors = false;
    options.omm_noise_mm = 0.0005;
    options.cmm_noise_mm = 0.0003;
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        options.seed = seed;
        ComparisonDataSet data = simulate_comparison(options);
        data.input.block_at_zero.clear();  // C exact: nothing to identify
        data.input.block_turned.clear();
        const ComparisonResult result = run_comparison(data.input);
        const Errors method = against_truth(result, data.truth_mm, &ComparisonPoint::deviation_mm);
        EXPECT_LT(method.rms_mm, 0.001) << seed;
        // Noise alone: about sqrt(0.5^2 + 0.5^2 + 0.3^2) = 0.77 um per point.
        EXPECT_GT(method.rms_mm, 0.0004) << seed;
    }
}

TEST(ComparisonTest, WithoutTheBlockTheCAxisErrorsStayInTheResult) {
    const ComparisonDataSet data = simulate_comparison({});
    ComparisonInput without = data.input;
    without.block_at_zero.clear();
    without.block_turned.clear();
    const ComparisonResult with_block = run_comparison(data.input);
    const ComparisonResult no_block = run_comparison(without);
    const Errors good = against_truth(with_block, data.truth_mm, &ComparisonPoint::deviation_mm);
    const Errors bad = against_truth(no_block, data.truth_mm, &ComparisonPoint::deviation_mm);
    EXPECT_GT(bad.rms_mm, 0.001);
    EXPECT_GT(bad.rms_mm, 20.0 * good.rms_mm);
    EXPECT_FALSE(no_block.c_axis_identified);
    ASSERT_FALSE(no_block.warnings.empty());
    EXPECT_EQ(no_block.warnings.front().code, "c_axis_not_identified");
}

TEST(ComparisonTest, NoisyBlockTouchesGiveAnUncertaintyThatCoversTheError) {
    // Over seeds the identified errors scatter about the truth by about the
    // reported standard uncertainty, and each point's uncertainty follows.
    ComparisonSimulationOptions options;
    options.omm_noise_mm = 0.0005;
    Eigen::Matrix<double, 6, 1> sum_sq = Eigen::Matrix<double, 6, 1>::Zero();
    Eigen::Matrix<double, 6, 1> reported = Eigen::Matrix<double, 6, 1>::Zero();
    constexpr int kSeeds = 40;
    for (int seed = 1; seed <= kSeeds; ++seed) {
        options.seed = static_cast<std::uint64_t>(seed);
        const ComparisonDataSet data = simulate_comparison(options);
        const CAxisIdentification c =
            identify_c_axis(data.input.block_at_zero, data.input.block_turned, data.input.c_axis);
        ASSERT_TRUE(c.uncertainty.has_value());
        const Eigen::Matrix<double, 6, 1> error = c.errors.vector() - data.true_c_axis.vector();
        sum_sq += error.cwiseProduct(error);
        reported += c.uncertainty->vector();
    }
    const Eigen::Matrix<double, 6, 1> scatter = (sum_sq / kSeeds).cwiseSqrt();
    reported /= kSeeds;
    for (int k = 0; k < 6; ++k) {
        EXPECT_GT(scatter(k), 0.5 * reported(k)) << k;
        EXPECT_LT(scatter(k), 1.6 * reported(k)) << k;
    }
    // Some urad of angle: micrometres at 100 mm from the axis.
    EXPECT_GT(reported(0), 5e-6);
    options.seed = 1;
    const ComparisonResult result = run_comparison(simulate_comparison(options).input);
    double largest = 0.0;
    for (const ComparisonPoint& p : result.points) {
        ASSERT_TRUE(p.c_axis_uncertainty_mm.has_value());
        largest = std::max(largest, *p.c_axis_uncertainty_mm);
    }
    EXPECT_GT(largest, 0.001);
    bool warned = false;
    for (const auto& w : result.warnings) warned = warned || w.code == "c_axis_uncertainty_large";
    EXPECT_TRUE(warned);
}

TEST(ComparisonTest, HandCaseAFlatPlateMeasuresItsOffsets) {
    // A flat plate z = 0 over 60 x 45 mm, normals +Z, an exact C axis: the
    // machine reads every point 10 um high; the reference is 2 um thick
    // everywhere (CMM), the test part 5 um. Deviation: 5 um; direct: 15 um;
    // system error: 10 um.
    ComparisonInput input;
    input.c_axis = {0.0, 0.0, 180.0};
    for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 4; ++j) {
            PlanPoint p;
            p.nominal = {100.0 + 12.0 * i, 15.0 * j, 0.0};
            p.normal = Eigen::Vector3d::UnitZ();
            input.plan.push_back(p);
            input.reference_cmm.push_back(p.nominal + Eigen::Vector3d(0, 0, 0.002));
            input.test_omm.push_back(p.nominal + Eigen::Vector3d(0, 0, 0.015));
            input.reference_omm.push_back(p.nominal + Eigen::Vector3d(0, 0, 0.012));
        }
    }
    input.tolerance_mm = 0.010;
    const ComparisonResult result = run_comparison(input);
    for (const ComparisonPoint& p : result.points) {
        EXPECT_NEAR(p.deviation_mm, 0.005, 1e-9);
        EXPECT_NEAR(p.direct_deviation_mm, 0.015, 1e-12);
        EXPECT_NEAR(p.system_error_mm, 0.010, 1e-9);
    }
    EXPECT_NEAR(result.deviation.rms_mm, 0.005, 1e-9);
    EXPECT_NEAR(result.direct.min_mm, 0.015, 1e-12);
    EXPECT_EQ(result.out_of_tolerance, 0u);
    EXPECT_EQ(result.direct_out_of_tolerance, 24u);
}

TEST(ComparisonTest, SummarizeIsMinMaxMeanRms) {
    const DeviationSummary s = summarize({0.003, -0.004});
    EXPECT_DOUBLE_EQ(s.min_mm, -0.004);
    EXPECT_DOUBLE_EQ(s.max_mm, 0.003);
    EXPECT_DOUBLE_EQ(s.mean_mm, -0.0005);
    EXPECT_NEAR(s.rms_mm, std::sqrt((9e-6 + 16e-6) / 2.0), 1e-15);
}

TEST(ComparisonTest, RefusesCountsThatDifferAndHalfABlock) {
    ComparisonDataSet data = simulate_comparison({});
    ComparisonInput fewer = data.input;
    fewer.test_omm.pop_back();
    EXPECT_THROW((void)run_comparison(fewer), InputError);
    ComparisonInput half = data.input;
    half.block_turned.clear();
    EXPECT_THROW((void)run_comparison(half), InputError);
    ComparisonInput tiny = data.input;
    tiny.plan.resize(10);
    EXPECT_THROW((void)run_comparison(tiny), InputError);
}

}  // namespace
}  // namespace probecycle
