// The Latency tab, offscreen, through its public API (ui/lab/latency_tab.h).

#include "ui/lab/latency_tab.h"

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <cmath>
#include <cstdlib>

#include "core/lab/delay_fit_report.h"
#include "tests/ui/lab/lab_test_data.h"

namespace probecycle::ui {
namespace {

using lab_test::lab_data;

constexpr double kFileRounding = 1e-8;

class LabLatencyTab : public ::testing::Test {
  protected:
    void SetUp() override {
        tab_.resize(1280, 800);
        tab_.show();
        QCoreApplication::processEvents();
    }

    // lab_delay.csv: X+ 8.5 ms from 10.000 over 5 feeds, Z- 9 ms from -50.000 over 3.
    bool import_delay(double period_s = 0.001) {
        tab_.set_interpolation_period_s(period_s);
        return tab_.import_file(lab_data("lab_delay.csv"));
    }

    QPushButton* apply_button() const {
        return tab_.findChild<QPushButton*>(QStringLiteral("apply-to-scenario"));
    }

    LatencyTab tab_;
};

TEST_F(LabLatencyTab, ImportGivesTheKnownDelayPerGroup) {
    ASSERT_TRUE(import_delay()) << tab_.last_error().toStdString();
    ASSERT_TRUE(tab_.delay_fit().has_value());
    const auto& groups = tab_.delay_fit()->groups;
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0].name(), "X+");
    EXPECT_NEAR(groups[0].delay_s, 0.0085, 1e-8);
    EXPECT_NEAR(groups[0].zero_speed_position_mm, 10.0, kFileRounding);
    EXPECT_NEAR(*groups[0].lag_cycles, 8.5, 1e-5);
    EXPECT_EQ(groups[1].name(), "Z-");
    EXPECT_NEAR(groups[1].delay_s, 0.009, 1e-8);

    const QStringList rows = tab_.results_text();
    ASSERT_EQ(rows.size(), 2);
    EXPECT_TRUE(rows[0].startsWith(QStringLiteral("X+ | 8.500"))) << rows[0].toStdString();
    EXPECT_TRUE(rows[0].contains(QStringLiteral("| 8.50 |"))) << rows[0].toStdString();
    EXPECT_TRUE(rows[0].contains(QStringLiteral("| 15"))) << rows[0].toStdString();
    EXPECT_TRUE(rows[1].startsWith(QStringLiteral("Z- | 9.000"))) << rows[1].toStdString();

    // Without the period there are no cycles.
    tab_.set_interpolation_period_s(0.0);
    EXPECT_FALSE(tab_.delay_fit()->groups[0].lag_cycles.has_value());
    EXPECT_TRUE(tab_.results_text()[0].contains(QStringLiteral("—")));
}

TEST_F(LabLatencyTab, TheChartHasEveryTouchAndTheFittedLine) {
    ASSERT_TRUE(import_delay());
    // X+: deviation = v * tau = feed / 60 * 8.5 ms, in µm.
    const QList<QPointF> x_touches = tab_.plotted_touches(0);
    ASSERT_EQ(x_touches.size(), 15);
    for (const QPointF& p : x_touches) {
        EXPECT_NEAR(p.y(), p.x() / 60.0 * 0.0085 * 1000.0, 1e-4) << p.x();
    }
    const QList<QPointF> x_line = tab_.plotted_line(0);
    ASSERT_EQ(x_line.size(), 2);
    EXPECT_EQ(x_line[0], QPointF(0.0, 0.0));
    EXPECT_NEAR(x_line[1].x(), 3000.0, 1e-9);
    EXPECT_NEAR(x_line[1].y(), 425.0, 1e-4);

    // Z-: travelling down, the deviation is negative.
    const QList<QPointF> z_touches = tab_.plotted_touches(1);
    ASSERT_EQ(z_touches.size(), 9);
    EXPECT_NEAR(tab_.plotted_line(1)[1].y(), -450.0, 1e-4);

    // A file with one group hides the second group's curves.
    tab_.set_touches_text(
        QStringLiteral("axis,direction,feed_mm_min,measured_mm\n"
                       "Y,-1,600,4.99\nY,-1,1200,4.98\nY,-1,1800,4.97\n"));
    ASSERT_TRUE(tab_.fit()) << tab_.last_error().toStdString();
    EXPECT_EQ(tab_.plotted_touches(0).size(), 3);
    EXPECT_TRUE(tab_.plotted_touches(1).isEmpty());
    EXPECT_NEAR(tab_.delay_fit()->groups[0].delay_s, 0.001, 1e-9);
}

