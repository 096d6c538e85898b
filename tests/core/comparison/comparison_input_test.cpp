// The comparison's input files: CSV and DMIS, and every refusal naming the
// line and the column.

#include "core/comparison/comparison_input.h"

#include <gtest/gtest.h>

#include <string>

#include "core/common/csv_reader.h"
#include "tests/core/common/line_ends.h"

namespace probecycle {
namespace {

std::string plan_text(int points, const std::string& extra = "") {
    std::string text = "# an inspection plan\nx_mm,y_mm,z_mm,i,j,k\n";
    for (int k = 0; k < points; ++k) {
        text += std::to_string(10 + k) + "," + std::to_string(k % 4) + ",1.5,0,0,1\n";
    }
    return text + extra;
}

std::string points_text(int points) {
    std::string text = "x_mm,y_mm,z_mm\n";
    for (int k = 0; k < points; ++k) text += std::to_string(10 + k) + ",0,1.5\n";
    return text;
}

// Expects a CsvError at `line` (and `column` if given) whose text has `part`.
template <typename F>
void expect_error(F parse, std::size_t line, const std::string& column, const std::string& part) {
    try {
        parse();
        FAIL() << "no error; expected one at line " << line;
    } catch (const CsvError& e) {
        EXPECT_EQ(e.line(), line) << e.what();
        EXPECT_EQ(e.column(), column) << e.what();
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
}

TEST(ComparisonInputTest, ReadsAPlanAndNormalisesItsNormals) {
    const std::vector<PlanPoint> plan = parse_plan(plan_text(16) + "30,1,2,0,0.6,0.8004\n");
    ASSERT_EQ(plan.size(), 17u);
    EXPECT_EQ(plan[0].line, 3u);
    EXPECT_DOUBLE_EQ(plan[0].nominal.x(), 10.0);
    EXPECT_NEAR(plan[16].normal.norm(), 1.0, 1e-15);
}

TEST(ComparisonInputTest, RefusesNormalsThatAreNotUnitVectors) {
    expect_error([] { (void)parse_plan(plan_text(16) + "30,1,2,0,0,0\n"); }, 19, "i", "length 0");
    expect_error([] { (void)parse_plan(plan_text(16) + "30,1,2,0,0,1.01\n"); }, 19, "i",
                 "unit vector");
}

TEST(ComparisonInputTest, RefusesNaNAMissingColumnAndTooFewPoints) {
    expect_error([] { (void)parse_plan(plan_text(16) + "nan,1,2,0,0,1\n"); }, 19, "x_mm",
                 "not a number");
    expect_error([] { (void)parse_points("x_mm,z_mm\n1,2\n"); }, 1, "", "y_mm");
    expect_error([] { (void)parse_points(points_text(15)); }, 16, "", "16 points or more; got 15");
}

TEST(ComparisonInputTest, CountsMustMatchThePlan) {
    const std::vector<MeasuredPoint> points = parse_points(points_text(18));
    EXPECT_NO_THROW(check_point_count(points, 18));
    expect_error([&] { check_point_count(points, 17); }, 19, "", "point 18 has no plan point");
    expect_error([&] { check_point_count(points, 20); }, 19, "", "ends after 18 points");
}

// The points of plan_text(16) (y = k % 4), each moved by `offset`; the
// point on line `line` (1-based, after the header) replaced by `replacement`.
std::string points_of_plan(double offset, std::size_t line = 0,
                           const std::string& replacement = "") {
    std::string text = "x_mm,y_mm,z_mm\n";
    for (int k = 0; k < 16; ++k) {
        const std::string row =
            std::to_string(10 + k + offset) + "," + std::to_string(k % 4) + ",1.5\n";
        text += static_cast<std::size_t>(k) + 2 == line ? replacement + "\n" : row;
    }
    return text;
}

TEST(ComparisonInputTest, APointFarFromItsPlanPointIsNamedAtItsLine) {
    // Before: "the surface fit has no unique solution for these points", no file, no line.
    const std::vector<PlanPoint> plan = parse_plan(plan_text(16));
    EXPECT_EQ(parse_points_for_plan(points_of_plan(0.002), plan).size(), 16u);
    expect_error([&] { (void)parse_points_for_plan(points_of_plan(0.0, 5, "100000,3,1.5"), plan); },
                 5, "",
                 "this point lies 99987 mm from its plan point (plan line 6); allowed: "
                 "within the plan's extent, 15.2971 mm");
}

TEST(ComparisonInputTest, PointsOutOfThePlansOrderAreNamed) {
    const std::vector<PlanPoint> plan = parse_plan(plan_text(16));
    // Lines 3 and 4 swapped: the point of line 3 is the plan's fourth.
    std::string swapped = points_of_plan(0.0);
    const std::string third = "12.000000,2,1.5\n";
    const std::string fourth = "13.000000,3,1.5\n";
    swapped.replace(swapped.find(third), third.size(), "TMP\n");
    swapped.replace(swapped.find(fourth), fourth.size(), third);
    swapped.replace(swapped.find("TMP\n"), 4, fourth);
    expect_error([&] { (void)parse_points_for_plan(swapped, plan); }, 4, "",
                 "from the plan point of line 6: the points must follow the plan's order");
    // A whole part shifted by 0.3 mm is no disorder: each point is still nearest its own.
    EXPECT_EQ(parse_points_for_plan(points_of_plan(0.3), plan).size(), 16u);
}

TEST(ComparisonInputTest, ReadsDmisPointStatements) {
    std::string dmis = "DMISMN/'plan',4.0\nUNITS/MM,ANGDEG\n$$ a comment\n";
    for (int k = 0; k < 16; ++k) {
        dmis += "F(P" + std::to_string(k) + ")=FEAT/POINT,CART," + std::to_string(k) +
                ",0,0,0,0,1\nMEAS/POINT,F(P" + std::to_string(k) + "),1\nptmeas/cart," +
                std::to_string(k) + ".5,2,3.25,0,0,1\nENDMES\n";
    }
    dmis += "ENDFIL\n";
    const std::vector<PlanPoint> plan = parse_plan(dmis);
    ASSERT_EQ(plan.size(), 16u);
    EXPECT_DOUBLE_EQ(plan[1].nominal.x(), 1.5);
    EXPECT_DOUBLE_EQ(plan[1].nominal.z(), 3.25);
    EXPECT_EQ(plan[0].line, 6u);
    EXPECT_EQ(parse_points(dmis).size(), 16u);
    expect_error([] { (void)parse_plan("PTMEAS/CART,1,2,3\n"); }, 1, "", "needs 6");
    expect_error([] { (void)parse_points("PTMEAS/POL,1,2,3\n"); }, 1, "", "only PTMEAS/CART");
    expect_error([] { (void)parse_points("PTMEAS/CART,1,x,3\n"); }, 1, "y_mm", "not a number");
}

TEST(ComparisonInputTest, ReadsABlockAndRefusesAThinFaceOrAnUnknownFace) {
    std::string block = "face,x_mm,y_mm,z_mm\n";
    for (const char* face : {"A", "B", "c"}) {
        for (int k = 0; k < 3; ++k) block += std::string(face) + "," + std::to_string(k) + ",1,2\n";
    }
    const std::vector<BlockTouch> touches = parse_block(block);
    ASSERT_EQ(touches.size(), 9u);
    EXPECT_EQ(touches[8].face, BlockFace::c);
    expect_error([&] { (void)parse_block(block + "D,1,2,3\n"); }, 11, "face", "allowed: A, B, C");
    expect_error([] { (void)parse_block("face,x_mm,y_mm,z_mm\nA,1,2,3\nB,1,2,3\nC,1,2,3\n"); }, 4,
                 "face", "touches on face A: 1");
}

TEST(ComparisonInputTest, WindowsLineEndsReadAsUnixOnes) {
    const std::vector<PlanPoint> plan = parse_plan(plan_text(20));
    const std::vector<PlanPoint> plan_crlf = parse_plan(test::with_crlf(plan_text(20)));
    ASSERT_EQ(plan_crlf.size(), plan.size());
    for (std::size_t i = 0; i < plan.size(); ++i) {
        EXPECT_EQ(plan_crlf[i].nominal, plan[i].nominal) << i;
        EXPECT_EQ(plan_crlf[i].normal, plan[i].normal) << i;
        EXPECT_EQ(plan_crlf[i].line, plan[i].line) << i;
    }
    const std::vector<MeasuredPoint> points = parse_points(test::with_crlf(points_text(20)));
    ASSERT_EQ(points.size(), 20u);
    EXPECT_EQ(points.back().point, Eigen::Vector3d(29, 0, 1.5));
    const std::vector<BlockTouch> block =
        parse_block(test::with_crlf("face,x_mm,y_mm,z_mm\nA,1,2,3\nA,1,3,3\nA,1,2,4\nB,4,5,6\n"
                                    "B,5,5,6\nB,4,5,7\nC,7,8,9\nC,8,8,9\nC,7,9,9\n"));
    ASSERT_EQ(block.size(), 9u);
    EXPECT_EQ(block[8].face, BlockFace::c);
    EXPECT_EQ(block[8].point, Eigen::Vector3d(7, 9, 9));
}

}  // namespace
}  // namespace probecycle
