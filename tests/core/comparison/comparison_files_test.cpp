// The comparison's six files read into its input from hand-made files: what
// is read, the refusals before any file is opened, and a bad file named in
// its error; the example data set as files.

#include "core/comparison/comparison_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "core/common/csv_reader.h"
#include "core/common/file_io.h"
#include "core/comparison/comparison_report.h"

namespace probecycle {
namespace {

namespace fs = std::filesystem;

// 16 plan points, 4 by 4 on z = 1.5, the probe coming from above.
std::string plan_text() {
    std::string text = "x_mm,y_mm,z_mm,i,j,k\n";
    for (int k = 0; k < 16; ++k) {
        text += std::to_string(10 * (k % 4)) + "," + std::to_string(10 * (k / 4)) + ",1.5,0,0,1\n";
    }
    return text;
}

// The plan's points, `dz_mm` above them.
std::string points_text(double dz_mm) {
    std::string text = "x_mm,y_mm,z_mm\n";
    for (int k = 0; k < 16; ++k) {
        text += std::to_string(10 * (k % 4)) + "," + std::to_string(10 * (k / 4)) + "," +
                std::to_string(1.5 + dz_mm) + "\n";
    }
    return text;
}

std::string block_text() {
    return "face,x_mm,y_mm,z_mm\n"
           "A,0,1,1\nA,0,2,1\nA,0,1,2\n"
           "B,1,0,1\nB,2,0,1\nB,1,0,2\n"
           "C,1,1,0\nC,2,1,0\nC,1,2,0\n";
}

class ComparisonFilesTest : public testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("probecycle_comparison_files_test_" + std::to_string(std::random_device{}()) + "_" +
                testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        files_.plan = write("plan.csv", plan_text());
        files_.reference_cmm = write("reference_cmm.csv", points_text(0.0));
        files_.test_omm = write("test_omm.csv", points_text(0.002));
        files_.reference_omm = write("reference_omm.csv", points_text(0.001));
        files_.block_c0 = write("block_c0.csv", block_text());
        files_.block_c180 = write("block_c180.csv", block_text());
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text) const {
        const fs::path path = dir_ / name;
        std::ofstream(path, std::ios::binary) << text;
        return path.string();
    }

    // The error read_comparison_files throws; fails the test if it throws none.
    ComparisonFileError error_of(const ComparisonFiles& files) const {
        try {
            (void)read_comparison_files(files);
        } catch (const ComparisonFileError& e) {
            return e;
        }
        ADD_FAILURE() << "no ComparisonFileError";
        return {ComparisonFileError::Problem::refused, ComparisonFile::plan, {}, {}, {}};
    }

