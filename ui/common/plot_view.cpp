#include "ui/common/plot_view.h"

#include <QAreaSeries>
#include <QBoxLayout>
#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QEvent>
#include <QFontInfo>
#include <QFontMetrics>
#include <QGraphicsItemGroup>
#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QGraphicsTextItem>
#include <QLegend>
#include <QLineSeries>
#include <QLocale>
#include <QLogValueAxis>
#include <QPainter>
#include <QPen>
#include <QScatterSeries>
#include <QTextDocument>
#include <QValueAxis>
#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <utility>
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

bool finite_point(const QPointF& p) {
    return std::isfinite(p.x()) && std::isfinite(p.y());
}

// Qt Charts draws each marker of a scatter as an item of its own: a few
// hundred thousand take minutes and gigabytes to lay out. Beyond this many, a
// curve shows one marker per cell of a grid over its points' extent.
constexpr qsizetype kMaxMarkers = 4000;
// A category axis's width beside its widest label: the label padding and the
// axis line (Qt Charts' ChartCategoryAxisY::sizeHint adds both).
constexpr double kCategoryPadding = 8.0;

// The finite points, thinned to the first in each cell of the finest grid
// (1024 cells a side, then halved) that leaves at most kMaxMarkers. Markers
// that would be drawn over one another go; the shape, the spread and every
// outlier stay, since a point apart from the rest has a cell to itself.
void thin_markers(const QList<QPointF>& points, QList<QPointF>& shown) {
    std::copy_if(points.begin(), points.end(), std::back_inserter(shown), finite_point);
    if (shown.size() <= kMaxMarkers) return;
    const QList<QPointF> all = std::exchange(shown, {});
    double x0 = all.front().x(), x1 = x0, y0 = all.front().y(), y1 = y0;
    for (const QPointF& p : all) {
        x0 = std::min(x0, p.x());
        x1 = std::max(x1, p.x());
        y0 = std::min(y0, p.y());
        y1 = std::max(y1, p.y());
    }
    std::vector<bool> taken;
    for (std::size_t cells = 1024; cells >= 2; cells /= 2) {
        shown.clear();
        taken.assign(cells * cells, false);
        const auto cell = [cells](double v, double lo, double hi) {
            if (!(hi > lo)) return std::size_t{0};
            const auto k =
                static_cast<std::size_t>((v - lo) / (hi - lo) * static_cast<double>(cells));
            return std::min(k, cells - 1);
        };
        for (const QPointF& p : all) {
            const std::size_t k = cell(p.x(), x0, x1) * cells + cell(p.y(), y0, y1);
            if (taken[k]) continue;
            taken[k] = true;
            shown.append(p);
            if (shown.size() > kMaxMarkers) break;
        }
        if (shown.size() <= kMaxMarkers) return;
    }
}

PlotView::Range axis_range(const QAbstractAxis* axis) {
    if (const auto* value = qobject_cast<const QValueAxis*>(axis)) {
        return {value->min(), value->max()};
    }
    if (const auto* log = qobject_cast<const QLogValueAxis*>(axis)) return {log->min(), log->max()};
    return {};
}

// The number format of axis labels: the interface language's decimal sign,
// without group separators (an axis label is short and "10 000" reads as two).
QLocale axis_locale() {
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
    return locale;
}

// QTextDocument turns a no-break space into a space in plain text.
QString plain(QString text) {
    return text.replace(QChar(0x00A0), QLatin1Char(' '));
}

bool elided(const QString& text) {
    return text.endsWith(QStringLiteral("...")) || text.endsWith(QChar(0x2026));
}

// Our own legend instead of Qt Charts' single row, which elides its
// entries when they do not fit. Below the plot the entries flow into as many
// rows as the width needs; beside it, one a row. A swatch drawn with the
// curve's own pen or brush, then the name in full.
class Legend : public QWidget {
  public:
    enum class Swatch { line, marker, area };
    struct Entry {
        QString name;
        QPen pen;
        QBrush brush;
        Swatch swatch{Swatch::line};
    };

    explicit Legend(QWidget* parent) : QWidget(parent) { set_beside(false); }

    void set_entries(std::vector<Entry> entries) {
        const bool same = entries.size() == entries_.size() &&
                          std::equal(entries.begin(), entries.end(), entries_.begin(),
                                     [](const Entry& a, const Entry& b) {
                                         return a.name == b.name && a.pen == b.pen &&
                                                a.brush == b.brush && a.swatch == b.swatch;
                                     });
        if (same) return;
        entries_ = std::move(entries);
        updateGeometry();
        update();
    }
    const std::vector<Entry>& entries() const { return entries_; }

