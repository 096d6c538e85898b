// The Calibration tab, offscreen, through its public API (ui/lab/calibration_tab.h).

#include "ui/lab/calibration_tab.h"

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QPlainTextEdit>
#include <QTemporaryDir>
#include <cmath>
#include <map>

#include "core/common/report_header.h"
#include "tests/ui/lab/lab_test_data.h"

namespace probecycle::ui {
namespace {

using lab_test::lab_data;

// lab_ring.csv: gauge 50 mm centred at X100 Y-200, ball radius 2.995 mm,
// runout (0.003, -0.002); the values are written to 9 digits.
constexpr double kFileRounding = 1e-8;

class LabCalibrationTab : public ::testing::Test {
  protected:
    void SetUp() override {
        tab_.resize(1280, 800);
        tab_.show();
        QCoreApplication::processEvents();
    }

    bool import_ring() {
        tab_.set_gauge_diameter_mm(50.0);
        return tab_.import_file(lab_data("lab_ring.csv"));
    }

    CalibrationTab tab_;
};

QString read_file(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(file.readAll());
}

// "quantity,value,unit" rows of a report section, by quantity.
std::map<QString, QString> section_values(const QString& csv, const QString& section) {
    std::map<QString, QString> values;
    bool inside = false;
    for (const QString& line : csv.split(QLatin1Char('\n'))) {
        if (line.startsWith(QLatin1Char('#'))) {
            inside = line == QStringLiteral("# ") + section;
            continue;
        }
        const QStringList cells = line.split(QLatin1Char(','));
        if (inside && cells.size() == 3) values[cells[0]] = cells[1];
    }
    return values;
}

TEST_F(LabCalibrationTab, ImportingExactRingDataGivesTheKnownCentreRunoutAndRadius) {
    ASSERT_TRUE(import_ring()) << tab_.last_error().toStdString();
    ASSERT_TRUE(tab_.result().has_value());
    const RingCalibration& r = *tab_.result();
    EXPECT_NEAR(r.center_x_mm, 100.0, kFileRounding);
    EXPECT_NEAR(r.center_y_mm, -200.0, kFileRounding);
    ASSERT_TRUE(r.runout_x_mm && r.runout_y_mm);
    EXPECT_NEAR(*r.runout_x_mm, 0.003, kFileRounding);
    EXPECT_NEAR(*r.runout_y_mm, -0.002, kFileRounding);
    EXPECT_NEAR(r.effective_radius_mm, 2.995, kFileRounding);
    EXPECT_NEAR(*r.radius_by_direction.x_minus_mm, 2.995, kFileRounding);
    EXPECT_TRUE(tab_.last_error().isEmpty());
    EXPECT_TRUE(tab_.warning_codes().isEmpty()) << tab_.warning_codes().join(' ').toStdString();
    EXPECT_TRUE(tab_.points_text().contains(QStringLiteral("orientation_deg,x_mm,y_mm")));

    // What the user reads.
    const QString shown = tab_.results_text().join(QLatin1Char('\n'));
    EXPECT_TRUE(shown.contains(QStringLiteral("2.9950"))) << shown.toStdString();
    EXPECT_TRUE(shown.contains(QStringLiteral("100.0000"))) << shown.toStdString();
    EXPECT_TRUE(shown.contains(QStringLiteral("Y -200.0000"))) << shown.toStdString();
    EXPECT_TRUE(shown.contains(QStringLiteral("+3.0"))) << shown.toStdString();
    EXPECT_TRUE(shown.contains(QStringLiteral("\u22122.0"))) << shown.toStdString();
}

TEST_F(LabCalibrationTab, DrawsThePointsOfBothOrientationsAndTheTwoFittedCircles) {
    ASSERT_TRUE(import_ring());
    // Automatic: a 3.6 µm runout on a 22 mm circle is magnified 1000 times.
    EXPECT_EQ(tab_.deviation_magnification(), 1000.0);

    tab_.set_deviation_magnification(1.0);
    EXPECT_EQ(tab_.deviation_magnification(), 1.0);
    const QList<QPointF> at_0 = tab_.plotted_points(0);
    const QList<QPointF> at_180 = tab_.plotted_points(1);
    ASSERT_EQ(at_0.size(), 4);
    ASSERT_EQ(at_180.size(), 4);
    EXPECT_NEAR(at_0[0].x(), 122.002, 1e-9);
    EXPECT_NEAR(at_0[0].y(), -199.998, 1e-9);
    EXPECT_NEAR(at_180[3].x(), 100.003, 1e-9);
    EXPECT_NEAR(at_180[3].y(), -222.007, 1e-9);

    const RingCalibration& r = *tab_.result();
    for (int o = 0; o < 2; ++o) {
        const CircleFit& fit = *r.fits[static_cast<std::size_t>(o)];
        const QList<QPointF> circle = tab_.plotted_circle(o);
        ASSERT_GT(circle.size(), 60);
        for (const QPointF& p : circle) {
            EXPECT_NEAR(std::hypot(p.x() - fit.center_x_mm, p.y() - fit.center_y_mm), fit.radius_mm,
                        1e-9);
        }
    }

    // Magnified, the 0 deg points (3 µm inside the mean circle at X+) move inwards
    // by 1000 times that.
    tab_.set_deviation_magnification(1000.0);
    const QPointF x_plus = tab_.plotted_points(0)[0];
    EXPECT_NEAR(x_plus.x() - 100.0, 22.005 + 1000.0 * (22.002 - 22.005), 1e-3);
}

TEST_F(LabCalibrationTab, TextInANumberNamesTheLineAndKeepsThePreviousResult) {
    ASSERT_TRUE(import_ring());
    const QList<QPointF> drawn = tab_.plotted_points(0);
    const QStringList shown = tab_.results_text();

    EXPECT_FALSE(tab_.import_file(lab_data("lab_ring_text_in_number.csv")));
    EXPECT_TRUE(tab_.last_error().contains(QStringLiteral("line 4")))
        << tab_.last_error().toStdString();
    EXPECT_TRUE(tab_.last_error().contains(QStringLiteral("y_mm")))
        << tab_.last_error().toStdString();
    EXPECT_TRUE(tab_.last_error().contains(QStringLiteral("lab_ring_text_in_number.csv")));
    auto* error = tab_.findChild<QLabel*>(QStringLiteral("ring-error"));
    ASSERT_NE(error, nullptr);
    EXPECT_TRUE(error->isVisible());
    EXPECT_TRUE(error->text().contains(QStringLiteral("line 4")));

    ASSERT_TRUE(tab_.result().has_value());
    EXPECT_NEAR(tab_.result()->effective_radius_mm, 2.995, kFileRounding);
    EXPECT_EQ(tab_.plotted_points(0), drawn);
    EXPECT_EQ(tab_.results_text(), shown);
    // The bad text is in the paste box, to be corrected there.
    EXPECT_TRUE(tab_.points_text().contains(QStringLiteral("abc")));

    // Corrected and fitted again, the error goes.
    tab_.set_points_text(
        tab_.points_text().replace(QStringLiteral("abc"), QStringLiteral("-177.993")));
    EXPECT_TRUE(tab_.fit()) << tab_.last_error().toStdString();
    EXPECT_TRUE(tab_.last_error().isEmpty());
    EXPECT_FALSE(error->isVisible());
}

// A bad import shows the file so its named line can be fixed, and undo in the
// paste box brings back the points the user had pasted.
TEST_F(LabCalibrationTab, BadImportKeepsThePastedPointsOneUndoAway) {
    const QString pasted = read_file(lab_data("lab_ring.csv"));
    tab_.set_points_text(pasted);
    ASSERT_TRUE(tab_.fit());
    EXPECT_FALSE(tab_.import_file(lab_data("lab_ring_text_in_number.csv")));
    auto* editor = tab_.findChild<QPlainTextEdit*>();
    ASSERT_NE(editor, nullptr);
    EXPECT_NE(editor->toPlainText(), pasted);
    editor->undo();
    EXPECT_EQ(tab_.points_text(), pasted);
}

// The import reads through core's bounded reader: a folder or a file over
// the limit is refused with the reason, and what was pasted stays.
TEST_F(LabCalibrationTab, AFolderOrAFileOverTheLimitIsRefusedAndThePastedPointsStay) {
    const QString pasted = read_file(lab_data("lab_ring.csv"));
    tab_.set_points_text(pasted);
    QTemporaryDir dir;
    EXPECT_FALSE(tab_.import_file(dir.path()));
    EXPECT_TRUE(tab_.last_error().contains(QStringLiteral("directory")))
        << tab_.last_error().toStdString();
    const QString big = dir.filePath(QStringLiteral("big.csv"));
    {
        QFile file(big);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        const QByteArray line("0,10.0,0.0\n");
        QByteArray chunk;
        for (int i = 0; i < 100000; ++i) chunk += line;
        while (file.size() <= 17 * 1024 * 1024) file.write(chunk);
    }
    EXPECT_FALSE(tab_.import_file(big));
    EXPECT_TRUE(tab_.last_error().contains(QStringLiteral("MiB")))
        << tab_.last_error().toStdString();
    EXPECT_EQ(tab_.points_text(), pasted);
}

TEST_F(LabCalibrationTab, EveryBadFileIsAClearError) {
    struct Case {
        const char* file;
        const char* says;
    };
    for (const Case& c :
         {Case{"lab_ring_missing_column.csv", "y_mm"}, Case{"lab_ring_one_point.csv", "line 2"},
          Case{"lab_ring_empty.csv", "empty"}, Case{"does_not_exist.csv", "could not be read"}}) {
        EXPECT_FALSE(tab_.import_file(lab_data(c.file))) << c.file;
        EXPECT_TRUE(tab_.last_error().contains(QLatin1String(c.says)))
            << c.file << ": " << tab_.last_error().toStdString();
        EXPECT_FALSE(tab_.result().has_value());
    }
}

TEST_F(LabCalibrationTab, OneOrientationWarnsThatThereIsNoRunout) {
    tab_.set_gauge_diameter_mm(50.0);
    ASSERT_TRUE(tab_.import_file(lab_data("lab_ring_one_orientation.csv")));
    EXPECT_FALSE(tab_.result()->runout_x_mm.has_value());
    EXPECT_TRUE(tab_.warning_codes().contains(QStringLiteral("single_orientation")));
    EXPECT_TRUE(tab_.plotted_circle(1).isEmpty());
    EXPECT_EQ(tab_.plotted_points(0).size(), 4);
}

TEST_F(LabCalibrationTab, PastedPointsAndANewDiameterRefit) {
    tab_.set_points_text(read_file(lab_data("lab_ring.csv")));
    tab_.set_gauge_diameter_mm(50.0);
    ASSERT_TRUE(tab_.fit());
    EXPECT_NEAR(tab_.result()->effective_radius_mm, 2.995, kFileRounding);
    tab_.set_gauge_diameter_mm(50.01);
    EXPECT_NEAR(tab_.result()->effective_radius_mm, 3.0, kFileRounding);
    EXPECT_NEAR(tab_.gauge_diameter_mm(), 50.01, 1e-12);
}

TEST_F(LabCalibrationTab, ExportWritesTheReportRows) {
    ASSERT_TRUE(import_ring());
    tab_.set_length_inputs({10.0, QStringLiteral("110.0012; 110.0010"), 0.0, 100.0});
    const QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("calibration.csv"));
    ASSERT_TRUE(tab_.export_report(path)) << tab_.last_error().toStdString();
    const QString csv = read_file(path);
    // The header of every report, naming the imported file.
    EXPECT_TRUE(csv.startsWith(QStringLiteral("# ProbeCycle calibration report\n# date,") +
                               QString::fromStdString(report_date())))
        << csv.toStdString();
    EXPECT_TRUE(csv.contains(QStringLiteral("\n# points,lab_ring.csv\n\n# ring\n")));

