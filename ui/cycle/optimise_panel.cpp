#include "ui/cycle/optimise_panel.h"

#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

#include "core/common/input_error.h"
#include "core/common/units.h"
#include "core/common/vector_state.h"
#include "ui/common/parameter_info.h"
#include "ui/common/plot_view.h"
#include "ui/common/quantity_edit.h"
#include "ui/common/text_format.h"

namespace probecycle::ui {

namespace {

// The requirements that are scenario keys, in the order shown.
constexpr const char* kRequirementKeys[] = {
    "cycle.target_uncertainty_mm", "cycle.part_position_uncertainty_mm", "probe.max_feed_mm_min"};

// The log axes' floors (an uncertainty or a time of 0 is drawn there).
constexpr double kFloor_um = 1e-3;
constexpr double kFloor_s = 1e-3;

enum Row {
    row_strategy,
    row_probe_feed,
    row_measure_feed,
    row_backoff,
    row_approach,
    row_repeats,
    row_position_feed,
    row_cycle_time,
    row_uncertainty,
    row_overtravel,
    row_count,
};

QStringList column_of(const Candidate& c) {
    const Settings& s = c.settings;
    const bool two = s.strategy == Strategy::two_touch;
    QStringList out(row_count);
    out[row_strategy] = strategy_label(s.strategy);
    out[row_probe_feed] = format_feed(s.probe_feed_mm_min);
    out[row_measure_feed] = two ? format_feed(s.measure_feed_mm_min) : QStringLiteral("–");
    out[row_backoff] = two ? format_mm(s.backoff_mm) : QStringLiteral("–");
    out[row_approach] = format_mm(s.approach_mm);
    out[row_repeats] = QLocale().toString(s.repeats);
    out[row_position_feed] = format_feed(s.position_feed_mm_min);
    out[row_cycle_time] = format_seconds(c.cycle_time_s);
    out[row_uncertainty] = format_length(c.uncertainty_mm);
    out[row_overtravel] = format_mm(c.overtravel_mm);
    return out;
}

}  // namespace

OptimisePanel::OptimisePanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("optimise-panel"));
    auto* left = new QVBoxLayout;
    requirements_title_ = new QLabel(this);
    QFont bold = requirements_title_->font();
    bold.setBold(true);
    requirements_title_->setFont(bold);
    left->addWidget(requirements_title_);
    for (const char* key : kRequirementKeys) {
        const KeyInfo* info = find_key(key);
        if (info == nullptr) continue;
        auto* edit = new QuantityEdit(*info, this);
        // Not "spin:<key>": that name is the parameter panel's editor's.
        edit->setObjectName(QStringLiteral("optimise-edit:") + QLatin1String(key));
        edit->spin_box()->setObjectName(QStringLiteral("optimise-spin:") + QLatin1String(key));
        connect(edit, &QuantityEdit::edited, this,
                [this, key](double value) { emit requirement_edited(QLatin1String(key), value); });
        requirement_edits_.push_back(edit);
        left->addWidget(edit);
    }
    auto* fraction_row = new QHBoxLayout;
    fraction_label_ = new QLabel(this);
    fraction_ = new QDoubleSpinBox(this);
    fraction_->setObjectName(QStringLiteral("optimise-overtravel-fraction"));
    fraction_->setRange(100.0 * kMinOvertravelFraction, 100.0 * kMaxOvertravelFraction);
    fraction_->setDecimals(0);
    fraction_->setSingleStep(5.0);
    fraction_->setValue(100.0 * OptimiseRequirements{}.max_overtravel_fraction);
    fraction_->setSuffix(QStringLiteral(" %"));
    fraction_->setKeyboardTracking(false);
    fraction_label_->setBuddy(fraction_);
    connect(fraction_, &QDoubleSpinBox::valueChanged, this, [this] { emit options_changed(); });
    fraction_row->addWidget(fraction_label_, 1);
    fraction_row->addWidget(fraction_);
    left->addLayout(fraction_row);

    summary_ = new QLabel(this);
    summary_->setObjectName(QStringLiteral("optimise-summary"));
    summary_->setWordWrap(true);
    QFont large = summary_->font();
    large.setPointSizeF(large.pointSizeF() * 1.15);
    large.setBold(true);
    summary_->setFont(large);
    binding_ = new QLabel(this);
    binding_->setObjectName(QStringLiteral("optimise-binding"));
    binding_->setWordWrap(true);
    advice_ = new QLabel(this);
    advice_->setObjectName(QStringLiteral("optimise-advice"));
    advice_->setWordWrap(true);
    savings_ = new QLabel(this);
    savings_->setObjectName(QStringLiteral("optimise-savings"));
    savings_->setWordWrap(true);
    table_ = new QTableWidget(row_count, 2, this);
    table_->setObjectName(QStringLiteral("optimise-table"));
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionMode(QAbstractItemView::NoSelection);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table_->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    // Every row shows; no room kept below them for a scroll bar.
    table_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    table_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    apply_ = new QPushButton(this);
    apply_->setObjectName(QStringLiteral("optimise-apply"));
    connect(apply_, &QPushButton::clicked, this, [this] {
        if (result_) emit apply_requested(with_settings(scenario_, result_->best.settings));
    });

    left->addSpacing(8);
    left->addWidget(summary_);
    left->addWidget(table_);
    left->addWidget(apply_, 0, Qt::AlignLeft);
    left->addWidget(binding_);
    left->addWidget(savings_);
    left->addWidget(advice_);
    left->addStretch(1);

    pareto_ = new PlotView(this);
    pareto_->setObjectName(QStringLiteral("optimise-pareto"));
    pareto_->set_x_axis({PlotView::Scale::log, {}, QStringLiteral("%g"), {}, true});
    pareto_->set_y_axis(PlotView::Side::left,
                        {PlotView::Scale::log, {}, QStringLiteral("%g"), {}, true});
    pareto_line_ = pareto_->add_line({{}, QColor(0x1f, 0x77, 0xb4), 2.0});
    current_marker_ = pareto_->add_markers({{}, QColor(0x33, 0x33, 0x33), 2.0}, 10.0);
    best_marker_ = pareto_->add_markers({{}, QColor(0xff, 0x7f, 0x0e), 2.0}, 12.0);
    // The target (or, without one, the current uncertainty) on the chart.
    bound_rule_ = pareto_->add_rule(
        {QStringLiteral("t"), QColor(0x0b, 0x2f, 0x6b), 1.5, PlotView::Dash::dotted});

    auto* layout = new QHBoxLayout(this);
    auto* left_widget = new QWidget(this);
    left_widget->setLayout(left);
    left_widget->setMinimumWidth(380);
    left_widget->setMaximumWidth(560);
    layout->addWidget(left_widget);
    layout->addWidget(pareto_, 1);
    retranslate();
    show_result();
}

