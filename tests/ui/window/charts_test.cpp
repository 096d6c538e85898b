// The cycle charts drawn offscreen from a Computation: what an invalid cycle
// and invalid feeds look like, what the legends name, the log time axis's
// labels and the room around the markers. Mirrors ui/cycle/cycle_charts.h;
// the PlotView tests at the end mirror ui/common/plot_view.h.

#include "ui/cycle/cycle_charts.h"

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QStringList>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "core/common/file_io.h"
#include "core/cycle/preset.h"
#include "core/cycle/scenario.h"
#include "core/cycle/sweep.h"
#include "ui/common/plot_view.h"
#include "ui/common/text_format.h"
#include "ui/cycle/computation.h"

namespace probecycle::ui {
namespace {

using Side = PlotView::Side;

std::string joined(const QStringList& texts) {
    return texts.join(QLatin1Char('|')).toStdString();
}

bool has_y(const QPointF& p) {
    return std::isfinite(p.y());
}

// Where v sits on a log axis, 0 at its bottom (left), 1 at its top (right).
double log_fraction(double v, const PlotView::Range& range) {
    return std::log(v / range.lo) / std::log(range.hi / range.lo);
}

// Single-touch at 9000 mm/min against a 1 mm overtravel limit: every feed
// above about 1600 mm/min overtravels it, this one included.
Scenario over_the_limit() {
    Scenario s;
    s.cycle.strategy = Strategy::single_touch;
    s.cycle.probe_feed_mm_min = 9000.0;
    s.probe.overtravel_limit_mm = 1.0;
    return s;
}

// The same at 500 mm/min with room for any overtravel: every cycle valid.
Scenario all_valid() {
    Scenario s = over_the_limit();
    s.cycle.probe_feed_mm_min = 500.0;
    s.probe.overtravel_limit_mm = 100.0;
    return s;
}

// A short, stiff single touch: its cycle time falls to about 0.035 s.
Scenario fast_surface() {
    Scenario s;
    s.machine.time_constant_s = 0.01;
    s.machine.scan_period_s = 0.001;
    s.machine.controller_latency_s = 0.001;
    s.cycle.strategy = Strategy::single_touch;
    s.cycle.approach_mm = 0.5;
    s.cycle.probe_feed_mm_min = 3000.0;
    s.cycle.return_feed_mm_min = 30000.0;
    return s;
}

class ChartsTest : public ::testing::Test {
  protected:
    void SetUp() override {
        charts_.resize(1280, 720);
        charts_.show();
        cycle_time_ = charts_.findChild<PlotView*>(QStringLiteral("chart:cycle_time"));
        overtravel_ = charts_.findChild<PlotView*>(QStringLiteral("chart:overtravel"));
        motion_ = charts_.findChild<PlotView*>(QStringLiteral("chart:motion"));
        ASSERT_NE(cycle_time_, nullptr);
        ASSERT_NE(overtravel_, nullptr);
        ASSERT_NE(motion_, nullptr);
    }

    // Draws the scenario and lets the charts lay themselves out.
    const Computed& draw(const Scenario& scenario) {
        const Computed& computed = computation_.run(scenario);
        EXPECT_TRUE(computed.valid());
        charts_.show_result(computed);
        QCoreApplication::processEvents();
        QCoreApplication::processEvents();
        return computed;
    }

    QList<QPointF> points(const char* id) const { return charts_.series_points(QLatin1String(id)); }
    bool visible(const char* id) const { return charts_.series_visible(QLatin1String(id)); }

    // The feeds of a curve's points that have a y (the rest are breaks).
    static QList<double> drawn_feeds(const QList<QPointF>& curve) {
        QList<double> feeds;
        for (const QPointF& p : curve) {
            if (has_y(p)) feeds.append(p.x());
        }
        return feeds;
    }