    void set_beside(bool beside) {
        beside_ = beside;
        // Not Fixed below the plot: a fixed height is one row (the size hint's),
        // whatever heightForWidth says.
        QSizePolicy policy(QSizePolicy::Preferred, QSizePolicy::Preferred);
        policy.setHeightForWidth(!beside);
        setSizePolicy(policy);
        updateGeometry();
    }

    bool hasHeightForWidth() const override { return !beside_; }
    int heightForWidth(int width) const override {
        return entries_.empty() ? 0 : rows(width) * line() + 2 * kMargin;
    }
    QSize sizeHint() const override {
        if (entries_.empty()) return {0, 0};
        int widest = 0;
        int total = 0;
        for (const Entry& e : entries_) {
            widest = std::max(widest, entry_width(e));
            total += entry_width(e) + kGap;
        }
        if (beside_) {
            return {widest + 2 * kMargin, static_cast<int>(entries_.size()) * line() + 2 * kMargin};
        }
        return {total + 2 * kMargin, heightForWidth(width() > 0 ? width() : total)};
    }
    QSize minimumSizeHint() const override {
        if (entries_.empty()) return {0, 0};
        return {kSwatch + 4 * kGap, line() + 2 * kMargin};
    }

    // Entries not shown in full at the present size.
    QStringList cut() const {
        QStringList out;
        const std::vector<QRect> at = place(width());
        for (std::size_t i = 0; i < entries_.size(); ++i) {
            if (!rect().contains(at[i])) out << entries_[i].name;
        }
        return out;
    }

    bool beside() const { return beside_; }

    // The entries laid out at `width`, from the painter's origin.
    void paint(QPainter& painter, int width) const {
        painter.setRenderHint(QPainter::Antialiasing, true);
        painter.setFont(font());
        const std::vector<QRect> at = place(width);
        for (std::size_t i = 0; i < entries_.size(); ++i) {
            const Entry& e = entries_[i];
            const QRect r = at[i];
            const QRect swatch(r.left(), r.top(), kSwatch, r.height());
            const QPointF mid = QRectF(swatch).center();
            switch (e.swatch) {
                case Swatch::line: {
                    QPen pen = e.pen;
                    pen.setWidthF(std::min(pen.widthF(), 2.5));
                    painter.setPen(pen);
                    painter.drawLine(QPointF(swatch.left(), mid.y()),
                                     QPointF(swatch.right(), mid.y()));
                    break;
                }
                case Swatch::marker:
                    painter.setPen(Qt::NoPen);
                    painter.setBrush(e.brush);
                    painter.drawEllipse(mid, 4.5, 4.5);
                    break;
                case Swatch::area:
                    painter.setPen(e.pen);
                    painter.setBrush(e.brush);
                    painter.drawRect(QRectF(swatch.left() + 2, mid.y() - 5, kSwatch - 4, 10));
                    break;
            }
            painter.setPen(palette().color(QPalette::WindowText));
            painter.drawText(r.adjusted(kSwatch + kSwatchGap, 0, 0, 0),
                             Qt::AlignLeft | Qt::AlignVCenter, e.name);
        }
    }

  protected:
    void paintEvent(QPaintEvent* /*event*/) override {
        QPainter painter(this);
        paint(painter, width());
    }

  private:
    static constexpr int kMargin = 2;
    static constexpr int kSwatch = 22;
    static constexpr int kSwatchGap = 4;
    static constexpr int kGap = 14;

    int line() const { return fontMetrics().height() + 2; }
    int entry_width(const Entry& e) const {
        return kSwatch + kSwatchGap + fontMetrics().horizontalAdvance(e.name);
    }
    int rows(int width) const {
        const std::vector<QRect> at = place(width);
        return at.empty() ? 0 : (at.back().bottom() + 1 - kMargin) / line();
    }
    // Where each entry goes at `width`: rows below the plot, a column beside it.
    std::vector<QRect> place(int width) const {
        std::vector<QRect> at;
        at.reserve(entries_.size());
        int x = kMargin;
        int y = kMargin;
        for (const Entry& e : entries_) {
            const int w = entry_width(e);
            if (beside_) {
                at.emplace_back(kMargin, y, w, line());
                y += line();
                continue;
            }
            if (x > kMargin && x + w > width - kMargin) {
                x = kMargin;
                y += line();
            }
            at.emplace_back(x, y, w, line());
            x += w + kGap;
        }
        return at;
    }

    std::vector<Entry> entries_;
    bool beside_{false};
};

}  // namespace

struct PlotView::Impl {
    enum class Kind { line, markers, area, rule };

