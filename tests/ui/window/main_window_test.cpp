// The window's behaviour, driven as a user drives it (sliders, buttons,
// files), offscreen. Mirrors ui/main_window.h.

#include "ui/window/main_window.h"

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDate>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <cmath>
#include <map>
#include <string>

#include "core/cycle/cycle_report.h"
#include "core/cycle/scenario.h"
#include "core/program/program_writer.h"
#include "ui/common/language.h"
#include "ui/common/plot_view.h"
#include "ui/cycle/parameter_panel.h"
#include "ui/lab/calibration_tab.h"
#include "ui/lab/latency_tab.h"
#include "ui/program/program_dialog.h"
#include "ui/window/help_guide.h"

namespace probecycle::ui {
namespace {

using SeriesSnapshot = std::map<QString, QList<QPointF>>;

// Every preset of the Presets menu, machines first (the latched input last).
constexpr const char* kPresets[] = {":/presets/machine_standard_skip.json",
                                    ":/presets/machine_high_speed_skip.json",
                                    ":/presets/machine_fanuc_exponential_servo.json",
                                    ":/presets/machine_mitsubishi_g31.json",
                                    ":/presets/machine_linuxcnc.json",
                                    ":/presets/machine_linear_after_interpolation.json",
                                    ":/presets/machine_latched_input.json",
                                    ":/presets/probe_kinematic_optical.json",
                                    ":/presets/probe_kinematic_radio.json",
                                    ":/presets/probe_strain_gauge.json",
                                    ":/presets/probe_small_stylus.json"};

class MainWindowTest : public ::testing::Test {
  protected:
    void SetUp() override {
        MainWindowOptions options;
        options.persistent = false;
        options.show_dialogs = false;
        window_ = std::make_unique<MainWindow>(options);
        window_->resize(1280, 800);
        window_->show();
        settle();
    }

    // Lets the event loop run the coalesced recompute, as after a user's edit.
    void settle() {
        QCoreApplication::processEvents();
        window_->recompute_now();
    }

    QSlider* slider(const char* key) const {
        return window_->findChild<QSlider*>(QStringLiteral("slider:") + QLatin1String(key));
    }
    QDoubleSpinBox* spin(const char* key) const {
        return window_->findChild<QDoubleSpinBox*>(QStringLiteral("spin:") + QLatin1String(key));
    }
    QPushButton* fix_button(const char* code) const {
        return window_->findChild<QPushButton*>(QStringLiteral("fix:") + QLatin1String(code));
    }

    // Moves a slider to its position for a value (internal units), as a drag would end.
    void drag_to_fraction(QSlider* s, double fraction) {
        s->setValue(s->minimum() +
                    static_cast<int>(fraction * static_cast<double>(s->maximum() - s->minimum())));
        settle();
    }

    std::array<QString, kReadoutCount> readouts() const {
        std::array<QString, kReadoutCount> out;
        for (std::size_t i = 0; i < kReadoutCount; ++i) {
            out[i] = window_->readout_text(static_cast<Readout>(i));
        }
        return out;
    }

    SeriesSnapshot series() const {
        SeriesSnapshot out;
        for (const QString& id : window_->series_ids()) out[id] = window_->series_points(id);
        return out;
    }

    std::string json() const { return scenario_to_json(window_->scenario()); }

    std::unique_ptr<MainWindow> window_;
};

TEST_F(MainWindowTest, StartsWithTheDefaultScenarioAndDrawsEveryChart) {
    EXPECT_EQ(json(), scenario_to_json(Scenario{}));
    EXPECT_GE(window_->recompute_count(), 1);
    for (const char* id : {"cycle_time.single_touch", "cycle_time.two_touch",
                           "overtravel.overtravel", "overtravel.uncertainty"}) {
        EXPECT_EQ(window_->series_points(QLatin1String(id)).size(), 500) << id;
    }
    EXPECT_GE(window_->series_points(QStringLiteral("motion.position")).size(), 500);
    EXPECT_EQ(window_->series_points(QStringLiteral("cycle_time.knee")).size(), 1);
    EXPECT_FALSE(window_->series_points(QStringLiteral("phases.approach")).isEmpty());
    EXPECT_FALSE(window_->readout_text(Readout::cycle_time).isEmpty());
}

TEST_F(MainWindowTest, EveryScenarioKeyHasAnEditorWithUnitRangeAndTooltip) {
    for (const KeyInfo& key : numeric_keys()) {
        QDoubleSpinBox* box = spin(key.key);
        ASSERT_NE(box, nullptr) << key.key;
        EXPECT_FALSE(box->suffix().trimmed().isEmpty()) << key.key;
        EXPECT_FALSE(box->toolTip().isEmpty()) << key.key;
        EXPECT_LT(box->minimum(), box->maximum()) << key.key;
    }
    // Every word key has a combo box, with one item per allowed word and a tooltip.
    for (const KeyInfo& key : scenario_keys()) {
        if (key.kind != KeyKind::word) continue;
        const auto* combo =
            window_->findChild<QComboBox*>(QStringLiteral("combo:") + QLatin1String(key.key));
        ASSERT_NE(combo, nullptr) << key.key;
        EXPECT_EQ(static_cast<std::size_t>(combo->count()), allowed_words(key).size()) << key.key;
        EXPECT_FALSE(combo->toolTip().isEmpty()) << key.key;
    }
}

// The backoff measured from the recorded trigger position.
TEST_F(MainWindowTest, BackoffFromTheTriggerPosition) {
    auto* combo = window_->findChild<QComboBox*>(QStringLiteral("combo:cycle.backoff_from"));
    ASSERT_NE(combo, nullptr);
    EXPECT_TRUE(combo->isVisibleTo(window_.get()));
    const double from_stop = window_->computed().cycle().recommended_backoff_mm();
    combo->setCurrentIndex(combo->findData(static_cast<int>(BackoffFrom::trigger)));
    emit combo->activated(combo->currentIndex());
    settle();
    EXPECT_EQ(window_->scenario().cycle.backoff_from, BackoffFrom::trigger);
    // 0.205 mm recorded past the surface + 0.2 mm reseat, against 1.272 + 0.2 from the stop;
    // at the default 120 % feed override the touch at 2400 mm/min is recorded
    // 0.005 + 40 x 0.006 = 0.245 mm past, + 0.2 reseat.
    EXPECT_NEAR(window_->computed().cycle().recommended_backoff_mm(), 0.445, 1e-9);
    EXPECT_LT(window_->computed().cycle().recommended_backoff_mm(), from_stop);
    ASSERT_TRUE(window_->apply_fix_for(QStringLiteral("backoff_excess")));
    settle();
    EXPECT_TRUE(window_->computed().cycle().valid());
    EXPECT_FALSE(window_->warning_codes().contains(QStringLiteral("backoff_excess")));
    // Single-touch has no backoff: the row goes.
    Scenario s = window_->scenario();
    s.cycle.strategy = Strategy::single_touch;
    window_->edit_scenario(s, QStringLiteral("single touch"));
    settle();
    EXPECT_FALSE(combo->isVisibleTo(window_.get()));
}

// The filter after interpolation; its keys show with it.
TEST_F(MainWindowTest, FilterAfterInterpolationShowsItsKeysAndChangesTheCycle) {
    auto* combo = window_->findChild<QComboBox*>(QStringLiteral("combo:machine.filter"));
    ASSERT_NE(combo, nullptr);
    const auto shown = [this](const char* key) {
        auto* edit = window_->findChild<QWidget*>(QStringLiteral("edit:") + QLatin1String(key));
        return edit != nullptr && edit->isVisibleTo(window_.get());
    };
    EXPECT_FALSE(shown("machine.filter_time_s"));
    EXPECT_FALSE(shown("machine.in_position_mm"));
    EXPECT_TRUE(shown("machine.servo_time_constant_s"));
    const double overtravel = window_->computed().cycle().overtravel_mm();
    combo->setCurrentIndex(combo->findData(static_cast<int>(FilterKind::bell)));
    emit combo->activated(combo->currentIndex());
    settle();
    EXPECT_EQ(window_->scenario().machine.filter, FilterKind::bell);
    EXPECT_TRUE(shown("machine.filter_time_s"));
    EXPECT_TRUE(shown("machine.filter2_time_s"));
    EXPECT_TRUE(shown("machine.in_position_mm"));
    // The drain adds v (T1 + T2)/2 at 2000 mm/min: 33.3 mm/s x 20 ms.
    EXPECT_NEAR(window_->computed().cycle().overtravel_mm(), overtravel + 2000.0 / 60.0 * 0.02,
                1e-6);
    EXPECT_FALSE(window_->computed().cycle().motions().empty());
}

// Each slider moves readouts and chart data.
class SliderTest : public MainWindowTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(SliderTest, MovingTheSliderChangesReadoutsAndCharts) {
    QSlider* s = slider(GetParam());
    ASSERT_NE(s, nullptr) << GetParam();
    const double before_value = *get_number(window_->scenario(), GetParam());
    const auto before_readouts = readouts();
    const SeriesSnapshot before_series = series();
    const int recomputes = window_->recompute_count();

