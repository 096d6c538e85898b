#include "ui/cycle/cycle_charts.h"

#include <QEvent>
#include <QGridLayout>
#include <QLocale>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/units.h"
#include "ui/common/parameter_info.h"
#include "ui/common/text_format.h"

namespace probecycle::ui {

namespace {

constexpr double kFeedLo = kKneeSearchFrom_mm_min;
constexpr double kFeedHi = kKneeSearchTo_mm_min;
// The feed axes reach this factor beyond the sweep (a knee dot at
// 10000 mm/min was cut in half).
constexpr double kFeedPad = 1.15;
// The log time axis reaches this fraction of its span beyond the whole decades
// that hold the curves, for the same reason.
constexpr double kTimePadFraction = 0.04;
constexpr std::size_t kMotionSamples = 500;
constexpr double kBarHalfHeight = 0.36;
constexpr double kMinBarFraction = 0.004;
// Log axes cannot show zero; uncertainties below this are drawn at it.
constexpr double kUncertaintyFloor_um = 1e-3;

const QColor kSingleColour{0x1f, 0x77, 0xb4};
const QColor kTwoColour{0x2c, 0xa0, 0x2c};
const QColor kMarkerColour{0x44, 0x44, 0x44};
const QColor kInvalidColour{0xc0, 0x39, 0x2b};         // the red of the overtravel limit
const QColor kInvalidStretchColour{0x9a, 0x9a, 0x9a};  // curves where cycles are invalid
const QColor kKneeColour{0xff, 0x7f, 0x0e};
const QColor kOvertravelColour{0xc0, 0x39, 0x2b};
const QColor kUncertaintyColour{0x1f, 0x5f, 0xb4};
const QColor kPositionColour{0x1f, 0x77, 0xb4};
const QColor kSpeedColour{0xe6, 0x7e, 0x22};
const QColor kSurfaceColour{0x7f, 0x7f, 0x7f};

QColor phase_colour(Phase phase) {
    switch (phase) {
        case Phase::approach:
            return {0x4c, 0x78, 0xa8};
        case Phase::pretravel:
            return {0xf5, 0x85, 0x18};
        case Phase::interface_delay:
            return {0xe4, 0x57, 0x56};
        case Phase::controller_delay:
            return {0xb2, 0x79, 0xa2};
        case Phase::deceleration:
            return {0x48, 0x9e, 0x99};
        case Phase::backoff:
            return {0x9d, 0x75, 0x5d};
        case Phase::second_approach:
            return {0x54, 0xa2, 0x4b};
        case Phase::second_pretravel:
            return {0xf7, 0xa8, 0x58};
        case Phase::second_interface_delay:
            return {0xf0, 0x8a, 0x88};
        case Phase::second_controller_delay:
            return {0xcd, 0x9c, 0xc2};
        case Phase::second_deceleration:
            return {0x86, 0xc5, 0xc0};
        case Phase::return_move:
            return {0x79, 0x70, 0x6e};
        case Phase::position:
            return {0xba, 0xb0, 0xac};
        case Phase::lift:
            return {0xd7, 0xb5, 0xa6};
        case Phase::lower:
            return {0x9c, 0x9e, 0xde};
        case Phase::block_change:
            return {0x5a, 0x5a, 0x5a};
    }
    return Qt::gray;
}

// The row a phase is drawn on: a second touch's phase on its first touch's.
Phase row_phase(Phase phase) {
    switch (phase) {
        case Phase::second_approach:
            return Phase::approach;
        case Phase::second_pretravel:
            return Phase::pretravel;
        case Phase::second_interface_delay:
            return Phase::interface_delay;
        case Phase::second_controller_delay:
            return Phase::controller_delay;
        case Phase::second_deceleration:
            return Phase::deceleration;
        default:
            return phase;
    }
}

// Smallest 1, 2 or 5 times a power of ten at or above v.
double nice_ceiling(double v) {
    if (!(v > 0.0)) return 1.0;
    const double power = std::pow(10.0, std::floor(std::log10(v)));
    for (double step : {1.0, 2.0, 5.0, 10.0}) {
        if (step * power >= v * (1.0 - 1e-12)) return step * power;
    }
    return 10.0 * power;
}

}  // namespace

// Keeps an axis still while the data moves a little under a slider: the range
// changes only when the data leaves it or fills less than half of it, and then
// snaps to round numbers. Steadier to read, and each change costs a relayout.
bool StableRange::update(double want_lo, double want_hi) {
    if (!(want_hi > want_lo)) want_hi = want_lo + 1.0;
    const bool inside = set && want_lo >= lo && want_hi <= hi;
    if (inside && want_hi - want_lo >= 0.5 * (hi - lo)) return false;
    const double step = PlotView::nice_step((want_hi - want_lo) / 10.0);
    const double new_lo = std::floor(want_lo / step) * step;
    const double new_hi = std::ceil(want_hi / step) * step;
    set = true;
    if (new_lo == lo && new_hi == hi) return false;
    lo = new_lo;
    hi = new_hi;
    return true;
}

void CycleCharts::refit_ranges() {
    for (StableRange* range : {&phases_x_, &motion_x_, &motion_y_}) range->set = false;
}

namespace {

struct Span {
    double lo{std::numeric_limits<double>::infinity()};
    double hi{-std::numeric_limits<double>::infinity()};
    void add(double v) {
        if (!std::isfinite(v)) return;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    void add_y(const QList<QPointF>& points) {
        for (const QPointF& p : points) add(p.y());
    }
    bool empty() const { return lo > hi; }
};

// Decades that hold every value, for log axes.
std::pair<double, double> decade_range(const Span& span, double floor_value) {
    if (span.empty()) return {floor_value, floor_value * 10.0};
    const double lo = std::pow(10.0, std::floor(std::log10(std::max(span.lo, floor_value))));
    double hi = std::pow(10.0, std::ceil(std::log10(std::max(span.hi, floor_value))));
    if (hi <= lo) hi = lo * 10.0;
    return {lo, hi};
}

void fill_sweep(QList<QPointF>& out, const SweepResult& sweep, double SweepPoint::*member,
                double factor, double floor_value) {
    out.resize(static_cast<qsizetype>(sweep.points.size()));
    for (std::size_t i = 0; i < sweep.points.size(); ++i) {
        const SweepPoint& p = sweep.points[i];
        out[static_cast<qsizetype>(i)] = {p.feed_mm_min, std::max(p.*member * factor, floor_value)};
    }
}

// Moves the points of a sweep's curve that `keep` refuses into
// `out` (with the kept neighbours that join the two, so the line stays whole)
// and breaks the curve there (NaN); `out` is all NaN when every point is
// kept. Returns whether any point moved. A point already broken stays broken.
template <typename Keep>
bool split_off(QList<QPointF>& curve, QList<QPointF>& out, const SweepResult& sweep, Keep keep) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const qsizetype n = curve.size();
    out.resize(n);
    bool any = false;
    const auto kept = [&](qsizetype k) {
        return k < 0 || k >= n || keep(sweep.points[static_cast<std::size_t>(k)]);
    };
    for (qsizetype i = 0; i < n; ++i) {
        const bool here = kept(i);
        any = any || !here;
        out[i] = here && kept(i - 1) && kept(i + 1) ? QPointF(curve[i].x(), nan) : curve[i];
    }
    for (qsizetype i = 0; i < n; ++i) {
        if (!kept(i)) curve[i].setY(nan);
    }
    return any;
}

// The invalid feeds (grey, dashed).
bool split_invalid(QList<QPointF>& curve, QList<QPointF>& invalid, const SweepResult& sweep) {
    return split_off(curve, invalid, sweep, [](const SweepPoint& p) { return p.valid(); });
}

// The valid feeds the first touch never reaches from its start
// (dotted, in the curve's colour): not the programmed feed, and not the knee's.
bool split_unreached(QList<QPointF>& curve, QList<QPointF>& unreached, const SweepResult& sweep) {
    return split_off(curve, unreached, sweep,
                     [](const SweepPoint& p) { return p.feed_reached || !p.valid(); });
}

void fill_segment(QList<QPointF>& out, double x0, double y0, double x1, double y1) {
    out.resize(2);
    out[0] = {x0, y0};
    out[1] = {x1, y1};
}

// Samples the cycle evenly, plus every segment boundary, so speed peaks and
// the short trigger phases are drawn where they are.
void fill_motion(std::vector<double>& times, QList<QPointF>& position, QList<QPointF>& speed,
                 const CycleResult& cycle) {
    const double total = cycle.total();
    times.clear();
    for (std::size_t i = 0; i < kMotionSamples; ++i) {
        times.push_back(total * static_cast<double>(i) / static_cast<double>(kMotionSamples - 1));
    }
    const std::size_t grid = times.size();
    for (const TimedSegment& s : cycle.segments()) {
        times.push_back(s.start_s);
        times.push_back(s.start_s + s.duration_s);
    }
    std::sort(times.begin() + static_cast<std::ptrdiff_t>(grid), times.end());
    std::inplace_merge(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(grid),
                       times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    position.resize(static_cast<qsizetype>(times.size()));
    speed.resize(static_cast<qsizetype>(times.size()));
    const std::vector<PhaseRecord>& phases = cycle.phases();
    for (std::size_t i = 0; i < times.size(); ++i) {
        const double t = std::clamp(times[i], 0.0, total);
        const CycleState state = cycle.state_at(t);
        // A move between touches runs across the probing direction: the
        // position along it means nothing there, so the line breaks (it
        // stood at 0 as if the axis did not move) while the speed goes on.
        const PhaseRecord* phase =
            state.phase_index < phases.size() ? &phases[state.phase_index] : nullptr;
        const bool across = phase != nullptr && t > phase->start_s &&
                            t < phase->start_s + phase->time_s &&
                            (phase->phase == Phase::position || phase->phase == Phase::lift ||
                             phase->phase == Phase::lower);
        position[static_cast<qsizetype>(i)] = {
            t, across ? std::numeric_limits<double>::quiet_NaN() : state.position_mm};
        speed[static_cast<qsizetype>(i)] = {t, mm_s_to_mm_min(state.path_speed_mm_s)};
    }
}

}  // namespace

CycleCharts::CycleCharts(QWidget* parent) : QWidget(parent) {
    const qsizetype reserve = 1024;
    for (PingPong* b : {&single_, &two_, &overtravel_pts_, &overtravel2_pts_, &uncertainty_pts_}) {
        b->reserve(reserve);
    }
    position_pts_.reserve(2 * reserve);
    speed_pts_.reserve(2 * reserve);
    times_.reserve(2 * static_cast<std::size_t>(reserve));
    build();
    retranslate();
}

CycleCharts::Ref CycleCharts::add(const QString& id, PlotView* plot, PlotView::CurveId curve) {
    const Ref ref{plot, curve};
    refs_[id] = ref;
    return ref;
}

void CycleCharts::build() {
    using Side = PlotView::Side;
    using Dash = PlotView::Dash;
    using Scale = PlotView::Scale;
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setSpacing(6);

    cycle_time_ = new PlotView(this);
    cycle_time_->setObjectName(QStringLiteral("chart:cycle_time"));
    cycle_time_->set_x_axis({Scale::log, {}, QStringLiteral("%g"), {}, true});
    cycle_time_->set_y_axis(Side::left, {Scale::log, {}, QStringLiteral("%g"), {}});
    // A little beyond the swept feeds, so a dot at either end is drawn whole.
    cycle_time_->set_x_range(kFeedLo / kFeedPad, kFeedHi * kFeedPad);
    ct_base_single_ = add(QStringLiteral("cycle_time.baseline_single_touch"), cycle_time_,
                          cycle_time_->add_line({{}, kSingleColour, 1.5, Dash::dashed}));
    // Named so the legend has it while a baseline is pinned (retranslate names it).
    ct_base_two_ = add(QStringLiteral("cycle_time.baseline_two_touch"), cycle_time_,
                       cycle_time_->add_line({QStringLiteral("b"), kTwoColour, 1.5, Dash::dashed}));
    ct_single_ = add(QStringLiteral("cycle_time.single_touch"), cycle_time_,
                     cycle_time_->add_line({QStringLiteral("1"), kSingleColour, 2.0}));
    ct_two_ = add(QStringLiteral("cycle_time.two_touch"), cycle_time_,
                  cycle_time_->add_line({QStringLiteral("2"), kTwoColour, 2.0}));
    ct_single_invalid_ = add(QStringLiteral("cycle_time.single_touch_invalid"), cycle_time_,
                             cycle_time_->add_line({{}, kInvalidStretchColour, 1.5, Dash::dashed}));
    ct_two_invalid_ =
        add(QStringLiteral("cycle_time.two_touch_invalid"), cycle_time_,
            cycle_time_->add_line({QStringLiteral("i"), kInvalidStretchColour, 1.5, Dash::dashed}));
    ct_single_unreached_ =
        add(QStringLiteral("cycle_time.single_touch_unreached"), cycle_time_,
            cycle_time_->add_line({QStringLiteral("u1"), kSingleColour, 1.5, Dash::dotted}));
    ct_two_unreached_ =
        add(QStringLiteral("cycle_time.two_touch_unreached"), cycle_time_,
            cycle_time_->add_line({QStringLiteral("u2"), kTwoColour, 1.5, Dash::dotted}));
    // The current feed's vertical line explains itself: kept out of the legend.
    ct_feed_ = add(QStringLiteral("cycle_time.feed"), cycle_time_,
                   cycle_time_->add_line({{}, kMarkerColour, 1.5}));
    ct_knee_ = add(QStringLiteral("cycle_time.knee"), cycle_time_,
                   cycle_time_->add_markers({QStringLiteral("k"), kKneeColour}, 11.0));
    // The scenario's own cycle: above the two-touch curve by what its backoff wastes.
    ct_cycle_ = add(QStringLiteral("cycle_time.current"), cycle_time_,
                    cycle_time_->add_markers({QStringLiteral("c"), kMarkerColour}, 9.0));
    // An invalid cycle has no cycle time to plot: its feed is a red
    // dashed line across the chart, named as invalid in the legend, in place
    // of the dot and of the feed's grey line, only while the cycle is invalid.
    ct_cycle_invalid_ =
        add(QStringLiteral("cycle_time.current_invalid"), cycle_time_,
            cycle_time_->add_rule({QStringLiteral("ci"), kInvalidColour, 2.0, Dash::dashed}));
    cycle_time_->set_visible(ct_cycle_invalid_.curve, false);

    phases_ = new PlotView(this);
    phases_->setObjectName(QStringLiteral("chart:phases"));
    phases_->set_x_axis({Scale::linear, {}, QStringLiteral("%.3g"), {}});
    phases_->set_y_axis(Side::left, {Scale::category, {}, {}, {}});
    phases_->set_legend_visible(false);
    for (Phase phase : all_phases()) {
        const QColor colour = phase_colour(phase);
        phase_areas_[static_cast<std::size_t>(phase)] =
            add(QStringLiteral("phases.") + QString::fromUtf8(to_string(phase)), phases_,
                phases_->add_area({{}, colour, 0.0}, colour));
    }

    overtravel_ = new PlotView(this);
    overtravel_->setObjectName(QStringLiteral("chart:overtravel"));
    overtravel_->set_x_axis({Scale::log, {}, QStringLiteral("%g"), {}, true});
    overtravel_->set_y_axis(Side::left,
                            {Scale::linear, {}, QStringLiteral("%.3g"), kOvertravelColour});
    overtravel_->set_y_axis(Side::right,
                            {Scale::log, {}, QStringLiteral("%g"), kUncertaintyColour});
    overtravel_->set_x_range(kFeedLo / kFeedPad, kFeedHi * kFeedPad);
    ot_beyond_ =
        add(QStringLiteral("overtravel.beyond_limit"), overtravel_,
            overtravel_->add_area({{}, kOvertravelColour, 0.0}, QColor(0xc0, 0x39, 0x2b, 40)));
    ot_base_overtravel_ =
        add(QStringLiteral("overtravel.baseline_overtravel"), overtravel_,
            overtravel_->add_line({QStringLiteral("b"), kOvertravelColour, 1.5, Dash::dashed}));
    ot_base_uncertainty_ =
        add(QStringLiteral("overtravel.baseline_uncertainty"), overtravel_,
            overtravel_->add_line({{}, kUncertaintyColour, 1.5, Dash::dashed, Side::right}));
    ot_limit_ = add(
        QStringLiteral("overtravel.limit"), overtravel_,
        overtravel_->add_line({QStringLiteral("l"), QColor(0x8b, 0x00, 0x00), 1.5, Dash::dashed}));
    ot_target_ = add(QStringLiteral("overtravel.target"), overtravel_,
                     overtravel_->add_line({QStringLiteral("t"), QColor(0x0b, 0x2f, 0x6b), 1.5,
                                            Dash::dotted, Side::right}));
    ot_overtravel_ = add(QStringLiteral("overtravel.overtravel"), overtravel_,
                         overtravel_->add_line({QStringLiteral("o"), kOvertravelColour, 2.0}));
    ot_overtravel2_ =
        add(QStringLiteral("overtravel.second_touch"), overtravel_,
            overtravel_->add_line({QStringLiteral("o2"), kOvertravelColour, 2.0, Dash::dotted}));
    overtravel_->set_visible(ot_overtravel2_.curve, false);
    ot_uncertainty_ = add(QStringLiteral("overtravel.uncertainty"), overtravel_,
                          overtravel_->add_line({QStringLiteral("u"), kUncertaintyColour, 2.0,
                                                 Dash::solid, Side::right}));
    ot_feed_ = add(QStringLiteral("overtravel.probe_feed"), overtravel_,
                   overtravel_->add_line({{}, kMarkerColour, 1.5}));
    // Named in the legend (two-touch), and the cycle's own uncertainty, the
    // readout's figure, marked on it: at the measuring feed.
    ot_measure_feed_ =
        add(QStringLiteral("overtravel.measure_feed"), overtravel_,
            overtravel_->add_line({QStringLiteral("m"), kUncertaintyColour, 1.5, Dash::dotted}));
    ot_cycle_uncertainty_ =
        add(QStringLiteral("overtravel.cycle_uncertainty"), overtravel_,
            overtravel_->add_markers(
                {QStringLiteral("cu"), kUncertaintyColour, 2.0, Dash::solid, Side::right}, 9.0));

    motion_ = new PlotView(this);
    motion_->setObjectName(QStringLiteral("chart:motion"));
    motion_->set_x_axis({Scale::linear, {}, QStringLiteral("%.3g"), {}});
    motion_->set_y_axis(Side::left, {Scale::linear, {}, QStringLiteral("%.2f"), kPositionColour});
    motion_->set_y_axis(Side::right, {Scale::linear, {}, QStringLiteral("%.0f"), kSpeedColour});
    mo_surface_ = add(QStringLiteral("motion.surface"), motion_,
                      motion_->add_line({QStringLiteral("s"), kSurfaceColour, 1.0, Dash::dashed}));
    mo_base_position_ =
        add(QStringLiteral("motion.baseline_position"), motion_,
            motion_->add_line({QStringLiteral("b"), kPositionColour, 1.5, Dash::dashed}));
    mo_base_speed_ = add(QStringLiteral("motion.baseline_speed"), motion_,
                         motion_->add_line({{}, kSpeedColour, 1.5, Dash::dashed, Side::right}));
    mo_position_ = add(QStringLiteral("motion.position"), motion_,
                       motion_->add_line({QStringLiteral("p"), kPositionColour, 2.0}));
    mo_speed_ =
        add(QStringLiteral("motion.speed"), motion_,
            motion_->add_line({QStringLiteral("v"), kSpeedColour, 1.5, Dash::solid, Side::right}));

    grid->addWidget(cycle_time_, 0, 0);
    grid->addWidget(overtravel_, 0, 1);
    grid->addWidget(phases_, 1, 0);
    grid->addWidget(motion_, 1, 1);
    grid->setRowStretch(0, 1);
    grid->setRowStretch(1, 1);
    grid->setColumnStretch(0, 1);
    grid->setColumnStretch(1, 1);
    set_baseline(nullptr);
}

void CycleCharts::retranslate() {
    using Side = PlotView::Side;
    using Scale = PlotView::Scale;
    const QString feed_axis = tr("Probing feedrate [%1]").arg(unit_mm_min());
    cycle_time_->set_title(tr("Cycle time vs probing feedrate"));
    cycle_time_->set_x_axis({Scale::log, feed_axis, QStringLiteral("%g"), {}, true});
    cycle_time_->set_y_axis(
        Side::left, {Scale::log, tr("Cycle time [%1]").arg(unit_s()), QStringLiteral("%g"), {}});
    cycle_time_->set_name(ct_single_.curve, tr("Single-touch"));
    cycle_time_->set_name(ct_two_.curve, tr("Two-touch, best backoff"));
    cycle_time_->set_name(ct_cycle_.curve, tr("This cycle"));
    cycle_time_->set_name(ct_cycle_invalid_.curve, tr("This cycle (invalid)"));
    cycle_time_->set_name(ct_two_invalid_.curve, tr("Invalid"));
    cycle_time_->set_name(ct_single_unreached_.curve, tr("Single-touch, feed not reached"));
    cycle_time_->set_name(ct_two_unreached_.curve, tr("Two-touch, feed not reached"));
    cycle_time_->set_name(ct_knee_.curve, tr("Knee"));

    phases_->set_x_axis({Scale::linear, tr("Time [%1]").arg(unit_s()), QStringLiteral("%.3g"), {}});

    overtravel_->set_title(tr("Overtravel and uncertainty vs feedrate"));
    overtravel_->set_x_axis({Scale::log, feed_axis, QStringLiteral("%g"), {}, true});
    overtravel_->set_y_axis(Side::left, {Scale::linear, tr("Overtravel [%1]").arg(unit_mm()),
                                         QStringLiteral("%.3g"), kOvertravelColour});
    overtravel_->set_y_axis(Side::right, {Scale::log, tr("Uncertainty, k = 2 [%1]").arg(unit_um()),
                                          QStringLiteral("%g"), kUncertaintyColour});
    name_overtravel_curves();
    overtravel_->set_name(ot_limit_.curve, tr("Limit"));
    overtravel_->set_name(ot_uncertainty_.curve, tr("Uncertainty"));
    overtravel_->set_name(ot_target_.curve, tr("Target"));
    overtravel_->set_name(ot_measure_feed_.curve, tr("Measuring feedrate"));
    overtravel_->set_name(ot_cycle_uncertainty_.curve, tr("This cycle's uncertainty"));

    motion_->set_title(tr("Position and speed through the cycle"));
    motion_->set_x_axis({Scale::linear, tr("Time [%1]").arg(unit_s()), QStringLiteral("%.3g"), {}});
    motion_->set_y_axis(Side::left, {Scale::linear, tr("Position [%1]").arg(unit_mm()),
                                     QStringLiteral("%.2f"), kPositionColour});
    motion_->set_y_axis(Side::right, {Scale::linear, tr("Speed [%1]").arg(unit_mm_min()),
                                      QStringLiteral("%.0f"), kSpeedColour});
    motion_->set_name(mo_position_.curve, tr("Position"));
    motion_->set_name(mo_speed_.curve, tr("Speed"));
    motion_->set_name(mo_surface_.curve, tr("Surface"));

    cycle_time_->setToolTip(tr(
        "Cycle time of the whole cycle against the probing feed, for single-touch and two-touch "
        "with everything else as set. Vertical line: the current feed. Dot: the knee, the lowest "
        "valid feed within the knee tolerance of the best time. Grey, dashed: feeds whose cycle "
        "is invalid (overtravel over the limit, backoff too small). Dotted: feeds the first "
        "touch never reaches from its start, so the cycle is not at the feed it says (its time "
        "falls only because of that); the knee is not among them. A red dashed line: this "
        "cycle is invalid and has no cycle time (see the warnings)."));
    phases_->setToolTip(
        tr("The phases of the current cycle in time order, each row with its total "
           "time over all touches. Grey: the cycle is invalid and cannot run as set (the "
           "title and the warnings say why); its phases are what the model computes."));
    overtravel_->setToolTip(
        tr("Red: overtravel of a touch at each feed, at the highest feed override, against the "
           "probe's limit (dashed); the shaded feeds overtravel beyond it. Two-touch: the first "
           "touch solid, the second dotted; with a fixed backoff a fast first touch leaves the "
           "second too little room to brake, so the second may overtravel more. Blue, right axis: "
           "the uncertainty (k = 2) of a touch measured at each feed against the target (dotted); "
           "the dot is this cycle's, the readout's figure, at the feed of the touch that measures. "
           "Vertical lines: the probing feed and, for two-touch, the measuring feed (blue, "
           "dotted)."));
    motion_->setToolTip(
        tr("Position along the probing direction of each touch (the surface is dashed) and path "
           "speed through the whole cycle. The position line breaks during the moves between "
           "touches, which run across that direction; the speed shows them."));

    const QString baseline = tr("Baseline (dashed)");
    cycle_time_->set_name(ct_base_two_.curve, baseline);
    overtravel_->set_name(ot_base_overtravel_.curve, baseline);
    motion_->set_name(mo_base_position_.curve, baseline);
    set_phases_title();
}

void CycleCharts::set_phases_title() {
    if (!has_result_) {
        phases_->set_title(tr("Phases"));
    } else if (!cycle_valid_) {
        // As the cycle-time readout: what makes it invalid, in place of a total.
        QStringList why;
        for (const WarningCode code : invalid_reasons_) why << warning_title(code);
        //: %1: why the cycle cannot run, e.g. "Backoff too small"
        phases_->set_title(
            tr("Phases of an invalid cycle (grey): %1").arg(why.join(QStringLiteral("; "))));
    } else {
        phases_->set_title(tr("Phases: total %1").arg(format_seconds(total_s_)));
    }
}

void CycleCharts::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

bool CycleCharts::same_points(const Buffer& a, const Buffer& b) {
    const auto same = [](double u, double v) { return u == v || (std::isnan(u) && std::isnan(v)); };
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [&](const QPointF& p, const QPointF& q) {
                          return same(p.x(), q.x()) && same(p.y(), q.y());
                      });
}

void CycleCharts::set_if_changed(const Ref& ref, PingPong& buffers) {
    if (buffers.changed()) set(ref, buffers.lists[static_cast<std::size_t>(buffers.current)]);
}

void CycleCharts::show_result(const Computed& c) {
    if (!c.valid()) return;  // keep the last valid drawing; the warnings say why
    has_result_ = true;
    draw_cycle_time(c);
    draw_phases(c);
    draw_overtravel(c);
    draw_motion(c);
}

void CycleCharts::draw_cycle_time(const Computed& c) {
    Buffer& single = single_.next();
    Buffer& two = two_.next();
    fill_sweep(single, c.single_touch, &SweepPoint::cycle_time_s, 1.0, 0.0);
    fill_sweep(two, c.two_touch, &SweepPoint::cycle_time_s, 1.0, 0.0);
    Span span;
    span.add_y(single);
    span.add_y(two);
    Buffer& single_invalid = single_invalid_.next();
    Buffer& two_invalid = two_invalid_.next();
    const bool any_single = split_invalid(single, single_invalid, c.single_touch);
    const bool any_two = split_invalid(two, two_invalid, c.two_touch);
    Buffer& single_unreached = single_unreached_.next();
    Buffer& two_unreached = two_unreached_.next();
    const bool unreached_single = split_unreached(single, single_unreached, c.single_touch);
    const bool unreached_two = split_unreached(two, two_unreached, c.two_touch);
    if (baseline_) {
        span.add_y(baseline_->single);
        span.add_y(baseline_->two);
    }
    // This cycle's dot sits above the two-touch curve by what its backoff wastes,
    // possibly above both curves.
    if (c.cycle().valid()) span.add(c.cycle().total());
    const auto [decade_lo, decade_hi] = decade_range(span, 1e-3);
    const double pad = std::pow(decade_hi / decade_lo, kTimePadFraction);
    const double lo = decade_lo / pad;
    const double hi = decade_hi * pad;
    cycle_time_->set_y_range(PlotView::Side::left, lo, hi);
    set_if_changed(ct_single_, single_);
    set_if_changed(ct_two_, two_);
    set_if_changed(ct_single_invalid_, single_invalid_);
    set_if_changed(ct_two_invalid_, two_invalid_);
    set_if_changed(ct_single_unreached_, single_unreached_);
    set_if_changed(ct_two_unreached_, two_unreached_);
    cycle_time_->set_visible(ct_single_unreached_.curve, unreached_single);
    cycle_time_->set_visible(ct_two_unreached_.curve, unreached_two);
    // One legend entry for the grey stretches, on whichever curve has them.
    cycle_time_->set_visible(ct_single_invalid_.curve, any_single);
    cycle_time_->set_visible(ct_two_invalid_.curve, any_single || any_two);

    const double feed = std::clamp(c.scenario.cycle.probe_feed_mm_min, kFeedLo, kFeedHi);
    fill_segment(line_, feed, lo, feed, hi);
    set(ct_feed_, line_);
    knee_.clear();
    if (c.analysis.knee_feed_mm_min && c.analysis.knee_cycle_time_s) {
        knee_.append({*c.analysis.knee_feed_mm_min, *c.analysis.knee_cycle_time_s});
    }
    set(ct_knee_, knee_);
    current_cycle_.clear();
    current_cycle_.append({feed, c.cycle().total()});
    const bool valid = c.cycle().valid();
    set(valid ? ct_cycle_ : ct_cycle_invalid_, current_cycle_);
    set(valid ? ct_cycle_invalid_ : ct_cycle_, {});
    cycle_time_->set_visible(ct_cycle_.curve, valid);
    cycle_time_->set_visible(ct_feed_.curve, valid);
    cycle_time_->set_visible(ct_cycle_invalid_.curve, !valid);
}

void CycleCharts::draw_phases(const Computed& c) {
    const CycleResult& cycle = c.cycle();
    total_s_ = cycle.total();
    cycle_valid_ = cycle.valid();
    invalid_reasons_.clear();
    for (const Warning& w : cycle.warnings()) {
        if (w.severity == Severity::error) invalid_reasons_.push_back(w.code);
    }
    set_phases_title();

    // Rows in the order the phases first happen, the first at the top. A
    // second touch's phase shares its first touch's row in a lighter shade:
    // fewer, taller rows keep the labels readable (a Chinese label is tall).
    std::array<int, kPhaseCount> order{};
    order.fill(-1);
    phase_present_.fill(false);
    int rows = 0;
    for (const PhaseRecord& record : cycle.phases()) {
        phase_present_[static_cast<std::size_t>(record.phase)] = true;
        int& row = order[static_cast<std::size_t>(row_phase(record.phase))];
        if (row < 0) row = rows++;
    }
    for (Phase phase : all_phases()) {
        order[static_cast<std::size_t>(phase)] = order[static_cast<std::size_t>(row_phase(phase))];
    }
    // One unit down the column of times, not s and ms mixed; a shared row
    // gives both touches' times, first + second.
    std::vector<double> times;
    std::vector<Phase> timed;
    for (Phase phase : all_phases()) {
        if (!phase_present_[static_cast<std::size_t>(phase)]) continue;
        times.push_back(cycle.phase_time(phase));
        timed.push_back(phase);
    }
    const SecondsColumn shown = format_seconds_column(times);
    QStringList row_times;
    row_times.resize(rows);
    for (std::size_t i = 0; i < timed.size(); ++i) {
        QString& text = row_times[order[static_cast<std::size_t>(timed[i])]];
        text += (text.isEmpty() ? QString() : QStringLiteral(" + ")) +
                shown.numbers.at(static_cast<qsizetype>(i));
    }
    QStringList labels;
    labels.resize(rows);
    for (Phase phase : all_phases()) {
        const std::size_t k = static_cast<std::size_t>(phase);
        const int row = order[k];
        if (row >= 0 && row_phase(phase) == phase) {
            labels[rows - 1 - row] = phase_label(phase) + QStringLiteral(" \u00b7 ") +
                                     with_unit(row_times.at(row), shown.unit);
        }
        phase_upper_[k].clear();
        phase_lower_[k].clear();
    }
    // Sub-millisecond phases get a sliver of width so every row shows where it happens;
    // the row label carries the exact time.
    const double min_width = kMinBarFraction * total_s_;
    for (const PhaseRecord& record : cycle.phases()) {
        const std::size_t k = static_cast<std::size_t>(record.phase);
        const double y = static_cast<double>(rows - 1 - order[k]);
        const double s = record.start_s;
        const double e = record.start_s + std::max(record.time_s, min_width);
        Buffer& upper = phase_upper_[k];
        Buffer& lower = phase_lower_[k];
        if (!upper.isEmpty()) {
            // Between two occurrences the area collapses to nothing at the bar's foot.
            upper.append({upper.last().x(), y - kBarHalfHeight});
            upper.append({s, y - kBarHalfHeight});
            lower.append({lower.last().x(), y - kBarHalfHeight});
            lower.append({s, y - kBarHalfHeight});
        }
        upper.append({s, y + kBarHalfHeight});
        upper.append({e, y + kBarHalfHeight});
        lower.append({s, y - kBarHalfHeight});
        lower.append({e, y - kBarHalfHeight});
    }
    phases_->set_y_categories(labels);
    if (phases_x_.update(0.0, total_s_ > 0.0 ? total_s_ : 1.0)) {
        phases_->set_x_range(phases_x_.lo, phases_x_.hi);
    }
    for (Phase phase : all_phases()) {
        const std::size_t k = static_cast<std::size_t>(phase);
        const Ref& ref = phase_areas_[k];
        ref.plot->set_area(ref.curve, phase_upper_[k], phase_lower_[k]);
        // An invalid cycle's phases are grey, as the cycle-time
        // chart's invalid stretches: no bar of it looks like a cycle that runs.
        ref.plot->set_fill(ref.curve, cycle_valid_ ? phase_colour(phase) : kInvalidStretchColour);
        ref.plot->set_visible(ref.curve, phase_present_[k]);
    }
}

// The curves are the overtravel the limit is checked against, at
// the highest feed override; their names say so.
void CycleCharts::name_overtravel_curves() {
    if (overtravel_override_pct_ > 100.0) {
        const QString pct = QLocale().toString(overtravel_override_pct_, 'f', 0);
        overtravel_->set_name(ot_overtravel_.curve,
                              two_touch_overtravel_ ? tr("1st touch at %1 % override").arg(pct)
                                                    : tr("Overtravel at %1 % override").arg(pct));
        overtravel_->set_name(ot_overtravel2_.curve, tr("2nd touch at %1 % override").arg(pct));
        return;
    }
    overtravel_->set_name(ot_overtravel_.curve,
                          two_touch_overtravel_ ? tr("1st touch") : tr("Overtravel"));
    overtravel_->set_name(ot_overtravel2_.curve, tr("2nd touch"));
}

void CycleCharts::draw_overtravel(const Computed& c) {
    using Side = PlotView::Side;
    const SweepResult& own = c.own_sweep();
    const double limit = c.scenario.probe.overtravel_limit_mm;
    Buffer& overtravel = overtravel_pts_.next();
    Buffer& uncertainty = uncertainty_pts_.next();
    const bool two_touch = c.scenario.cycle.strategy == Strategy::two_touch;
    fill_sweep(overtravel, own, &SweepPoint::first_overtravel_mm, 1.0, 0.0);
    Buffer& overtravel2 = overtravel2_pts_.next();
    if (two_touch) {
        fill_sweep(overtravel2, own, &SweepPoint::second_overtravel_mm, 1.0, 0.0);
    } else {
        overtravel2.clear();
    }
    const double override_pct = c.scenario.cycle.feed_override_max_pct;
    if (two_touch != two_touch_overtravel_ || override_pct != overtravel_override_pct_) {
        two_touch_overtravel_ = two_touch;
        overtravel_override_pct_ = override_pct;
        name_overtravel_curves();
        overtravel_->set_visible(ot_overtravel2_.curve, two_touch);
    }
    // Uncertainty of one touch at each feed: the single-touch sweep measures at the swept feed.
    fill_sweep(uncertainty, c.single_touch, &SweepPoint::uncertainty_mm, 1000.0,
               kUncertaintyFloor_um);

    Span left;
    left.add(limit);
    left.add_y(overtravel);
    left.add_y(overtravel2);
    // The readout's uncertainty, at the feed of the touch that measures.
    const double measuring_feed = std::clamp(
        two_touch ? c.scenario.cycle.measure_feed_mm_min : c.scenario.cycle.probe_feed_mm_min,
        kFeedLo, kFeedHi);
    const double cycle_um = std::max(c.cycle().uncertainty_mm() * 1000.0, kUncertaintyFloor_um);
    cycle_uncertainty_ = {{measuring_feed, cycle_um}};
    Span right;
    right.add_y(uncertainty);
    right.add(cycle_um);
    const double target_um = c.scenario.cycle.target_uncertainty_mm * 1000.0;
    if (target_um > 0.0) right.add(target_um);
    if (baseline_) {
        left.add_y(baseline_->overtravel);
        right.add_y(baseline_->uncertainty);
    }
    const double top = nice_ceiling(left.hi * 1.05);
    overtravel_->set_y_range(Side::left, 0.0, top);
    auto [ulo, uhi] = decade_range(right, kUncertaintyFloor_um);
    // The limit (left axis) and the target (right axis) are two lines across
    // the whole chart: when they would fall within 6 % of the height of each
    // other (5 mm on 0-20 mm and 5 um on 1-1000 um), a decade more below the
    // uncertainty lifts the target clear of the limit.
    if (target_um > 0.0) {
        const auto height = [&](double lo, double hi) {
            return (std::log10(target_um) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
        };
        if (std::abs(height(ulo, uhi) - limit / top) < 0.06) ulo /= 10.0;
    }
    overtravel_->set_y_range(Side::right, ulo, uhi);
    set_if_changed(ot_overtravel_, overtravel_pts_);
    set_if_changed(ot_overtravel2_, overtravel2_pts_);
    set_if_changed(ot_uncertainty_, uncertainty_pts_);
    set(ot_cycle_uncertainty_, cycle_uncertainty_);

    fill_segment(line_, kFeedLo / kFeedPad, limit, kFeedHi * kFeedPad, limit);
    set(ot_limit_, line_);
    if (target_um > 0.0) {
        fill_segment(line2_, kFeedLo / kFeedPad, target_um, kFeedHi * kFeedPad, target_um);
    } else {
        line2_.clear();
    }
    set(ot_target_, line2_);
    // No "Target" in the legend without a target.
    overtravel_->set_visible(ot_target_.curve, target_um > 0.0);

    // Shade from the first feed whose overtravel reaches the limit (overtravel grows with feed).
    band_upper_.clear();
    band_lower_.clear();
    const auto& points = own.points;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (points[i].checked_overtravel_mm < limit) continue;
        double from = points[i].feed_mm_min;
        if (i > 0) {
            const SweepPoint& a = points[i - 1];
            const SweepPoint& b = points[i];
            const double f = (limit - a.checked_overtravel_mm) /
                             (b.checked_overtravel_mm - a.checked_overtravel_mm);
            from = a.feed_mm_min * std::pow(b.feed_mm_min / a.feed_mm_min, std::clamp(f, 0.0, 1.0));
        }
        band_upper_ = {{from, top}, {kFeedHi * kFeedPad, top}};
        band_lower_ = {{from, 0.0}, {kFeedHi * kFeedPad, 0.0}};
        break;
    }
    ot_beyond_.plot->set_area(ot_beyond_.curve, band_upper_, band_lower_);

    const double feed = std::clamp(c.scenario.cycle.probe_feed_mm_min, kFeedLo, kFeedHi);
    fill_segment(line_, feed, 0.0, feed, top);
    set(ot_feed_, line_);
    if (c.scenario.cycle.strategy == Strategy::two_touch) {
        const double measure = std::clamp(c.scenario.cycle.measure_feed_mm_min, kFeedLo, kFeedHi);
        fill_segment(line2_, measure, 0.0, measure, top);
    } else {
        line2_.clear();
    }
    set(ot_measure_feed_, line2_);
    overtravel_->set_visible(ot_measure_feed_.curve, two_touch);
}

void CycleCharts::draw_motion(const Computed& c) {
    using Side = PlotView::Side;
    Buffer& position = position_pts_.next();
    Buffer& path_speed = speed_pts_.next();
    fill_motion(times_, position, path_speed, c.cycle());
    const double approach = c.scenario.cycle.approach_mm;
    Span pos;
    pos.add(0.0);
    pos.add(approach);
    pos.add_y(position);
    Span speed;
    speed.add(0.0);
    speed.add_y(path_speed);
    double t_end = c.cycle().total();
    if (baseline_) {
        pos.add_y(baseline_->position);
        speed.add_y(baseline_->speed);
        t_end = std::max(t_end, baseline_->total_s);
    }
    if (!(t_end > 0.0)) t_end = 1.0;
    const double pad = 0.05 * std::max(pos.hi - pos.lo, 1e-3);
    if (motion_x_.update(0.0, t_end)) motion_->set_x_range(motion_x_.lo, motion_x_.hi);
    if (motion_y_.update(pos.lo - pad, pos.hi + pad)) {
        motion_->set_y_range(Side::left, motion_y_.lo, motion_y_.hi);
    }
    motion_->set_y_range(Side::right, 0.0, nice_ceiling(speed.hi * 1.05));
    set_if_changed(mo_position_, position_pts_);
    set_if_changed(mo_speed_, speed_pts_);
    fill_segment(line_, 0.0, approach, motion_x_.hi, approach);
    set(mo_surface_, line_);
}

void CycleCharts::set_baseline(const Computed* baseline) {
    if (baseline == nullptr || !baseline->valid()) {
        baseline_.reset();
    } else {
        Baseline b;
        fill_sweep(b.single, baseline->single_touch, &SweepPoint::cycle_time_s, 1.0, 0.0);
        fill_sweep(b.two, baseline->two_touch, &SweepPoint::cycle_time_s, 1.0, 0.0);
        fill_sweep(b.overtravel, baseline->own_sweep(), &SweepPoint::checked_overtravel_mm, 1.0,
                   0.0);
        fill_sweep(b.uncertainty, baseline->single_touch, &SweepPoint::uncertainty_mm, 1000.0,
                   kUncertaintyFloor_um);
        std::vector<double> times;
        fill_motion(times, b.position, b.speed, baseline->cycle());
        b.total_s = baseline->cycle().total();
        baseline_ = std::move(b);
    }
    draw_baseline();
}

void CycleCharts::draw_baseline() {
    const bool on = baseline_.has_value();
    const Buffer none;
    set(ct_base_single_, on ? baseline_->single : none);
    set(ct_base_two_, on ? baseline_->two : none);
    set(ot_base_overtravel_, on ? baseline_->overtravel : none);
    set(ot_base_uncertainty_, on ? baseline_->uncertainty : none);
    set(mo_base_position_, on ? baseline_->position : none);
    set(mo_base_speed_, on ? baseline_->speed : none);
    for (const Ref* ref : {&ct_base_single_, &ct_base_two_, &ot_base_overtravel_,
                           &ot_base_uncertainty_, &mo_base_position_, &mo_base_speed_}) {
        ref->plot->set_visible(ref->curve, on);
    }
}

QList<QPointF> CycleCharts::series_points(const QString& id) const {
    const auto it = refs_.find(id);
    return it == refs_.end() ? QList<QPointF>{} : it->second.plot->points(it->second.curve);
}

QStringList CycleCharts::series_ids() const {
    QStringList ids;
    for (const auto& [id, ref] : refs_) ids.append(id);
    return ids;
}

bool CycleCharts::series_visible(const QString& id) const {
    const auto it = refs_.find(id);
    return it != refs_.end() && it->second.plot->is_visible(it->second.curve);
}

QColor CycleCharts::series_color(const QString& id) const {
    const auto it = refs_.find(id);
    return it != refs_.end() ? it->second.plot->fill(it->second.curve) : QColor();
}

}  // namespace probecycle::ui