    Computation computation_;
    CycleCharts charts_;
    PlotView* cycle_time_{nullptr};
    PlotView* overtravel_{nullptr};
    PlotView* motion_{nullptr};
};

// Item 1: an invalid cycle has no time to plot. No dot; its feed is a red
// dashed line across the plot, named in the legend, in place of the feed's line.
TEST_F(ChartsTest, AnInvalidCycleIsMarkedAtItsFeedAndHasNoDot) {
    const Computed& invalid = draw(over_the_limit());
    ASSERT_FALSE(invalid.cycle().valid());
    EXPECT_TRUE(points("cycle_time.current").isEmpty());
    EXPECT_FALSE(visible("cycle_time.current"));
    EXPECT_FALSE(visible("cycle_time.feed"));
    EXPECT_TRUE(visible("cycle_time.current_invalid"));
    const QList<QPointF> rule = points("cycle_time.current_invalid");
    ASSERT_EQ(rule.size(), 1);
    EXPECT_DOUBLE_EQ(rule.front().x(), 9000.0);
    const QStringList legend = cycle_time_->legend_texts();
    EXPECT_EQ(legend.count(QStringLiteral("This cycle (invalid)")), 1) << joined(legend);
    EXPECT_FALSE(legend.contains(QStringLiteral("This cycle"))) << joined(legend);

    const Computed& valid = draw(all_valid());
    ASSERT_TRUE(valid.cycle().valid());
    const QList<QPointF> dot = points("cycle_time.current");
    ASSERT_EQ(dot.size(), 1);
    EXPECT_DOUBLE_EQ(dot.front().x(), 500.0);
    EXPECT_DOUBLE_EQ(dot.front().y(), valid.cycle().total());
    EXPECT_TRUE(visible("cycle_time.current"));
    EXPECT_TRUE(visible("cycle_time.feed"));
    EXPECT_FALSE(visible("cycle_time.current_invalid"));
    EXPECT_FALSE(cycle_time_->legend_texts().contains(QStringLiteral("This cycle (invalid)")));
    EXPECT_TRUE(cycle_time_->legend_texts().contains(QStringLiteral("This cycle")));
}

// Item 5: the phases of an invalid cycle are grey, as the cycle-time chart's
// invalid stretches, and the title says why instead of giving a total.
TEST_F(ChartsTest, AnInvalidCyclesPhasesAreGreyAndTitledWithTheReason) {
    auto* phases = charts_.findChild<PlotView*>(QStringLiteral("chart:phases"));
    ASSERT_NE(phases, nullptr);
    const QColor grey = charts_.series_color(QStringLiteral("cycle_time.two_touch_invalid"));
    const auto shown_phases = [&] {
        QStringList ids;
        for (const QString& id : charts_.series_ids()) {
            if (id.startsWith(QLatin1String("phases.")) && charts_.series_visible(id)) ids << id;
        }
        return ids;
    };

    const Computed& invalid = draw(over_the_limit());
    ASSERT_FALSE(invalid.cycle().valid());
    const QStringList invalid_ids = shown_phases();
    ASSERT_GE(invalid_ids.size(), 5) << joined(invalid_ids);
    for (const QString& id : invalid_ids) {
        EXPECT_EQ(charts_.series_color(id), grey) << id.toStdString();
    }
    EXPECT_TRUE(phases->title().contains(QLatin1String("invalid")))
        << phases->title().toStdString();
    EXPECT_TRUE(phases->title().contains(warning_title(WarningCode::overtravel_limit)))
        << phases->title().toStdString();
    EXPECT_FALSE(phases->title().contains(QLatin1String("total")));

    const Computed& valid = draw(all_valid());
    ASSERT_TRUE(valid.cycle().valid());
    const QStringList valid_ids = shown_phases();
    ASSERT_GE(valid_ids.size(), 5);
    QStringList colours;
    for (const QString& id : valid_ids) {
        const QColor colour = charts_.series_color(id);
        EXPECT_NE(colour, grey) << id.toStdString();
        colours << colour.name();
    }
    colours.removeDuplicates();
    EXPECT_EQ(colours.size(), valid_ids.size()) << joined(colours);  // one colour a phase
    EXPECT_TRUE(phases->title().startsWith(QLatin1String("Phases: total")))
        << phases->title().toStdString();
}

// A second touch's phases share their first touch's rows, in a lighter
// shade: a two-touch cycle has 7 rows, not 12, each labelled with both
// touches' times in one unit.
TEST_F(ChartsTest, ASecondTouchsPhasesShareTheirFirstTouchsRows) {
    Scenario s = all_valid();
    s.cycle.strategy = Strategy::two_touch;
    const Computed& c = draw(s);
    ASSERT_TRUE(c.cycle().valid());
    auto* phases = charts_.findChild<PlotView*>(QStringLiteral("chart:phases"));
    ASSERT_NE(phases, nullptr);
    const QStringList texts = phases->texts();
    QStringList rows;
    for (const QString& text : texts) {
        if (text.contains(QStringLiteral(" \u00b7 "))) rows << text;
    }
    ASSERT_EQ(rows.size(), 7) << joined(rows);
    // Top to bottom as they happen: the top row (last category) is the approach.
    const SecondsColumn times = format_seconds_column(
        {c.cycle().phase_time(Phase::approach), c.cycle().phase_time(Phase::second_approach)});
    EXPECT_EQ(rows.last(), QStringLiteral("Approach \u00b7 ") + times.numbers.at(0) +
                               QStringLiteral(" + ") + with_unit(times.numbers.at(1), times.unit))
        << joined(rows);
    const auto row_of = [&](const char* id) {
        const QList<QPointF> points = charts_.series_points(QString::fromLatin1(id));
        return points.isEmpty() ? -1.0 : std::round(points.first().y());
    };
    EXPECT_EQ(row_of("phases.second_approach"), row_of("phases.approach"));
    EXPECT_EQ(row_of("phases.second_deceleration"), row_of("phases.deceleration"));
    EXPECT_NE(row_of("phases.backoff"), row_of("phases.approach"));
    EXPECT_NE(charts_.series_color(QStringLiteral("phases.second_approach")),
              charts_.series_color(QStringLiteral("phases.approach")));
}

// Item 2: each curve is drawn exactly where its cycles are valid, and grey at
// the feeds where they are not (reaching to the valid neighbour so the line
// stays whole, nowhere else), with one legend entry for the grey.
TEST_F(ChartsTest, CurvesAreGreyAtTheInvalidFeedsOfTheirSweep) {
    const Computed& c = draw(over_the_limit());
    int invalid_total = 0;
    for (const auto& entry : {std::pair{"cycle_time.single_touch", &c.single_touch},
                              std::pair{"cycle_time.two_touch", &c.two_touch}}) {
        // Named, not structured bindings: the lambda below captures them.
        const char* id = entry.first;
        const SweepResult* sweep = entry.second;
        const QList<QPointF> curve = charts_.series_points(QLatin1String(id));
        const QList<QPointF> grey =
            charts_.series_points(QString::fromLatin1(id) + QStringLiteral("_invalid"));
        ASSERT_EQ(curve.size(), static_cast<qsizetype>(sweep->points.size())) << id;
        ASSERT_EQ(grey.size(), curve.size()) << id;
        const auto invalid_at = [&](qsizetype k) {
            return k >= 0 && k < curve.size() &&
                   !sweep->points[static_cast<std::size_t>(k)].valid();
        };
        QList<double> valid_feeds;
        for (qsizetype k = 0; k < curve.size(); ++k) {
            const SweepPoint& p = sweep->points[static_cast<std::size_t>(k)];
            EXPECT_EQ(curve[k].x(), p.feed_mm_min) << id;
            EXPECT_EQ(grey[k].x(), p.feed_mm_min) << id;
            if (p.valid()) valid_feeds.append(p.feed_mm_min);
            invalid_total += p.valid() ? 0 : 1;
            const bool joins = invalid_at(k - 1) || invalid_at(k + 1);
            EXPECT_EQ(has_y(grey[k]), !p.valid() || joins) << id << " at " << p.feed_mm_min;
            if (has_y(grey[k])) {
                EXPECT_DOUBLE_EQ(grey[k].y(), p.cycle_time_s) << id;
            }
        }
        EXPECT_EQ(drawn_feeds(curve), valid_feeds) << id;
    }
    // Over a 1 mm limit the fast feeds of both strategies are invalid.
    EXPECT_GT(invalid_total, 100);
    const QStringList legend = cycle_time_->legend_texts();
    EXPECT_EQ(legend.count(QStringLiteral("Invalid")), 1) << joined(legend);
}

TEST_F(ChartsTest, NoGreyAndNoGreyLegendWhenEveryCycleIsValid) {
    draw(over_the_limit());
    const Computed& c = draw(all_valid());
    for (const SweepResult* sweep : {&c.single_touch, &c.two_touch}) {
        for (const SweepPoint& p : sweep->points) ASSERT_TRUE(p.valid()) << p.feed_mm_min;
    }
    EXPECT_TRUE(drawn_feeds(points("cycle_time.single_touch_invalid")).isEmpty());
    EXPECT_TRUE(drawn_feeds(points("cycle_time.two_touch_invalid")).isEmpty());
    EXPECT_EQ(drawn_feeds(points("cycle_time.single_touch")).size(), 500);
    EXPECT_EQ(drawn_feeds(points("cycle_time.two_touch")).size(), 500);
    EXPECT_FALSE(visible("cycle_time.single_touch_invalid"));
    EXPECT_FALSE(visible("cycle_time.two_touch_invalid"));
    EXPECT_FALSE(cycle_time_->legend_texts().contains(QStringLiteral("Invalid")))
        << joined(cycle_time_->legend_texts());
}

// Item 3: a pinned baseline is named in each chart's legend, once; unpinned, nowhere.
TEST_F(ChartsTest, TheLegendNamesThePinnedBaselineOnlyWhilePinned) {
    const QString baseline = QStringLiteral("Baseline (dashed)");
    const Computed pinned = draw(all_valid());
    for (const PlotView* plot : {cycle_time_, overtravel_, motion_}) {
        EXPECT_FALSE(plot->legend_texts().contains(baseline)) << joined(plot->legend_texts());
    }
    charts_.set_baseline(&pinned);
    draw(over_the_limit());
    for (const PlotView* plot : {cycle_time_, overtravel_, motion_}) {
        EXPECT_EQ(plot->legend_texts().count(baseline), 1) << joined(plot->legend_texts());
    }
    EXPECT_TRUE(visible("cycle_time.baseline_two_touch"));
    charts_.set_baseline(nullptr);
    for (const PlotView* plot : {cycle_time_, overtravel_, motion_}) {
        EXPECT_FALSE(plot->legend_texts().contains(baseline)) << joined(plot->legend_texts());
    }
}

// Item 4: "Target" only with a target uncertainty.
TEST_F(ChartsTest, TheOvertravelLegendHasATargetOnlyWhenOneIsSet) {
    Scenario s = all_valid();
    s.cycle.target_uncertainty_mm = 0.0;
    draw(s);
    EXPECT_FALSE(overtravel_->legend_texts().contains(QStringLiteral("Target")))
        << joined(overtravel_->legend_texts());
    s.cycle.target_uncertainty_mm = 0.005;
    draw(s);
    EXPECT_EQ(overtravel_->legend_texts().count(QStringLiteral("Target")), 1)
        << joined(overtravel_->legend_texts());
    s.cycle.target_uncertainty_mm = 0.0;
    draw(s);
    EXPECT_FALSE(overtravel_->legend_texts().contains(QStringLiteral("Target")));
}

// The chart shows what the readout says. Two-touch measures at the
// measuring feed: the cycle's uncertainty is a dot there (the readout's
// figure), and the measuring feed's line is in the legend; single-touch's dot
// is at the probing feed. The overtravel curves name the feed override they
// are at.
TEST_F(ChartsTest, TheUncertaintyDotIsTheReadoutsAtTheFeedThatMeasures) {
    Scenario s = all_valid();
    s.cycle.strategy = Strategy::two_touch;
    s.cycle.measure_feed_mm_min = 50.0;
    const Computed& two = draw(s);
    QList<QPointF> dot = points("overtravel.cycle_uncertainty");
    ASSERT_EQ(dot.size(), 1);
    EXPECT_DOUBLE_EQ(dot[0].x(), 50.0);
    EXPECT_DOUBLE_EQ(dot[0].y(), two.cycle().uncertainty_mm() * 1000.0);
    QStringList legend = overtravel_->legend_texts();
    EXPECT_TRUE(legend.contains(QStringLiteral("Measuring feedrate"))) << joined(legend);
    EXPECT_TRUE(legend.contains(QStringLiteral("This cycle's uncertainty"))) << joined(legend);
    EXPECT_TRUE(legend.contains(QStringLiteral("1st touch at 120 % override"))) << joined(legend);

    s.cycle.strategy = Strategy::single_touch;
    s.cycle.feed_override_max_pct = 100.0;
    const Computed& single = draw(s);
    dot = points("overtravel.cycle_uncertainty");
    ASSERT_EQ(dot.size(), 1);
    EXPECT_DOUBLE_EQ(dot[0].x(), s.cycle.probe_feed_mm_min);
    EXPECT_DOUBLE_EQ(dot[0].y(), single.cycle().uncertainty_mm() * 1000.0);
    legend = overtravel_->legend_texts();
    EXPECT_FALSE(legend.contains(QStringLiteral("Measuring feedrate"))) << joined(legend);
    EXPECT_TRUE(legend.contains(QStringLiteral("Overtravel"))) << joined(legend);
}

// Feeds the first touch never reaches from its start are dotted in
// the curve's colour, named in the legend, and out of the solid curve (the
// Renishaw note's geometry: 2.5 mm start, T = 0.06 s, so up to about 5000
// mm/min).
TEST_F(ChartsTest, FeedsTheFirstTouchNeverReachesAreDottedApart) {
    Scenario s;
    s.cycle.strategy = Strategy::single_touch;
    s.cycle.approach_mm = 2.5;
    s.cycle.return_feed_mm_min = 5000.0;
    s.cycle.feed_override_max_pct = 100.0;
    s.probe.overtravel_limit_mm = 50.0;
    draw(s);
    const QList<double> solid = drawn_feeds(points("cycle_time.single_touch"));
    const QList<double> dotted = drawn_feeds(points("cycle_time.single_touch_unreached"));
    ASSERT_FALSE(solid.isEmpty());
    ASSERT_FALSE(dotted.isEmpty());
    for (double feed : solid) EXPECT_LE(feed, 5011.0);
    EXPECT_GE(*std::max_element(dotted.begin(), dotted.end()), 9000.0);
    EXPECT_TRUE(visible("cycle_time.single_touch_unreached"));
    EXPECT_TRUE(
        cycle_time_->legend_texts().contains(QStringLiteral("Single-touch, feed not reached")))
        << joined(cycle_time_->legend_texts());
    s.cycle.approach_mm = 20.0;  // every feed reached
    draw(s);
    EXPECT_FALSE(visible("cycle_time.single_touch_unreached"));
}

// Item 5: the log time axis labels times under 1 s, and shows at least two
// labels whatever the range.
TEST_F(ChartsTest, TheLogTimeAxisLabelsTimesUnderOneSecond) {
    const Computed& c = draw(fast_surface());
    double fastest = 1e9;
    for (const SweepPoint& p : c.single_touch.points) fastest = std::min(fastest, p.cycle_time_s);
    ASSERT_LT(fastest, 0.1);
    const QStringList labels = cycle_time_->y_labels(Side::left);
    EXPECT_TRUE(labels.contains(QStringLiteral("0.01"))) << joined(labels);
    EXPECT_TRUE(labels.contains(QStringLiteral("0.1"))) << joined(labels);
    EXPECT_TRUE(labels.contains(QStringLiteral("1"))) << joined(labels);
    EXPECT_EQ(cycle_time_->x_labels(),
              QStringList({QStringLiteral("10"), QStringLiteral("100"), QStringLiteral("1000"),
                           QStringLiteral("10000")}));
    for (const Scenario& s : {Scenario{}, over_the_limit(), all_valid(), fast_surface()}) {
        draw(s);
        EXPECT_GE(cycle_time_->y_labels(Side::left).size(), 2)
            << joined(cycle_time_->y_labels(Side::left));
    }
}

// Item 6: the knee and this cycle's dot are drawn whole, even at the ends of
// the feed range: the axes reach a little beyond every point drawn.
TEST_F(ChartsTest, TheAxesLeaveRoomAroundEveryDot) {
    const PlotView::Range x = cycle_time_->x_range();
    EXPECT_LT(x.lo, kKneeSearchFrom_mm_min);
    EXPECT_GT(x.hi, kKneeSearchTo_mm_min);

    Scenario at_the_end = all_valid();
    at_the_end.cycle.probe_feed_mm_min = 10000.0;
    // Two-touch at 10 mm/min from 1.2 mm with a 2 mm backoff: the curves stay
    // under 10 s, this cycle's wasted backoff takes it above.
    Scenario above_the_curves;
    above_the_curves.cycle.probe_feed_mm_min = 10.0;
    above_the_curves.cycle.approach_mm = 1.2;
    above_the_curves.cycle.backoff_mm = 2.0;
    const Computed& above = draw(above_the_curves);
    ASSERT_TRUE(above.cycle().valid());
    for (const SweepResult* sweep : {&above.single_touch, &above.two_touch}) {
        for (const SweepPoint& p : sweep->points) ASSERT_LT(p.cycle_time_s, 10.0);
    }
    ASSERT_GT(above.cycle().total(), 10.0);

    for (const Scenario& s :
         {Scenario{}, all_valid(), at_the_end, fast_surface(), above_the_curves}) {
        draw(s);
        const PlotView::Range y = cycle_time_->y_range(Side::left);
        for (const char* id : {"cycle_time.knee", "cycle_time.current", "cycle_time.single_touch",
                               "cycle_time.two_touch"}) {
            for (const QPointF& p : points(id)) {
                if (!has_y(p)) continue;
                EXPECT_GE(log_fraction(p.x(), x), 0.01) << id << " at " << p.x();
                EXPECT_LE(log_fraction(p.x(), x), 0.99) << id << " at " << p.x();
                EXPECT_GE(log_fraction(p.y(), y), 0.01) << id << " at " << p.x();
                EXPECT_LE(log_fraction(p.y(), y), 0.99) << id << " at " << p.x();
            }
        }
    }
}

// Lets a plot lay itself out, as after the event loop ran.
void lay_out(PlotView& plot) {
    plot.show();
    QCoreApplication::processEvents();
    QCoreApplication::processEvents();
}

// PlotView: a curve named after it was added joins the legend while shown;
// unnamed again, it leaves.
// Under a slider the time axis keeps still; after a jump (refit_ranges())
// it fits the new cycle, not the longest one seen before.
// A bore's moves between touches run across the probing direction: the
// position line breaks there (it stood at 0), while the speed shows the move.
TEST_F(ChartsTest, ThePositionBreaksDuringMovesBetweenTouches) {
    Scenario bore;
    bore.cycle.feature = Feature::bore;
    bore.cycle.feature_size_mm = 40.0;
    draw(bore);
    const QList<QPointF> position = points("motion.position");
    const QList<QPointF> speed = points("motion.speed");
    ASSERT_EQ(position.size(), speed.size());
    int gaps = 0;
    bool in_gap = false;
    double fastest_in_gaps = 0.0;
    for (qsizetype i = 0; i < position.size(); ++i) {
        const bool gap = !has_y(position[i]);
        if (gap) fastest_in_gaps = std::max(fastest_in_gaps, speed[i].y());
        if (gap && !in_gap) ++gaps;
        in_gap = gap;
    }
    EXPECT_GT(fastest_in_gaps, bore.cycle.probe_feed_mm_min);  // the positioning feed
    // From the centre to the first side, between the four sides, and back.
    EXPECT_GE(gaps, 3);
    // Single-touch on a surface has no such move: no break.
    draw(fast_surface());
    for (const QPointF& p : points("motion.position")) EXPECT_TRUE(has_y(p));
}

// The overtravel limit (left axis) and the uncertainty target (right, log)
// never draw as one line: on the Fanuc-type preset's bore, 5 mm on 0-20 mm
// and 5 um on 1-1000 um fell together.
TEST_F(ChartsTest, TheLimitAndTheTargetLinesStandApart) {
    Scenario s = scenario_from_json(
        read_text_file(PROBECYCLE_SOURCE_DIR "/resources/examples/bore_two_touch.json"));
    s = merge_json(s, parse_preset(read_text_file(PROBECYCLE_SOURCE_DIR
                                                  "/resources/presets/"
                                                  "machine_fanuc_exponential_servo.json"))
                          .scenario_json);
    const Computed& c = computation_.run(s);
    charts_.show_result(c);
    QCoreApplication::processEvents();
    const PlotView::Range left = overtravel_->y_range(PlotView::Side::left);
    const PlotView::Range right = overtravel_->y_range(PlotView::Side::right);
    const double limit = s.probe.overtravel_limit_mm / (left.hi - left.lo);
    const double target =
        (std::log10(s.cycle.target_uncertainty_mm * 1000.0) - std::log10(right.lo)) /
        (std::log10(right.hi) - std::log10(right.lo));
    EXPECT_GE(std::abs(limit - target), 0.06) << limit << " " << target;
}

TEST_F(ChartsTest, TheTimeAxisFitsTheCycleAfterAJump) {
    Scenario slow = fast_surface();
    slow.cycle.probe_feed_mm_min = 200.0;
    draw(slow);
    const double long_axis = motion_->x_range().hi;
    // A quicker cycle that still fills more than half of that axis.
    Scenario quick = fast_surface();
    double quick_total = 0.0;
    for (double feed = 250.0; feed <= 3000.0; feed += 50.0) {
        quick.cycle.probe_feed_mm_min = feed;
        quick_total = computation_.run(quick).cycle().total();
        if (quick_total < 0.85 * long_axis) break;
    }
    ASSERT_GT(quick_total, 0.55 * long_axis);
    // As a slider leaves it: still.
    draw(quick);
    EXPECT_EQ(motion_->x_range().hi, long_axis);
    // After a jump: fitted to the cycle.
    charts_.refit_ranges();
    draw(quick);
    EXPECT_GE(motion_->x_range().hi, quick_total);
    EXPECT_LT(motion_->x_range().hi, long_axis);
}

TEST(PlotViewTest, ACurveNamedLaterJoinsTheLegendWhileVisible) {
    PlotView plot;
    plot.set_x_axis({});
    plot.set_y_axis(Side::left, {});
    const PlotView::CurveId named = plot.add_line({QStringLiteral("Named"), Qt::blue});
    const PlotView::CurveId later = plot.add_line({{}, Qt::green});
    lay_out(plot);
    EXPECT_EQ(plot.legend_texts(), QStringList({QStringLiteral("Named")}));
    plot.set_name(later, QStringLiteral("Later"));
    lay_out(plot);
    EXPECT_EQ(plot.legend_texts(), QStringList({QStringLiteral("Named"), QStringLiteral("Later")}));
    plot.set_visible(later, false);
    lay_out(plot);
    EXPECT_EQ(plot.legend_texts(), QStringList({QStringLiteral("Named")}));
    plot.set_visible(later, true);
    plot.set_name(named, {});
    lay_out(plot);
    EXPECT_EQ(plot.legend_texts(), QStringList({QStringLiteral("Later")}));
    plot.set_legend_visible(false);
    EXPECT_TRUE(plot.legend_texts().isEmpty());
}

// PlotView: a NaN breaks a line; what was handed over reads back as it was.
TEST(PlotViewTest, ABrokenLineReadsBackWithItsBreaks) {
    PlotView plot;
    plot.set_x_axis({});
    plot.set_y_axis(Side::left, {});
    const PlotView::CurveId line = plot.add_line({QStringLiteral("Line"), Qt::blue});
    const double gap = std::nan("");
    const QList<QPointF> broken{{0, 1}, {1, 2}, {2, gap}, {3, 3}, {4, 4}, {5, gap}, {6, 5}, {7, 6}};
    plot.set_points(line, broken);
    lay_out(plot);
    const QList<QPointF> back = plot.points(line);
    ASSERT_EQ(back.size(), broken.size());
    for (qsizetype i = 0; i < back.size(); ++i) {
        EXPECT_EQ(back[i].x(), broken[i].x());
        EXPECT_EQ(std::isnan(back[i].y()), std::isnan(broken[i].y()));
    }
    // One legend entry however many stretches.
    EXPECT_EQ(plot.legend_texts(), QStringList({QStringLiteral("Line")}));
    plot.set_points(line, {{0, 1}, {1, 2}});
    lay_out(plot);
    EXPECT_EQ(plot.point_count(line), 2);
    EXPECT_EQ(plot.legend_texts(), QStringList({QStringLiteral("Line")}));
}

// PlotView: a scatter of a ring's 290 000 points draws a few thousand
// markers (Qt Charts makes an item of each); every point still reads back,
// and a few points are drawn as they are.
TEST(PlotViewTest, ManyMarkersAreThinnedForDrawingOnly) {
    PlotView plot;
    plot.set_x_axis({});
    plot.set_y_axis(Side::left, {});
    const PlotView::CurveId markers = plot.add_markers({QStringLiteral("Points"), Qt::blue}, 6.0);
    QList<QPointF> ring;
    for (int i = 0; i < 290000; ++i) {
        const double angle = 2.0 * std::numbers::pi * i / 290000.0;
        const double r = 25.0 + 0.001 * (i % 13);
        ring.append({r * std::cos(angle), r * std::sin(angle)});
    }
    plot.set_points(markers, ring);
    lay_out(plot);
    EXPECT_EQ(plot.point_count(markers), 290000);
    EXPECT_GT(plot.drawn_count(markers), 1000);
    EXPECT_LE(plot.drawn_count(markers), 4000);
    const QList<QPointF> few{{0, 1}, {0, 1}, {1, 2}, {2, std::nan("")}, {3, 3}};
    plot.set_points(markers, few);
    EXPECT_EQ(plot.drawn_count(markers), 4);
}

// PlotView: Qt Charts rounds ln(0.1) / ln(10) above -1 and would drop the
// label of a decade below 1 at the bottom of a log axis.
TEST(PlotViewTest, ALogAxisFromADecadeBelowOneLabelsThatDecade) {
    PlotView plot;
    plot.resize(600, 400);
    PlotView::AxisSpec log_axis;
    log_axis.scale = PlotView::Scale::log;
    plot.set_x_axis(log_axis);
    plot.set_y_axis(Side::left, log_axis);
    plot.set_x_range(10.0, 10000.0);
    plot.set_y_range(Side::left, 0.1, 10.0);
    plot.set_points(plot.add_line({QStringLiteral("Line"), Qt::blue}), {{10, 0.2}, {10000, 5}});
    lay_out(plot);
    EXPECT_EQ(plot.y_labels(Side::left),
              QStringList({QStringLiteral("0.1"), QStringLiteral("1"), QStringLiteral("10")}));
    EXPECT_EQ(plot.x_labels(), QStringList({QStringLiteral("10"), QStringLiteral("100"),
                                            QStringLiteral("1000"), QStringLiteral("10000")}));
}

}  // namespace
}  // namespace probecycle::ui