    drag_to_fraction(s, s->value() > s->maximum() / 2 ? 0.15 : 0.85);

    EXPECT_NE(*get_number(window_->scenario(), GetParam()), before_value);
    EXPECT_GT(window_->recompute_count(), recomputes);
    EXPECT_NE(readouts(), before_readouts);
    const SeriesSnapshot after_series = series();
    int changed = 0;
    for (const auto& [id, points] : after_series) changed += points != before_series.at(id) ? 1 : 0;
    EXPECT_GT(changed, 0);
    // The spin box beside the slider follows it.
    const double shown = spin(GetParam())->value();
    EXPECT_NE(shown, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Sliders, SliderTest,
                         ::testing::Values("cycle.probe_feed_mm_min", "machine.time_constant_s",
                                           "machine.scan_period_s", "cycle.backoff_mm"));

TEST_F(MainWindowTest, FeedSliderIsLogarithmicFrom10To10000) {
    QSlider* s = slider("cycle.probe_feed_mm_min");
    drag_to_fraction(s, 0.0);
    EXPECT_DOUBLE_EQ(window_->scenario().cycle.probe_feed_mm_min, 10.0);
    drag_to_fraction(s, 1.0);
    EXPECT_DOUBLE_EQ(window_->scenario().cycle.probe_feed_mm_min, 10000.0);
    // The geometric middle of 10..10000 (316), to a round stop within 10 %.
    drag_to_fraction(s, 0.5);
    const double middle = window_->scenario().cycle.probe_feed_mm_min;
    EXPECT_NEAR(std::log(middle / 316.0), 0.0, std::log(1.1)) << middle;
    const QList<QPointF> marker = window_->series_points(QStringLiteral("cycle_time.feed"));
    ASSERT_EQ(marker.size(), 2);
    EXPECT_EQ(marker[0].x(), middle);
}

TEST_F(MainWindowTest, ScanPeriodSliderSpans1usTo20ms) {
    QSlider* s = slider("machine.scan_period_s");
    drag_to_fraction(s, 0.0);
    EXPECT_DOUBLE_EQ(window_->scenario().machine.scan_period_s, 1e-6);
    drag_to_fraction(s, 1.0);
    EXPECT_DOUBLE_EQ(window_->scenario().machine.scan_period_s, 0.02);
}

TEST_F(MainWindowTest, ManySliderStepsInOnePassRecomputeOnce) {
    QSlider* s = slider("cycle.probe_feed_mm_min");
    const int before = window_->recompute_count();
    for (int i = 0; i < 20; ++i) s->setValue(100 + 10 * i);
    QCoreApplication::processEvents();
    EXPECT_EQ(window_->recompute_count(), before + 1);
}

TEST_F(MainWindowTest, OvertravelWarningAppearsOverTheLimitAndGoesWhenTheFeedDrops) {
    QSlider* feed = slider("cycle.probe_feed_mm_min");
    drag_to_fraction(feed, 0.3);
    EXPECT_FALSE(window_->warning_codes().contains(QStringLiteral("overtravel_limit")));
    EXPECT_EQ(window_->readout_alert(Readout::overtravel), Alert::none);

    drag_to_fraction(feed, 1.0);  // 10000 mm/min: far over the default 5 mm limit
    ASSERT_GE(window_->computed().cycle().overtravel_mm(),
              window_->scenario().probe.overtravel_limit_mm);
    EXPECT_TRUE(window_->warning_codes().contains(QStringLiteral("overtravel_limit")));
    EXPECT_EQ(window_->readout_alert(Readout::overtravel), Alert::alarm);
    // The beyond-limit feeds are shaded.
    EXPECT_FALSE(window_->series_points(QStringLiteral("overtravel.beyond_limit")).isEmpty());

    drag_to_fraction(feed, 0.3);
    EXPECT_FALSE(window_->warning_codes().contains(QStringLiteral("overtravel_limit")));
    EXPECT_EQ(window_->readout_alert(Readout::overtravel), Alert::none);
}

TEST_F(MainWindowTest, OneClickFixSetsTheBackoffToTheRecommendedValue) {
    drag_to_fraction(slider("cycle.backoff_mm"), 1.0);  // 10 mm: far more than needed
    ASSERT_TRUE(window_->warning_codes().contains(QStringLiteral("backoff_excess")));
    QPushButton* button = fix_button("backoff_excess");
    ASSERT_NE(button, nullptr);
    ASSERT_TRUE(button->isVisible());
    const double recommended = window_->computed().cycle().recommended_backoff_mm();
    button->click();
    settle();
    EXPECT_NEAR(window_->scenario().cycle.backoff_mm, recommended, 0.001);
    EXPECT_GE(window_->scenario().cycle.backoff_mm, recommended);
    EXPECT_FALSE(window_->warning_codes().contains(QStringLiteral("backoff_excess")));
    EXPECT_FALSE(window_->warning_codes().contains(QStringLiteral("backoff_too_small")));
}

TEST_F(MainWindowTest, OneClickFixDropsTheFeedToTheKnee) {
    drag_to_fraction(slider("cycle.probe_feed_mm_min"), 0.95);
    ASSERT_TRUE(window_->warning_codes().contains(QStringLiteral("feed_beyond_knee")));
    const double knee = *window_->computed().analysis.knee_feed_mm_min;
    QPushButton* button = fix_button("feed_beyond_knee");
    ASSERT_NE(button, nullptr);
    button->click();
    settle();
    EXPECT_LE(window_->scenario().cycle.probe_feed_mm_min, knee);
    EXPECT_GT(window_->scenario().cycle.probe_feed_mm_min, knee - 1.0);
    EXPECT_FALSE(window_->warning_codes().contains(QStringLiteral("feed_beyond_knee")));
}

// With a 50 mm approach every faster feed still saves time up to the
// end of the knee search; the window says the knee depends on that range, with
// no fix to offer. A looser knee tolerance moves the knee down.
TEST_F(MainWindowTest, FastestCycleAtTheEndOfTheSearchRangeIsSaid) {
    Scenario s = window_->scenario();
    s.cycle.strategy = Strategy::single_touch;
    window_->edit_scenario(s, QStringLiteral("single touch"));
    settle();
    EXPECT_FALSE(window_->warning_codes().contains(QStringLiteral("knee_at_range_end")));
    ASSERT_TRUE(window_->computed().analysis.knee_feed_mm_min.has_value());
    const double knee = *window_->computed().analysis.knee_feed_mm_min;

    s.cycle.knee_tolerance = 0.1;
    window_->edit_scenario(s, QStringLiteral("looser knee"));
    settle();
    ASSERT_TRUE(window_->computed().analysis.knee_feed_mm_min.has_value());
    EXPECT_LT(*window_->computed().analysis.knee_feed_mm_min, knee);

    s.cycle.approach_mm = 50.0;
    s.probe.overtravel_limit_mm = 20.0;  // 5 mm would end the valid feeds first, at 7880 mm/min
    window_->edit_scenario(s, QStringLiteral("long approach"));
    settle();
    ASSERT_TRUE(window_->warning_codes().contains(QStringLiteral("knee_at_range_end")));
    const QStringList texts = window_->warning_texts();
    EXPECT_TRUE(texts.join(QLatin1Char('\n')).contains(QStringLiteral("search faster feeds too")))
        << texts.join(QLatin1Char('\n')).toStdString();
    QPushButton* button = fix_button("knee_at_range_end");
    EXPECT_TRUE(button == nullptr || !button->isVisible());
}

TEST_F(MainWindowTest, OneClickFixStartsFarEnoughOutToTouchAtFullFeed) {
    Scenario s = window_->scenario();
    s.cycle.strategy = Strategy::single_touch;  // the touch measures
    s.cycle.approach_mm = 0.2;  // 2000 mm/min needs 1 mm to reach the feed at T = 60 ms
    window_->edit_scenario(s, QStringLiteral("short approach"));
    settle();
    ASSERT_TRUE(window_->warning_codes().contains(QStringLiteral("touch_while_accelerating")));
    QPushButton* button = fix_button("touch_while_accelerating");
    ASSERT_NE(button, nullptr);
    button->click();
    settle();
    EXPECT_GT(window_->scenario().cycle.approach_mm, 0.2);
    EXPECT_FALSE(window_->warning_codes().contains(QStringLiteral("touch_while_accelerating")));
}

TEST_F(MainWindowTest, CsvExportWritesTheCoreReport) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("report.csv"));
    ASSERT_TRUE(window_->export_csv_report(path)) << window_->last_error().toStdString();
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QString csv = QString::fromUtf8(file.readAll());
    for (const char* section : {"# scenario", "# summary", "# phases", "# warnings", "# sweep"}) {
        EXPECT_TRUE(csv.contains(QLatin1String(section))) << section;
    }
    const QStringList lines = csv.split(QLatin1Char('\n'));
    // One row per phase of the current cycle, after the header.
    const qsizetype phases = lines.indexOf(QStringLiteral("# phases"));
    ASSERT_GE(phases, 0);
    EXPECT_EQ(lines[phases + 1], QStringLiteral("touch,name,start_s,time_s,distance_mm"));
    EXPECT_EQ(lines.indexOf(QStringLiteral(""), phases) - phases - 2,
              static_cast<qsizetype>(window_->computed().cycle().phases().size()));
    // The same bytes as `probecycle-cli report` writes for the scenario.
    const Computed& c = window_->computed();
    EXPECT_EQ(csv.toStdString(), csv_report(window_->scenario(), window_->report_header()));
    // The sweep has one row per report feed.
    const qsizetype sweep = lines.indexOf(QStringLiteral("# sweep"));
    EXPECT_TRUE(lines[sweep + 1].startsWith(QLatin1String("feed_mm_min,cycle_time_s")));
    qsizetype rows = 0;
    for (qsizetype i = sweep + 2; i < lines.size() && !lines[i].isEmpty(); ++i) ++rows;
    EXPECT_EQ(rows, static_cast<qsizetype>(report_feeds(c.scenario, c.analysis).size()));
}

// The toolbar's CSV report is the current tab's: the cycle's, or the
// Calibration and Latency tabs' own reports, which say nothing was fitted
// rather than write an empty file.
TEST_F(MainWindowTest, CsvExportWritesTheCurrentTabsReport) {
    QTemporaryDir dir;
    auto* tabs = window_->findChild<QTabWidget*>(QStringLiteral("tabs"));
    ASSERT_NE(tabs, nullptr);
    const auto first_line = [](const QString& path) {
        QFile file(path);
        return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readLine()).trimmed()
                                              : QString();
    };
    auto* ring = window_->findChild<CalibrationTab*>();
    auto* lab = window_->findChild<LatencyTab*>();
    ASSERT_NE(ring, nullptr);
    ASSERT_NE(lab, nullptr);