    fs::path dir_;
    ComparisonFiles files_;
};

TEST_F(ComparisonFilesTest, ReadsEveryFileIntoTheInput) {
    const ComparisonInput input = read_comparison_files(files_);
    ASSERT_EQ(input.plan.size(), 16u);
    EXPECT_EQ(input.plan[5].line, 7u);
    EXPECT_DOUBLE_EQ(input.plan[5].nominal.x(), 10.0);
    EXPECT_DOUBLE_EQ(input.plan[5].nominal.y(), 10.0);
    ASSERT_EQ(input.reference_cmm.size(), 16u);
    ASSERT_EQ(input.test_omm.size(), 16u);
    ASSERT_EQ(input.reference_omm.size(), 16u);
    EXPECT_DOUBLE_EQ(input.test_omm[3].z(), 1.502);
    EXPECT_DOUBLE_EQ(input.reference_omm[3].z(), 1.501);
    EXPECT_EQ(input.block_at_zero.size(), 9u);
    EXPECT_EQ(input.block_turned.size(), 9u);
    // The settings are the caller's.
    EXPECT_FALSE(input.tolerance_mm.has_value());
}

TEST_F(ComparisonFilesTest, TheBlocksAreOptionalButBothOrNeither) {
    ComparisonFiles files = files_;
    files.block_c0.clear();
    files.block_c180.clear();
    EXPECT_TRUE(blocks_paired(files));
    const ComparisonInput input = read_comparison_files(files);
    EXPECT_TRUE(input.block_at_zero.empty());
    EXPECT_TRUE(input.block_turned.empty());

    files.block_c0 = files_.block_c0;
    EXPECT_FALSE(blocks_paired(files));
    const ComparisonFileError e = error_of(files);
    EXPECT_EQ(e.problem(), ComparisonFileError::Problem::one_block);
    EXPECT_EQ(e.file(), ComparisonFile::block_c180);
    EXPECT_NE(std::string(e.what()).find("both angles"), std::string::npos) << e.what();
}

TEST_F(ComparisonFilesTest, ANeededFileNotGivenIsNamedBeforeAnyIsRead) {
    ComparisonFiles files = files_;
    files.plan = (dir_ / "missing.csv").string();  // would be a FileError if it were read
    files.test_omm.clear();
    const ComparisonFileError e = error_of(files);
    EXPECT_EQ(e.problem(), ComparisonFileError::Problem::not_given);
    EXPECT_EQ(e.file(), ComparisonFile::test_omm);
    EXPECT_EQ(std::string(e.what()), "no file given for test_omm");
}

TEST_F(ComparisonFilesTest, ABadFileIsNamedWithItsLineAndColumn) {
    ComparisonFiles files = files_;
    files.reference_omm = write("bad.csv", "x_mm,y_mm,z_mm\n1,2,3\nabc,2,3\n");
    const ComparisonFileError e = error_of(files);
    EXPECT_EQ(e.problem(), ComparisonFileError::Problem::refused);
    EXPECT_EQ(e.file(), ComparisonFile::reference_omm);
    EXPECT_EQ(e.path(), files.reference_omm);
    // The CLI prints what(): the path, then the parser's text.
    EXPECT_EQ(std::string(e.what()).rfind(files.reference_omm + ": line 3, column x_mm: ", 0), 0u)
        << e.what();
    // The cause keeps the position for a translated text.
    try {
        std::rethrow_exception(e.cause());
    } catch (const CsvError& cause) {
        EXPECT_EQ(cause.line(), 3u);
        EXPECT_EQ(cause.column(), "x_mm");
    }
}

TEST_F(ComparisonFilesTest, PointsThatDoNotFollowThePlanNameTheirFile) {
    ComparisonFiles files = files_;
    // The last point a metre from its plan point.
    std::string far = points_text(0.0);
    far.erase(far.rfind('\n', far.size() - 2) + 1);
    files.reference_cmm = write("far.csv", far + "1030,30,1.5\n");
    const ComparisonFileError e = error_of(files);
    EXPECT_EQ(e.file(), ComparisonFile::reference_cmm);
    EXPECT_EQ(std::string(e.what()).rfind(files.reference_cmm + ": line 17: ", 0), 0u) << e.what();
}

TEST_F(ComparisonFilesTest, AFileThatCannotBeReadIsAFileErrorNamingIt) {
    ComparisonFiles files = files_;
    files.block_c180 = (dir_ / "missing.csv").string();
    try {
        (void)read_comparison_files(files);
        FAIL() << "no FileError";
    } catch (const FileError& e) {
        EXPECT_EQ(e.path(), files.block_c180);
        EXPECT_EQ(e.action(), FileError::Action::read);
    }
}

TEST_F(ComparisonFilesTest, ABlockFileAloneIsReadAndRefusedTheSameWay) {
    EXPECT_EQ(read_block_file(ComparisonFile::block_c0, files_.block_c0).size(), 9u);
    const std::string thin = write("thin.csv", "face,x_mm,y_mm,z_mm\nA,1,2,3\nB,1,2,3\nC,1,2,3\n");
    try {
        (void)read_block_file(ComparisonFile::block_c180, thin);
        FAIL() << "no ComparisonFileError";
    } catch (const ComparisonFileError& e) {
        EXPECT_EQ(e.file(), ComparisonFile::block_c180);
        EXPECT_EQ(std::string(e.what()).rfind(thin + ": line 4, column face: ", 0), 0u) << e.what();
    }
}

TEST(ComparisonExampleFiles, TheSixInputsInOrderThenTheTruth) {
    ComparisonSimulationOptions options;
    options.columns = 4;
    options.rows = 4;
    const ComparisonDataSet data = simulate_comparison(options);
    const std::vector<ComparisonExampleFile> files = comparison_example_files(data);
    ASSERT_EQ(files.size(), kComparisonFiles + 1);
    for (std::size_t k = 0; k < kComparisonFiles; ++k) {
        EXPECT_EQ(files[k].name, example_file_name(static_cast<ComparisonFile>(k)));
    }
    EXPECT_EQ(files[0].text, plan_csv(data.input.plan));
    EXPECT_EQ(files[2].text, points_csv(data.input.test_omm));
    EXPECT_EQ(files[5].text, block_csv(data.input.block_turned));
    EXPECT_EQ(files[6].name, "truth.csv");
    EXPECT_EQ(files[6].text, truth_csv(data.input.plan, data.truth_mm));
}

}  // namespace
}  // namespace probecycle
