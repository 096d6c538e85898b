#pragma once

// The four live charts: cycle time against feed, the phases of the current
// cycle, overtravel and uncertainty against feed, and position and speed
// through the cycle. Draws a Computed; all drawing goes through PlotView.

#include <QList>
#include <QPointF>
#include <QString>
#include <QWidget>
#include <array>
#include <map>
#include <optional>
#include <vector>

#include "ui/common/plot_view.h"
#include "ui/cycle/computation.h"

namespace probecycle::ui {

struct StableRange {
    double lo{0.0};
    double hi{0.0};
    bool set{false};
    // True when the range changed.
    bool update(double want_lo, double want_hi);
};

class CycleCharts : public QWidget {
    Q_OBJECT

  public:
    explicit CycleCharts(QWidget* parent = nullptr);

    // Redraws every chart from the computation (buffers reused, axes kept).
    void show_result(const Computed& computed);
    // Pins the given result as the dashed baseline; nullptr removes it.
    void set_baseline(const Computed* baseline);
    // The next show_result() fits the time and position axes to its data
    // anew: after a jump (a preset, a fix, undo, another file), where the
    // ranges kept still under a slider would leave a 7 s cycle on a 13 s axis.
    void refit_ranges();

    // What a chart draws, by a stable id ("cycle_time.two_touch", ...): for
    // tests, and for anyone checking what the user sees.
    QList<QPointF> series_points(const QString& id) const;
    QStringList series_ids() const;
    bool series_visible(const QString& id) const;
    // An area's fill, a line's colour (grey where a cycle is invalid).
    QColor series_color(const QString& id) const;
    // The four charts in reading order (across, then down), for the PDF report.
    QList<PlotView*> plots() const { return {cycle_time_, overtravel_, phases_, motion_}; }

  protected:
    void changeEvent(QEvent* event) override;

  private:
    struct Ref {
        PlotView* plot{nullptr};
        PlotView::CurveId curve{-1};
    };
    using Buffer = QList<QPointF>;
    // Exactly equal, a break (NaN) equal to a break. QPointF's == is fuzzy and
    // never equal at NaN: a curve broken at its invalid feeds would look changed
    // at every recompute and be handed over again.
    static bool same_points(const Buffer& a, const Buffer& b);
    // Two buffers per big curve, used in turn: the plot shares the one handed over
    // last (QList is implicitly shared), so the other refills in place. Reserved
    // once, they are never reallocated while a slider moves.
    struct PingPong {
        std::array<Buffer, 2> lists;
        int current{0};
        Buffer& next() {
            current ^= 1;
            return lists[static_cast<std::size_t>(current)];
        }
        void reserve(qsizetype n) {
            for (Buffer& b : lists) b.reserve(n);
        }
        // After filling next(): false, and back to the previous buffer, when
        // nothing changed (a feed change leaves the feed sweeps as they are).
        bool changed() {
            const std::size_t now = static_cast<std::size_t>(current);
            if (!same_points(lists[now], lists[now ^ 1U])) return true;
            current ^= 1;
            return false;
        }
    };

    void build();
    void set_phases_title();
    void retranslate();
    Ref add(const QString& id, PlotView* plot, PlotView::CurveId curve);
    void set(const Ref& ref, const Buffer& points) { ref.plot->set_points(ref.curve, points); }
    // Hands over the buffer just filled unless the plot already shows the same points.
    void set_if_changed(const Ref& ref, PingPong& buffers);

    void draw_cycle_time(const Computed& c);
    void draw_phases(const Computed& c);
    void draw_overtravel(const Computed& c);
    void draw_motion(const Computed& c);
    void draw_baseline();

    PlotView* cycle_time_{nullptr};
    PlotView* phases_{nullptr};
    PlotView* overtravel_{nullptr};
    PlotView* motion_{nullptr};
    std::map<QString, Ref> refs_;

    // Curves, by chart.
    Ref ct_single_, ct_two_, ct_feed_, ct_knee_, ct_cycle_, ct_base_single_, ct_base_two_;
    Ref ct_cycle_invalid_;  // the scenario's own feed when the model marks its cycle invalid
    // The stretches of each curve where the cycles are invalid, grey.
    Ref ct_single_invalid_, ct_two_invalid_, ct_single_unreached_, ct_two_unreached_;
    std::array<Ref, kPhaseCount> phase_areas_{};
    Ref ot_overtravel_, ot_overtravel2_, ot_limit_, ot_beyond_, ot_uncertainty_, ot_target_,
        ot_feed_, ot_measure_feed_, ot_base_overtravel_, ot_base_uncertainty_,
        ot_cycle_uncertainty_;
    Ref mo_position_, mo_speed_, mo_surface_, mo_base_position_, mo_base_speed_;

    PingPong single_invalid_, two_invalid_, single_unreached_, two_unreached_;
    PingPong single_, two_, overtravel_pts_, overtravel2_pts_, uncertainty_pts_, position_pts_,
        speed_pts_;
    // Two-touch draws each touch's overtravel (a fast first touch can
    // overtravel less than the second); the legend names them then.
    bool two_touch_overtravel_{false};
    // The feed override the overtravel curves are at, in %.
    double overtravel_override_pct_{100.0};
    void name_overtravel_curves();
    Buffer line_, line2_, band_upper_, band_lower_, knee_, current_cycle_, cycle_uncertainty_;
    std::array<Buffer, kPhaseCount> phase_upper_, phase_lower_;
    std::vector<double> times_;

    // The pinned baseline's curves, drawn dashed.
    struct Baseline {
        Buffer single, two, overtravel, uncertainty, position, speed;
        double total_s{0.0};
    };
    std::optional<Baseline> baseline_;
    bool has_result_{false};
    double total_s_{0.0};
    bool cycle_valid_{true};  // an invalid cycle's phases are grey, titled with why, no total
    std::vector<WarningCode> invalid_reasons_;
    std::array<bool, kPhaseCount> phase_present_{};
    StableRange phases_x_, motion_x_, motion_y_;
};

}  // namespace probecycle::ui
