#include "ui/lab/delay_fit_panel.h"

#include <QComboBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/lab/compensation.h"  // lag_cycles_for_delay
#include "core/lab/delay_fit_report.h"
#include "core/lab/lab_examples.h"
#include "ui/common/file_write.h"
#include "ui/common/parameter_info.h"
#include "ui/common/plot_view.h"
#include "ui/common/text_format.h"
#include "ui/common/unit_spin_box.h"
#include "ui/lab/fit_input.h"
#include "ui/lab/lab_widgets.h"
#include "ui/program/program_dialog.h"

namespace probecycle::ui {

namespace {

// The results column's usual width (the tree of groups, the warnings).
constexpr int kResultsWidth = 480;

// One colour per (axis, direction) group, in the order of the file.
const QColor kGroupColours[] = {{0x1f, 0x77, 0xb4}, {0xd6, 0x27, 0x28}, {0x2c, 0xa0, 0x2c},
                                {0x94, 0x67, 0xbd}, {0xe6, 0x7e, 0x22}, {0x17, 0xbe, 0xcf}};

constexpr double kMmToUm = 1000.0;

enum TreeColumn { col_name, col_delay, col_lag, col_position, col_stability, col_n, col_count };

}  // namespace

DelayFitPanel::DelayFitPanel(QWidget* parent) : QGroupBox(parent) {
    setObjectName(QStringLiteral("delay-fit"));
    build_plot();
    auto* top = new QHBoxLayout;
    top->addWidget(build_input_column());
    top->addWidget(delay_plot_, 1);
    top->addWidget(build_results_column());
    auto* column = new QVBoxLayout(this);
    column->addLayout(top, 1);
    column->addLayout(build_apply_row());

    connect(input_->import_button(), &QPushButton::clicked, this, &DelayFitPanel::import_dialog);
    connect(input_->program_button(), &QPushButton::clicked, this,
            [this] { open_program_dialog(); });
    connect(period_, &QDoubleSpinBox::valueChanged, this, &DelayFitPanel::apply_period);
    connect(apply_group_, &QComboBox::currentIndexChanged, this, [this] { update_apply(); });
    connect(apply_button_, &QPushButton::clicked, this, [this] { apply_to_scenario(); });
    connect(export_button_, &QPushButton::clicked, this, &DelayFitPanel::export_dialog);
    retranslate();
}

DelayFitPanel::~DelayFitPanel() = default;

// The paste box, the period and the buttons.
QWidget* DelayFitPanel::build_input_column() {
    format_hint_ = new QLabel(this);
    format_hint_->setWordWrap(true);
    input_ = new FitInput(ProgramKind::delay,
                          {"delay-touches", "delay-program", "delay-import-log", "delay-error"},
                          this, last_error_, [this] { return fit_.has_value(); });
    input_->set_fit_text(
        [this](const QString& text, const QString& source) { return fit_text(text, source); });
    input_->set_example_text([this] {
        return QString::fromStdString(example_delay_csv(scenario_.value_or(Scenario{})));
    });
    touches_edit_ = input_->make_editor(this);
    period_ = new UnitSpinBox(0.0, 0.1, 3, 0.0, this, 1000.0);
    period_->setObjectName(QStringLiteral("fit-interpolation-period"));
    period_->set_unit(unit_ms);
    period_label_ = new QLabel(this);
    period_label_->setBuddy(period_);
    input_->make_buttons(this);
    auto* period_row = new QHBoxLayout;
    period_row->addWidget(period_label_);
    period_row->addWidget(period_, 1);
    auto* input = new QWidget(this);
    auto* input_column = new QVBoxLayout(input);
    input_column->setContentsMargins(0, 0, 0, 0);
    input_column->addWidget(format_hint_);
    input_column->addWidget(touches_edit_, 1);
    input_column->addLayout(period_row);
    input_->add_buttons_to(input_column);
    input->setFixedWidth(320);
    return input;
}

// The deviation chart; its curves are made per group as fits need them.
void DelayFitPanel::build_plot() {
    delay_plot_ = new PlotView(this);
    delay_plot_->setObjectName(QStringLiteral("delay-plot"));
    delay_plot_->set_x_axis({PlotView::Scale::linear, {}, QStringLiteral("%g"), {}});
    delay_plot_->set_y_axis(PlotView::Side::left,
                            {PlotView::Scale::linear, {}, QStringLiteral("%g"), {}});
    delay_plot_->set_x_range(0.0, 1000.0);
    delay_plot_->set_y_range(PlotView::Side::left, 0.0, 100.0);
}

// The tree of groups and feeds, and the warnings under it.
QWidget* DelayFitPanel::build_results_column() {
    tree_ = new QTreeWidget(this);
    tree_->setObjectName(QStringLiteral("delay-groups"));
    tree_->setColumnCount(col_count);
    tree_->setRootIsDecorated(true);
    tree_->setUniformRowHeights(true);
    tree_->setAlternatingRowColors(true);
    tree_->header()->setStretchLastSection(false);
    tree_->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    warnings_title_ = new QLabel(this);
    QFont bold = warnings_title_->font();
    bold.setBold(true);
    warnings_title_->setFont(bold);
    warnings_ = new WarningList;
    warnings_->setObjectName(QStringLiteral("delay-warnings"));
    auto* warnings_scroll = new QScrollArea(this);
    warnings_scroll->setWidget(warnings_);
    warnings_scroll->setWidgetResizable(true);
    warnings_scroll->setFrameShape(QFrame::NoFrame);
    warnings_scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    export_status_ = new QLabel(this);
    export_status_->setObjectName(QStringLiteral("delay-export-status"));
    export_status_->setWordWrap(true);
    export_status_->hide();
    export_button_ = new QPushButton(this);
    export_button_->setObjectName(QStringLiteral("delay-export"));
    export_button_->setEnabled(false);
    auto* export_row = new QHBoxLayout;
    export_row->addStretch(1);
    export_row->addWidget(export_button_);
    auto* results = new QWidget(this);
    auto* results_column = new QVBoxLayout(results);
    results_column->setContentsMargins(0, 0, 0, 0);
    results_column->addWidget(tree_, 3);
    results_column->addWidget(warnings_title_);
    results_column->addWidget(warnings_scroll, 2);
    results_column->addWidget(export_status_);
    results_column->addLayout(export_row);
    results_ = results;
    results->setFixedWidth(kResultsWidth);
    return results;
}

// "Delay to apply: [group]  breakdown  [Apply to scenario]".
QLayout* DelayFitPanel::build_apply_row() {
    apply_label_ = new QLabel(this);
    apply_group_ = new QComboBox(this);
    apply_group_->setObjectName(QStringLiteral("apply-group"));
    apply_group_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    apply_label_->setBuddy(apply_group_);
    apply_breakdown_ = new QLabel(this);
    apply_breakdown_->setObjectName(QStringLiteral("apply-breakdown"));
    apply_breakdown_->setWordWrap(true);
    apply_breakdown_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    apply_button_ = new QPushButton(this);
    apply_button_->setObjectName(QStringLiteral("apply-to-scenario"));
    apply_button_->setEnabled(false);
    auto* apply_row = new QHBoxLayout;
    apply_row->addWidget(apply_label_);
    apply_row->addWidget(apply_group_);
    apply_row->addSpacing(8);
    apply_row->addWidget(apply_breakdown_, 1);
    apply_row->addWidget(apply_button_);
    return apply_row;
}

void DelayFitPanel::retranslate() {
    setTitle(tr("Delay from touches at several feeds (delay-stability test)"));
    format_hint_->setText(
        tr("Touch the same surface several times at each of several feeds, per axis and "
           "direction, starting far enough out to be at full speed. Paste or import the "
           "positions: <code>axis,direction,feed_mm_min,measured_mm</code> (direction +1 or −1, "
           "of travel)."));
    touches_edit_->setPlaceholderText(
        QStringLiteral("axis,direction,feed_mm_min,measured_mm\nX,+1,100,10.0142\n"
                       "X,+1,1000,10.1417\nX,+1,3000,10.4250\n...") +
        QLatin1Char('\n') + tr("(example)"));
    period_label_->setText(tr("Interpolation period"));
    period_->setToolTip(
        tr("The control's interpolation cycle, to express the delay in cycles "
           "(optional)."));
    period_->setSpecialValueText(tr("none"));
    input_->retranslate();
    input_->program_button()->setToolTip(
        tr("The delay-stability test as a program for your control (LinuxCNC, grbl, Fanuc, Haas, "
           "Mitsubishi, Siemens), with the "
           "plan that the import of its log needs."));
    input_->log_button()->setToolTip(
        tr("What the control recorded while it ran the program, read with the program's plan "
           "into the touches and fitted."));
    delay_plot_->set_title(tr("Measured minus zero-speed position, against feed"));
    delay_plot_->set_x_axis(
        {PlotView::Scale::linear, tr("Feed [%1]").arg(unit_mm_min()), QStringLiteral("%g"), {}});
    delay_plot_->set_y_axis(
        PlotView::Side::left,
        {PlotView::Scale::linear, tr("Deviation [%1]").arg(unit_um()), QStringLiteral("%g"), {}});
    tree_->setHeaderLabels({tr("Group / feed"), tr("Delay τ"), tr("Cycles"), tr("p₀ / mean"),
                            tr("2σ / range"), tr("n")});
    QTreeWidgetItem* header = tree_->headerItem();
    header->setToolTip(col_delay, tr("The total delay: the slope of the line over the feeds."));
    header->setToolTip(col_lag, tr("The delay in interpolation cycles (with the period given)."));
    header->setToolTip(col_position, tr("Group: the zero-speed position p₀. Feed: the mean "
                                        "deviation from p₀."));
    header->setToolTip(col_stability, tr("Group: twice the standard deviation of the residuals "
                                         "of the line. Feed: the range (max − min) of its "
                                         "touches, the delay's stability."));
    header->setToolTip(col_n, tr("Touches"));
    warnings_title_->setText(tr("Warnings"));
    warnings_->set_empty_text(tr("No warnings."));
    export_button_->setText(tr("Export CSV report…"));
    export_button_->setToolTip(
        tr("The delay per group, its stability per feed, every touch's residual and the "
           "warnings as CSV: the same file as probecycle-cli latency fit --report."));
    apply_label_->setText(tr("Delay to apply:"));
    apply_button_->setText(tr("Apply to scenario"));
    apply_button_->setToolTip(
        tr("Sets machine.controller_latency_s to the fitted delay less the probe's interface "
           "delay and half the scan period. With a latched input the fitted delay is the "
           "interface delay: it sets probe.interface_delay_s and leaves the latency alone."));
    period_->retranslate();
    show_fit();
}

void DelayFitPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QGroupBox::changeEvent(event);
}