    // One series a curve draws, with two buffers used in turn: the series shares
    // the one handed over last, so the other refills in place, never reallocated.
    struct Piece {
        QXYSeries* series{nullptr};
        std::array<QList<QPointF>, 2> buffers;
        std::size_t current{0};
        QList<QPointF>& next() {
            current ^= 1U;
            QList<QPointF>& buffer = buffers[current];
            buffer.clear();
            return buffer;
        }
    };

    struct Curve {
        Kind kind{Kind::line};
        QXYSeries* series{nullptr};       // line or scatter; upper line of an area
        QLineSeries* lower{nullptr};      // areas only
        QAreaSeries* area{nullptr};       // areas only
        QAbstractSeries* shown{nullptr};  // what the chart holds
        Side side{Side::left};
        bool in_legend{false};
        QList<QPointF> given;  // as handed over, breaks included
        // pieces[0] draws through `series`; a broken line's further stretches get
        // series of their own, with the same pen and out of the legend.
        std::vector<Piece> pieces;
    };

    QChart* chart{nullptr};
    QChartView* view{nullptr};
    QBoxLayout* layout{nullptr};
    Legend* legend{nullptr};
    bool legend_visible{true};
    QFont category_font;  // the category axis's full-size label font
    QFont title_font;     // the axes' full-size title font
    bool fitting_categories{false};
    QRectF equal_bounds;  // set_equal_scales(): empty when off
    bool fitting_scales{false};
    QAbstractAxis* x_axis{nullptr};
    QAbstractAxis* y_left{nullptr};
    QAbstractAxis* y_right{nullptr};
    QStringList categories;
    std::vector<Curve> curves;
    QList<QPointF> rule_points;  // a rule's segments before they are split

    QAbstractAxis*& y_axis(Side side) { return side == Side::left ? y_left : y_right; }

    // Qt Charts formats localised labels only from a format with a precision
    // ("%.6g"; a bare "%g" gives no label at all).
    static QString localised_format(const QString& format) {
        if (format.contains(QLatin1Char('.'))) return format;
        QString out = format;
        return out.replace(QLatin1Char('%'), QStringLiteral("%.6"));
    }

