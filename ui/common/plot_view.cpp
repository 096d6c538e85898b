#include "ui/common/plot_view.h"

#include <QAreaSeries>
#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QGraphicsLayout>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QPen>
#include <QScatterSeries>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>
#include <cmath>
#include <vector>

namespace probecycle::ui {

namespace {

Qt::PenStyle pen_style(PlotView::Dash dash) {
    switch (dash) {
        case PlotView::Dash::dashed:
            return Qt::DashLine;
        case PlotView::Dash::dotted:
            return Qt::DotLine;
        case PlotView::Dash::solid:
            break;
    }
    return Qt::SolidLine;
}

// 1, 2 or 5 times a power of ten, nearest above `raw`.
// A one-pixel cosmetic pen: the raster engine's fast path for grid lines.
QPen hairline(const QColor& colour) {
    QPen pen(colour, 1.0);
    pen.setCosmetic(true);
    return pen;
}

QPen make_pen(const PlotView::LineSpec& spec) {
    QPen pen(spec.color);
    pen.setWidthF(spec.width);
    pen.setStyle(pen_style(spec.dash));
    pen.setCapStyle(Qt::FlatCap);
    return pen;
}

}  // namespace

struct PlotView::Impl {
    struct Curve {
        QXYSeries* series{nullptr};       // line or scatter; upper line of an area
        QLineSeries* lower{nullptr};      // areas only
        QAreaSeries* area{nullptr};       // areas only
        QAbstractSeries* shown{nullptr};  // what the chart holds
        bool in_legend{false};
    };

    QChart* chart{nullptr};
    QChartView* view{nullptr};
    QAbstractAxis* x_axis{nullptr};
    QAbstractAxis* y_left{nullptr};
    QAbstractAxis* y_right{nullptr};
    QStringList categories;
    std::vector<Curve> curves;

    QAbstractAxis*& y_axis(Side side) { return side == Side::left ? y_left : y_right; }

    static QAbstractAxis* make_axis(const AxisSpec& spec) {
        switch (spec.scale) {
            case Scale::log: {
                auto* axis = new QLogValueAxis;
                axis->setBase(10.0);
                axis->setLabelFormat(spec.label_format);
                axis->setMinorTickCount(spec.minor_grid ? -1 : 0);
                return axis;
            }
            case Scale::category: {
                auto* axis = new QCategoryAxis;
                axis->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
                axis->setGridLineVisible(false);
                axis->setTruncateLabels(false);  // row names are the point of this axis
                QFont font = axis->labelsFont();
                font.setPointSizeF(font.pointSizeF() * 0.9);
                axis->setLabelsFont(font);
                return axis;
            }
            case Scale::linear:
                break;
        }
        auto* axis = new QValueAxis;
        axis->setLabelFormat(spec.label_format);
        axis->setTickType(QValueAxis::TicksDynamic);
        axis->setTickAnchor(0.0);
        axis->setTickInterval(1.0);
        return axis;
    }

    static void style_axis(QAbstractAxis* axis, const AxisSpec& spec) {
        // Solid hairlines: the theme's dashed minor grid costs more to paint than the curves.
        axis->setGridLinePen(hairline(QColor(0xdd, 0xdd, 0xdd)));
        axis->setMinorGridLinePen(hairline(QColor(0xee, 0xee, 0xee)));
        if (axis->titleText() != spec.title) axis->setTitleText(spec.title);
        QFont title_font = axis->titleFont();
        title_font.setBold(false);
        axis->setTitleFont(title_font);
        if (spec.color.isValid()) {
            axis->setTitleBrush(spec.color);
            axis->setLabelsColor(spec.color);
            QPen line = axis->linePen();
            line.setColor(spec.color);
            axis->setLinePen(line);
        }
    }

    static void set_range(QAbstractAxis* axis, double lo, double hi) {
        if (axis == nullptr || !std::isfinite(lo) || !std::isfinite(hi)) return;
        if (hi <= lo) hi = lo + (lo == 0.0 ? 1.0 : std::abs(lo) * 0.1);
        if (auto* value = qobject_cast<QValueAxis*>(axis)) {
            // Ticks on round numbers whatever the range: 0, 2, 4 ... rather than 2.19, 4.37.
            const double step = nice_step((hi - lo) / 5.0);
            if (value->tickInterval() != step) value->setTickInterval(step);
            if (value->min() != lo || value->max() != hi) value->setRange(lo, hi);
        } else if (auto* log = qobject_cast<QLogValueAxis*>(axis)) {
            if (lo <= 0.0) return;
            if (log->min() != lo || log->max() != hi) log->setRange(lo, hi);
        } else {
            axis->setRange(lo, hi);
        }
    }