void DelayFitPanel::set_scenario(const probecycle::Scenario& scenario) {
    scenario_ = scenario;
    update_apply();
}

void DelayFitPanel::set_touches_text(const QString& csv) {
    touches_edit_->setPlainText(csv);
}

QString DelayFitPanel::touches_text() const {
    return touches_edit_->toPlainText();
}

void DelayFitPanel::set_interpolation_period_s(double period_s) {
    {
        const QSignalBlocker block(period_);
        period_->set_internal_value(period_s);
    }
    apply_period();
}

void DelayFitPanel::apply_period() {
    // As the box shows it (rounded to its decimals).
    const double period_s = period_->internal_value();
    DelayFitOptions options = fit_options_;
    options.interpolation_period_s =
        period_s > 0.0 ? std::optional<double>(period_s) : std::nullopt;
    if (!fit_) {
        fit_options_ = options;
        return;
    }
    try {
        DelayFit fit = fit_delay(touches_, options);
        fit_options_ = options;
        fit_ = std::move(fit);
    } catch (const std::exception&) {
        set_error(current_error_text());
        return;
    }
    show_fit();
}

bool DelayFitPanel::load_example() {
    return input_->load_example();
}

bool DelayFitPanel::fit() {
    return input_->fit();
}

bool DelayFitPanel::import_file(const QString& path) {
    return input_->import_file(path);
}