double OptimisePanel::overtravel_fraction() const {
    return fraction_->value() / 100.0;
}

void OptimisePanel::set_overtravel_fraction(double fraction) {
    fraction_->setValue(100.0 * fraction);
}

void OptimisePanel::show_scenario(const Scenario& scenario) {
    scenario_ = scenario;
    for (QuantityEdit* edit : requirement_edits_) {
        edit->set_value(get_number(scenario, edit->key().toStdString()).value_or(0.0));
    }
    OptimiseRequirements requirements;
    requirements.max_overtravel_fraction = overtravel_fraction();
    if (optimised_scenario_ == scenario &&
        optimised_fraction_ == requirements.max_overtravel_fraction) {
        return;  // shown already
    }
    optimised_scenario_ = scenario;
    optimised_fraction_ = requirements.max_overtravel_fraction;
    try {
        clear_vector_upper_state();  // what Qt painted may have left them in use
        result_ = optimise(scenario, requirements);
        refusal_.reset();
    } catch (const InputError& e) {
        result_.reset();
        refusal_ = e.to_message();
    }
    ++optimise_count_;
    show_result();
}

QString OptimisePanel::problem() const {
    return refusal_ ? translate(*refusal_) : QString();
}

QString OptimisePanel::saved_text() const {
    if (!result_) return problem();
    const OptimiseResult& r = *result_;
    if (!r.current_meets_requirements) {
        return tr("The current settings do not meet the requirements; the fastest that do take "
                  "%1 a cycle.")
            .arg(format_seconds(r.best.cycle_time_s));
    }
    if (r.saved_s <= 0.0005 * r.current.cycle_time_s) {
        return tr("The current settings are already the fastest that meet the requirements.");
    }
    return tr("The best settings save %1 a cycle: %2 instead of %3 (%4 % less).")
        .arg(format_seconds(r.saved_s), format_seconds(r.best.cycle_time_s),
             format_seconds(r.current.cycle_time_s),
             format_number(100.0 * r.saved_s / r.current.cycle_time_s, 0));
}