    tabs->setCurrentWidget(lab);
    const QString nothing = dir.filePath(QStringLiteral("nothing.csv"));
    EXPECT_FALSE(window_->export_csv_report(nothing));
    EXPECT_TRUE(window_->last_error().contains(QLatin1String("fit the touches first")))
        << window_->last_error().toStdString();
    EXPECT_FALSE(QFileInfo::exists(nothing));

    ASSERT_TRUE(lab->import_file(QStringLiteral(PROBECYCLE_LAB_DATA_DIR "/lab_delay.csv")));
    const QString delay = dir.filePath(QStringLiteral("delay.csv"));
    ASSERT_TRUE(window_->export_csv_report(delay)) << window_->last_error().toStdString();
    EXPECT_EQ(first_line(delay), QStringLiteral("# ProbeCycle delay fit report"));

    tabs->setCurrentWidget(ring);
    ASSERT_TRUE(ring->import_file(QStringLiteral(PROBECYCLE_LAB_DATA_DIR "/lab_ring.csv")));
    const QString calibration = dir.filePath(QStringLiteral("ring.csv"));
    ASSERT_TRUE(window_->export_csv_report(calibration)) << window_->last_error().toStdString();
    EXPECT_EQ(first_line(calibration), QStringLiteral("# ProbeCycle calibration report"));

    tabs->setCurrentIndex(0);
    const QString cycle = dir.filePath(QStringLiteral("cycle.csv"));
    ASSERT_TRUE(window_->export_csv_report(cycle));
    EXPECT_EQ(first_line(cycle), QStringLiteral("# ProbeCycle cycle report"));
}

// Every slider stops at round numbers in its unit (the feed went 3000 -> 3220),
// finely enough to drag, and a round value typed in the spin box puts the
// slider on it and back.
TEST_F(MainWindowTest, SlidersStopAtRoundValuesThatRoundTripThroughTheSpinBox) {
    const QList<QSlider*> sliders = window_->findChildren<QSlider*>();
    int checked = 0;
    for (QSlider* s : sliders) {
        if (!s->objectName().startsWith(QLatin1String("slider:"))) continue;
        const QString key = s->objectName().mid(7);
        auto* box = window_->findChild<QDoubleSpinBox*>(QStringLiteral("spin:") + key);
        ASSERT_NE(box, nullptr) << key.toStdString();
        std::vector<double> values;
        for (int p = s->minimum(); p <= s->maximum(); ++p) {
            s->setValue(p);
            values.push_back(box->value());
        }
        ASSERT_GE(values.size(), 30U) << key.toStdString();
        const bool log = values.front() > 0.0 && values.back() / values.front() >= 100.0;
        const double step = values[1] - values[0];
        for (std::size_t i = 0; i < values.size(); ++i) {
            const double v = values[i];
            const std::string what = key.toStdString() + " at " + std::to_string(v);
            if (i > 0) {
                EXPECT_GT(v, values[i - 1]) << what;
            }
            if (log) {
                // Two significant digits, each stop at most 10 % past the one below
                // (or one step of the spin box's last digit where that is coarser).
                const double m = v / std::pow(10.0, std::floor(std::log10(v)));
                EXPECT_NEAR(m * 10.0, std::round(m * 10.0), 1e-6) << what;
                const double last_digit = std::pow(10.0, -box->decimals());
                if (i > 0 && v - values[i - 1] > 1.5 * last_digit) {
                    EXPECT_LE(v / values[i - 1], 1.1 + 1e-9) << what;
                }
            } else {
                // A 1-2-5 step, the same all along, from a multiple of it.
                const double mantissa = step / std::pow(10.0, std::floor(std::log10(step)));
                EXPECT_TRUE(std::abs(mantissa - 1.0) < 1e-6 || std::abs(mantissa - 2.0) < 1e-6 ||
                            std::abs(mantissa - 5.0) < 1e-6)
                    << key.toStdString() << " steps by " << step;
                EXPECT_NEAR(v / step, std::round(v / step), 1e-6) << what;
                if (i > 0) {
                    EXPECT_NEAR(v - values[i - 1], step, 1e-9) << what;
                }
            }
        }
        // A round value typed in puts the slider on its stop, and the stop gives it back.
        for (std::size_t i = 0; i < values.size(); i += 7) {
            box->setValue(values[(i + values.size() / 2) % values.size()]);
            box->setValue(values[i]);
            EXPECT_EQ(s->value(), s->minimum() + static_cast<int>(i)) << key.toStdString();
            s->setValue(s->value() == s->maximum() ? s->minimum() : s->maximum());
            s->setValue(s->minimum() + static_cast<int>(i));
            EXPECT_EQ(box->value(), values[i]) << key.toStdString();
        }
        ++checked;
    }
    EXPECT_GE(checked, 4);  // feed, time constant, scan period, backoff
    settle();
    // The feed's next stop after 3000 mm/min is 3200.
    spin("cycle.probe_feed_mm_min")->setValue(3000.0);
    QSlider* feed = slider("cycle.probe_feed_mm_min");
    feed->setValue(feed->value() + 1);
    EXPECT_EQ(spin("cycle.probe_feed_mm_min")->value(), 3200.0);
    settle();
    EXPECT_EQ(window_->scenario().cycle.probe_feed_mm_min, 3200.0);
}