    const auto ring = section_values(csv, QStringLiteral("ring"));
    ASSERT_EQ(ring.count(QStringLiteral("center_x")), 1u) << csv.toStdString();
    EXPECT_NEAR(ring.at(QStringLiteral("gauge_diameter")).toDouble(), 50.0, 1e-12);
    EXPECT_NEAR(ring.at(QStringLiteral("center_x")).toDouble(), 100.0, kFileRounding);
    EXPECT_NEAR(ring.at(QStringLiteral("center_y")).toDouble(), -200.0, kFileRounding);
    EXPECT_NEAR(ring.at(QStringLiteral("runout_x")).toDouble(), 0.003, kFileRounding);
    EXPECT_NEAR(ring.at(QStringLiteral("runout_y")).toDouble(), -0.002, kFileRounding);
    EXPECT_NEAR(ring.at(QStringLiteral("effective_radius")).toDouble(), 2.995, kFileRounding);
    EXPECT_NEAR(ring.at(QStringLiteral("radius_y_plus")).toDouble(), 2.995, kFileRounding);

    // One row per point, with its direction.
    EXPECT_TRUE(csv.contains(
        QStringLiteral("# points\nline,orientation_deg,x_mm,y_mm,direction,effective_radius_mm,"
                       "residual_mm\n3,0,122.002,-199.998,X+,")))
        << csv.toStdString();
    EXPECT_TRUE(csv.contains(QStringLiteral("\n10,180,100.003,-222.007,Y-,")));
    EXPECT_TRUE(
        csv.contains(QStringLiteral("# fits\norientation_deg,center_x_mm,center_y_mm,"
                                    "radius_mm,residual_max_mm\n0,99.997,-199.998,22.005,")))
        << csv.toStdString();

