#include "ui/lab/compensation_panel.h"

#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QShowEvent>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "ui/common/parameter_info.h"
#include "ui/common/plot_view.h"
#include "ui/common/text_format.h"
#include "ui/common/unit_spin_box.h"
#include "ui/lab/lab_widgets.h"

namespace probecycle::ui {

namespace {

const QColor kMethodColours[kCompensationMethodCount] = {
    {0x7f, 0x7f, 0x7f},  // uncompensated
    {0xc0, 0x39, 0x2b},  // naive v * tau
    {0x1f, 0x77, 0xb4},  // cycle lag
    {0x2c, 0xa0, 0x2c},  // timestamp
};

// Speeds at the trigger, as fractions of the feed, for the braking sweep:
// from braking just begun down to almost stopped.
constexpr int kSweepPoints = 40;

constexpr double kMmToUm = 1000.0;

QString method_label(CompensationMethod method) {
    switch (method) {
        case CompensationMethod::uncompensated:
            return CompensationPanel::tr("Uncompensated");
        case CompensationMethod::naive_v_tau:
            return CompensationPanel::tr("Naive v·τ");
        case CompensationMethod::cycle_lag:
            return CompensationPanel::tr("Cycle lag (real increments)");
        case CompensationMethod::timestamp:
            return CompensationPanel::tr("Timestamp interpolation");
    }
    return {};
}

// The legend's short names; the table says it in full.
QString method_legend(CompensationMethod method) {
    switch (method) {
        case CompensationMethod::uncompensated:
            return CompensationPanel::tr("Uncompensated");
        case CompensationMethod::naive_v_tau:
            return CompensationPanel::tr("Naive v·τ");
        case CompensationMethod::cycle_lag:
            return CompensationPanel::tr("Real increments");
        case CompensationMethod::timestamp:
            return CompensationPanel::tr("Timestamp");
    }
    return {};
}

}  // namespace

CompensationPanel::CompensationPanel(QWidget* parent) : QGroupBox(parent) {
    setObjectName(QStringLiteral("compensation"));
    comparison_timer_.setSingleShot(true);
    comparison_timer_.setInterval(0);
    connect(&comparison_timer_, &QTimer::timeout, this, &CompensationPanel::update_comparison_now);

    QWidget* input = build_input_column();
    build_plot();
    build_lag_plot();
    QWidget* table = build_table_column();
    auto* row = new QHBoxLayout(this);
    row->addWidget(input);
    // Two charts, one at a time at full size: the methods while braking, and
    // the real increments against the compensated lag.
    charts_ = new QTabWidget(this);
    charts_->setObjectName(QStringLiteral("compensation-charts"));
    charts_->setDocumentMode(true);
    charts_->addTab(comparison_plot_, QString());
    charts_->addTab(lag_plot_, QString());
    row->addWidget(charts_, 1);
    row->addWidget(table);

    for (UnitSpinBox* box : {feed_, ipo_period_, speed_fraction_}) {
        connect(box, &QDoubleSpinBox::valueChanged, this, &CompensationPanel::schedule_comparison);
    }
    for (QSpinBox* box : {lag_cycles_, compensated_lag_}) {
        connect(box, &QSpinBox::valueChanged, this, &CompensationPanel::schedule_comparison);
    }
    connect(touch_, &QComboBox::currentIndexChanged, this, [this] {
        speed_fraction_->setEnabled(inputs().touch == TouchMotion::braking);
        schedule_comparison();
    });
    connect(lag_from_fit_, &QPushButton::clicked, this, &CompensationPanel::lag_from_fit_requested);

    retranslate();
    update_comparison_now();
}

CompensationPanel::~CompensationPanel() = default;

// The setup form, "Take period and lag from the fit" and the error line.
QWidget* CompensationPanel::build_input_column() {
    const Inputs defaults;
    feed_ = new UnitSpinBox(1.0, 100000.0, 0, defaults.feed_mm_min, this);
    feed_->setObjectName(QStringLiteral("compensation-feed"));
    feed_->set_unit(unit_mm_min);
    ipo_period_ = new UnitSpinBox(1e-5, 0.1, 3, defaults.interpolation_period_s, this, 1000.0);
    ipo_period_->setObjectName(QStringLiteral("compensation-period"));
    ipo_period_->set_unit(unit_ms);
    lag_cycles_ = new QSpinBox(this);
    lag_cycles_->setObjectName(QStringLiteral("compensation-lag"));
    lag_cycles_->setRange(0, static_cast<int>(IncrementRing::kCapacity) - 1);
    lag_cycles_->setValue(defaults.lag_cycles);
    lag_cycles_->setKeyboardTracking(false);
    lag_cycles_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    // -1 shows as "as the lag" (retranslate() sets the text).
    compensated_lag_ = new QSpinBox(this);
    compensated_lag_->setObjectName(QStringLiteral("compensation-compensated-lag"));
    compensated_lag_->setRange(-1, static_cast<int>(IncrementRing::kCapacity) - 1);
    compensated_lag_->setValue(defaults.compensated_lag_cycles);
    compensated_lag_->setKeyboardTracking(false);
    compensated_lag_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    touch_ = new QComboBox(this);
    touch_->setObjectName(QStringLiteral("compensation-touch"));
    touch_->addItem(QString(), static_cast<int>(TouchMotion::constant_speed));
    touch_->addItem(QString(), static_cast<int>(TouchMotion::braking));
    touch_->setCurrentIndex(defaults.touch == TouchMotion::braking ? 1 : 0);
    speed_fraction_ = new UnitSpinBox(0.001, 1.0, 1, defaults.speed_fraction, this, 100.0);
    speed_fraction_->setObjectName(QStringLiteral("compensation-speed-fraction"));
    speed_fraction_->set_unit([] { return QStringLiteral("%"); });
    lag_from_fit_ = new QPushButton(this);
    lag_from_fit_->setObjectName(QStringLiteral("lag-from-fit"));
    lag_from_fit_->setEnabled(false);
    form_ = new QFormLayout;
    form_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    // QFormLayout makes no label for an empty text; retranslate() fills these.
    for (QWidget* field :
         {static_cast<QWidget*>(feed_), static_cast<QWidget*>(ipo_period_),
          static_cast<QWidget*>(lag_cycles_), static_cast<QWidget*>(compensated_lag_),
          static_cast<QWidget*>(touch_), static_cast<QWidget*>(speed_fraction_)}) {
        auto* label = new QLabel(this);
        label->setBuddy(field);
        form_->addRow(label, field);
    }
    error_label_ = new QLabel(this);
    error_label_->setObjectName(QStringLiteral("compensation-error"));
    error_label_->setWordWrap(true);
    error_label_->hide();
    auto* input = new QWidget(this);
    auto* input_column = new QVBoxLayout(input);
    input_column->setContentsMargins(0, 0, 0, 0);
    input_column->addLayout(form_);
    input_column->addWidget(lag_from_fit_, 0, Qt::AlignRight);
    input_column->addWidget(error_label_);
    input_column->addStretch(1);
    input->setFixedWidth(320);
    return input;
}

// The error of each method against the speed at the trigger, while braking.
void CompensationPanel::build_plot() {
    comparison_plot_ = new PlotView(this);
    comparison_plot_->setObjectName(QStringLiteral("comparison-plot"));
    comparison_plot_->set_x_axis({PlotView::Scale::linear, {}, QStringLiteral("%g"), {}});
    comparison_plot_->set_y_axis(PlotView::Side::left,
                                 {PlotView::Scale::linear, {}, QStringLiteral("%g"), {}});
    comparison_plot_->set_x_range(0.0, 100.0);
    current_fraction_curve_ =
        comparison_plot_->add_line({{}, QColor(0x55, 0x55, 0x55), 1.0, PlotView::Dash::dotted});
    for (std::size_t m = 0; m < kCompensationMethodCount; ++m) {
        const bool exact = m == static_cast<std::size_t>(CompensationMethod::timestamp);
        // Named, so in the legend; retranslate() sets the names.
        method_curves_[m] =
            comparison_plot_->add_line({QStringLiteral(" "), kMethodColours[m], 2.0,
                                        exact ? PlotView::Dash::dashed : PlotView::Dash::solid});
    }
}

// The real-increments method's error against the lag it compensates, with
// the machine's true lag as set: a lag set wrong shows as a slope.
void CompensationPanel::build_lag_plot() {
    lag_plot_ = new PlotView(this);
    lag_plot_->setObjectName(QStringLiteral("lag-plot"));
    lag_plot_->set_x_axis({PlotView::Scale::linear, {}, QStringLiteral("%g"), {}});
    lag_plot_->set_y_axis(PlotView::Side::left,
                          {PlotView::Scale::linear, {}, QStringLiteral("%g"), {}});
    lag_plot_->set_x_range(0.0, static_cast<double>(IncrementRing::kCapacity) - 1.0);
    lag_plot_->set_legend_visible(false);
    true_lag_marker_curve_ =
        lag_plot_->add_line({{}, QColor(0x55, 0x55, 0x55), 1.0, PlotView::Dash::dashed});
    lag_marker_curve_ =
        lag_plot_->add_line({{}, QColor(0x55, 0x55, 0x55), 1.0, PlotView::Dash::dotted});
    lag_error_curve_ = lag_plot_->add_line(
        {{}, kMethodColours[static_cast<std::size_t>(CompensationMethod::cycle_lag)], 2.0});
}

// The four methods at the current setup, the trigger's summary and a note.
QWidget* CompensationPanel::build_table_column() {
    note_ = new QLabel(this);
    note_->setWordWrap(true);
    note_->setStyleSheet(QStringLiteral("color: #555555;"));
    methods_table_ = new QTableWidget(static_cast<int>(kCompensationMethodCount), 3, this);
    methods_table_->setObjectName(QStringLiteral("compensation-methods"));
    methods_table_->verticalHeader()->hide();
    methods_table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    methods_table_->setSelectionMode(QAbstractItemView::NoSelection);
    methods_table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    methods_table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    methods_table_->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    for (int r = 0; r < methods_table_->rowCount(); ++r) {
        for (int c = 0; c < 3; ++c) {
            auto* item = new QTableWidgetItem;
            if (c > 0) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            methods_table_->setItem(r, c, item);
        }
        methods_table_->item(r, 0)->setForeground(kMethodColours[r]);
    }
    methods_table_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    methods_table_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // Compact rows, and as high as its four rows, no more.
    methods_table_->verticalHeader()->setDefaultSectionSize(methods_table_->fontMetrics().height() +
                                                            8);
    methods_table_->setFixedHeight(methods_table_->horizontalHeader()->sizeHint().height() +
                                   methods_table_->rowCount() *
                                       methods_table_->verticalHeader()->defaultSectionSize() +
                                   2 * methods_table_->frameWidth());
    trigger_summary_ = new QLabel(this);
    trigger_summary_->setObjectName(QStringLiteral("compensation-summary"));
    trigger_summary_->setWordWrap(true);
    trigger_summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* table = new QWidget(this);
    auto* table_column = new QVBoxLayout(table);
    table_column->setContentsMargins(0, 0, 0, 0);
    table_column->addWidget(methods_table_);
    table_column->addWidget(trigger_summary_);
    table_column->addWidget(note_);
    table_column->addStretch(1);
    table->setFixedWidth(380);
    return table;
}

QString CompensationPanel::field_label(const std::string& key) {
    if (key == "feed-mm-min") return tr("Feed");
    if (key == "interpolation-period-s") return tr("Interpolation period");
    if (key == "lag-cycles") return tr("Lag");
    if (key == "compensated-lag-cycles") return tr("Compensated lag");
    if (key == "speed-fraction") return tr("Speed at the trigger");
    if (key == "direction") return tr("Direction of travel");
    if (key == "trigger-phase") return tr("Trigger phase in its cycle");
    if (key == "counts-per-mm") return tr("Encoder counts per mm");
    if (key == "counter-bits") return tr("Encoder counter width");
    if (key == "naive-delay-s") return tr("Delay for v·τ");
    return QString::fromStdString(key);
}

void CompensationPanel::retranslate() {
    setTitle(tr("Compensation of the trigger position"));
    const auto set_label = [this](QWidget* field, const QString& text, const QString& tip) {
        if (auto* label = qobject_cast<QLabel*>(form_->labelForField(field))) {
            label->setText(text);
        }
        field->setToolTip(tip);
    };
    set_label(feed_, tr("Feed"), tr("The programmed probing feed."));
    set_label(ipo_period_, tr("Interpolation period"), tr("The control's interpolation cycle."));
    set_label(lag_cycles_, tr("Lag"),
              tr("Cycles between the end of the trigger's cycle and the recorded position; the "
                 "delay-stability test above measures it."));
    lag_cycles_->setSuffix(tr(" cycles"));
    set_label(compensated_lag_, tr("Compensated lag"),
              tr("The lag the real-increments method subtracts. Controls are often set up with "
                 "a lag other than the machine's (a published study compensated 7 to 9 cycles on "
                 "a machine that lagged about 10): each cycle too few leaves one cycle's travel "
                 "of error. Lowest value: the lag itself."));
    compensated_lag_->setSuffix(tr(" cycles"));
    compensated_lag_->setSpecialValueText(tr("as the lag"));
    lag_plot_->set_title(tr("Real increments: error against the compensated lag"));
    charts_->setTabText(0, tr("While braking"));
    charts_->setTabText(1, tr("Against the compensated lag"));
    lag_plot_->set_x_axis(
        {PlotView::Scale::linear, tr("Compensated lag [cycles]"), QStringLiteral("%g"), {}});
    lag_plot_->set_y_axis(
        PlotView::Side::left,
        {PlotView::Scale::linear, tr("Error [%1]").arg(unit_um()), QStringLiteral("%g"), {}});
    lag_plot_->setToolTip(
        tr("Dashed: the machine's lag. Dotted: the lag compensated. The error grows by one "
           "cycle's travel for each cycle the compensation is off."));
    set_label(touch_, tr("Touch"), tr("At constant speed, or while the axis is braking."));
    touch_->setItemText(0, tr("At constant speed"));
    touch_->setItemText(1, tr("While braking"));
    set_label(speed_fraction_, tr("Speed at the trigger"),
              tr("While braking: the speed at the trigger, in % of the feed."));
    lag_from_fit_->setText(tr("Take period and lag from the fit"));
    note_->setText(
        tr("Machine dynamics from the scenario. While braking, v·τ assumes the feed through "
           "the whole delay and over-corrects; the real increments of the last cycles stay "
           "within one cycle's travel."));
    comparison_plot_->set_title(tr("Error of the corrected position while braking"));
    comparison_plot_->set_x_axis({PlotView::Scale::linear,
                                  tr("Speed at the trigger [% of the feed]"),
                                  QStringLiteral("%g"),
                                  {}});
    comparison_plot_->set_y_axis(
        PlotView::Side::left,
        {PlotView::Scale::linear, tr("Error [%1]").arg(unit_um()), QStringLiteral("%g"), {}});
    for (std::size_t m = 0; m < kCompensationMethodCount; ++m) {
        comparison_plot_->set_name(method_curves_[m],
                                   method_legend(static_cast<CompensationMethod>(m)));
        methods_table_->item(static_cast<int>(m), 0)
            ->setText(method_label(static_cast<CompensationMethod>(m)));
    }
    methods_table_->setHorizontalHeaderLabels(
        {tr("Method"), tr("Position [%1]").arg(unit_mm()), tr("Error [%1]").arg(unit_um())});
    for (UnitSpinBox* box : {feed_, ipo_period_, speed_fraction_}) box->retranslate();
    show_comparison();
}

void CompensationPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QGroupBox::changeEvent(event);
}