    static QAbstractAxis* make_axis(const AxisSpec& spec) {
        switch (spec.scale) {
            case Scale::log: {
                auto* axis = new QLogValueAxis;
                axis->setBase(10.0);
                axis->setLabelFormat(localised_format(spec.label_format));
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
        axis->setLabelFormat(localised_format(spec.label_format));
        axis->setTickType(QValueAxis::TicksDynamic);
        axis->setTickAnchor(0.0);
        axis->setTickInterval(1.0);
        return axis;
    }

    static void style_axis(QAbstractAxis* axis, const AxisSpec& spec, const QFont& title_font) {
        // Solid hairlines: the theme's dashed minor grid costs more to paint than the curves.
        axis->setGridLinePen(hairline(QColor(0xdd, 0xdd, 0xdd)));
        axis->setMinorGridLinePen(hairline(QColor(0xee, 0xee, 0xee)));
        if (axis->titleText() != spec.title) axis->setTitleText(spec.title);
        if (axis->titleFont() != title_font) axis->setTitleFont(title_font);
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
            // Qt Charts labels a log axis from ceil(ln(min) / ln(base)), which rounds a
            // decade below 1 up past itself (ln(0.1) / ln(10) = -0.99999999999999989):
            // a range from 0.1 s would lose its 0.1 label. A hair below keeps it.
            const double decade = std::log10(lo);
            if (std::abs(decade - std::round(decade)) < 1e-9) lo *= 1.0 - 1e-9;
            if (log->min() != lo || log->max() != hi) log->setRange(lo, hi);
        } else {
            axis->setRange(lo, hi);
        }
    }

    void attach(QAbstractSeries* shown, Side side) {
        chart->addSeries(shown);
        if (x_axis != nullptr) shown->attachAxis(x_axis);
        if (QAbstractAxis* y = y_axis(side)) shown->attachAxis(y);
    }

    // The legend's entries: the named curves that are shown, in the order added.
    void refresh_legend() {
        std::vector<Legend::Entry> entries;
        if (legend_visible) {
            for (const Curve& c : curves) {
                if (!c.in_legend || !c.shown->isVisible()) continue;
                Legend::Entry e{c.shown->name(), c.series->pen(), {}, Legend::Swatch::line};
                if (c.kind == Kind::markers) {
                    e.swatch = Legend::Swatch::marker;
                    e.brush = static_cast<QScatterSeries*>(c.series)->color();
                } else if (c.kind == Kind::area) {
                    e.swatch = Legend::Swatch::area;
                    e.pen = c.area->pen();
                    e.brush = c.area->brush();
                }
                entries.push_back(std::move(e));
            }
        }
        legend->set_entries(std::move(entries));
        legend->setVisible(legend_visible && !legend->entries().empty());
    }

    // Every row of a category axis keeps its label whole: Qt Charts hides a
    // label that would overlap the one below and cuts one too wide, so the
    // font shrinks to the row height and the axis's width, not under 6 pixels.
    void fit_categories() {
        auto* axis = qobject_cast<QCategoryAxis*>(y_left);
        if (axis == nullptr || categories.isEmpty() || fitting_categories) return;
        const double row = chart->plotArea().height() / static_cast<double>(categories.size());
        if (!(row > 0.0)) return;
        // Measured as the axis lays its labels out (a text document: a Chinese
        // label's fallback font is taller than the axis font says).
        const auto height = [&](const QFont& f) {
            double tallest = 0.0;
            QTextDocument doc;
            doc.setDocumentMargin(0.0);
            doc.setDefaultFont(f);
            for (const QString& label : categories) {
                doc.setPlainText(label);
                tallest = std::max(tallest, doc.size().height());
            }
            return tallest + 2.0;  // Qt Charts' own margins
        };
        // Qt Charts gives the vertical axes at most 40 % of the chart's width
        // (maxAxisPortion in its CartesianChartLayout) and squeezes a wider
        // axis, cutting its labels' starts off at the chart's edge.
        const QRectF inner = chart->geometry().marginsRemoved(chart->margins().toMarginsF());
        const double widest_allowed = 0.4 * inner.width() - kCategoryPadding;
        const auto width = [&](const QFont& f) {
            const QFontMetricsF metrics(f);
            double widest = 0.0;
            for (const QString& label : categories) {
                widest = std::max(widest, metrics.boundingRect(label).width());
            }
            return widest;
        };
        QFont font = category_font;
        for (int px = QFontInfo(category_font).pixelSize();
             px > 6 && (height(font) > row || width(font) > widest_allowed); --px) {
            font.setPixelSize(px - 1);
        }
        if (font == axis->labelsFont()) return;
        fitting_categories = true;
        axis->setLabelsFont(font);
        fitting_categories = false;
    }

    // Ranges at equal scales on x and the left y axis that hold
    // equal_bounds with a margin, for the plot area as it is now. New ranges
    // can change the tick labels' widths and so the plot area: the change it
    // signals brings the next pass, until the scales agree within 1 %.
    void fit_equal_scales() {
        if (equal_bounds.isEmpty() || fitting_scales || x_axis == nullptr || y_left == nullptr) {
            return;
        }
        const QRectF plot = chart->plotArea();
        if (!(plot.width() > 1.0 && plot.height() > 1.0)) return;
        const QPointF centre = equal_bounds.center();
        const double half_x = std::max(equal_bounds.width(), 1e-3) * 0.55;
        const double half_y = std::max(equal_bounds.height(), 1e-3) * 0.55;
        const double mm_per_pixel = std::max(half_x / plot.width(), half_y / plot.height());
        const double want_x = mm_per_pixel * plot.width();
        const double want_y = mm_per_pixel * plot.height();
        const auto* x = qobject_cast<const QValueAxis*>(x_axis);
        const auto* y = qobject_cast<const QValueAxis*>(y_left);
        if (x != nullptr && y != nullptr &&
            std::abs((x->max() - x->min()) / 2.0 - want_x) <= 0.01 * want_x &&
            std::abs((y->max() - y->min()) / 2.0 - want_y) <= 0.01 * want_y &&
            std::abs((x->max() + x->min()) / 2.0 - centre.x()) <= 0.01 * want_x &&
            std::abs((y->max() + y->min()) / 2.0 - centre.y()) <= 0.01 * want_y) {
            return;
        }
        fitting_scales = true;
        set_range(x_axis, centre.x() - want_x, centre.x() + want_x);
        set_range(y_left, centre.y() - want_y, centre.y() + want_y);
        redraw_rules(Side::left);
        fitting_scales = false;
    }

    // An axis title longer than its axis takes a smaller font (down to 7
    // pixels) rather than being cut short.
    void fit_titles() {
        const QRectF plot = chart->plotArea();
        for (QAbstractAxis* axis : {x_axis, y_left, y_right}) {
            if (axis == nullptr || axis->titleText().isEmpty()) continue;
            const double room = (axis == x_axis ? plot.width() : plot.height()) - 4.0;
            QFont font = title_font;
            for (int px = QFontInfo(title_font).pixelSize();
                 px > 7 && QFontMetricsF(font).horizontalAdvance(axis->titleText()) > room; --px) {
                font.setPixelSize(px - 1);
            }
            if (font != axis->titleFont()) axis->setTitleFont(font);
        }
    }

    // Every text item the chart draws (axis labels and titles, its title).
    std::vector<const QGraphicsTextItem*> drawn_text_items() const {
        std::vector<const QGraphicsTextItem*> out;
        const QGraphicsScene* scene = chart->scene();
        if (scene == nullptr) return out;
        for (QGraphicsItem* item : scene->items()) {
            const auto* text = dynamic_cast<const QGraphicsTextItem*>(item);
            if (text != nullptr && text->isVisible() && chart->isAncestorOf(text)) {
                out.push_back(text);
            }
        }
        return out;
    }

    // Every text the chart draws, as plain text.
    QStringList drawn_texts() const {
        QStringList out;
        for (const QGraphicsTextItem* text : drawn_text_items()) out << plain(text->toPlainText());
        return out;
    }

    // The drawn texts that reach past the chart's left or right edge, where
    // the view cuts them off (an axis squeezed narrower than its labels).
    QStringList texts_past_edges() const {
        QStringList out;
        const QRectF bounds = chart->geometry();
        for (const QGraphicsTextItem* text : drawn_text_items()) {
            const double margin = text->document()->documentMargin();
            const QRectF drawn = text->sceneBoundingRect().adjusted(margin, 0.0, -margin, 0.0);
            if (drawn.left() < bounds.left() - 0.5 || drawn.right() > bounds.right() + 0.5) {
                out << plain(text->toPlainText());
            }
        }
        return out;
    }

    CurveId add(Kind kind, QXYSeries* series, QLineSeries* lower, QAreaSeries* area,
                const LineSpec& spec) {
        QAbstractSeries* shown = area != nullptr ? static_cast<QAbstractSeries*>(area) : series;
        shown->setName(spec.name);
        const bool in_legend = !spec.name.isEmpty();
        attach(shown, spec.axis);
        Curve curve{kind, series, lower, area, shown, spec.axis, in_legend, {}, {}};
        curve.pieces.resize(1);
        curve.pieces[0].series = series;
        curves.push_back(std::move(curve));
        refresh_legend();
        return static_cast<CurveId>(curves.size() - 1);
    }

    Piece& piece(Curve& curve, std::size_t k) {
        if (k >= curve.pieces.size()) {
            auto* series = new QLineSeries;
            series->setPen(curve.series->pen());
            attach(series, curve.side);
            series->setVisible(curve.shown->isVisible());
            curve.pieces.push_back({});
            curve.pieces.back().series = series;
        }
        return curve.pieces[k];
    }

    // Draws `points`: unbroken, handed straight to the series; otherwise each
    // finite stretch to a series of its own (markers: the finite points).
    void draw(Curve& curve, const QList<QPointF>& points) {
        const bool broken = !std::all_of(points.begin(), points.end(), finite_point);
        std::size_t used = 1;
        if (curve.kind == Kind::markers && (broken || points.size() > kMaxMarkers)) {
            QList<QPointF>& shown = curve.pieces[0].next();
            thin_markers(points, shown);
            curve.series->replace(shown);
        } else if (!broken) {
            curve.series->replace(points);
        } else {
            used = 0;
            for (auto it = points.begin(); it != points.end();) {
                const auto begin = std::find_if(it, points.end(), finite_point);
                it = std::find_if_not(begin, points.end(), finite_point);
                if (begin == it) continue;
                Piece& p = piece(curve, used++);
                QList<QPointF>& stretch = p.next();
                std::copy(begin, it, std::back_inserter(stretch));
                p.series->replace(stretch);
            }
            if (used == 0) curve.series->replace(QList<QPointF>{});
            used = std::max<std::size_t>(used, 1);
        }
        for (std::size_t k = used; k < curve.pieces.size(); ++k) {
            if (curve.pieces[k].series->count() > 0)
                curve.pieces[k].series->replace(QList<QPointF>{});
        }
    }

    // A rule's points become segments across the y range, apart from each other.
    void draw_rule(Curve& curve) {
        const Range y = axis_range(y_axis(curve.side));
        rule_points.clear();
        for (const QPointF& p : curve.given) {
            if (!std::isfinite(p.x())) continue;
            if (!rule_points.isEmpty()) rule_points.append({qQNaN(), qQNaN()});
            rule_points.append({p.x(), y.lo});
            rule_points.append({p.x(), y.hi});
        }
        draw(curve, rule_points);
    }

    void redraw_rules(Side side) {
        for (Curve& curve : curves) {
            if (curve.kind == Kind::rule && curve.side == side) draw_rule(curve);
        }
    }

    enum class Where { x, left, right };
    // The labels an axis shows, read from the scene the chart laid out: the
    // visible text items in an axis's label group, placed by where they sit
    // around the plot area (Qt Charts offers no public list of them).
    QStringList labels(Where where) const {
        const QGraphicsScene* scene = chart->scene();
        if (scene == nullptr) return {};
        const QRectF plot = chart->mapRectToScene(chart->plotArea());
        std::vector<std::pair<double, QString>> found;
        for (QGraphicsItem* item : scene->items()) {
            const auto* text = dynamic_cast<const QGraphicsTextItem*>(item);
            if (text == nullptr || !text->isVisible() || !chart->isAncestorOf(text)) continue;
            if (dynamic_cast<const QGraphicsItemGroup*>(text->parentItem()) == nullptr) continue;
            const QString label = text->toPlainText();
            if (label.isEmpty()) continue;
            const QPointF c = text->sceneBoundingRect().center();
            const bool beside = c.y() >= plot.top() - 1.0 && c.y() <= plot.bottom() + 1.0;
            const bool below =
                c.y() > plot.bottom() && c.x() >= plot.left() - 1.0 && c.x() <= plot.right() + 1.0;
            if (where == Where::x && below) found.emplace_back(c.x(), label);
            if (where == Where::left && beside && c.x() < plot.left()) {
                found.emplace_back(-c.y(), label);
            }
            if (where == Where::right && beside && c.x() > plot.right()) {
                found.emplace_back(-c.y(), label);
            }
        }
        std::sort(found.begin(), found.end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        QStringList out;
        for (const auto& [position, label] : found) out.append(label);
        return out;
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
    impl_->chart->legend()->hide();  // ours (Legend) wraps instead of eliding
    impl_->chart->setLocalizeNumbers(true);
    impl_->chart->setLocale(axis_locale());
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
    impl_->legend = new Legend(this);
    impl_->legend->setVisible(false);
    impl_->layout = new QBoxLayout(QBoxLayout::TopToBottom, this);
    impl_->layout->setContentsMargins(0, 0, 0, 0);
    impl_->layout->setSpacing(0);
    impl_->layout->addWidget(impl_->view, 1);
    impl_->layout->addWidget(impl_->legend);
    connect(impl_->chart, &QChart::plotAreaChanged, this, [this] {
        impl_->fit_categories();
        impl_->fit_titles();
        impl_->fit_equal_scales();
    });
}

QImage PlotView::picture(QSize size, double scale) {
    QImage image(size * scale, QImage::Format_RGB32);
    image.setDevicePixelRatio(scale);
    image.fill(Qt::white);
    // Below the chart, as tall as its rows at this width; or beside it, as wide
    // as its widest entry.
    const Legend& legend = *impl_->legend;
    QRect legend_rect;
    if (!legend.isHidden() && legend.beside()) {
        const int width = legend.sizeHint().width();
        legend_rect = QRect(size.width() - width, 0, width, size.height());
    } else if (!legend.isHidden()) {
        const int height = legend.heightForWidth(size.width());
        legend_rect = QRect(0, size.height() - height, size.width(), height);
    }
    const QSizeF chart_size(legend.beside() ? size.width() - legend_rect.width() : size.width(),
                            legend.beside() ? size.height() : size.height() - legend_rect.height());

    // The chart laid out at the picture's size now (its layout otherwise waits
    // for the event loop), drawn, then given its own size back.
    QChart& chart = *impl_->chart;
    const QSizeF own = chart.size();
    const auto lay_out = [&chart](const QSizeF& at) {
        chart.resize(at);
        chart.layout()->invalidate();
        chart.layout()->activate();
    };
    lay_out(chart_size);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing, true);
    chart.scene()->render(&painter, QRectF(QPointF(0.0, 0.0), chart_size),
                          QRectF(chart.pos(), chart_size));
    if (!legend_rect.isEmpty()) {
        painter.translate(legend_rect.topLeft());
        legend.paint(painter, legend_rect.width());
    }
    painter.end();
    lay_out(own);
    return image;
}

void PlotView::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) impl_->chart->setLocale(axis_locale());
    QWidget::changeEvent(event);
}

