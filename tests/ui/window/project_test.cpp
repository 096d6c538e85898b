// The window's project file (docs/files.md, "The project file";
// MainWindow::save_project/open_scenario in ui/window/main_window.h): the
// whole session opens again exactly, a bad file changes nothing, plain
// scenario files keep working, and unsaved lab data is asked about.

#include <gtest/gtest.h>

#include <QApplication>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QTemporaryDir>
#include <memory>
#include <string>

#include "core/common/file_io.h"
#include "core/cycle/scenario.h"
#include "core/project/project_file.h"
#include "tests/ui/window/test_window.h"
#include "ui/comparison/comparison_tab.h"
#include "ui/lab/calibration_tab.h"
#include "ui/lab/latency_tab.h"
#include "ui/window/main_window.h"

namespace probecycle::ui {
namespace {

const QString kLabData = QStringLiteral(PROBECYCLE_TEST_DATA_DIR);

CalibrationTab* calibration(const MainWindow& w) {
    return w.findChild<CalibrationTab*>();
}
LatencyTab* latency(const MainWindow& w) {
    return w.findChild<LatencyTab*>();
}
ComparisonTab* comparison(const MainWindow& w) {
    return w.findChild<ComparisonTab*>();
}

std::string read(const QString& path) {
    return read_text_file(QFile::encodeName(path).toStdString());
}

void write(const QString& path, const std::string& text) {
    write_file_atomically(QFile::encodeName(path).toStdString(), text);
}

// A session with something in every part: an edited scenario, a baseline,
// a ring fit whose paste box was edited afterwards, a delay fit, the
// compensation setup and a comparison run on simulated files.
void fill_session(MainWindow& w, const QString& data_folder) {
    Scenario s = w.scenario();
    s.cycle.probe_feed_mm_min = 1500.0;
    w.edit_scenario(s, QStringLiteral("edit"));
    w.pin_baseline();
    s.cycle.probe_feed_mm_min = 2500.0;
    w.edit_scenario(s, QStringLiteral("edit"));

    CalibrationTab* ring = calibration(w);
    ring->set_gauge_diameter_mm(50.0);
    ASSERT_TRUE(ring->import_file(kLabData + QStringLiteral("/lab_ring.csv")))
        << ring->last_error().toStdString();
    ring->set_deviation_magnification(100.0);
    ring->set_points_text(QStringLiteral("orientation_deg,x_mm,y_mm\n0,1,2\n"));  // not fitted
    ring->set_length_inputs({-10.0, QStringLiteral("-9.9; -9.91"), 100.0, 0.0});

    LatencyTab* lab = latency(w);
    lab->set_interpolation_period_s(0.001);
    ASSERT_TRUE(lab->import_file(kLabData + QStringLiteral("/lab_delay.csv")))
        << lab->last_error().toStdString();
    lab->set_applied_group(QStringLiteral("Z-"));
    LatencyTab::CompensationInputs inputs;
    inputs.feed_mm_min = 3000.0;
    inputs.lag_cycles = 10;
    inputs.compensated_lag_cycles = 9;
    inputs.touch = TouchMotion::constant_speed;
    lab->set_compensation_inputs(inputs);

    ASSERT_TRUE(comparison(w)->simulate_example(data_folder))
        << comparison(w)->last_error().toStdString();
    QCoreApplication::processEvents();
}

TEST(ProjectFileWindow, OpensAgainExactly) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("cell.probecycle"));
    auto first = make_window();
    fill_session(*first, dir.filePath(QStringLiteral("data")));
    ASSERT_TRUE(first->save_project(path)) << first->last_error().toStdString();
    EXPECT_TRUE(first->current_is_project());
    EXPECT_FALSE(first->has_unsaved_changes());
    // The comparison's files are stored relative to the project.
    const Project stored = parse_project(read(path));
    EXPECT_EQ(stored.comparison.plan, "data/plan.csv");

    auto second = make_window();
    ASSERT_TRUE(second->open_scenario(path)) << second->last_error().toStdString();
    QCoreApplication::processEvents();
    EXPECT_TRUE(second->current_is_project());
    EXPECT_FALSE(second->has_unsaved_changes());
    EXPECT_EQ(scenario_to_json(second->scenario()), scenario_to_json(first->scenario()));
    EXPECT_TRUE(second->has_baseline());

    EXPECT_EQ(calibration(*second)->points_text(), calibration(*first)->points_text());
    ASSERT_TRUE(calibration(*second)->result().has_value());
    EXPECT_EQ(calibration(*second)->results_text(), calibration(*first)->results_text());
    EXPECT_EQ(calibration(*second)->deviation_magnification(), 100.0);
    EXPECT_EQ(calibration(*second)->plotted_points(0), calibration(*first)->plotted_points(0));
    ASSERT_TRUE(calibration(*second)->length_result().has_value());
    EXPECT_EQ(calibration(*second)->length_result()->effective_length_mm,
              calibration(*first)->length_result()->effective_length_mm);

