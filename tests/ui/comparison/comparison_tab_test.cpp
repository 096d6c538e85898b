// The Comparison tab, offscreen, through its public API
// (ui/comparison/comparison_tab.h).

#include "ui/comparison/comparison_tab.h"

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QFile>
#include <QImage>
#include <QPushButton>
#include <QTemporaryDir>
#include <cmath>
#include <cstdlib>

#include "core/common/file_io.h"
#include "core/comparison/comparison_input.h"
#include "core/comparison/comparison_report.h"
#include "ui/common/language.h"
#include "ui/common/plot_view.h"

namespace probecycle::ui {
namespace {

using File = ComparisonTab::InputFile;

std::string read(const QString& path) {
    return read_text_file(QFile::encodeName(path).toStdString());
}

void write(const QString& path, const std::string& text) {
    write_file_atomically(QFile::encodeName(path).toStdString(), text);
}

// With PROBECYCLE_LAB_SCREENSHOTS=DIR, the tab as shown, to look at.
void save_screenshot(QWidget& tab, const QString& name) {
    const char* out = std::getenv("PROBECYCLE_LAB_SCREENSHOTS");
    if (out == nullptr) return;
    QCoreApplication::processEvents();
    tab.grab().save(QString::fromLocal8Bit(out) + QLatin1Char('/') + name + QStringLiteral(".png"));
}

class ComparisonTabTest : public ::testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(dir_.isValid());
        tab_.resize(1400, 860);
        tab_.show();
        QCoreApplication::processEvents();
    }
    QString path(const QString& name) const { return dir_.filePath(name); }

    QTemporaryDir dir_;
    ComparisonTab tab_;
};

TEST_F(ComparisonTabTest, SimulatedExampleShowsTheMethodWorking) {
    ASSERT_TRUE(tab_.simulate_example(dir_.path())) << tab_.last_error().toStdString();
    ASSERT_TRUE(tab_.result().has_value());
    const ComparisonResult& r = *tab_.result();
    ASSERT_EQ(r.points.size(), 192u);
    EXPECT_TRUE(r.c_axis_identified);
    EXPECT_EQ(tab_.file(File::plan), path(QStringLiteral("plan.csv")));
    EXPECT_EQ(tab_.map_point_count(), 192);
    // Direct OMM is off by the machine's 10-20 um; the comparison is not.
    EXPECT_GT(r.direct.rms_mm, 0.010);
    EXPECT_LT(r.deviation.rms_mm, r.direct.rms_mm);
    const QStringList summary = tab_.summary_text();
    ASSERT_EQ(summary.size(), 3);
    EXPECT_TRUE(summary[0].startsWith(QStringLiteral("Direct OMM: "))) << summary[0].toStdString();
    EXPECT_TRUE(summary[1].startsWith(QStringLiteral("Comparison: ")));
    EXPECT_TRUE(summary[1].contains(QStringLiteral("/ 192"))) << summary[1].toStdString();
    const QStringList c_axis = tab_.c_axis_text();
    ASSERT_EQ(c_axis.size(), 6);
    // ez = 30 urad = 6.19 arcsec, identified exactly from noise-free touches.
    EXPECT_TRUE(c_axis[2].contains(QStringLiteral("30.00"))) << c_axis[2].toStdString();
    EXPECT_TRUE(c_axis[2].contains(QStringLiteral("6.19″"))) << c_axis[2].toStdString();
    // The worst point first.
    const QList<int> order = tab_.point_order();
    ASSERT_EQ(order.size(), 192);
    double worst = 0.0;
    for (const ComparisonPoint& p : r.points) worst = std::max(worst, std::abs(p.deviation_mm));
    EXPECT_DOUBLE_EQ(std::abs(r.points[static_cast<std::size_t>(order.front() - 1)].deviation_mm),
                     worst);
    save_screenshot(tab_, QStringLiteral("comparison_tab"));
}

TEST_F(ComparisonTabTest, TheExportIsTheCoresReport) {
    ASSERT_TRUE(tab_.simulate_example(dir_.path()));
    ASSERT_TRUE(tab_.export_report(path(QStringLiteral("report.csv"))));
    // The same files through core, as `compare run --report` reads them.
    ComparisonInput input;
    input.plan = parse_plan(read(path(QStringLiteral("plan.csv"))));
    const auto points = [&](const char* name) {
        std::vector<Eigen::Vector3d> out;
        for (const MeasuredPoint& p : parse_points(read(path(QString::fromLatin1(name))))) {
            out.push_back(p.point);
        }
        return out;
    };
    input.reference_cmm = points("reference_cmm.csv");
    input.test_omm = points("test_omm.csv");
    input.reference_omm = points("reference_omm.csv");
    input.block_at_zero = parse_block(read(path(QStringLiteral("block_c0.csv"))));
    input.block_turned = parse_block(read(path(QStringLiteral("block_c180.csv"))));
    input.c_axis = {200.0, 100.0, 180.0};
    input.tolerance_mm = tab_.tolerance_mm();
    ReportHeader header;
    header.date = report_date();
    header.subject = "test_omm.csv";
    const std::string report = read(path(QStringLiteral("report.csv")));
    EXPECT_EQ(report, comparison_report_csv(input, run_comparison(input), header));
    EXPECT_EQ(report.rfind("# ProbeCycle comparison report\n# date,", 0), 0u) << report;
}