PlotView::~PlotView() = default;

void PlotView::set_title(const QString& title) {
    if (impl_->chart->title() != title) impl_->chart->setTitle(title);
}

QString PlotView::title() const {
    return impl_->chart->title();
}

void PlotView::set_legend_visible(bool visible) {
    impl_->legend_visible = visible;
    impl_->refresh_legend();
}

void PlotView::set_legend_beside(bool beside) {
    impl_->layout->setDirection(beside ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom);
    impl_->legend->set_beside(beside);
}

void PlotView::set_x_axis(const AxisSpec& spec) {
    if (impl_->x_axis == nullptr) {
        impl_->x_axis = Impl::make_axis(spec);
        impl_->chart->addAxis(impl_->x_axis, Qt::AlignBottom);
    }
    if (impl_->title_font == QFont()) {
        impl_->title_font = impl_->x_axis->titleFont();
        impl_->title_font.setBold(false);
    }
    Impl::style_axis(impl_->x_axis, spec, impl_->title_font);
    impl_->fit_titles();
}

void PlotView::set_y_axis(Side side, const AxisSpec& spec) {
    QAbstractAxis*& axis = impl_->y_axis(side);
    if (axis == nullptr) {
        axis = Impl::make_axis(spec);
        if (const auto* categories = qobject_cast<const QCategoryAxis*>(axis)) {
            impl_->category_font = categories->labelsFont();
        }
        impl_->chart->addAxis(axis, side == Side::left ? Qt::AlignLeft : Qt::AlignRight);
        if (side == Side::right) {
            // The left axis draws the grid; a second grid would only cost paint time.
            axis->setGridLineVisible(false);
            axis->setMinorGridLineVisible(false);
            if (auto* log = qobject_cast<QLogValueAxis*>(axis)) log->setMinorTickCount(0);
        }
    }
    if (impl_->title_font == QFont()) {
        impl_->title_font = axis->titleFont();
        impl_->title_font.setBold(false);
    }
    Impl::style_axis(axis, spec, impl_->title_font);
    impl_->fit_titles();
}