void CompensationPanel::set_scenario(const probecycle::Scenario& scenario) {
    scenario_ = scenario;
    schedule_comparison();
}

void CompensationPanel::set_lag_from_fit_available(bool available) {
    lag_from_fit_->setEnabled(available);
}

void CompensationPanel::set_inputs(const Inputs& wanted) {
    feed_->set_internal_value(wanted.feed_mm_min);
    ipo_period_->set_internal_value(wanted.interpolation_period_s);
    lag_cycles_->setValue(wanted.lag_cycles);
    compensated_lag_->setValue(wanted.compensated_lag_cycles);
    touch_->setCurrentIndex(touch_->findData(static_cast<int>(wanted.touch)));
    speed_fraction_->set_internal_value(wanted.speed_fraction);
    update_comparison_now();
}

CompensationPanel::Inputs CompensationPanel::inputs() const {
    Inputs out;
    out.feed_mm_min = feed_->internal_value();
    out.interpolation_period_s = ipo_period_->internal_value();
    out.lag_cycles = lag_cycles_->value();
    out.compensated_lag_cycles = compensated_lag_->value();
    out.touch = static_cast<TouchMotion>(touch_->currentData().toInt());
    out.speed_fraction = speed_fraction_->internal_value();
    return out;
}

void CompensationPanel::schedule_comparison() {
    // The window hands every scenario edit over; a hidden tab (the user is
    // dragging sliders on the Cycle tab) defers the simulation to its showing.
    if (!isVisible()) {
        comparison_stale_ = true;
        return;
    }
    if (!comparison_timer_.isActive()) comparison_timer_.start();
}