QString OptimisePanel::binding_text() const {
    if (!result_ || result_->binding.empty()) return {};
    const OptimiseResult& r = *result_;
    QStringList parts;
    for (const Requirement requirement : r.binding) {
        switch (requirement) {
            case Requirement::valid_cycle:
                parts << tr("a cycle that can run (the backoff and the probe's overtravel limit)");
                break;
            case Requirement::target_uncertainty:
                parts
                    << tr("the target uncertainty, %1").arg(format_length(r.uncertainty_bound_mm));
                break;
            case Requirement::current_uncertainty:
                parts << tr("the current uncertainty, %1 (no target is set)")
                             .arg(format_length(r.uncertainty_bound_mm));
                break;
            case Requirement::overtravel_fraction:
                parts << tr("the overtravel allowed, %1 % of the probe's limit")
                             .arg(format_number(100.0 * overtravel_fraction(), 0));
                break;
            case Requirement::probe_max_feed:
                parts << tr("the probe's maximum feed, %1")
                             .arg(format_feed(scenario_.probe.max_feed_mm_min));
                break;
            case Requirement::machine_rapid:
                parts << tr("the machine's rapid feed, %1")
                             .arg(format_feed(scenario_.machine.rapid_feed_mm_min));
                break;
            case Requirement::start_distance:
                parts << tr("the start distance: at least %1, and the part's position "
                            "uncertainty plus the distance to reach the probing feed")
                             .arg(format_mm(scenario_.cycle.min_start_mm));
                break;
            case Requirement::min_feed:
                parts << tr("the slowest feed allowed, %1")
                             .arg(format_feed(scenario_.cycle.min_feed_mm_min));
                break;
            case Requirement::repeats_limit:
                parts << tr("at most %1 measurements").arg(kMaxRepeats);
                break;
        }
    }
    return tr("What limits it: %1.").arg(parts.join(QStringLiteral("; ")));
}

QStringList OptimisePanel::advice_texts() const {
    QStringList out;
    if (!result_) return out;
    for (const Advice& advice : result_->advice) out << translate(advice.message);
    return out;
}

QString OptimisePanel::savings_text() const {
    if (!result_ || !result_->savings) return {};
    const Savings& s = *result_->savings;
    QString text = tr("Saved per part: %1; per year: %2 h of machine time")
                       .arg(format_seconds(s.saved_per_part_s), format_number(s.hours_per_year, 1));
    if (s.cost_per_year) {
        text += tr(", worth %1 at the machine rate").arg(format_number(*s.cost_per_year, 0));
    }
    return text + QLatin1Char('.');
}

QList<QStringList> OptimisePanel::table_rows() const {
    QList<QStringList> rows;
    if (!result_) return rows;
    QStringList header = {QString()};
    for (int column = 0; column < table_->columnCount(); ++column) {
        header << table_->horizontalHeaderItem(column)->text();
    }
    rows << header;
    for (int row = 0; row < table_->rowCount(); ++row) {
        QStringList line = {table_->verticalHeaderItem(row)->text()};
        for (int column = 0; column < table_->columnCount(); ++column) {
            line << table_->item(row, column)->text();
        }
        rows << line;
    }
    return rows;
}

QList<QPointF> OptimisePanel::pareto_points() const {
    return pareto_->points(pareto_line_);
}

QList<QPointF> OptimisePanel::bound_points() const {
    return pareto_->points(bound_rule_);
}

QPair<double, double> OptimisePanel::pareto_x_range() const {
    const PlotView::Range range = pareto_->x_range();
    return {range.lo, range.hi};
}