TEST_F(LabLatencyTab, BadFilesNameTheLineAndKeepThePreviousFit) {
    ASSERT_TRUE(import_delay());
    const QStringList shown = tab_.results_text();
    EXPECT_FALSE(tab_.import_file(lab_data("lab_delay_text_in_number.csv")));
    EXPECT_TRUE(tab_.last_error().contains(QStringLiteral("line 3, column feed_mm_min")))
        << tab_.last_error().toStdString();
    auto* error = tab_.findChild<QLabel*>(QStringLiteral("delay-error"));
    ASSERT_NE(error, nullptr);
    EXPECT_TRUE(error->isVisible());
    ASSERT_TRUE(tab_.delay_fit().has_value());
    EXPECT_EQ(tab_.delay_fit()->groups.size(), 2u);
    EXPECT_EQ(tab_.results_text(), shown);
    EXPECT_EQ(tab_.plotted_touches(0).size(), 15);

    EXPECT_FALSE(tab_.import_file(lab_data("lab_delay_one_feed.csv")));
    EXPECT_TRUE(tab_.last_error().contains(QStringLiteral("line 2")))
        << tab_.last_error().toStdString();
    EXPECT_FALSE(tab_.import_file(lab_data("lab_delay_missing_column.csv")));
    EXPECT_TRUE(tab_.last_error().contains(QStringLiteral("direction")))
        << tab_.last_error().toStdString();
    EXPECT_EQ(tab_.results_text(), shown);
}

// The tab exports its fit and stability results, the bytes of
// `latency fit --report` (core delay_fit_report.h), under a header naming the
// touches' file while they are that file's, and "pasted" once edited.
TEST_F(LabLatencyTab, ExportWritesTheCoresFitAndStabilityReport) {
    const QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("delay.csv"));
    auto* button = tab_.findChild<QPushButton*>(QStringLiteral("delay-export"));
    ASSERT_NE(button, nullptr);
    EXPECT_FALSE(button->isEnabled());
    EXPECT_FALSE(tab_.export_report(path));  // nothing fitted yet
    EXPECT_FALSE(tab_.last_error().isEmpty());
    EXPECT_FALSE(QFile::exists(path));

    ASSERT_TRUE(import_delay()) << tab_.last_error().toStdString();
    EXPECT_TRUE(button->isEnabled());
    ASSERT_TRUE(tab_.export_report(path)) << tab_.last_error().toStdString();
    const auto read = [&path] {
        QFile file(path);
        return file.open(QIODevice::ReadOnly) ? file.readAll().toStdString() : std::string();
    };
    const std::vector<DelayTouch> touches = parse_delay_csv(tab_.touches_text().toStdString());
    DelayFitOptions options;
    options.interpolation_period_s = 0.001;
    ReportHeader header{.date = report_date(), .subject = "lab_delay.csv"};
    EXPECT_EQ(read(), delay_fit_report_csv(touches, options, *tab_.delay_fit(), header));
    EXPECT_NE(read().find("\n# touches,lab_delay.csv\n"), std::string::npos);
    EXPECT_NE(read().find("\nX+,X,1,0.0085,10,8.5,8,0,15\n"), std::string::npos) << read();

    // Edited in the paste box and fitted again: no longer the file's.
    tab_.set_touches_text(tab_.touches_text() + QStringLiteral("X,+1,1500,10.2125\n"));
    ASSERT_TRUE(tab_.fit()) << tab_.last_error().toStdString();
    ASSERT_TRUE(tab_.export_report(path));
    EXPECT_NE(read().find("\n# touches,pasted\n"), std::string::npos) << read();
    EXPECT_NE(read().find("\nX+,1500,0.2125,"), std::string::npos) << read();

    // A folder cannot be written: false, the reason, and the status says so.
    EXPECT_FALSE(tab_.export_report(dir.path()));
    EXPECT_FALSE(tab_.last_error().isEmpty());
}

TEST_F(LabLatencyTab, FewFeedsWarn) {
    tab_.set_touches_text(
        QStringLiteral("axis,direction,feed_mm_min,measured_mm\n"
                       "X,1,100,10.001\nX,1,100,10.001\nX,1,1000,10.01\n"
                       "X,1,1000,10.01\n"));
    ASSERT_TRUE(tab_.fit());
    EXPECT_TRUE(tab_.warning_codes().contains(QStringLiteral("few_feeds")));
}