// The report says what it is, when, by which version and of which
// scenario, in comment lines a spreadsheet shows as name and value.
TEST_F(MainWindowTest, CsvReportOpensWithTitleDateVersionAndTheScenariosName) {
    QTemporaryDir dir;
    const QString scenario = dir.filePath(QStringLiteral("bore, left.json"));
    ASSERT_TRUE(window_->save_scenario(scenario)) << window_->last_error().toStdString();
    const QString path = dir.filePath(QStringLiteral("report.csv"));
    for (const QString& name :
         {QStringLiteral("untitled"), QStringLiteral("\"bore, left.json\"")}) {
        if (name != QStringLiteral("untitled")) {
            ASSERT_TRUE(window_->open_scenario(scenario));
        } else {
            window_->set_unsaved_answer(UnsavedAnswer::discard);
            ASSERT_TRUE(window_->new_scenario());
        }
        ASSERT_TRUE(window_->export_csv_report(path)) << window_->last_error().toStdString();
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'));
        ASSERT_GT(lines.size(), 5);
        EXPECT_EQ(lines[0], QStringLiteral("# ProbeCycle cycle report"));
        EXPECT_EQ(lines[1], QStringLiteral("# date,") + QString::fromStdString(report_date()));
        EXPECT_TRUE(QDate::fromString(lines[1].mid(7), Qt::ISODate).isValid())
            << lines[1].toStdString();
        EXPECT_EQ(lines[2],
                  QStringLiteral("# version,") + QString::fromStdString(program_version()));
        EXPECT_EQ(lines[3], QStringLiteral("# scenario,") + name);
        EXPECT_EQ(lines[4], QString());
        EXPECT_EQ(lines[5], QStringLiteral("# scenario"));
    }
}

TEST_F(MainWindowTest, ChartsExportAsPng) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("charts.png"));
    ASSERT_TRUE(window_->export_charts_png(path));
    QImage image(path);
    EXPECT_FALSE(image.isNull());
    // At the width asked for (1920 by default), whatever the window's.
    EXPECT_GE(image.width(), 1920);
    EXPECT_GT(image.height(), 400);

    // The current tab's content: the Latency tab gives another picture, with
    // the same title band above it.
    auto* tabs = window_->findChild<QTabWidget*>(QStringLiteral("tabs"));
    ASSERT_NE(tabs, nullptr);
    const QImage cycle = window_->export_image(1280);
    tabs->setCurrentIndex(2);
    settle();
    const QImage latency = window_->export_image(1280);
    EXPECT_GE(latency.width(), 1280);
    EXPECT_NE(cycle.size(), latency.size());
    EXPECT_NE(cycle.copy(0, cycle.height() / 2, 200, 50),
              latency.copy(0, latency.height() / 2, 200, 50));
}

// New and Open ask before unsaved edits would go.
TEST_F(MainWindowTest, NewAsksBeforeUnsavedEditsGo) {
    Scenario edited = window_->scenario();
    edited.cycle.probe_feed_mm_min = 1234.0;
    window_->edit_scenario(edited, QStringLiteral("edit"));
    window_->set_unsaved_answer(UnsavedAnswer::cancel);
    EXPECT_FALSE(window_->new_scenario());
    EXPECT_EQ(window_->scenario().cycle.probe_feed_mm_min, 1234.0);
    EXPECT_TRUE(window_->isWindowModified());
    window_->set_unsaved_answer(UnsavedAnswer::discard);
    EXPECT_TRUE(window_->new_scenario());
    EXPECT_EQ(json(), scenario_to_json(Scenario{}));
    EXPECT_FALSE(window_->isWindowModified());
}

TEST_F(MainWindowTest, SaveAndOpenRoundTrip) {
    drag_to_fraction(slider("cycle.probe_feed_mm_min"), 0.7);
    drag_to_fraction(slider("machine.scan_period_s"), 0.2);
    const std::string edited = json();
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("scenario.json"));
    ASSERT_TRUE(window_->save_scenario(path));
    EXPECT_FALSE(window_->isWindowModified());

    window_->new_scenario();
    settle();
    EXPECT_EQ(json(), scenario_to_json(Scenario{}));
    ASSERT_TRUE(window_->open_scenario(path)) << window_->last_error().toStdString();
    settle();
    EXPECT_EQ(json(), edited);
    // The file is what the CLI reads.
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_EQ(scenario_to_json(scenario_from_json(file.readAll().toStdString())), edited);
}

// The window writes with core's atomic writer, as the CLI does: saving
// through a symbolic link keeps the link, a file keeps its permissions, and a
// failed write keeps the old file.
TEST_F(MainWindowTest, SaveWritesThroughLinksKeepsPermissionsAndOldFileOnFailure) {
    QTemporaryDir dir;
    const QString target = dir.filePath(QStringLiteral("target.json"));
    const QString link = dir.filePath(QStringLiteral("link.json"));
    ASSERT_TRUE(window_->save_scenario(target));
    ASSERT_TRUE(QFile::setPermissions(target, QFile::ReadOwner | QFile::WriteOwner));
    ASSERT_TRUE(QFile::link(target, link));

    drag_to_fraction(slider("cycle.probe_feed_mm_min"), 0.7);
    ASSERT_TRUE(window_->save_scenario(link)) << window_->last_error().toStdString();
    EXPECT_TRUE(QFileInfo(link).isSymLink());
    EXPECT_EQ(QFile::permissions(target) & (QFile::ReadGroup | QFile::ReadOther),
              QFile::Permissions());
    QFile file(target);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_EQ(file.readAll().toStdString(), json());
    file.close();

    // A directory that does not exist: refused, named, nothing written.
    const QString missing = dir.filePath(QStringLiteral("no/such/dir/s.json"));
    EXPECT_FALSE(window_->save_scenario(missing));
    EXPECT_TRUE(window_->last_error().contains(QStringLiteral("no/such/dir")))
        << window_->last_error().toStdString();
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 2);
}

TEST_F(MainWindowTest, BadFileNamesTheProblemAndKeepsTheCurrentScenario) {
    drag_to_fraction(slider("cycle.probe_feed_mm_min"), 0.6);
    const std::string current = json();
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bad.json"));
    {
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(R"({"machine": {"scan_period_s": -1}})");
    }
    EXPECT_FALSE(window_->open_scenario(path));
    EXPECT_TRUE(window_->last_error().contains(QStringLiteral("machine.scan_period_s")))
        << window_->last_error().toStdString();
    settle();
    EXPECT_EQ(json(), current);
    EXPECT_TRUE(window_->current_file().isEmpty());

    {
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(R"({"machine": {"scan_period": 0.004}})");  // unknown key
    }
    EXPECT_FALSE(window_->open_scenario(path));
    EXPECT_TRUE(window_->last_error().contains(QStringLiteral("scan_period")));
    EXPECT_FALSE(window_->open_scenario(dir.filePath(QStringLiteral("missing.json"))));
    settle();
    EXPECT_EQ(json(), current);
}