    const auto length = section_values(csv, QStringLiteral("length"));
    EXPECT_NEAR(length.at(QStringLiteral("effective_length")).toDouble(), 100.0011, 1e-9);
    EXPECT_NEAR(length.at(QStringLiteral("wear")).toDouble(), 0.0011, 1e-9);
    EXPECT_EQ(length.at(QStringLiteral("touches")), QStringLiteral("2"));
    EXPECT_TRUE(csv.endsWith(QStringLiteral("# warnings\ncode,severity,message\n")))
        << csv.toStdString();
}

TEST_F(LabCalibrationTab, ExportWithNothingToExportWritesNothing) {
    const QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("calibration.csv"));
    EXPECT_FALSE(tab_.export_report(path));
    EXPECT_FALSE(tab_.last_error().isEmpty());
    EXPECT_FALSE(QFile::exists(path));
}

TEST_F(LabCalibrationTab, LengthFromASurfaceOfKnownZ) {
    tab_.set_length_inputs({10.0, QStringLiteral("110.0012 110.0010"), 0.0, 0.0});
    ASSERT_TRUE(tab_.length_result().has_value()) << tab_.length_error().toStdString();
    EXPECT_NEAR(tab_.length_result()->effective_length_mm, 100.0011, 1e-9);
    EXPECT_FALSE(tab_.length_result()->wear_mm.has_value());
    EXPECT_NEAR(tab_.length_result()->trigger_z_range_mm, 0.0002, 1e-9);

    // Wear against a nominal far off warns.
    tab_.set_length_inputs({10.0, QStringLiteral("110.0012"), 0.0, 99.0});
    ASSERT_TRUE(tab_.length_result().has_value());
    EXPECT_NEAR(*tab_.length_result()->wear_mm, 1.0012, 1e-9);
    EXPECT_TRUE(tab_.warning_codes().contains(QStringLiteral("length_wear")));

    tab_.set_length_inputs({10.0, QStringLiteral("110.0012; oops"), 0.0, 0.0});
    EXPECT_FALSE(tab_.length_result().has_value());
    EXPECT_TRUE(tab_.length_error().contains(QStringLiteral("oops")));

    tab_.set_length_inputs({200.0, QStringLiteral("110"), 0.0, 0.0});
    EXPECT_FALSE(tab_.length_result().has_value());
    EXPECT_TRUE(tab_.length_error().contains(QStringLiteral("not positive")));
}