TEST_F(LabLatencyTab, ApplyEmitsTheControllerLatencyByTheCliRule) {
    ASSERT_TRUE(import_delay());
    QSignalSpy spy(&tab_, &LatencyTab::delay_applied);

    // No scenario yet: nothing to apply to.
    EXPECT_FALSE(apply_button()->isEnabled());
    EXPECT_FALSE(tab_.apply_to_scenario());
    EXPECT_EQ(spy.count(), 0);

    Scenario scenario;
    scenario.probe.interface_delay_s = 0.002;
    scenario.machine.scan_period_s = 0.004;
    scenario.machine.latched_input = false;
    tab_.set_scenario(scenario);
    EXPECT_TRUE(apply_button()->isEnabled());

    // Two groups: the longest delay, Z- 9 ms, less 2 ms interface, less 2 ms half scan.
    const auto pending = tab_.pending_application();
    ASSERT_TRUE(pending.has_value());
    EXPECT_EQ(pending->group, "Z-");
    EXPECT_NE(render(pending->rule).find("longest delay"), std::string::npos)
        << render(pending->rule);
    ASSERT_TRUE(tab_.apply_to_scenario()) << tab_.last_error().toStdString();
    ASSERT_EQ(spy.count(), 1);
    EXPECT_EQ(spy.at(0).at(0).toString(), QStringLiteral("machine.controller_latency_s"));
    EXPECT_NEAR(spy.at(0).at(1).toDouble(), 0.005, 1e-9);

    // X+ chosen: 8.5 - 2 - 2 ms, as the CLI's --group x+.
    tab_.set_applied_group(QStringLiteral("x+"));
    apply_button()->click();
    ASSERT_EQ(spy.count(), 2);
    EXPECT_NEAR(spy.at(1).at(1).toDouble(), 0.0045, 1e-9);
    auto* breakdown = tab_.findChild<QLabel*>(QStringLiteral("apply-breakdown"));
    ASSERT_NE(breakdown, nullptr);
    EXPECT_TRUE(breakdown->text().contains(QStringLiteral("4.500")))
        << breakdown->text().toStdString();

    // A latched input: the fitted delay is the interface delay, and
    // the controller latency is left alone, which the breakdown says.
    scenario.machine.latched_input = true;
    tab_.set_scenario(scenario);
    ASSERT_TRUE(tab_.apply_to_scenario());
    EXPECT_EQ(spy.at(2).at(0).toString(), QStringLiteral("probe.interface_delay_s"));
    EXPECT_NEAR(spy.at(2).at(1).toDouble(), 0.0085, 1e-9);
    EXPECT_TRUE(breakdown->text().contains(QStringLiteral("left as it is")))
        << breakdown->text().toStdString();
}

TEST_F(LabLatencyTab, ANegativeControllerLatencyIsAnErrorAndEmitsNothing) {
    ASSERT_TRUE(import_delay());
    QSignalSpy spy(&tab_, &LatencyTab::delay_applied);
    Scenario scenario;
    scenario.probe.interface_delay_s = 0.008;
    scenario.machine.scan_period_s = 0.004;
    tab_.set_scenario(scenario);
    tab_.set_applied_group(QStringLiteral("X+"));
    EXPECT_FALSE(apply_button()->isEnabled());
    EXPECT_FALSE(tab_.apply_to_scenario());
    EXPECT_EQ(spy.count(), 0);
    EXPECT_TRUE(tab_.last_error().contains(QStringLiteral("negative")))
        << tab_.last_error().toStdString();
}