    CurveId add(QXYSeries* series, QLineSeries* lower, QAreaSeries* area, const LineSpec& spec) {
        QAbstractSeries* shown = area != nullptr ? static_cast<QAbstractSeries*>(area) : series;
        shown->setName(spec.name);
        chart->addSeries(shown);
        if (x_axis != nullptr) shown->attachAxis(x_axis);
        if (QAbstractAxis* y = y_axis(spec.axis)) shown->attachAxis(y);
        const bool in_legend = !spec.name.isEmpty();
        for (QLegendMarker* marker : chart->legend()->markers(shown)) marker->setVisible(in_legend);
        curves.push_back({series, lower, area, shown, in_legend});
        return static_cast<CurveId>(curves.size() - 1);
    }

    Curve* find(CurveId id) {
        if (id < 0 || static_cast<std::size_t>(id) >= curves.size()) return nullptr;
        return &curves[static_cast<std::size_t>(id)];
    }
    const Curve* find(CurveId id) const {
        if (id < 0 || static_cast<std::size_t>(id) >= curves.size()) return nullptr;
        return &curves[static_cast<std::size_t>(id)];
    }
};

double PlotView::nice_step(double raw) {
    if (!(raw > 0.0) || !std::isfinite(raw)) return 1.0;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0}) {
        if (m * power >= raw) return m * power;
    }
    return 10.0 * power;
}

PlotView::PlotView(QWidget* parent) : QWidget(parent), impl_(std::make_unique<Impl>()) {
    impl_->chart = new QChart;
    impl_->chart->setAnimationOptions(QChart::NoAnimation);
    impl_->chart->legend()->setAlignment(Qt::AlignBottom);
    impl_->chart->setMargins(QMargins(4, 4, 4, 4));
    impl_->chart->layout()->setContentsMargins(0, 0, 0, 0);
    impl_->chart->setBackgroundRoundness(0);
    impl_->chart->setDropShadowEnabled(false);
    // The view's viewport already paints the white background; a second fill per
    // repaint of the chart's own background is wasted time.
    impl_->chart->setBackgroundVisible(false);
    QFont title_font = impl_->chart->titleFont();
    title_font.setBold(true);
    impl_->chart->setTitleFont(title_font);
    impl_->view = new QChartView(impl_->chart, this);
    impl_->view->setRenderHint(QPainter::Antialiasing, true);
    impl_->view->setFrameShape(QFrame::NoFrame);
    // A slider step changes lines across the whole plot: one full repaint is cheaper
    // than clipping every item to a region of many small dirty rectangles.
    impl_->view->setViewportUpdateMode(QGraphicsView::FullViewportUpdate);
    impl_->view->setOptimizationFlags(QGraphicsView::DontSavePainterState);
    impl_->view->setMinimumSize(220, 160);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(impl_->view);
}

PlotView::~PlotView() = default;

void PlotView::set_title(const QString& title) {
    if (impl_->chart->title() != title) impl_->chart->setTitle(title);
}

QString PlotView::title() const {
    return impl_->chart->title();
}

void PlotView::set_legend_visible(bool visible) {
    impl_->chart->legend()->setVisible(visible);
}

void PlotView::set_legend_beside(bool beside) {
    impl_->chart->legend()->setAlignment(beside ? Qt::AlignRight : Qt::AlignBottom);
}

void PlotView::set_x_axis(const AxisSpec& spec) {
    if (impl_->x_axis == nullptr) {
        impl_->x_axis = Impl::make_axis(spec);
        impl_->chart->addAxis(impl_->x_axis, Qt::AlignBottom);
    }
    Impl::style_axis(impl_->x_axis, spec);
}