void OptimisePanel::show_result() {
    summary_->setText(saved_text());
    binding_->setText(binding_text());
    binding_->setVisible(!binding_->text().isEmpty());
    const QStringList advice = advice_texts();
    advice_->setText(advice.isEmpty() ? QString()
                                      : tr("What else would save time:") + QStringLiteral("\n• ") +
                                            advice.join(QStringLiteral("\n• ")));
    advice_->setVisible(!advice.isEmpty());
    table_->setVisible(result_.has_value());
    apply_->setVisible(result_.has_value());
    savings_->setVisible(false);
    if (!result_) {
        pareto_->set_points(pareto_line_, {});
        pareto_->set_points(current_marker_, {});
        pareto_->set_points(best_marker_, {});
        pareto_->set_points(bound_rule_, {});
        return;
    }
    const OptimiseResult& r = *result_;
    // The overtravel the checks take: at the highest feed override.
    if (QTableWidgetItem* header = table_->verticalHeaderItem(row_count - 1)) {
        header->setText(
            tr("Overtravel at %1 %")
                .arg(QLocale().toString(scenario_.cycle.feed_override_max_pct, 'f', 0)));
    }
    const QStringList current = column_of(r.current);
    const QStringList best = column_of(r.best);
    for (int row = 0; row < row_count; ++row) {
        for (int column = 0; column < 2; ++column) {
            const QString& text = column == 0 ? current[row] : best[row];
            QTableWidgetItem* item = table_->item(row, column);
            if (item == nullptr) {
                item = new QTableWidgetItem;
                table_->setItem(row, column, item);
            }
            item->setText(text);
            QFont font = item->font();
            font.setBold(column == 1 && current[row] != best[row]);
            item->setFont(font);
        }
    }
    apply_->setEnabled(r.saved_s > 0.0 || !r.current_meets_requirements);
    savings_->setText(savings_text());
    savings_->setVisible(!savings_->text().isEmpty());

    // The front spans decades of uncertainty (the probe's repeatability over
    // sqrt(20) to a fast single touch's scan range) and of time: log axes. An
    // uncertainty of 0 (a latched input and a perfect probe) sits at the
    // axis's floor.
    const auto shown = [](double uncertainty_mm, double time_s) {
        return QPointF(std::max(1000.0 * uncertainty_mm, kFloor_um), std::max(time_s, kFloor_s));
    };
    QList<QPointF> front;
    for (const Candidate& c : r.pareto) front.append(shown(c.uncertainty_mm, c.cycle_time_s));
    const QPointF current_point = shown(r.current.uncertainty_mm, r.current.cycle_time_s);
    const QPointF best_point = shown(r.best.uncertainty_mm, r.best.cycle_time_s);
    pareto_->set_points(pareto_line_, front);
    pareto_->set_points(current_marker_, {current_point});
    pareto_->set_points(best_marker_, {best_point});
    const QPointF bound_point = shown(r.uncertainty_bound_mm, best_point.y());
    pareto_->set_points(bound_rule_, {bound_point});
    pareto_->set_name(bound_rule_, scenario_.cycle.target_uncertainty_mm > 0.0
                                       ? tr("Target uncertainty")
                                       : tr("Current uncertainty"));
    QList<QPointF> all = front;
    all << current_point << best_point << bound_point;
    double x_lo = all.front().x();
    double x_hi = x_lo;
    double y_lo = all.front().y();
    double y_hi = y_lo;
    for (const QPointF& p : all) {
        x_lo = std::min(x_lo, p.x());
        x_hi = std::max(x_hi, p.x());
        y_lo = std::min(y_lo, p.y());
        y_hi = std::max(y_hi, p.y());
    }
    pareto_->set_x_range(x_lo / 1.5, x_hi * 1.5);
    pareto_->set_y_range(PlotView::Side::left, y_lo / 1.5, y_hi * 1.5);
}

void OptimisePanel::retranslate() {
    requirements_title_->setText(tr("Requirements"));
    for (QuantityEdit* edit : requirement_edits_) edit->retranslate();
    fraction_label_->setText(tr("Overtravel allowed, of the probe's limit"));
    fraction_->setToolTip(
        tr("The optimiser keeps the overtravel at or under this share of the probe's overtravel "
           "limit (80 %: where the cycle starts to warn)."));
    table_->setHorizontalHeaderLabels({tr("Current"), tr("Best")});
    table_->setVerticalHeaderLabels(
        {tr("Strategy"), tr("Probing feedrate"), tr("Measuring feedrate"), tr("Backoff"),
         tr("Approach distance"), tr("Measurements"), tr("Positioning feed"), tr("Cycle time"),
         tr("Uncertainty (k = 2)"), tr("Overtravel")});
    apply_->setText(tr("Apply the best settings"));
    apply_->setToolTip(
        tr("Sets strategy, feeds, backoff, start distance and measurements to "
           "the best ones, as one step that Undo takes back"));
    pareto_->set_title(tr("Fastest cycle at each uncertainty"));
    pareto_->set_x_axis(
        {PlotView::Scale::log, tr("Uncertainty, k = 2 [µm]"), QStringLiteral("%g"), {}, true});
    pareto_->set_y_axis(
        PlotView::Side::left,
        {PlotView::Scale::log, tr("Cycle time [s]"), QStringLiteral("%g"), {}, true});
    pareto_->set_name(pareto_line_, tr("Fastest valid settings"));
    pareto_->set_name(current_marker_, tr("Current"));
    pareto_->set_name(best_marker_, tr("Best"));
    if (result_ || refusal_) show_result();
}

void OptimisePanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

}  // namespace probecycle::ui