std::optional<std::string> DelayFitPanel::report_csv(ReportRows rows) {
    if (!fit_) {
        show_live_error(export_status_, [this] {
            return last_error_ = tr("Nothing to export: fit the touches first.");
        });
        return std::nullopt;
    }
    ReportHeader header;
    header.date = report_date();
    header.subject = touches_from_;
    return delay_fit_report_csv(touches_, fit_options_, *fit_, header, rows);
}

bool DelayFitPanel::export_report(const QString& path, ReportRows rows) {
    const std::optional<std::string> csv = report_csv(rows);
    return csv && write_report(path, *csv, export_status_, last_error_);
}

void DelayFitPanel::export_dialog() {
    const QString path =
        ask_report_path(this, tr("Export delay fit report"), QStringLiteral("delay-report.csv"));
    if (!path.isEmpty()) export_report(path);
}

bool DelayFitPanel::fit_text(const QString& text, const QString& source) {
    DelayFitOptions options = fit_options_;
    const double period_s = period_->internal_value();
    options.interpolation_period_s =
        period_s > 0.0 ? std::optional<double>(period_s) : std::nullopt;
    std::vector<DelayTouch> touches;
    DelayFit fit;
    try {
        touches = parse_delay_csv(text.toStdString());
        fit = fit_delay(touches, options);
    } catch (const std::exception&) {
        input_->show_fit_error(source);
        return false;
    }
    touches_ = std::move(touches);
    touches_from_ = input_->source_of(text);
    fit_options_ = options;
    fit_ = std::move(fit);
    fitted_text_ = text;
    set_error({});
    show_fit();
    return true;
}

