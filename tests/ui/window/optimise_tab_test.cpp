// The Optimise tab (docs/window.md; OptimisePanel in ui/cycle/optimise_panel.h
// and its place in MainWindow): it shows the core optimiser's answer for the
// current scenario, its requirements edit the scenario as undoable steps, Apply
// is one undoable edit, and a requirement nothing meets is named.

#include <gtest/gtest.h>

#include <QApplication>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QTabWidget>
#include <QUndoStack>
#include <memory>

#include "core/cycle/cycle.h"
#include "core/cycle/scenario.h"
#include "core/optimise/optimiser.h"
#include "tests/ui/window/test_window.h"
#include "ui/cycle/optimise_panel.h"
#include "ui/window/main_window.h"

namespace probecycle::ui {
namespace {

Scenario bore() {
    Scenario s;
    s.cycle.feature = Feature::bore;
    s.cycle.probe_feed_mm_min = 3000.0;
    s.cycle.backoff_mm = 3.0;
    s.cycle.target_uncertainty_mm = 0.004;
    return s;
}

void show_tab(MainWindow& window, QWidget* tab) {
    auto* tabs = window.findChild<QTabWidget*>(QStringLiteral("tabs"));
    ASSERT_NE(tabs, nullptr);
    tabs->setCurrentWidget(tab);
    QCoreApplication::processEvents();
}

TEST(OptimiseTab, ShowsTheCoresAnswerAndAppliesItAsOneUndoableStep) {
    auto window = make_window();
    window->edit_scenario(bore(), QStringLiteral("bore"));
    OptimisePanel* panel = window->optimise_panel();
    show_tab(*window, panel);
    ASSERT_TRUE(panel->result().has_value()) << panel->problem().toStdString();
    // The same answer as the core's (the CLI's) for this scenario.
    const OptimiseResult expected = optimise(window->scenario());
    EXPECT_EQ(panel->result()->best.cycle_time_s, expected.best.cycle_time_s);
    EXPECT_LT(panel->result()->best.cycle_time_s, panel->result()->current.cycle_time_s);
    EXPECT_TRUE(panel->saved_text().contains(QStringLiteral("save")))
        << panel->saved_text().toStdString();
    EXPECT_TRUE(panel->binding_text().startsWith(QStringLiteral("What limits it:")));
    // The target lies on the Pareto chart, a vertical line.
    const QList<QPointF> bound = panel->bound_points();
    ASSERT_EQ(bound.size(), 1);
    EXPECT_DOUBLE_EQ(bound[0].x(), 1000.0 * panel->result()->uncertainty_bound_mm);
    EXPECT_GT(bound[0].x(), panel->pareto_x_range().first);
    EXPECT_LT(bound[0].x(), panel->pareto_x_range().second);
    // The Pareto front: uncertainty up, time down.
    const QList<QPointF> front = panel->pareto_points();
    ASSERT_GE(front.size(), 3);
    for (qsizetype i = 1; i < front.size(); ++i) {
        EXPECT_GT(front[i].x(), front[i - 1].x());
        EXPECT_LT(front[i].y(), front[i - 1].y());
    }

    const Scenario before = window->scenario();
    const int steps = window->undo_stack()->count();
    auto* apply = panel->findChild<QPushButton*>(QStringLiteral("optimise-apply"));
    ASSERT_NE(apply, nullptr);
    ASSERT_TRUE(apply->isEnabled());
    apply->click();
    window->recompute_now();
    EXPECT_EQ(window->undo_stack()->count(), steps + 1);
    const Scenario applied = window->scenario();
    EXPECT_EQ(settings_of(applied).probe_feed_mm_min, expected.best.settings.probe_feed_mm_min);
    EXPECT_EQ(applied.cycle.approach_mm, expected.best.settings.approach_mm);
    EXPECT_NEAR(evaluate(applied).total(), expected.best.cycle_time_s, 1e-12);
    EXPECT_TRUE(window->computed().valid());
    // Optimised again at once: nothing left to save.
    ASSERT_TRUE(panel->result().has_value());
    EXPECT_FALSE(apply->isEnabled());
    window->undo_stack()->undo();
    window->recompute_now();
    EXPECT_EQ(window->scenario().cycle.probe_feed_mm_min, before.cycle.probe_feed_mm_min);
    EXPECT_EQ(window->scenario().cycle.approach_mm, before.cycle.approach_mm);
}

// The optimiser (its front included) runs again only when the scenario or
// the overtravel requirement changed: a recompute that changed neither keeps
// the result it has.
TEST(OptimiseTab, OptimisesAgainOnlyWhenTheScenarioChanged) {
    auto window = make_window();
    window->edit_scenario(bore(), QStringLiteral("bore"));
    OptimisePanel* panel = window->optimise_panel();
    show_tab(*window, panel);
    ASSERT_TRUE(panel->result().has_value());
    const int runs = panel->optimise_count();
    panel->show_scenario(window->scenario());
    EXPECT_EQ(panel->optimise_count(), runs);
    Scenario faster = window->scenario();
    faster.cycle.probe_feed_mm_min += 100.0;
    panel->show_scenario(faster);
    EXPECT_EQ(panel->optimise_count(), runs + 1);
    panel->set_overtravel_fraction(0.7);  // (the window may optimise its own scenario)
    panel->show_scenario(faster);
    const int after = panel->optimise_count();
    EXPECT_GT(after, runs + 1);
    panel->show_scenario(faster);
    EXPECT_EQ(panel->optimise_count(), after);
}

TEST(OptimiseTab, ARequirementIsAnUndoableEditAndOptimisesAgain) {
    auto window = make_window();
    window->edit_scenario(bore(), QStringLiteral("bore"));
    OptimisePanel* panel = window->optimise_panel();
    show_tab(*window, panel);
    const int runs = panel->optimise_count();
    auto* target = panel->findChild<QDoubleSpinBox*>(
        QStringLiteral("optimise-spin:cycle.target_uncertainty_mm"));
    ASSERT_NE(target, nullptr);
    EXPECT_DOUBLE_EQ(target->value(), 4.0);  // shown in µm
    target->setValue(3.6);
    QCoreApplication::processEvents();
    window->recompute_now();
    EXPECT_DOUBLE_EQ(window->scenario().cycle.target_uncertainty_mm, 0.0036);
    EXPECT_GT(panel->optimise_count(), runs);
    ASSERT_TRUE(panel->result().has_value());
    EXPECT_LE(panel->result()->best.uncertainty_mm, 0.0036 + 1e-12);
    window->undo_stack()->undo();
    window->recompute_now();
    EXPECT_DOUBLE_EQ(window->scenario().cycle.target_uncertainty_mm, 0.004);

    // The overtravel allowed is the session's: it changes the answer, not the scenario.
    auto* fraction =
        panel->findChild<QDoubleSpinBox*>(QStringLiteral("optimise-overtravel-fraction"));
    ASSERT_NE(fraction, nullptr);
    const Scenario kept = window->scenario();
    fraction->setValue(40.0);
    QCoreApplication::processEvents();
    ASSERT_TRUE(panel->result().has_value());
    EXPECT_LE(panel->result()->best.overtravel_mm, 0.4 * kept.probe.overtravel_limit_mm + 1e-12);
    EXPECT_EQ(scenario_to_json(window->scenario()), scenario_to_json(kept));
}

TEST(OptimiseTab, ATargetNothingMeetsIsNamed) {
    auto window = make_window();
    Scenario s = bore();
    s.cycle.target_uncertainty_mm = 0.0001;  // under 1 µm / sqrt(20)
    window->edit_scenario(s, QStringLiteral("bore"));
    OptimisePanel* panel = window->optimise_panel();
    show_tab(*window, panel);
    EXPECT_FALSE(panel->result().has_value());
    EXPECT_TRUE(panel->problem().contains(QStringLiteral("cycle.target_uncertainty_mm")))
        << panel->problem().toStdString();
    auto* apply = panel->findChild<QPushButton*>(QStringLiteral("optimise-apply"));
    ASSERT_NE(apply, nullptr);
    EXPECT_FALSE(apply->isVisible());
}

TEST(OptimiseTab, ThePdfReportCarriesTheRecommendation) {
    auto window = make_window();
    window->edit_scenario(bore(), QStringLiteral("bore"));
    const QByteArray pdf = window->pdf_report_bytes();
    EXPECT_TRUE(pdf.startsWith("%PDF-"));
    OptimisePanel* panel = window->optimise_panel();
    ASSERT_TRUE(panel->result().has_value());
    const QList<QStringList> rows = panel->table_rows();
    ASSERT_EQ(rows.size(), 11);  // header and ten settings (the positioning feed too)
    EXPECT_EQ(rows[0].size(), 3);
}

}  // namespace
}  // namespace probecycle::ui