void CompensationPanel::showEvent(QShowEvent* event) {
    QGroupBox::showEvent(event);
    if (comparison_stale_) {
        comparison_stale_ = false;
        schedule_comparison();
    }
}

void CompensationPanel::update_comparison_now() {
    comparison_timer_.stop();
    comparison_stale_ = false;
    const Inputs current = inputs();
    CompensationSetup setup;
    // The machine's dynamics; the defaults while the scenario is invalid
    // (its editors may hold a half-typed value).
    const Scenario machine = scenario_ && validate(*scenario_).empty() ? *scenario_ : Scenario{};
    setup.limits = machine.motion_limits();
    setup.feed_mm_min = current.feed_mm_min;
    setup.interpolation_period_s = current.interpolation_period_s;
    setup.lag_cycles = current.lag_cycles;
    if (current.compensated_lag_cycles >= 0) {
        setup.compensated_lag_cycles = current.compensated_lag_cycles;
    }
    setup.touch = current.touch;
    setup.braking_speed_fraction = current.speed_fraction;

    comparison_error_.clear();
    if (const auto errors = validate(setup); !errors.empty()) {
        QStringList messages;
        for (const FieldError& e : errors) {
            // The field by this panel's name for it, not the CLI's option.
            FieldError named = e;
            named.key = field_label(e.key).toStdString();
            messages << translate(named.to_message());
        }
        comparison_error_ = messages.join(QLatin1Char('\n'));
        comparison_.reset();
        sweep_.clear();
        lag_sweep_.clear();
    } else {
        lag_sweep_ = sweep_compensated_lag(setup);
        comparison_ = simulate_compensation(setup);
        std::vector<double> fractions;
        fractions.reserve(kSweepPoints);
        for (int k = kSweepPoints; k >= 1; --k) {
            fractions.push_back(static_cast<double>(k) / kSweepPoints);
        }
        sweep_ = sweep_braking(setup, fractions);
    }
    show_comparison();
}