DelaySession DelayFitPanel::session() const {
    DelaySession session;
    session.touches_csv = touches_edit_->toPlainText().toStdString();
    if (fit_) session.fitted_csv = fitted_text_.toStdString();
    session.interpolation_period_s = period_->internal_value();
    if (const std::optional<std::string> group = chosen_group()) session.applied_group = *group;
    return session;
}

bool DelayFitPanel::restore(const DelaySession& session) {
    {
        const QSignalBlocker block(period_);
        period_->set_internal_value(session.interpolation_period_s);
    }
    fit_.reset();
    touches_.clear();
    fitted_text_.clear();
    set_error({});
    bool fitted = true;
    if (!session.fitted_csv.empty()) {
        fitted = fit_text(QString::fromStdString(session.fitted_csv), QString());
    } else {
        apply_period();
        show_fit();
    }
    set_touches_text(QString::fromStdString(session.touches_csv));
    set_applied_group(QString::fromStdString(session.applied_group));
    return fitted;
}

void DelayFitPanel::set_error(LiveText text) {
    input_->set_error(std::move(text));
}

void DelayFitPanel::show_fit() {
    tree_->clear();
    std::vector<WarningList::Item> items;
    if (fit_) {
        for (const DelayGroup& g : fit_->groups) {
            const QString name = QString::fromStdString(g.name());
            auto* top = new QTreeWidgetItem(tree_);
            top->setText(col_name, name);
            top->setText(col_delay, lab_ms(g.delay_s));
            top->setText(col_lag,
                         g.lag_cycles ? format_number(*g.lag_cycles, 2) : QStringLiteral("—"));
            top->setText(col_position, lab_mm(g.zero_speed_position_mm));
            top->setText(col_stability,
                         g.residual_2sigma_mm
                             ? lab_signed_um(*g.residual_2sigma_mm).remove(QLatin1Char('+'))
                             : QStringLiteral("—"));
            std::size_t n = 0;
            for (const FeedScatter& f : g.feeds) n += f.n;
            top->setText(col_n, QLocale().toString(n));
            QFont bold = top->font(col_name);
            bold.setBold(true);
            for (int c = 0; c < col_count; ++c) top->setFont(c, bold);
            for (const FeedScatter& f : g.feeds) {
                auto* child = new QTreeWidgetItem(top);
                child->setText(col_name, format_feed(f.feed_mm_min));
                child->setText(col_position, lab_signed_um(f.mean_mm - g.zero_speed_position_mm));
                child->setText(col_stability, lab_signed_um(f.range_mm).remove(QLatin1Char('+')));
                child->setText(col_n, QLocale().toString(f.n));
            }
            for (int c = col_delay; c < col_count; ++c) {
                top->setTextAlignment(c, Qt::AlignRight | Qt::AlignVCenter);
                for (int i = 0; i < top->childCount(); ++i) {
                    top->child(i)->setTextAlignment(c, Qt::AlignRight | Qt::AlignVCenter);
                }
            }
            for (const LatencyWarning& w : g.warnings) items.push_back(warning_item(w, name));
        }
        tree_->expandAll();
    }
    // Every column in view: the column widens when the fit's numbers and the
    // language's headers need more than its usual width (Russian), never less.
    int needed = 2 * tree_->frameWidth() + tree_->verticalScrollBar()->sizeHint().width();
    for (int c = 0; c < col_count; ++c) needed += tree_->header()->sectionSize(c);
    results_->setFixedWidth(std::max(kResultsWidth, needed));
    warnings_->show_items(items);
    export_button_->setEnabled(fit_.has_value());
    export_status_->hide();

    // The group choice for "Apply": the CLI's rule first, then each group.
    const QString chosen = apply_group_->currentData().toString();
    {
        const QSignalBlocker block(apply_group_);
        apply_group_->clear();
        apply_group_->addItem(tr("Longest delay (safe side)"), QString());
        if (fit_) {
            for (const DelayGroup& g : fit_->groups) {
                const QString name = QString::fromStdString(g.name());
                apply_group_->addItem(name, name);
            }
        }
        apply_group_->setCurrentIndex(std::max(apply_group_->findData(chosen), 0));
    }
    draw_fit();
    update_apply();
}