void PlotView::set_x_range(double lo, double hi) {
    Impl::set_range(impl_->x_axis, lo, hi);
}

void PlotView::set_y_range(Side side, double lo, double hi) {
    Impl::set_range(impl_->y_axis(side), lo, hi);
    impl_->redraw_rules(side);
}

void PlotView::set_equal_scales(const QRectF& bounds) {
    impl_->equal_bounds = bounds;
    impl_->fit_equal_scales();
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
    impl_->fit_categories();
}

PlotView::CurveId PlotView::add_line(const LineSpec& spec) {
    auto* series = new QLineSeries;
    series->setPen(make_pen(spec));
    return impl_->add(Impl::Kind::line, series, nullptr, nullptr, spec);
}

PlotView::CurveId PlotView::add_rule(const LineSpec& spec) {
    auto* series = new QLineSeries;
    series->setPen(make_pen(spec));
    return impl_->add(Impl::Kind::rule, series, nullptr, nullptr, spec);
}

PlotView::CurveId PlotView::add_markers(const LineSpec& spec, double marker_size) {
    auto* series = new QScatterSeries;
    series->setMarkerShape(QScatterSeries::MarkerShapeCircle);
    series->setMarkerSize(marker_size);
    series->setColor(spec.color);
    series->setBorderColor(QColor(Qt::white));
    return impl_->add(Impl::Kind::markers, series, nullptr, nullptr, spec);
}