TEST_F(ComparisonTabTest, ABadFileIsNamedWithItsLineAndThePreviousResultStays) {
    ASSERT_TRUE(tab_.simulate_example(dir_.path()));
    const double rms = tab_.result()->deviation.rms_mm;
    write(path(QStringLiteral("bad.csv")), "x_mm,y_mm,z_mm\n1,2,3\nabc,2,3\n");
    tab_.set_file(File::test_omm, path(QStringLiteral("bad.csv")));
    EXPECT_FALSE(tab_.run());
    EXPECT_TRUE(tab_.last_error().startsWith(QStringLiteral("bad.csv: line 3, column x_mm:")))
        << tab_.last_error().toStdString();
    ASSERT_TRUE(tab_.result().has_value());
    EXPECT_DOUBLE_EQ(tab_.result()->deviation.rms_mm, rms);
    // Only one block file: refused, saying why.
    tab_.set_file(File::test_omm, path(QStringLiteral("test_omm.csv")));
    tab_.set_file(File::block_c180, QString());
    EXPECT_FALSE(tab_.run());
    EXPECT_TRUE(tab_.last_error().contains(QStringLiteral("both block files")));
}

TEST_F(ComparisonTabTest, TheToleranceRecountsThePointsOutside) {
    ASSERT_TRUE(tab_.simulate_example(dir_.path()));
    tab_.set_tolerance_mm(0.010);
    const std::size_t at_10 = tab_.result()->out_of_tolerance.value();
    tab_.set_tolerance_mm(0.002);
    const std::size_t at_2 = tab_.result()->out_of_tolerance.value();
    EXPECT_GT(at_2, at_10);
    EXPECT_GT(tab_.result()->direct_out_of_tolerance.value(), at_2);
}

TEST_F(ComparisonTabTest, AProjectSavesAndOpensAndABadOneChangesNothing) {
    ASSERT_TRUE(tab_.simulate_example(dir_.path()));
    tab_.set_tolerance_mm(0.005);
    ASSERT_TRUE(tab_.save_project(path(QStringLiteral("job.json"))));
    const std::string saved = read(path(QStringLiteral("job.json")));
    EXPECT_NE(saved.find("\"plan\": \"plan.csv\""), std::string::npos) << saved;

    ComparisonTab other;
    ASSERT_TRUE(other.open_project(path(QStringLiteral("job.json"))))
        << other.last_error().toStdString();
    EXPECT_EQ(other.file(File::block_c180), path(QStringLiteral("block_c180.csv")));
    EXPECT_DOUBLE_EQ(other.tolerance_mm(), 0.005);
    ASSERT_TRUE(other.result().has_value());
    EXPECT_DOUBLE_EQ(other.result()->deviation.rms_mm, tab_.result()->deviation.rms_mm);

    write(path(QStringLiteral("bad.json")), "{\"angle_deg\": 0, \"plan\": \"elsewhere.csv\"}");
    EXPECT_FALSE(other.open_project(path(QStringLiteral("bad.json"))));
    EXPECT_TRUE(other.last_error().contains(QStringLiteral("angle_deg")))
        << other.last_error().toStdString();
    EXPECT_EQ(other.file(File::plan), path(QStringLiteral("plan.csv")));
    EXPECT_DOUBLE_EQ(other.tolerance_mm(), 0.005);
}

TEST_F(ComparisonTabTest, NothingToExportBeforeARun) {
    EXPECT_FALSE(tab_.export_report(path(QStringLiteral("r.csv"))));
    EXPECT_FALSE(QFile::exists(path(QStringLiteral("r.csv"))));
    EXPECT_FALSE(tab_.run());
    EXPECT_TRUE(tab_.last_error().contains(QStringLiteral("Inspection plan")))
        << tab_.last_error().toStdString();
}

class ComparisonLanguage : public ::testing::TestWithParam<const char*> {
  protected:
    void SetUp() override {
        ASSERT_EQ(apply_language(QLatin1String(GetParam())), QLatin1String(GetParam()));
    }
    void TearDown() override { apply_language(QStringLiteral("en")); }
};

TEST_P(ComparisonLanguage, TheTabSpeaksTheLanguage) {
    QTemporaryDir dir;
    ComparisonTab tab;
    tab.resize(1400, 860);
    tab.show();
    ASSERT_TRUE(tab.simulate_example(dir.path()));
    const QStringList summary = tab.summary_text();
    ASSERT_EQ(summary.size(), 3);
    EXPECT_FALSE(summary[0].startsWith(QStringLiteral("Direct OMM"))) << summary[0].toStdString();
    const auto* run = tab.findChild<QPushButton*>();
    ASSERT_NE(run, nullptr);
    // An error from core, in the language too.
    write(dir.filePath(QStringLiteral("bad.csv")), "x_mm,y_mm,z_mm\n1,2,3\nabc,2,3\n");
    tab.set_file(File::reference_cmm, dir.filePath(QStringLiteral("bad.csv")));
    EXPECT_FALSE(tab.run());
    EXPECT_FALSE(tab.last_error().contains(QStringLiteral("is not a number")))
        << tab.last_error().toStdString();
    tab.set_file(File::reference_cmm, dir.filePath(QStringLiteral("reference_cmm.csv")));
    ASSERT_TRUE(tab.run());
    save_screenshot(tab, QStringLiteral("comparison_tab_") + QLatin1String(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Languages, ComparisonLanguage, testing::Values("zh_CN", "ru"));

}  // namespace
}  // namespace probecycle::ui