// The machine lags 10 cycles, the control compensates 8: the true lag and the
// compensated lag apart.
TEST_F(LabLatencyTab, TheCompensatedLagIsSetApartAndCharted) {
    tab_.set_scenario(Scenario{});
    LatencyTab::CompensationInputs inputs;
    inputs.feed_mm_min = 2000.0;
    inputs.interpolation_period_s = 0.001;
    inputs.lag_cycles = 10;
    inputs.touch = TouchMotion::constant_speed;
    inputs.compensated_lag_cycles = 8;
    tab_.set_compensation_inputs(inputs);
    ASSERT_TRUE(tab_.comparison_error().isEmpty()) << tab_.comparison_error().toStdString();
    EXPECT_EQ(tab_.compensation_inputs().compensated_lag_cycles, 8);
    // Two cycles too few: (1 + 10 - 8 - 0.4) cycles of 33.3 µm = 86.7 µm.
    const double cycle_um = 2000.0 / 60.0;
    ASSERT_TRUE(tab_.comparison().has_value());
    EXPECT_NEAR(tab_.comparison()->result(CompensationMethod::cycle_lag).error_mm * 1000.0,
                2.6 * cycle_um, 0.1);
    // The chart: one point per compensated lag, 0 to 49, falling by a cycle's
    // travel per cycle at constant speed.
    const QList<QPointF> curve = tab_.compensation_panel()->lag_curve();
    ASSERT_EQ(curve.size(), 50);
    EXPECT_DOUBLE_EQ(curve.front().x(), 0.0);
    EXPECT_NEAR(curve[8].y(), 2.6 * cycle_um, 0.1);
    EXPECT_NEAR(curve[10].y(), 0.6 * cycle_um, 0.1);
    EXPECT_NEAR(curve[9].y() - curve[10].y(), cycle_um, 0.1);
    // -1: the lag itself.
    inputs.compensated_lag_cycles = -1;
    tab_.set_compensation_inputs(inputs);
    EXPECT_NEAR(tab_.comparison()->result(CompensationMethod::cycle_lag).error_mm * 1000.0,
                0.6 * cycle_um, 0.1);
    auto* box = tab_.findChild<QSpinBox*>(QStringLiteral("compensation-compensated-lag"));
    ASSERT_NE(box, nullptr);
    EXPECT_EQ(box->text(), QStringLiteral("as the lag"));
}

TEST_F(LabLatencyTab, TheComparisonChartHasOneCurvePerMethod) {
    tab_.set_scenario(Scenario{});
    LatencyTab::CompensationInputs inputs;
    inputs.feed_mm_min = 2000.0;
    inputs.interpolation_period_s = 0.001;
    inputs.lag_cycles = 8;
    inputs.touch = TouchMotion::braking;
    inputs.speed_fraction = 0.25;
    tab_.set_compensation_inputs(inputs);
    ASSERT_TRUE(tab_.comparison_error().isEmpty()) << tab_.comparison_error().toStdString();

    const auto curve = [&](CompensationMethod m) { return tab_.comparison_curve(m); };
    const QList<QPointF> naive = curve(CompensationMethod::naive_v_tau);
    const QList<QPointF> cycle_lag = curve(CompensationMethod::cycle_lag);
    const QList<QPointF> timestamp = curve(CompensationMethod::timestamp);
    const QList<QPointF> uncompensated = curve(CompensationMethod::uncompensated);
    for (const auto* c : {&naive, &cycle_lag, &timestamp, &uncompensated}) {
        ASSERT_EQ(c->size(), 40);
        EXPECT_DOUBLE_EQ(c->front().x(), 100.0);
        EXPECT_DOUBLE_EQ(c->back().x(), 2.5);
    }
    // A cycle at the feed is 33.3 mm/s * 1 ms = 33 µm: real increments stay
    // within it at every speed; the naive v * tau is off by far more once the
    // axis has slowed, and the uncompensated position by the whole delay travel.
    const double cycle_travel_um = 2000.0 / 60.0 * 0.001 * 1000.0;
    double worst_cycle_lag = 0.0;
    double worst_naive = 0.0;
    for (qsizetype i = 0; i < naive.size(); ++i) {
        worst_cycle_lag = std::max(worst_cycle_lag, std::abs(cycle_lag[i].y()));
        worst_naive = std::max(worst_naive, std::abs(naive[i].y()));
        EXPECT_LE(std::abs(timestamp[i].y()), std::abs(cycle_lag[i].y()) + 0.2) << i;
    }
    EXPECT_LT(worst_cycle_lag, cycle_travel_um);
    EXPECT_GT(worst_naive, 5.0 * cycle_travel_um);
    // Slowest touch: naive over-corrects (negative for + travel), cycle lag does not.
    EXPECT_LT(naive.back().y(), -3.0 * cycle_travel_um);
    EXPECT_LT(std::abs(cycle_lag.back().y()), 0.1 * cycle_travel_um);
    EXPECT_GT(uncompensated.front().y(), 7.0 * cycle_travel_um);

    // The table: the current setup, braking at 25 % of the feed.
    ASSERT_TRUE(tab_.comparison().has_value());
    const auto& c = *tab_.comparison();
    EXPECT_NEAR(c.trigger_speed_mm_s, 0.25 * 2000.0 / 60.0, 1e-6);
    EXPECT_LT(std::abs(c.result(CompensationMethod::cycle_lag).error_mm),
              std::abs(c.result(CompensationMethod::naive_v_tau).error_mm) / 10.0);

    // At constant speed the naive correction is right as well.
    inputs.touch = TouchMotion::constant_speed;
    tab_.set_compensation_inputs(inputs);
    EXPECT_LT(std::abs(tab_.comparison()->result(CompensationMethod::naive_v_tau).error_mm),
              cycle_travel_um / 1000.0);
}