// File > Import Machine > LinuxCNC INI: the machine section is replaced in one
// undoable edit; the probe and the cycle stay as they were.
TEST_F(MainWindowTest, ImportingALinuxCncIniIsOneUndoableEdit) {
    drag_to_fraction(slider("cycle.probe_feed_mm_min"), 0.6);
    const std::string before = json();
    const Scenario edited = window_->scenario();
    const int steps = window_->undo_stack()->count();

    const QString ini = QStringLiteral(PROBECYCLE_TEST_DATA_DIR "/linuxcnc/mill_inch.ini");
    ASSERT_TRUE(window_->import_linuxcnc_machine(ini)) << window_->last_error().toStdString();
    settle();
    const Machine& m = window_->scenario().machine;
    EXPECT_EQ(m.accel_model, AccelModel::constant_accel);
    EXPECT_EQ(m.max_accel_mm_s2, 635.0);
    EXPECT_EQ(m.rapid_feed_mm_min, 3810.0);
    EXPECT_EQ(m.scan_period_s, 0.0005);
    EXPECT_EQ(m.controller_latency_s, 0.001);
    EXPECT_EQ(scenario_to_json(
                  Scenario{edited.machine, window_->scenario().probe, window_->scenario().cycle}),
              before);
    EXPECT_EQ(window_->undo_stack()->count(), steps + 1);
    EXPECT_TRUE(window_->undo_stack()->undoText().contains(QStringLiteral("mill_inch.ini")))
        << window_->undo_stack()->undoText().toStdString();
    EXPECT_TRUE(window_->computed().valid());
    EXPECT_TRUE(window_->has_unsaved_changes());

    const std::string imported = json();
    window_->undo_stack()->undo();
    settle();
    EXPECT_EQ(json(), before);
    window_->undo_stack()->redo();
    settle();
    EXPECT_EQ(json(), imported);

    // The action sits in File > Import Machine.
    auto* action = window_->findChild<QAction*>(QStringLiteral("action-import-linuxcnc"));
    ASSERT_NE(action, nullptr);
    bool in_file_menu = false;
    for (QAction* menu : window_->menuBar()->actions()) {
        if (menu->menu() == nullptr) continue;
        for (QAction* item : menu->menu()->actions()) {
            if (item->menu() != nullptr && item->menu()->actions().contains(action)) {
                in_file_menu = true;
            }
        }
    }
    EXPECT_TRUE(in_file_menu);
}

TEST_F(MainWindowTest, ABadLinuxCncIniIsRefusedAndChangesNothing) {
    drag_to_fraction(slider("cycle.probe_feed_mm_min"), 0.6);
    const std::string before = json();
    const int steps = window_->undo_stack()->count();
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("mill.ini"));
    {
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(
            "[EMCMOT]\nSERVO_PERIOD = 1000000\n[TRAJ]\nLINEAR_UNITS = mm\n"
            "[AXIS_X]\nMAX_VELOCITY = 100\nMAX_ACCELERATION = 0.5\n"
            "[AXIS_Y]\nMAX_VELOCITY = 100\nMAX_ACCELERATION = 800\n"
            "[AXIS_Z]\nMAX_VELOCITY = 100\nMAX_ACCELERATION = 800\n");
    }
    EXPECT_FALSE(window_->import_linuxcnc_machine(path));
    const QString error = window_->last_error();
    for (const char* part : {"mill.ini", "[AXIS_X] MAX_ACCELERATION, line 7", "0.5",
                             "machine.max_accel_mm_s2", "mm/s^2"}) {
        EXPECT_TRUE(error.contains(QLatin1String(part))) << part << " in " << error.toStdString();
    }
    EXPECT_FALSE(window_->import_linuxcnc_machine(dir.filePath(QStringLiteral("missing.ini"))));
    EXPECT_TRUE(window_->last_error().contains(QStringLiteral("missing.ini")));
    settle();
    EXPECT_EQ(json(), before);
    EXPECT_EQ(window_->undo_stack()->count(), steps);
}

// The Latency tab's Apply puts the fitted delay into the scenario
// as one undoable edit (the delay less the interface and half the scan).
TEST_F(MainWindowTest, LatencyTabAppliesTheFittedDelayUndoably) {
    auto* tab = window_->findChild<LatencyTab*>();
    ASSERT_NE(tab, nullptr);
    // X+ with a total delay of 9 ms: p = 10 + v * 0.009 at 100, 1000, 3000 mm/min.
    tab->set_touches_text(
        QStringLiteral("axis,direction,feed_mm_min,measured_mm\n"
                       "X,1,100,10.015\nX,1,1000,10.15\nX,1,3000,10.45\n"));
    ASSERT_TRUE(tab->fit()) << tab->last_error().toStdString();
    const double before = window_->scenario().machine.controller_latency_s;
    ASSERT_TRUE(tab->apply_to_scenario()) << tab->apply_problem().toStdString();
    settle();
    // 9 ms - interface 2 ms - half of the 4 ms scan = 5 ms.
    EXPECT_NEAR(window_->scenario().machine.controller_latency_s, 0.005, 1e-9);
    window_->undo_stack()->undo();
    settle();
    EXPECT_DOUBLE_EQ(window_->scenario().machine.controller_latency_s, before);
}

// The compensation comparison uses the scenario's machine; edits made on the
// Cycle tab reach the hidden Latency tab, which catches up when shown.
TEST_F(MainWindowTest, HiddenLatencyTabCatchesUpWhenShown) {
    auto* tabs = window_->findChild<QTabWidget*>(QStringLiteral("tabs"));
    auto* tab = window_->findChild<LatencyTab*>();
    ASSERT_NE(tabs, nullptr);
    ASSERT_NE(tab, nullptr);
    ASSERT_EQ(tab->compensation_inputs().touch, TouchMotion::braking);
    tabs->setCurrentWidget(tab);
    settle();
    ASSERT_TRUE(tab->comparison().has_value());
    const double recorded_before = tab->comparison()->recorded_speed_mm_s;

    tabs->setCurrentIndex(0);
    settle();
    Scenario slower = window_->scenario();
    slower.machine.time_constant_s = 0.2;  // gentler braking: faster when recorded
    window_->edit_scenario(slower, QStringLiteral("time constant"));
    settle();
    tabs->setCurrentWidget(tab);
    settle();
    ASSERT_TRUE(tab->comparison().has_value());
    EXPECT_GT(tab->comparison()->recorded_speed_mm_s, recorded_before);
}

// Moving the start out to reach 10000 mm/min (5 mm) would make a 10 mm bore
// narrower than two approach distances: that fix is not offered.
TEST_F(MainWindowTest, AFixThatWouldInvalidateTheScenarioIsNotOffered) {
    Scenario bore = window_->scenario();
    bore.cycle.strategy = Strategy::single_touch;  // the touch measures
    bore.cycle.feature = Feature::bore;
    bore.cycle.feature_size_mm = 10.0;
    bore.cycle.approach_mm = 1.0;
    bore.cycle.probe_feed_mm_min = 10000.0;
    window_->edit_scenario(bore, QStringLiteral("small bore"));
    settle();
    ASSERT_TRUE(window_->warning_codes().contains(QStringLiteral("touch_while_accelerating")));
    EXPECT_FALSE(window_->apply_fix_for(QStringLiteral("touch_while_accelerating")));
    settle();
    EXPECT_EQ(window_->scenario().cycle.approach_mm, 1.0);
    EXPECT_TRUE(validate(window_->scenario()).empty());
}

// Errors first, counted in the panel's title and on the Cycle tab.
TEST_F(MainWindowTest, ErrorsAreListedFirstAndCounted) {
    Scenario s = window_->scenario();  // two-touch surface
    s.cycle.approach_mm = 0.2;         // inside the part's position uncertainty: a warning
    s.cycle.part_position_uncertainty_mm = 0.3;
    s.cycle.backoff_mm = 0.5;  // an error
    window_->edit_scenario(s, QStringLiteral("errors"));
    settle();
    const QStringList codes = window_->warning_codes();
    ASSERT_GE(codes.size(), 2) << codes.join(QLatin1Char(' ')).toStdString();
    EXPECT_EQ(codes.front(), QStringLiteral("backoff_too_small"));
    auto* title = window_->findChild<QLabel*>(QStringLiteral("warnings-title"));
    ASSERT_NE(title, nullptr);
    EXPECT_TRUE(title->text().contains(QStringLiteral("Errors: 1"))) << title->text().toStdString();
    EXPECT_TRUE(title->text().contains(QStringLiteral("Warnings: ")))
        << title->text().toStdString();
    auto* tabs = window_->findChild<QTabWidget*>(QStringLiteral("tabs"));
    ASSERT_NE(tabs, nullptr);
    EXPECT_TRUE(tabs->tabText(0).startsWith(QStringLiteral("Cycle (")))
        << tabs->tabText(0).toStdString();
    EXPECT_FALSE(tabs->tabIcon(0).isNull());

    window_->edit_scenario(Scenario{}, QStringLiteral("defaults"));
    settle();
    const int problems = static_cast<int>(window_->warning_codes().size());
    EXPECT_EQ(tabs->tabText(0), problems == 0 ? QStringLiteral("Cycle") : tabs->tabText(0));
}