void DelayFitPanel::draw_fit() {
    const std::size_t groups = fit_ ? fit_->groups.size() : 0;
    // Curves are made once per group slot and reused; unused ones are hidden.
    while (group_curves_.size() < groups) {
        const QColor colour = kGroupColours[group_curves_.size() % std::size(kGroupColours)];
        GroupCurves curves;
        curves.line = delay_plot_->add_line({QStringLiteral(" "), colour, 2.0});
        curves.touches = delay_plot_->add_markers({{}, colour}, 8.0);
        group_curves_.push_back(curves);
    }
    double max_feed = 0.0;
    double lo = 0.0;
    double hi = 0.0;
    for (std::size_t i = 0; i < group_curves_.size(); ++i) {
        const GroupCurves& curves = group_curves_[i];
        if (i >= groups) {
            delay_plot_->set_points(curves.touches, {});
            delay_plot_->set_points(curves.line, {});
            delay_plot_->set_visible(curves.touches, false);
            delay_plot_->set_visible(curves.line, false);
            continue;
        }
        const DelayGroup& g = fit_->groups[i];
        QList<QPointF> touches;
        double group_max_feed = 0.0;
        for (const DelayTouch& t : touches_) {
            if (t.axis != g.axis || t.direction != g.direction) continue;
            const double deviation_um = (t.measured_mm - g.zero_speed_position_mm) * kMmToUm;
            touches.append({t.feed_mm_min, deviation_um});
            group_max_feed = std::max(group_max_feed, t.feed_mm_min);
            lo = std::min(lo, deviation_um);
            hi = std::max(hi, deviation_um);
        }
        const double end_um = (g.predicted_mm(group_max_feed) - g.zero_speed_position_mm) * kMmToUm;
        lo = std::min(lo, end_um);
        hi = std::max(hi, end_um);
        max_feed = std::max(max_feed, group_max_feed);
        delay_plot_->set_points(curves.touches, touches);
        delay_plot_->set_points(curves.line, {{0.0, 0.0}, {group_max_feed, end_um}});
        delay_plot_->set_name(
            curves.line, tr("%1: τ = %2").arg(QString::fromStdString(g.name()), lab_ms(g.delay_s)));
        delay_plot_->set_visible(curves.touches, true);
        delay_plot_->set_visible(curves.line, true);
    }
    if (groups > 0) {
        const double pad = std::max(hi - lo, 1.0) * 0.06;
        delay_plot_->set_x_range(0.0, max_feed * 1.04);
        delay_plot_->set_y_range(PlotView::Side::left, lo - pad, hi + pad);
    }
}

QStringList DelayFitPanel::warning_codes() const {
    return warnings_->codes();
}

QStringList DelayFitPanel::results_text() const {
    QStringList out;
    for (int i = 0; i < tree_->topLevelItemCount(); ++i) {
        const QTreeWidgetItem* item = tree_->topLevelItem(i);
        QStringList cells;
        for (int c = 0; c < col_count; ++c) cells << item->text(c);
        out << cells.join(QStringLiteral(" | "));
    }
    return out;
}

QList<QPointF> DelayFitPanel::plotted_touches(int group) const {
    if (group < 0 || static_cast<std::size_t>(group) >= group_curves_.size()) return {};
    return delay_plot_->points(group_curves_[static_cast<std::size_t>(group)].touches);
}

QList<QPointF> DelayFitPanel::plotted_line(int group) const {
    if (group < 0 || static_cast<std::size_t>(group) >= group_curves_.size()) return {};
    return delay_plot_->points(group_curves_[static_cast<std::size_t>(group)].line);
}

void DelayFitPanel::import_dialog() {
    input_->import_dialog(tr("Import touches"));
}

ProgramDialog* DelayFitPanel::open_program_dialog() {
    return input_->open_program_dialog(scenario_.value_or(Scenario{}));
}