TEST_F(LabLatencyTab, AScenarioChangeRecomputesOnceInTheEventLoop) {
    tab_.set_compensation_inputs(tab_.compensation_inputs());  // synchronous
    const double before = tab_.comparison()->trigger_position_mm;
    Scenario slower;
    slower.machine.time_constant_s = 0.2;
    tab_.set_scenario(slower);
    tab_.set_scenario(slower);
    EXPECT_EQ(tab_.comparison()->trigger_position_mm, before);  // pending
    QCoreApplication::processEvents();
    EXPECT_NE(tab_.comparison()->trigger_position_mm, before);
}

TEST_F(LabLatencyTab, LagAndPeriodCanBeTakenFromTheFit) {
    ASSERT_TRUE(import_delay(0.001));
    tab_.set_applied_group(QStringLiteral("X+"));
    auto* button = tab_.findChild<QPushButton*>(QStringLiteral("lag-from-fit"));
    ASSERT_NE(button, nullptr);
    ASSERT_TRUE(button->isEnabled());
    button->click();
    // 8.5 ms at 1 ms: 8 whole cycles plus the half cycle to the end of the trigger's.
    EXPECT_EQ(tab_.compensation_inputs().lag_cycles, 8);
    EXPECT_NEAR(tab_.compensation_inputs().interpolation_period_s, 0.001, 1e-12);
}

TEST_F(LabLatencyTab, RendersAt1280x800) {
    ASSERT_TRUE(import_delay());
    tab_.set_scenario(Scenario{});
    QCoreApplication::processEvents();
    const QImage image = tab_.grab().toImage();
    ASSERT_FALSE(image.isNull());
    EXPECT_EQ(image.width(), 1280);
    const QRgb first = image.pixel(0, 0);
    bool varied = false;
    for (int y = 0; y < image.height() && !varied; y += 7) {
        for (int x = 0; x < image.width() && !varied; x += 7) varied = image.pixel(x, y) != first;
    }
    EXPECT_TRUE(varied);
    const char* out = std::getenv("PROBECYCLE_LAB_SCREENSHOTS");
    if (out != nullptr)
        image.save(QString::fromLocal8Bit(out) + QStringLiteral("/latency_tab.png"));

    // With warnings, an error and a delay that cannot be applied.
    tab_.set_touches_text(
        QStringLiteral("axis,direction,feed_mm_min,measured_mm\n"
                       "X,1,100,10.0011\nX,1,100,10.0013\nX,1,1000,10.0100\n"
                       "X,1,1000,10.0180\nY,-1,500,5.0\nY,-1,900,4.9999\n"));
    ASSERT_TRUE(tab_.fit()) << tab_.last_error().toStdString();
    EXPECT_FALSE(tab_.warning_codes().isEmpty());
    EXPECT_FALSE(tab_.import_file(lab_data("lab_delay_text_in_number.csv")));
    QCoreApplication::processEvents();
    const QImage with_error = tab_.grab().toImage();
    EXPECT_NE(with_error, image);
    if (out != nullptr) {
        with_error.save(QString::fromLocal8Bit(out) + QStringLiteral("/latency_tab_error.png"));
    }
}

// "Example data": the delay test for the scenario's machine and probe, fitted
// at once; "Apply" would give the scenario's own latency back.
TEST_F(LabLatencyTab, ExampleDataFitsToTheScenariosDelay) {
    Scenario s;
    s.machine.controller_latency_s = 0.005;
    tab_.set_scenario(s);
    ASSERT_TRUE(tab_.load_example()) << tab_.last_error().toStdString();
    ASSERT_TRUE(tab_.delay_fit().has_value());
    ASSERT_EQ(tab_.delay_fit()->groups.size(), 1u);
    const double drawn =
        s.probe.interface_delay_s + s.machine.controller_latency_s + s.machine.scan_period_s / 2;
    EXPECT_NEAR(tab_.delay_fit()->groups[0].delay_s, drawn, 0.001);
    const std::optional<AppliedDelay> applied = tab_.pending_application();
    ASSERT_TRUE(applied.has_value());
    EXPECT_NEAR(applied->value_s, 0.005, 0.001);
}

}  // namespace
}  // namespace probecycle::ui