// The warnings panel keeps room for about three problems at 1280x800, and
// dragging it up leaves the charts readable.
TEST_F(MainWindowTest, WarningsPanelAndChartsKeepTheirRoom) {
    auto* box = window_->findChild<QWidget*>(QStringLiteral("warnings-box"));
    ASSERT_NE(box, nullptr);
    const int line = window_->fontMetrics().height();
    EXPECT_GE(box->height(), 8 * line);
    auto* splitter = qobject_cast<QSplitter*>(box->parentWidget());
    ASSERT_NE(splitter, nullptr);
    splitter->setSizes({1, 10000});  // the user drags the panel up as far as it goes
    QCoreApplication::processEvents();
    EXPECT_GE(splitter->widget(0)->height(), 20 * line);
}

// Every one-click fix offered, on every preset over the defaults
// and over the README's bore example, clears the warning it fixes.
TEST_F(MainWindowTest, EveryOneClickFixOnEveryPresetClearsItsWarning) {
    Scenario bore;  // resources/examples/bore_two_touch.json
    bore.cycle.feature = Feature::bore;
    bore.cycle.feature_size_mm = 40.0;
    bore.cycle.backoff_mm = 3.0;
    bore.cycle.target_uncertainty_mm = 0.005;
    int applied = 0;
    for (const Scenario& base : {Scenario{}, bore}) {
        for (const char* preset : kPresets) {
            for (double feed : {3000.0, 9500.0}) {
                Scenario s = base;
                s.cycle.probe_feed_mm_min = feed;
                window_->edit_scenario(s, QStringLiteral("base"));
                settle();
                ASSERT_TRUE(window_->apply_preset(QLatin1String(preset))) << preset;
                settle();
                const Scenario before = window_->scenario();
                for (const QString& code : window_->warning_codes()) {
                    window_->edit_scenario(before, QStringLiteral("back"));
                    settle();
                    if (!window_->apply_fix_for(code)) continue;
                    ++applied;
                    settle();
                    EXPECT_FALSE(window_->warning_codes().contains(code))
                        << preset << " at " << feed << ": " << code.toStdString();
                }
            }
        }
    }
    EXPECT_GT(applied, 10);
}

TEST_F(MainWindowTest, UndoRestoresAndRedoReapplies) {
    const std::string original = json();
    QSlider* feed = slider("cycle.probe_feed_mm_min");
    // A drag is many steps of one key: one undo step.
    for (int position : {100, 200, 300, 400}) feed->setValue(position);
    settle();
    const std::string dragged = json();
    ASSERT_NE(dragged, original);
    EXPECT_EQ(window_->undo_stack()->count(), 1);
    window_->undo_stack()->undo();
    settle();
    EXPECT_EQ(json(), original);
    EXPECT_EQ(feed->value(), slider("cycle.probe_feed_mm_min")->value());
    window_->undo_stack()->redo();
    settle();
    EXPECT_EQ(json(), dragged);

    // Fixes and presets undo too.
    ASSERT_TRUE(window_->apply_preset(QStringLiteral(":/presets/machine_high_speed_skip.json")));
    settle();
    EXPECT_DOUBLE_EQ(window_->scenario().machine.scan_period_s, 4e-6);
    window_->undo_stack()->undo();
    settle();
    EXPECT_EQ(json(), dragged);
}

// A preset says what it overwrote (here a measured latency), and
// Undo brings it back.
TEST_F(MainWindowTest, APresetSaysWhatItOverwrote) {
    Scenario measured = window_->scenario();
    measured.machine.controller_latency_s = 0.0123;
    window_->edit_scenario(measured, QStringLiteral("apply the measured delay"));
    settle();
    ASSERT_TRUE(window_->apply_preset(QStringLiteral(":/presets/machine_standard_skip.json")));
    settle();
    const QStringList changes = window_->last_preset_changes();
    ASSERT_EQ(changes.size(), 1) << changes.join(QLatin1Char('|')).toStdString();
    EXPECT_TRUE(changes.front().contains(QStringLiteral("12.300 ms")))
        << changes.front().toStdString();
    EXPECT_TRUE(changes.front().contains(QStringLiteral("2.000 ms")))
        << changes.front().toStdString();
    EXPECT_DOUBLE_EQ(window_->scenario().machine.controller_latency_s, 0.002);
    // The status bar says the same (it once compared the scenario with itself).
    const QString status = window_->statusBar()->currentMessage();
    EXPECT_TRUE(status.contains(QStringLiteral("12.300 ms"))) << status.toStdString();
    EXPECT_FALSE(status.contains(QStringLiteral("nothing to change"))) << status.toStdString();
    window_->undo_stack()->undo();
    settle();
    EXPECT_DOUBLE_EQ(window_->scenario().machine.controller_latency_s, 0.0123);
}

// A message longer than the status bar (a preset that changes many keys,
// in a narrow window) is cut with an ellipsis inside the bar, not at the
// window's edge, and its whole text is the bar's tooltip; in a window wide
// enough it is whole, with no tooltip.
TEST_F(MainWindowTest, ALongStatusMessageIsCutToTheBarAndWholeInItsTooltip) {
    window_->resize(1024, 700);
    settle();
    ASSERT_TRUE(
        window_->apply_preset(QStringLiteral(":/presets/machine_linear_after_interpolation.json")));
    settle();
    QStatusBar* bar = window_->statusBar();
    const QString shown = bar->currentMessage();
    const QString whole = bar->toolTip();
    ASSERT_FALSE(whole.isEmpty()) << shown.toStdString();
    EXPECT_LE(bar->fontMetrics().horizontalAdvance(shown), bar->width());
    EXPECT_TRUE(shown.endsWith(QChar(0x2026))) << shown.toStdString();
    EXPECT_TRUE(whole.startsWith(shown.chopped(1))) << whole.toStdString();
    const QStringList changes = window_->last_preset_changes();
    ASSERT_GT(changes.size(), 1);
    for (const QString& change : changes) {
        EXPECT_TRUE(whole.contains(change)) << change.toStdString();
    }
    window_->resize(bar->fontMetrics().horizontalAdvance(whole) + 200, 700);
    settle();
    EXPECT_EQ(bar->currentMessage(), whole);
    EXPECT_TRUE(bar->toolTip().isEmpty());
}

TEST_F(MainWindowTest, EveryPresetLoadsAndChangesOnlyItsKeys) {
    for (const char* preset : kPresets) {
        const Cycle cycle_before = window_->scenario().cycle;
        EXPECT_TRUE(window_->apply_preset(QLatin1String(preset))) << preset;
        settle();
        EXPECT_EQ(window_->scenario().cycle.probe_feed_mm_min, cycle_before.probe_feed_mm_min);
        EXPECT_TRUE(window_->computed().valid()) << preset;
    }
    EXPECT_TRUE(window_->scenario().machine.latched_input);  // the last machine preset
    // The latched preset names the input only: the linear filter stays.
    EXPECT_EQ(window_->scenario().machine.filter, FilterKind::linear);
    EXPECT_DOUBLE_EQ(window_->scenario().machine.filter_time_s, 0.064);
    EXPECT_DOUBLE_EQ(window_->scenario().probe.overtravel_limit_mm, 2.0);
}

TEST_F(MainWindowTest, PinnedBaselineStaysDrawnAndReadoutsShowTheDifference) {
    EXPECT_FALSE(window_->series_visible(QStringLiteral("cycle_time.baseline_two_touch")));
    window_->pin_baseline();
    settle();
    const QList<QPointF> baseline =
        window_->series_points(QStringLiteral("cycle_time.baseline_two_touch"));
    EXPECT_EQ(baseline.size(), 500);
    EXPECT_TRUE(window_->series_visible(QStringLiteral("cycle_time.baseline_two_touch")));
    // 20 ms: a shorter stop, still a valid cycle with the 2 mm backoff.
    drag_to_fraction(slider("machine.time_constant_s"), 0.3);
    ASSERT_TRUE(window_->computed().cycle().valid());
    EXPECT_EQ(window_->series_points(QStringLiteral("cycle_time.baseline_two_touch")), baseline);
    EXPECT_NE(window_->series_points(QStringLiteral("cycle_time.two_touch")), baseline);
    EXPECT_TRUE(window_->readout_detail(Readout::cycle_time).contains(QStringLiteral("baseline")));
    window_->clear_baseline();
    settle();
    EXPECT_FALSE(window_->series_visible(QStringLiteral("cycle_time.baseline_two_touch")));
    EXPECT_FALSE(window_->readout_detail(Readout::cycle_time).contains(QStringLiteral("baseline")));
}