bool DelayFitPanel::import_machine_log(const MachineLogChoice& choice) {
    return input_->import_machine_log(choice);
}

void DelayFitPanel::set_applied_group(const QString& name) {
    const int index = name.isEmpty() ? 0 : apply_group_->findData(name.toUpper());
    if (index >= 0) apply_group_->setCurrentIndex(index);
}

std::optional<std::string> DelayFitPanel::chosen_group() const {
    const QString name = apply_group_->currentData().toString();
    if (name.isEmpty()) return std::nullopt;
    return name.toStdString();
}

DelayFitPanel::ApplyState DelayFitPanel::evaluate_apply() const {
    ApplyState state;
    if (!fit_ || fit_->groups.empty()) {
        state.problem = tr("Fit the touches first.");
        return state;
    }
    if (!scenario_) {
        state.problem = tr("No scenario to apply the delay to.");
        return state;
    }
    try {
        // The CLI's --apply-to rule, from the core; it refuses a negative latency.
        AppliedDelay applied = delay_to_apply(*fit_, *scenario_, chosen_group());
        // The result must be a valid scenario (the key's range).
        apply_delay(*scenario_, applied);
        state.applied = std::move(applied);
    } catch (const std::exception& e) {
        // InputError from the rule, ScenarioError from the key's range.
        state.problem = error_text(e);
    }
    return state;
}

std::optional<AppliedDelay> DelayFitPanel::pending_application() const {
    return evaluate_apply().applied;
}

QString DelayFitPanel::apply_problem() const {
    return evaluate_apply().problem;
}

void DelayFitPanel::update_apply() {
    const ApplyState state = evaluate_apply();
    if (state.applied) {
        const AppliedDelay& a = *state.applied;
        if (a.latched) {
            //: %1 group, %2 its delay (the result), %3 the interface delay now
            apply_breakdown_->setText(
                tr("Latched input: interface delay = %1 delay <b>%2</b> (now %3); the "
                   "controller latency is left as it is")
                    .arg(QString::fromStdString(a.group), lab_ms(a.value_s), lab_ms(a.previous_s)));
        } else {
            //: %1 group, %2 its delay, %3 interface delay, %4 half scan period, %5 result, %6 now
            apply_breakdown_->setText(
                tr("Controller latency = %1 delay %2 − interface %3 − half scan %4 = <b>%5</b> "
                   "(now %6)")
                    .arg(QString::fromStdString(a.group), lab_ms(a.total_delay_s),
                         lab_ms(a.interface_delay_s), lab_ms(a.half_scan_s), lab_ms(a.value_s),
                         lab_ms(a.previous_s)));
        }
        apply_breakdown_->setStyleSheet({});
        apply_breakdown_->setToolTip(translate(a.rule));
    } else if (fit_ && scenario_) {
        show_error(apply_breakdown_, state.problem);
        apply_breakdown_->setToolTip({});
    } else {
        apply_breakdown_->setStyleSheet({});
        apply_breakdown_->setText(state.problem);
        apply_breakdown_->setToolTip({});
    }
    apply_breakdown_->show();
    apply_button_->setEnabled(state.applied.has_value());
    emit fit_changed();
}

bool DelayFitPanel::apply_to_scenario() {
    const ApplyState state = evaluate_apply();
    if (!state.applied) {
        last_error_ = state.problem;
        return false;
    }
    last_error_.clear();
    emit delay_applied(QString::fromStdString(state.applied->key), state.applied->value_s);
    return true;
}

QStringList DelayFitPanel::warning_texts() const {
    return warnings_->texts();
}

std::optional<DelayFitPanel::LagFromFit> DelayFitPanel::lag_from_fit() const {
    if (!fit_ || fit_->groups.empty() || !fit_options_.interpolation_period_s) return std::nullopt;
    // The group "Apply" uses (core choose_group), and the lag rule the
    // simulator assumes (core lag_cycles_for_delay).
    const DelayGroup* chosen = nullptr;
    try {
        chosen = choose_group(*fit_, chosen_group()).group;
    } catch (const std::invalid_argument&) {
        return std::nullopt;  // a name no longer in the fit: nothing to take
    }
    const double period_s = *fit_options_.interpolation_period_s;
    return LagFromFit{period_s, lag_cycles_for_delay(chosen->delay_s, period_s)};
}

}  // namespace probecycle::ui