    EXPECT_EQ(latency(*second)->touches_text(), latency(*first)->touches_text());
    ASSERT_TRUE(latency(*second)->delay_fit().has_value());
    EXPECT_EQ(latency(*second)->results_text(), latency(*first)->results_text());
    EXPECT_EQ(latency(*second)->pending_application()->group,
              latency(*first)->pending_application()->group);
    const auto a = latency(*first)->compensation_inputs();
    const auto b = latency(*second)->compensation_inputs();
    EXPECT_EQ(b.feed_mm_min, a.feed_mm_min);
    EXPECT_EQ(b.lag_cycles, a.lag_cycles);
    EXPECT_EQ(b.compensated_lag_cycles, a.compensated_lag_cycles);
    EXPECT_EQ(b.touch, a.touch);

    for (int i = 0; i < ComparisonTab::kInputFiles; ++i) {
        const auto which = static_cast<ComparisonTab::InputFile>(i);
        EXPECT_EQ(comparison(*second)->file(which), comparison(*first)->file(which));
    }
    ASSERT_TRUE(comparison(*second)->result().has_value());
    EXPECT_EQ(comparison(*second)->summary_text(), comparison(*first)->summary_text());

    // Saved again, byte for byte the same file.
    const QString again = dir.filePath(QStringLiteral("again.probecycle"));
    ASSERT_TRUE(second->save_project(again));
    EXPECT_EQ(read(again), read(path));
}

TEST(ProjectFileWindow, ABadProjectChangesNothing) {
    QTemporaryDir dir;
    auto window = make_window();
    fill_session(*window, dir.filePath(QStringLiteral("data")));
    const QString good = dir.filePath(QStringLiteral("good.probecycle"));
    ASSERT_TRUE(window->save_project(good));
    std::string text = read(good);
    const std::string key = "\"gauge_diameter_mm\": 50.0";
    ASSERT_NE(text.find(key), std::string::npos);
    text.replace(text.find(key), key.size(), "\"gauge_diameter_mm\": -1");
    const QString bad = dir.filePath(QStringLiteral("bad.probecycle"));
    write(bad, text);

    const std::string before = read(good);
    Scenario changed = window->scenario();
    changed.cycle.backoff_mm = 3.0;
    window->edit_scenario(changed, QStringLiteral("edit"));
    const QStringList ring_before = calibration(*window)->results_text();
    EXPECT_FALSE(window->open_scenario(bad));
    EXPECT_TRUE(window->last_error().contains(QStringLiteral("ring.gauge_diameter_mm")))
        << window->last_error().toStdString();
    EXPECT_TRUE(window->last_error().contains(QStringLiteral("0.1")))  // the allowed range
        << window->last_error().toStdString();
    EXPECT_EQ(window->scenario().cycle.backoff_mm, 3.0);
    EXPECT_EQ(window->current_file(), QFileInfo(good).absoluteFilePath());
    EXPECT_EQ(calibration(*window)->results_text(), ring_before);
    EXPECT_EQ(read(good), before);
}

TEST(ProjectFileWindow, PlainScenarioFilesKeepWorkingAndLeaveTheLab) {
    QTemporaryDir dir;
    auto window = make_window();
    fill_session(*window, dir.filePath(QStringLiteral("data")));
    const QString scenario_path = dir.filePath(QStringLiteral("plain.json"));
    ASSERT_TRUE(window->save_scenario(scenario_path));
    EXPECT_FALSE(window->current_is_project());
    // What the CLI reads: a scenario, no lab.
    EXPECT_FALSE(is_project_text(read(scenario_path)));
    EXPECT_EQ(scenario_to_json(scenario_from_json(read(scenario_path))),
              scenario_to_json(window->scenario()));

    // A scenario replaces the scenario only; the lab's fits stay.
    Scenario other;
    other.cycle.probe_feed_mm_min = 777.0;
    const QString other_path = dir.filePath(QStringLiteral("other.json"));
    write(other_path, scenario_to_json(other));
    ASSERT_TRUE(window->open_scenario(other_path));
    EXPECT_EQ(window->scenario().cycle.probe_feed_mm_min, 777.0);
    EXPECT_TRUE(calibration(*window)->result().has_value());
    EXPECT_TRUE(latency(*window)->delay_fit().has_value());
    EXPECT_FALSE(window->has_unsaved_changes());
}