PlotView::CurveId PlotView::add_area(const LineSpec& spec, const QColor& fill) {
    auto* upper = new QLineSeries;
    auto* lower = new QLineSeries;
    auto* area = new QAreaSeries(upper, lower);
    QPen pen = make_pen(spec);
    if (spec.width <= 0.0) pen = QPen(Qt::NoPen);
    area->setPen(pen);
    area->setBrush(fill);
    return impl_->add(Impl::Kind::area, upper, lower, area, spec);
}

void PlotView::set_points(CurveId curve, const QList<QPointF>& points) {
    Impl::Curve* c = impl_->find(curve);
    if (c == nullptr) return;
    if (c->kind == Impl::Kind::area) {
        c->series->replace(points);  // the upper line
        return;
    }
    c->given = points;
    if (c->kind == Impl::Kind::rule) {
        impl_->draw_rule(*c);
    } else {
        impl_->draw(*c, points);
    }
}

void PlotView::set_area(CurveId curve, const QList<QPointF>& upper, const QList<QPointF>& lower) {
    Impl::Curve* c = impl_->find(curve);
    if (c == nullptr || c->lower == nullptr) return;
    c->lower->replace(lower);
    c->series->replace(upper);
}

void PlotView::set_name(CurveId curve, const QString& name) {
    Impl::Curve* c = impl_->find(curve);
    if (c == nullptr) return;
    if (c->shown->name() != name) c->shown->setName(name);
    // A curve named after it was added (a baseline named once translated) joins the legend.
    c->in_legend = !name.isEmpty();
    impl_->refresh_legend();
}