void PlotView::set_y_axis(Side side, const AxisSpec& spec) {
    QAbstractAxis*& axis = impl_->y_axis(side);
    if (axis == nullptr) {
        axis = Impl::make_axis(spec);
        impl_->chart->addAxis(axis, side == Side::left ? Qt::AlignLeft : Qt::AlignRight);
        if (side == Side::right) {
            // The left axis draws the grid; a second grid would only cost paint time.
            axis->setGridLineVisible(false);
            axis->setMinorGridLineVisible(false);
            if (auto* log = qobject_cast<QLogValueAxis*>(axis)) log->setMinorTickCount(0);
        }
    }
    Impl::style_axis(axis, spec);
}

void PlotView::set_x_range(double lo, double hi) {
    Impl::set_range(impl_->x_axis, lo, hi);
}

void PlotView::set_y_range(Side side, double lo, double hi) {
    Impl::set_range(impl_->y_axis(side), lo, hi);
}

void PlotView::set_y_categories(const QStringList& labels) {
    auto* axis = qobject_cast<QCategoryAxis*>(impl_->y_left);
    if (axis == nullptr || labels == impl_->categories) return;
    if (labels.size() == impl_->categories.size()) {
        // Same rows, new texts: relabel in place rather than rebuild.
        for (qsizetype i = 0; i < labels.size(); ++i) {
            if (labels[i] != impl_->categories[i])
                axis->replaceLabel(impl_->categories[i], labels[i]);
        }
    } else {
        for (const QString& label : impl_->categories) axis->remove(label);
        for (qsizetype i = 0; i < labels.size(); ++i)
            axis->append(labels[i], static_cast<qreal>(i));
    }
    impl_->categories = labels;
    axis->setStartValue(-0.5);
    axis->setRange(-0.5, static_cast<qreal>(std::max<qsizetype>(labels.size(), 1)) - 0.5);
}

PlotView::CurveId PlotView::add_line(const LineSpec& spec) {
    auto* series = new QLineSeries;
    series->setPen(make_pen(spec));
    return impl_->add(series, nullptr, nullptr, spec);
}

PlotView::CurveId PlotView::add_markers(const LineSpec& spec, double marker_size) {
    auto* series = new QScatterSeries;
    series->setMarkerShape(QScatterSeries::MarkerShapeCircle);
    series->setMarkerSize(marker_size);
    series->setColor(spec.color);
    series->setBorderColor(QColor(Qt::white));
    return impl_->add(series, nullptr, nullptr, spec);
}

PlotView::CurveId PlotView::add_area(const LineSpec& spec, const QColor& fill) {
    auto* upper = new QLineSeries;
    auto* lower = new QLineSeries;
    auto* area = new QAreaSeries(upper, lower);
    QPen pen = make_pen(spec);
    if (spec.width <= 0.0) pen = QPen(Qt::NoPen);
    area->setPen(pen);
    area->setBrush(fill);
    return impl_->add(upper, lower, area, spec);
}

void PlotView::set_points(CurveId curve, const QList<QPointF>& points) {
    if (Impl::Curve* c = impl_->find(curve)) c->series->replace(points);
}

void PlotView::set_area(CurveId curve, const QList<QPointF>& upper, const QList<QPointF>& lower) {
    Impl::Curve* c = impl_->find(curve);
    if (c == nullptr || c->lower == nullptr) return;
    c->lower->replace(lower);
    c->series->replace(upper);
}

void PlotView::set_name(CurveId curve, const QString& name) {
    Impl::Curve* c = impl_->find(curve);
    if (c != nullptr && c->shown->name() != name) c->shown->setName(name);
}

void PlotView::set_visible(CurveId curve, bool visible) {
    Impl::Curve* c = impl_->find(curve);
    if (c == nullptr || c->shown->isVisible() == visible) return;
    c->shown->setVisible(visible);
    // Qt Charts shows the marker again with the series; keep unnamed ones out.
    for (QLegendMarker* marker : impl_->chart->legend()->markers(c->shown)) {
        marker->setVisible(visible && c->in_legend);
    }
}

QList<QPointF> PlotView::points(CurveId curve) const {
    const Impl::Curve* c = impl_->find(curve);
    return c != nullptr ? c->series->points() : QList<QPointF>{};
}

qsizetype PlotView::point_count(CurveId curve) const {
    const Impl::Curve* c = impl_->find(curve);
    return c != nullptr ? c->series->count() : 0;
}

bool PlotView::is_visible(CurveId curve) const {
    const Impl::Curve* c = impl_->find(curve);
    return c != nullptr && c->shown->isVisible();
}

}  // namespace probecycle::ui