// A backoff too small makes the cycle invalid. The readout shows no time but
// why, the chart's dot is the invalid one, and against a pinned baseline no
// time difference is offered.
// An invalid cycle is drawn as invalid. Its feed is a red dashed rule (no dot
// at a time it does not have), the curves are grey where their cycles are
// invalid, with one legend entry; the legend names the baseline and has no
// target without one; the log time axis labels values under 1 s; and a dot at
// the end of the feed axis is drawn whole.
TEST_F(MainWindowTest, ChartsDrawInvalidCyclesAsInvalidAndNameWhatTheyShow) {
    auto* cycle_time = window_->findChild<PlotView*>(QStringLiteral("chart:cycle_time"));
    auto* overtravel = window_->findChild<PlotView*>(QStringLiteral("chart:overtravel"));
    ASSERT_NE(cycle_time, nullptr);
    ASSERT_NE(overtravel, nullptr);
    Scenario roomy = window_->scenario();
    roomy.probe.overtravel_limit_mm = 50.0;  // every feed valid
    window_->edit_scenario(roomy, QStringLiteral("roomy"));
    settle();
    EXPECT_FALSE(cycle_time->legend_texts().contains(QStringLiteral("Invalid")));
    EXPECT_FALSE(window_->series_visible(QStringLiteral("cycle_time.single_touch_invalid")));
    EXPECT_FALSE(overtravel->legend_texts().contains(QStringLiteral("Target")));
    EXPECT_FALSE(cycle_time->legend_texts().contains(QStringLiteral("Baseline (dashed)")));
    EXPECT_GT(cycle_time->x_range().hi, 10000.0);
    EXPECT_LT(cycle_time->x_range().lo, 10.0);

    Scenario s = window_->scenario();
    s.cycle.strategy = Strategy::single_touch;
    s.cycle.approach_mm = 2.0;
    s.cycle.probe_feed_mm_min = 9000.0;
    s.probe.overtravel_limit_mm = 3.0;
    window_->edit_scenario(s, QStringLiteral("fast"));
    settle();
    ASSERT_FALSE(window_->computed().cycle().valid());
    EXPECT_FALSE(window_->series_visible(QStringLiteral("cycle_time.current")));
    EXPECT_FALSE(window_->series_visible(QStringLiteral("cycle_time.feed")));
    EXPECT_TRUE(window_->series_visible(QStringLiteral("cycle_time.current_invalid")));
    const QList<QPointF> rule =
        window_->series_points(QStringLiteral("cycle_time.current_invalid"));
    ASSERT_EQ(rule.size(), 1);
    EXPECT_DOUBLE_EQ(rule.front().x(), 9000.0);

    const SweepResult& sweep = window_->computed().single_touch;
    const QList<QPointF> curve = window_->series_points(QStringLiteral("cycle_time.single_touch"));
    const QList<QPointF> grey =
        window_->series_points(QStringLiteral("cycle_time.single_touch_invalid"));
    ASSERT_EQ(curve.size(), static_cast<qsizetype>(sweep.points.size()));
    ASSERT_EQ(grey.size(), curve.size());
    int invalid = 0;
    for (std::size_t i = 0; i < sweep.points.size(); ++i) {
        const auto k = static_cast<qsizetype>(i);
        const bool valid = sweep.points[i].valid();
        invalid += valid ? 0 : 1;
        EXPECT_EQ(std::isfinite(curve[k].y()), valid) << sweep.points[i].feed_mm_min;
        if (!valid) {
            EXPECT_DOUBLE_EQ(grey[k].y(), sweep.points[i].cycle_time_s);
        }
    }
    EXPECT_GT(invalid, 0);
    EXPECT_TRUE(cycle_time->legend_texts().contains(QStringLiteral("Invalid")))
        << cycle_time->legend_texts().join(QLatin1Char('|')).toStdString();
    // The curve reaches 0.2 s: the log axis labels 0.1.
    EXPECT_TRUE(cycle_time->y_labels(PlotView::Side::left).contains(QStringLiteral("0.1")))
        << cycle_time->y_labels(PlotView::Side::left).join(QLatin1Char('|')).toStdString();

    window_->pin_baseline();
    s.cycle.target_uncertainty_mm = 0.01;
    window_->edit_scenario(s, QStringLiteral("target"));
    settle();
    EXPECT_TRUE(overtravel->legend_texts().contains(QStringLiteral("Target")));
    EXPECT_TRUE(cycle_time->legend_texts().contains(QStringLiteral("Baseline (dashed)")));
    window_->clear_baseline();
    settle();
    EXPECT_FALSE(cycle_time->legend_texts().contains(QStringLiteral("Baseline (dashed)")));
}

TEST_F(MainWindowTest, AnInvalidCycleShowsNoTimeButWhy) {
    window_->pin_baseline();
    settle();
    EXPECT_FALSE(window_->series_points(QStringLiteral("cycle_time.current")).isEmpty());
    EXPECT_TRUE(window_->series_points(QStringLiteral("cycle_time.current_invalid")).isEmpty());
    Scenario s = window_->scenario();
    s.cycle.backoff_mm = 0.5;
    window_->edit_scenario(s, QStringLiteral("short backoff"));
    settle();
    ASSERT_FALSE(window_->computed().cycle().valid());
    EXPECT_EQ(window_->readout_text(Readout::cycle_time), QStringLiteral("Invalid"));
    EXPECT_TRUE(
        window_->readout_detail(Readout::cycle_time).contains(QStringLiteral("Backoff too small")))
        << window_->readout_detail(Readout::cycle_time).toStdString();
    EXPECT_FALSE(window_->readout_detail(Readout::cycle_time).contains(QStringLiteral("baseline")));
    EXPECT_EQ(window_->readout_alert(Readout::cycle_time), Alert::alarm);
    EXPECT_TRUE(window_->series_points(QStringLiteral("cycle_time.current")).isEmpty());
    ASSERT_EQ(window_->series_points(QStringLiteral("cycle_time.current_invalid")).size(), 1);
    EXPECT_TRUE(window_->series_visible(QStringLiteral("cycle_time.current_invalid")));
    EXPECT_FALSE(window_->series_visible(QStringLiteral("cycle_time.current")));
    const auto* phases = window_->findChild<PlotView*>(QStringLiteral("chart:phases"));
    ASSERT_NE(phases, nullptr);
    // Grey phases, titled with what the readout gives as the reason.
    EXPECT_TRUE(phases->title().startsWith(QLatin1String("Phases of an invalid cycle (grey): ")))
        << phases->title().toStdString();
    EXPECT_TRUE(phases->title().endsWith(window_->readout_detail(Readout::cycle_time)))
        << phases->title().toStdString();

    ASSERT_TRUE(window_->apply_fix_for(QStringLiteral("backoff_too_small")));
    settle();
    EXPECT_TRUE(window_->computed().cycle().valid());
    EXPECT_NE(window_->readout_text(Readout::cycle_time), QStringLiteral("Invalid"));
    EXPECT_FALSE(window_->series_visible(QStringLiteral("cycle_time.current_invalid")));
    EXPECT_TRUE(phases->title().startsWith(QStringLiteral("Phases: total")))
        << phases->title().toStdString();
}

TEST_F(MainWindowTest, LanguagesSwitchTheInterface) {
    const QString english = window_->menuBar()->actions().first()->text();
    const QString english_time = window_->readout_text(Readout::cycle_time);
    window_->set_language(QStringLiteral("ru"));
    settle();
    EXPECT_EQ(current_language(), QStringLiteral("ru"));
    EXPECT_NE(window_->menuBar()->actions().first()->text(), english);
    EXPECT_NE(window_->readout_text(Readout::cycle_time), english_time);  // "с", decimal comma
    window_->set_language(QStringLiteral("zh_CN"));
    settle();
    EXPECT_EQ(current_language(), QStringLiteral("zh_CN"));
    window_->set_language(QStringLiteral("en"));
    settle();
    EXPECT_EQ(window_->menuBar()->actions().first()->text(), english);
}