void PlotView::set_visible(CurveId curve, bool visible) {
    Impl::Curve* c = impl_->find(curve);
    if (c == nullptr || c->shown->isVisible() == visible) return;
    c->shown->setVisible(visible);
    for (std::size_t k = 1; k < c->pieces.size(); ++k) c->pieces[k].series->setVisible(visible);
    impl_->refresh_legend();
}

void PlotView::set_fill(CurveId curve, const QColor& color) {
    Impl::Curve* c = impl_->find(curve);
    if (c == nullptr || fill(curve) == color) return;
    if (c->area != nullptr) {
        c->area->setBrush(color);
        QPen pen = c->area->pen();
        if (pen.style() != Qt::NoPen) {
            pen.setColor(color);
            c->area->setPen(pen);
        }
        return;
    }
    c->series->setColor(color);
    for (std::size_t k = 1; k < c->pieces.size(); ++k) c->pieces[k].series->setColor(color);
}

QColor PlotView::fill(CurveId curve) const {
    const Impl::Curve* c = impl_->find(curve);
    if (c == nullptr) return {};
    return c->area != nullptr ? c->area->brush().color() : c->series->color();
}

QList<QPointF> PlotView::points(CurveId curve) const {
    const Impl::Curve* c = impl_->find(curve);
    if (c == nullptr) return {};
    return c->kind == Impl::Kind::area ? c->series->points() : c->given;
}

qsizetype PlotView::point_count(CurveId curve) const {
    return points(curve).size();
}

qsizetype PlotView::drawn_count(CurveId curve) const {
    const Impl::Curve* c = impl_->find(curve);
    if (c == nullptr) return 0;
    qsizetype count = 0;
    for (const auto& piece : c->pieces) count += piece.series->count();
    return count;
}

bool PlotView::is_visible(CurveId curve) const {
    const Impl::Curve* c = impl_->find(curve);
    return c != nullptr && c->shown->isVisible();
}

QStringList PlotView::legend_texts() const {
    QStringList texts;
    for (const Legend::Entry& e : impl_->legend->entries()) texts.append(e.name);
    return texts;
}

PlotView::Range PlotView::x_range() const {
    return axis_range(impl_->x_axis);
}

PlotView::Range PlotView::y_range(Side side) const {
    return axis_range(impl_->y_axis(side));
}

QStringList PlotView::x_labels() const {
    return impl_->labels(Impl::Where::x);
}

QStringList PlotView::y_labels(Side side) const {
    return impl_->labels(side == Side::left ? Impl::Where::left : Impl::Where::right);
}

QStringList PlotView::texts() const {
    QStringList out{impl_->chart->title()};
    for (const QAbstractAxis* axis : {impl_->x_axis, impl_->y_left, impl_->y_right}) {
        if (axis != nullptr) out << axis->titleText();
    }
    out << legend_texts() << impl_->categories;
    out.removeAll(QString());
    return out;
}

int PlotView::smallest_axis_title_px() const {
    int smallest = 0;
    for (const QAbstractAxis* axis : {impl_->x_axis, impl_->y_left, impl_->y_right}) {
        if (axis == nullptr || !axis->isVisible() || !axis->isTitleVisible() ||
            axis->titleText().isEmpty()) {
            continue;
        }
        const int px = QFontInfo(axis->titleFont()).pixelSize();
        smallest = smallest == 0 ? px : std::min(smallest, px);
    }
    return smallest;
}

int PlotView::category_label_px() const {
    const auto* axis = qobject_cast<const QCategoryAxis*>(impl_->y_left);
    return axis == nullptr ? 0 : QFontInfo(axis->labelsFont()).pixelSize();
}

QStringList PlotView::cut_texts() const {
    const QStringList drawn = impl_->drawn_texts();
    QStringList cut;
    const auto whole = [&](const QString& text) {
        if (!text.isEmpty() && !drawn.contains(plain(text))) cut << text;
    };
    whole(impl_->chart->title());
    for (const QAbstractAxis* axis : {impl_->x_axis, impl_->y_left, impl_->y_right}) {
        if (axis != nullptr && axis->isVisible() && axis->isTitleVisible())
            whole(axis->titleText());
    }
    if (qobject_cast<const QCategoryAxis*>(impl_->y_left) != nullptr) {
        const QStringList shown = y_labels(Side::left);
        for (const QString& label : impl_->categories) {
            if (!shown.contains(plain(label))) cut << label;
        }
    }
    for (const QString& text : drawn) {
        if (elided(text)) cut << text;
    }
    cut << impl_->texts_past_edges();
    if (impl_->legend->isVisible()) cut << impl_->legend->cut();
    return cut;
}

}  // namespace probecycle::ui
