#pragma once

// The one place that knows the plotting library. Everything else in ui/ draws
// through this class in its own terms (curves, bands, axes), so moving from
// Qt Charts (deprecated from Qt 6.10) to Qt Graphs touches this file and
// plot_view.cpp only. No Qt Charts header is included here on purpose.

#include <QColor>
#include <QImage>
#include <QList>
#include <QPointF>
#include <QRectF>
#include <QSize>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <memory>

namespace probecycle::ui {

class PlotView : public QWidget {
    Q_OBJECT

  public:
    enum class Scale { linear, log, category };
    enum class Side { left, right };
    enum class Dash { solid, dashed, dotted };

    struct AxisSpec {
        Scale scale{Scale::linear};
        QString title;
        QString label_format{QStringLiteral("%g")};
        QColor color;            // invalid = theme default
        bool minor_grid{false};  // log axes: lines at 2..9 of each decade
    };

    struct LineSpec {
        QString name;  // legend text; empty = not in the legend (set_name can change it)
        QColor color;
        double width{2.0};
        Dash dash{Dash::solid};
        Side axis{Side::left};
    };

    using CurveId = int;

    struct Range {
        double lo{0.0};
        double hi{0.0};
    };

    explicit PlotView(QWidget* parent = nullptr);

    // The round axis step (1, 2 or 5 times a power of ten) at or above `raw`.
    static double nice_step(double raw);
    ~PlotView() override;

    void set_title(const QString& title);
    QString title() const;
    void set_legend_visible(bool visible);
    // Below the plot (the default), wrapped into as many rows as its entries
    // need, or beside it on the right, one entry per line: the right suits a
    // legend that is a colour scale. Entries are never cut short.
    void set_legend_beside(bool beside);

    // Axes are created on the first call and only retitled/re-ranged later.
    void set_x_axis(const AxisSpec& spec);
    void set_y_axis(Side side, const AxisSpec& spec);
    void set_x_range(double lo, double hi);
    void set_y_range(Side side, double lo, double hi);
    // A drawing in millimetres on x and the left y axis, at equal scales (a
    // circle looks round, an 80 x 60 mm part wider than tall): the ranges
    // hold `bounds` with a margin and follow the plot area as it resizes.
    // An empty rectangle ends it; the ranges stay as they are.
    void set_equal_scales(const QRectF& bounds);
    // Labels of a category y axis, bottom to top, placed at 0, 1, 2, ...
    // Their font shrinks (to a readable floor) so that every row keeps its label.
    void set_y_categories(const QStringList& labels);

    // Curves must be added after the axes they use. A point that is not finite
    // (NaN) breaks a line: the stretches on either side are drawn apart, and
    // markers are not drawn there.
    CurveId add_line(const LineSpec& spec);
    CurveId add_markers(const LineSpec& spec, double marker_size);
    // Vertical lines across the whole plot, at the x of each point handed over
    // (y is ignored): they span the y axis of spec.axis whatever its range.
    CurveId add_rule(const LineSpec& spec);
    // A filled region between an upper and a lower polyline.
    CurveId add_area(const LineSpec& spec, const QColor& fill);

    // Hands the buffer to the plot (a replace, never clear + append).
    void set_points(CurveId curve, const QList<QPointF>& points);
    void set_area(CurveId curve, const QList<QPointF>& upper, const QList<QPointF>& lower);
    void set_name(CurveId curve, const QString& name);
    void set_visible(CurveId curve, bool visible);
    // An area's fill (its outline, if it has one, too); a line's or markers'
    // colour. fill() reads it back.
    void set_fill(CurveId curve, const QColor& color);
    QColor fill(CurveId curve) const;

    // What is drawn: for tests and for the compare feature. points() are the
    // points handed over (with their breaks; a rule's x).
    QList<QPointF> points(CurveId curve) const;
    qsizetype point_count(CurveId curve) const;
    // The points the chart draws: markers beyond a few thousand are thinned to
    // one per cell of a grid over them (a fit still uses every point).
    qsizetype drawn_count(CurveId curve) const;
    bool is_visible(CurveId curve) const;
    // The legend's entries as shown after the last layout, in order (none while
    // the legend is hidden).
    QStringList legend_texts() const;
    Range x_range() const;
    Range y_range(Side side) const;
    // The tick labels an axis shows after the last layout: left to right,
    // bottom to top. Labels the plot hides (overlapping, cut at an edge) are left out.
    QStringList x_labels() const;
    QStringList y_labels(Side side) const;
    // The texts the plot shows only in part or not at all after the last
    // layout: the title, axis titles and legend entries cut short, category
    // labels dropped, tick labels elided. Empty when everything is whole.
    QStringList cut_texts() const;
    // The smallest pixel size among the axis titles' fonts as drawn after the
    // last layout (0 without an axis title).
    int smallest_axis_title_px() const;
    // The pixel size of the category labels' font after the last layout (0
    // without a category axis).
    int category_label_px() const;
    // Every text the plot has to show: its title, the axis titles, the legend
    // entries and the category labels (for checks of the language in use).
    QStringList texts() const;

    // The chart and its legend drawn at `size` logical pixels, `scale` device
    // pixels each, on white: laid out for the picture whatever the widget's
    // size and whether it is shown (the PDF report draws charts for its page).
    QImage picture(QSize size, double scale);

  protected:
    // Axis labels follow the interface language's number format.
    void changeEvent(QEvent* event) override;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace probecycle::ui