TEST(ProjectFileWindow, LabEditsInAProjectAreUnsavedChanges) {
    QTemporaryDir dir;
    auto window = make_window();
    fill_session(*window, dir.filePath(QStringLiteral("data")));
    const QString path = dir.filePath(QStringLiteral("cell.probecycle"));
    ASSERT_TRUE(window->save_project(path));
    EXPECT_FALSE(window->isWindowModified());

    latency(*window)->set_interpolation_period_s(0.002);
    EXPECT_TRUE(window->has_unsaved_changes());
    window->set_unsaved_answer(UnsavedAnswer::cancel);
    EXPECT_FALSE(window->new_scenario());
    EXPECT_EQ(window->current_file(), QFileInfo(path).absoluteFilePath());
    // Save writes the project (the lab with it).
    window->set_unsaved_answer(UnsavedAnswer::save);
    EXPECT_TRUE(window->new_scenario());
    EXPECT_EQ(parse_project(read(path)).delay.interpolation_period_s, 0.002);
    // New keeps the lab's data (the session's) but is no longer the project.
    EXPECT_FALSE(window->current_is_project());
    EXPECT_TRUE(latency(*window)->delay_fit().has_value());
}

TEST(ProjectFileWindow, TheTitleMarksLabEditsAsTheyHappen) {
    QTemporaryDir dir;
    auto window = make_window();
    fill_session(*window, dir.filePath(QStringLiteral("data")));
    ASSERT_TRUE(window->save_project(dir.filePath(QStringLiteral("cell.probecycle"))));
    ASSERT_FALSE(window->isWindowModified());
    const double saved_period = latency(*window)->compensation_inputs().interpolation_period_s;

    // No change of tab: the edit itself marks the title.
    LatencyTab::CompensationInputs inputs = latency(*window)->compensation_inputs();
    inputs.interpolation_period_s = saved_period * 2.0;
    latency(*window)->set_compensation_inputs(inputs);
    QCoreApplication::processEvents();
    EXPECT_TRUE(window->isWindowModified());

    // The value the file holds again: nothing to save.
    inputs.interpolation_period_s = saved_period;
    latency(*window)->set_compensation_inputs(inputs);
    QCoreApplication::processEvents();
    EXPECT_FALSE(window->isWindowModified());
}

TEST(ProjectFileWindow, OpeningAProjectAsksWhenItWouldReplaceUnsavedLabData) {
    QTemporaryDir dir;
    auto source = make_window();
    const QString path = dir.filePath(QStringLiteral("cell.probecycle"));
    ASSERT_TRUE(source->save_project(path));  // an empty lab

    auto window = make_window();
    ASSERT_TRUE(calibration(*window)->import_file(kLabData + QStringLiteral("/lab_ring.csv")));
    // No project yet: the lab's data is in no file, and the project would replace it.
    window->set_unsaved_answer(UnsavedAnswer::cancel);
    EXPECT_FALSE(window->open_asking(path));
    EXPECT_TRUE(calibration(*window)->result().has_value());
    // A scenario leaves the lab alone, so it does not ask.
    const QString scenario_path = dir.filePath(QStringLiteral("s.json"));
    write(scenario_path, scenario_to_json(Scenario{}));
    EXPECT_TRUE(window->open_asking(scenario_path));
    EXPECT_TRUE(calibration(*window)->result().has_value());
    window->set_unsaved_answer(UnsavedAnswer::discard);
    EXPECT_TRUE(window->open_asking(path));
    EXPECT_FALSE(calibration(*window)->result().has_value());
    EXPECT_TRUE(window->current_is_project());
}

// The lab's data outlives a quit outside any project; a discarded project
// comes back as its file has it.
TEST(ProjectFileWindow, TheLabComesBackAfterAQuit) {
    QSettings().clear();  // test mode: never the user's settings
    QTemporaryDir dir;
    MainWindowOptions options;
    options.show_dialogs = false;
    options.unsaved_answer = UnsavedAnswer::discard;
    QStringList ring;
    {
        MainWindow first(options);
        first.show();
        ASSERT_TRUE(calibration(first)->import_file(kLabData + QStringLiteral("/lab_ring.csv")));
        ring = calibration(first)->results_text();
        EXPECT_TRUE(first.close());
    }
    const QString path = dir.filePath(QStringLiteral("cell.probecycle"));
    {
        MainWindow second(options);
        second.show();
        EXPECT_EQ(calibration(second)->results_text(), ring);
        ASSERT_TRUE(second.save_project(path));
        // An edit of the project's lab, discarded at the quit.
        calibration(second)->set_gauge_diameter_mm(50.01);
        EXPECT_TRUE(second.has_unsaved_changes());
        EXPECT_TRUE(second.close());
    }
    MainWindow third(options);
    EXPECT_TRUE(third.current_is_project());
    EXPECT_EQ(calibration(third)->gauge_diameter_mm(), 50.0);
    EXPECT_EQ(calibration(third)->results_text(), ring);
    EXPECT_FALSE(third.has_unsaved_changes());
    QSettings().clear();
}

}  // namespace
}  // namespace probecycle::ui