TEST_F(LabCalibrationTab, RendersAt1280x800) {
    ASSERT_TRUE(import_ring());
    QCoreApplication::processEvents();
    const QImage image = tab_.grab().toImage();
    ASSERT_FALSE(image.isNull());
    EXPECT_EQ(image.width(), 1280);
    // Not a blank widget: more than one colour.
    const QRgb first = image.pixel(0, 0);
    bool varied = false;
    for (int y = 0; y < image.height() && !varied; y += 7) {
        for (int x = 0; x < image.width() && !varied; x += 7) varied = image.pixel(x, y) != first;
    }
    EXPECT_TRUE(varied);
    const char* out = std::getenv("PROBECYCLE_LAB_SCREENSHOTS");
    if (out != nullptr)
        image.save(QString::fromLocal8Bit(out) + QStringLiteral("/calibration_tab.png"));

    // With an error, warnings and a length shown.
    tab_.set_length_inputs({10.0, QStringLiteral("110.0012 110.0010"), 0.0, 99.0});
    tab_.set_points_text(
        QStringLiteral("orientation_deg,x_mm,y_mm\n0,122.002,-199.998\n"
                       "0,77.992,-199.998\n0,99.997,-177.993\n"
                       "0,99.997,-222.013\n"));
    ASSERT_TRUE(tab_.fit());
    EXPECT_FALSE(tab_.import_file(lab_data("lab_ring_text_in_number.csv")));
    QCoreApplication::processEvents();
    const QImage with_error = tab_.grab().toImage();
    EXPECT_FALSE(with_error.isNull());
    EXPECT_NE(with_error, image);
    if (out != nullptr) {
        with_error.save(QString::fromLocal8Bit(out) + QStringLiteral("/calibration_tab_error.png"));
    }
}

// "Example data": the scenario's probe in the gauge set, fitted at once;
// the fit finds the runout and radius the example was drawn with.
TEST_F(LabCalibrationTab, ExampleDataFitsToTheRunoutAndRadiusDrawn) {
    Scenario s;
    s.probe.pretravel_mm = 0.008;
    tab_.set_scenario(s);
    tab_.set_gauge_diameter_mm(30.0);
    ASSERT_TRUE(tab_.load_example()) << tab_.last_error().toStdString();
    ASSERT_TRUE(tab_.result().has_value());
    EXPECT_NEAR(tab_.result()->effective_radius_mm, 1.5 - 0.008, 0.001);
    ASSERT_TRUE(tab_.result()->runout_x_mm.has_value());
    EXPECT_NEAR(*tab_.result()->runout_x_mm, 0.003, 0.001);
    EXPECT_TRUE(tab_.points_text().startsWith(QStringLiteral("# example")));
    EXPECT_EQ(tab_.fitted_points().size(), 16u);
}

}  // namespace
}  // namespace probecycle::ui