void CompensationPanel::show_comparison() {
    show_error(error_label_, comparison_error_);
    double lo = 0.0;
    double hi = 0.0;
    for (std::size_t m = 0; m < kCompensationMethodCount; ++m) {
        QList<QPointF> curve;
        curve.reserve(static_cast<qsizetype>(sweep_.size()));
        for (const BrakingRow& row : sweep_) {
            const double error_um = row.error_mm[m] * kMmToUm;
            curve.append({row.speed_fraction * 100.0, error_um});
            lo = std::min(lo, error_um);
            hi = std::max(hi, error_um);
        }
        comparison_plot_->set_points(method_curves_[m], curve);
    }
    const double pad = std::max(hi - lo, 1.0) * 0.06;
    comparison_plot_->set_y_range(PlotView::Side::left, lo - pad, hi + pad);
    comparison_plot_->set_x_range(0.0, 100.0);
    const Inputs current = inputs();
    const bool braking = current.touch == TouchMotion::braking && comparison_;
    comparison_plot_->set_points(current_fraction_curve_,
                                 braking
                                     ? QList<QPointF>{{current.speed_fraction * 100.0, lo - pad},
                                                      {current.speed_fraction * 100.0, hi + pad}}
                                     : QList<QPointF>{});
    comparison_plot_->set_visible(current_fraction_curve_, braking);

    show_lag_sweep();

    for (std::size_t m = 0; m < kCompensationMethodCount; ++m) {
        const int row = static_cast<int>(m);
        if (comparison_) {
            const MethodResult& r = comparison_->methods[m];
            methods_table_->item(row, 1)->setText(format_number(r.position_mm, 4));
            methods_table_->item(row, 2)->setText(lab_signed_um(r.error_mm));
        } else {
            methods_table_->item(row, 1)->setText(QStringLiteral("—"));
            methods_table_->item(row, 2)->setText(QStringLiteral("—"));
        }
    }
    if (comparison_) {
        const CompensationComparison& c = *comparison_;
        //: %1 speed at the trigger, %2 lag in cycles, %3 speed then, %4 the delay v·τ uses
        QString text = tr("Trigger at %1 mm/s, recorded %2 cycles later at %3 mm/s; v·τ "
                          "uses τ = %4.")
                           .arg(format_number(c.trigger_speed_mm_s, 1))
                           .arg(current.lag_cycles)
                           .arg(format_number(c.recorded_speed_mm_s, 1), lab_ms(c.naive_delay_s));
        if (c.counter_wraps > 0) {
            text += QLatin1Char(' ') + tr("Counter roll-overs: %1.").arg(c.counter_wraps);
        }
        trigger_summary_->setText(text);
    } else {
        trigger_summary_->clear();
    }
    methods_table_->resizeColumnsToContents();
    methods_table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
}