// Help has a guide (F1) with the phases, the formulas, the charts
// and how to measure the delay, in the interface language, with a link to
// the README.
TEST_F(MainWindowTest, HelpHasAGuideInTheInterfaceLanguage) {
    auto* action = window_->findChild<QAction*>(QStringLiteral("action-guide"));
    ASSERT_NE(action, nullptr);
    EXPECT_EQ(action->shortcut(), QKeySequence(QKeySequence::HelpContents));
    HelpGuide* guide = window_->show_guide();
    ASSERT_NE(guide, nullptr);
    EXPECT_TRUE(guide->isVisible());
    EXPECT_EQ(window_->show_guide(), guide);  // one guide window
    const QString english = guide->html();
    for (const char* words : {"Pretravel", "Overtravel = pretravel", "the knee",
                              "Measuring the delay", "Open the README"}) {
        EXPECT_TRUE(english.contains(QLatin1String(words))) << words;
    }
    // It opens on getting started: what to enter first, what the readouts mean.
    const qsizetype start = english.indexOf(QLatin1String("Getting started"));
    EXPECT_GE(start, 0);
    EXPECT_LT(start, english.indexOf(QLatin1String("One touch, phase by phase")));
    EXPECT_TRUE(english.contains(QLatin1String("Start near your machine")));
    window_->set_language(QStringLiteral("ru"));
    settle();
    const QString russian = guide->html();
    EXPECT_NE(russian, english);
    EXPECT_TRUE(russian.contains(QStringLiteral("Перебег"))) << russian.toStdString();
    window_->set_language(QStringLiteral("en"));
    settle();
    guide->close();
}

// Quit asks about unsaved edits (untitled ones too) and means the
// answer: Save keeps them in the file and they come back; Discard does not
// bring them back; Cancel keeps the window open.
TEST(MainWindowSettingsTest, QuitSavesOrDiscardsAsAnswered) {
    QSettings().clear();  // test mode: ~/.qttest, never the user's settings
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("kept.json"));
    MainWindowOptions options;
    options.show_dialogs = false;
    Scenario saved;
    saved.cycle.probe_feed_mm_min = 1234.0;
    Scenario edited = saved;
    edited.machine.scan_period_s = 0.001;
    {
        options.unsaved_answer = UnsavedAnswer::save;
        MainWindow first(options);
        first.resize(1111, 777);
        first.show();
        first.edit_scenario(saved, QStringLiteral("edit"));
        ASSERT_TRUE(first.save_scenario(path));
        first.edit_scenario(edited, QStringLiteral("edit"));
        EXPECT_TRUE(first.close());  // saves the edits into the file
    }
    {
        MainWindow second(options);
        EXPECT_EQ(scenario_to_json(second.scenario()), scenario_to_json(edited));
        EXPECT_EQ(second.current_file(), QFileInfo(path).absoluteFilePath());
        EXPECT_EQ(second.size(), QSize(1111, 777));
    }
    {
        // Cancel: the window stays open with its edits.
        options.unsaved_answer = UnsavedAnswer::cancel;
        MainWindow third(options);
        third.show();
        Scenario more = third.scenario();
        more.cycle.backoff_mm = 3.0;
        third.edit_scenario(more, QStringLiteral("edit"));
        EXPECT_FALSE(third.close());
        EXPECT_TRUE(third.isVisible());
        // Discard: closed, and the next start has the file as saved.
        third.set_unsaved_answer(UnsavedAnswer::discard);
        EXPECT_TRUE(third.close());
    }
    MainWindow fourth(options);
    EXPECT_EQ(scenario_to_json(fourth.scenario()), scenario_to_json(edited));
    EXPECT_FALSE(fourth.isWindowModified());
    QSettings().clear();
}

TEST(MainWindowSettingsTest, DiscardedUntitledEditsDoNotComeBack) {
    QSettings().clear();
    MainWindowOptions options;
    options.show_dialogs = false;
    options.unsaved_answer = UnsavedAnswer::discard;
    {
        MainWindow first(options);
        first.show();
        Scenario edited;
        edited.cycle.probe_feed_mm_min = 1234.0;
        first.edit_scenario(edited, QStringLiteral("edit"));
        EXPECT_TRUE(first.close());
    }
    MainWindow second(options);
    EXPECT_EQ(scenario_to_json(second.scenario()), scenario_to_json(Scenario{}));
    QSettings().clear();
}

// The parameter panel's width follows the window's size at every start
// (two columns at 1920x1080, one at 1280x800) until the user drags the
// divider; from then on the width they chose comes back.
TEST(MainWindowSettingsTest, ThePanelsWidthFollowsTheWindowUntilTheUserSetsIt) {
    QSettings().clear();
    MainWindowOptions options;
    options.show_dialogs = false;
    options.unsaved_answer = UnsavedAnswer::discard;
    const auto panel_width = [](MainWindow& window) {
        return window.findChild<QSplitter*>(QStringLiteral("main-splitter"))->sizes().value(0);
    };
    {
        MainWindow first(options);
        first.resize(1920, 1080);
        first.show();
        QCoreApplication::processEvents();
        EXPECT_GT(panel_width(first), ParameterPanel::two_column_width());
        EXPECT_TRUE(first.close());
        // Neither divider was dragged: neither is kept (the warnings pane's
        // height follows its warnings at the next start too).
        EXPECT_FALSE(QSettings().contains(QStringLiteral("window/splitter")));
        EXPECT_FALSE(QSettings().contains(QStringLiteral("window/right_splitter")));
    }
    {
        MainWindow second(options);  // remembered 1920x1080, made smaller
        second.resize(1280, 800);
        second.show();
        QCoreApplication::processEvents();
        EXPECT_EQ(panel_width(second), ParameterPanel::one_column_width());
        auto* splitter = second.findChild<QSplitter*>(QStringLiteral("main-splitter"));
        splitter->setSizes({400, splitter->width() - 400});
        emit splitter->splitterMoved(400, 1);  // as a drag of the divider says
        EXPECT_TRUE(second.close());
    }
    MainWindow third(options);
    third.show();
    QCoreApplication::processEvents();
    EXPECT_EQ(panel_width(third), 400);
    QSettings().clear();
}

TEST_F(MainWindowTest, InvalidCombinationIsShownAndKeepsTheLastCharts) {
    Scenario s = window_->scenario();
    s.cycle.feature = Feature::bore;
    s.cycle.feature_size_mm = 5.0;  // narrower than two approach distances
    s.cycle.approach_mm = 5.0;
    window_->edit_scenario(s, QStringLiteral("invalid"));
    settle();
    EXPECT_TRUE(window_->warning_codes().contains(QStringLiteral("invalid:cycle.feature_size_mm")));
    EXPECT_EQ(window_->series_points(QStringLiteral("cycle_time.two_touch")).size(), 500);
}

// File > "Program for the Control…" opens the tuned cycle's dialog
// on the window's scenario (the default: a surface); its program is the
// core's for that scenario.
TEST_F(MainWindowTest, ProgramForTheControlWritesTheWindowsCycle) {
    QAction* action = nullptr;
    for (QAction* a : window_->menuBar()->actions().front()->menu()->actions()) {
        if (a->text().contains(QStringLiteral("Program for the"))) action = a;
    }
    ASSERT_NE(action, nullptr);
    ProgramDialog* dialog = window_->open_cycle_program_dialog();
    ASSERT_NE(dialog, nullptr);
    EXPECT_EQ(dialog->kind(), ProgramKind::cycle);
    dialog->set_dialect(DialectId::linuxcnc);
    dialog->update_now();
    ASSERT_TRUE(dialog->can_save()) << dialog->problem().toStdString();
    EXPECT_EQ(dialog->program_text().toStdString(),
              write_program(make_cycle_plan(window_->scenario(), {}), dialect(DialectId::linuxcnc),
                            dialog->date()));
    dialog->close();
}

}  // namespace
}  // namespace probecycle::ui