void CompensationPanel::show_lag_sweep() {
    QList<QPointF> curve;
    curve.reserve(static_cast<qsizetype>(lag_sweep_.size()));
    double lo = 0.0;
    double hi = 0.0;
    for (const LagRow& row : lag_sweep_) {
        const double error_um = row.error_mm * kMmToUm;
        curve.append({static_cast<double>(row.compensated_lag_cycles), error_um});
        lo = std::min(lo, error_um);
        hi = std::max(hi, error_um);
    }
    lag_plot_->set_points(lag_error_curve_, curve);
    const double pad = std::max(hi - lo, 1.0) * 0.06;
    lag_plot_->set_y_range(PlotView::Side::left, lo - pad, hi + pad);
    const Inputs current = inputs();
    const double used =
        current.compensated_lag_cycles >= 0 ? current.compensated_lag_cycles : current.lag_cycles;
    const auto vertical = [&](double x) {
        return curve.isEmpty() ? QList<QPointF>{} : QList<QPointF>{{x, lo - pad}, {x, hi + pad}};
    };
    lag_plot_->set_points(true_lag_marker_curve_, vertical(current.lag_cycles));
    lag_plot_->set_points(lag_marker_curve_, vertical(used));
}

QList<QPointF> CompensationPanel::lag_curve() const {
    return lag_plot_->points(lag_error_curve_);
}

QList<QPointF> CompensationPanel::comparison_curve(CompensationMethod method) const {
    return comparison_plot_->points(method_curves_[static_cast<std::size_t>(method)]);
}

}  // namespace probecycle::ui
