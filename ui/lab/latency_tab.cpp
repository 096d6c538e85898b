#include "ui/lab/latency_tab.h"

#include <QComboBox>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QShowEvent>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ui/common/parameter_info.h"
#include "ui/common/plot_view.h"
#include "ui/common/text_format.h"
#include "ui/lab/lab_widgets.h"

namespace probecycle::ui {

namespace {

// One colour per (axis, direction) group, in the order of the file.
const QColor kGroupColours[] = {{0x1f, 0x77, 0xb4}, {0xd6, 0x27, 0x28}, {0x2c, 0xa0, 0x2c},
                                {0x94, 0x67, 0xbd}, {0xe6, 0x7e, 0x22}, {0x17, 0xbe, 0xcf}};

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

enum TreeColumn { col_name, col_delay, col_lag, col_position, col_stability, col_n, col_count };

QString method_label(CompensationMethod method) {
    switch (method) {
        case CompensationMethod::uncompensated:
            return LatencyTab::tr("Uncompensated");
        case CompensationMethod::naive_v_tau:
            return LatencyTab::tr("Naive v·τ");
        case CompensationMethod::cycle_lag:
            return LatencyTab::tr("Cycle lag (real increments)");
        case CompensationMethod::timestamp:
            return LatencyTab::tr("Timestamp interpolation");
    }
    return {};
}

// The legend's short names; the table says it in full.
QString method_legend(CompensationMethod method) {
    switch (method) {
        case CompensationMethod::uncompensated:
            return LatencyTab::tr("Uncompensated");
        case CompensationMethod::naive_v_tau:
            return LatencyTab::tr("Naive v·τ");
        case CompensationMethod::cycle_lag:
            return LatencyTab::tr("Real increments");
        case CompensationMethod::timestamp:
            return LatencyTab::tr("Timestamp");
    }
    return {};
}

QString number(double value, int decimals) {
    return QLocale().toString(value, 'f', decimals);
}

// A setup field as the window names it: validate() names the fields by the
// CLI's options ("feed-mm-min"), which mean nothing here.
QString setup_field_label(const std::string& key) {
    if (key == "feed-mm-min") return LatencyTab::tr("Feed");
    if (key == "interpolation-period-s") return LatencyTab::tr("Interpolation period");
    if (key == "lag-cycles") return LatencyTab::tr("Lag");
    if (key == "speed-fraction") return LatencyTab::tr("Speed at the trigger");
    if (key == "direction") return LatencyTab::tr("Direction of travel");
    if (key == "trigger-phase") return LatencyTab::tr("Trigger phase in its cycle");
    if (key == "counts-per-mm") return LatencyTab::tr("Encoder counts per mm");
    if (key == "counter-bits") return LatencyTab::tr("Encoder counter width");
    if (key == "naive-delay-s") return LatencyTab::tr("Delay for v·τ");
    return QString::fromStdString(key);
}

// A setup error with the window's name of its field.
QString setup_error_text(FieldError error) {
    error.key = setup_field_label(error.key).toStdString();
    return translate(error.to_message());
}

}  // namespace

LatencyTab::LatencyTab(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("lab-latency"));
    comparison_timer_.setSingleShot(true);
    comparison_timer_.setInterval(0);
    connect(&comparison_timer_, &QTimer::timeout, this, &LatencyTab::update_comparison_now);

    build_delay_section();
    build_compensation_section();
    splitter_ = new QSplitter(Qt::Vertical, this);
    splitter_->setChildrenCollapsible(false);
    splitter_->addWidget(delay_group_);
    splitter_->addWidget(compensation_group_);
    // Its inputs, table and notes need this much; the touches and the tree above can scroll.
    compensation_group_->setMinimumHeight(270);
    delay_group_->setMinimumHeight(300);
    splitter_->setStretchFactor(0, 6);
    splitter_->setStretchFactor(1, 5);
    auto* root = new QVBoxLayout(this);
    root->addWidget(splitter_);

    retranslate();
    update_comparison_now();
}

LatencyTab::~LatencyTab() = default;

void LatencyTab::build_delay_section() {
    delay_group_ = new QGroupBox(this);

    // Input column
    format_hint_ = new QLabel(delay_group_);
    format_hint_->setWordWrap(true);
    touches_edit_ = make_csv_editor(delay_group_);
    touches_edit_->setObjectName(QStringLiteral("delay-touches"));
    period_ = new UnitSpinBox(0.0, 0.1, 3, 0.0, delay_group_, 1000.0);
    period_->setObjectName(QStringLiteral("fit-interpolation-period"));
    period_->set_unit(unit_ms);
    period_label_ = new QLabel(delay_group_);
    period_label_->setBuddy(period_);
    import_button_ = new QPushButton(delay_group_);
    fit_button_ = new QPushButton(delay_group_);
    error_label_ = new QLabel(delay_group_);
    error_label_->setObjectName(QStringLiteral("delay-error"));
    error_label_->setWordWrap(true);
    error_label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    error_label_->hide();
    auto* period_row = new QHBoxLayout;
    period_row->addWidget(period_label_);
    period_row->addWidget(period_, 1);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(import_button_);
    buttons->addStretch(1);
    buttons->addWidget(fit_button_);
    auto* input = new QWidget(delay_group_);
    auto* input_column = new QVBoxLayout(input);
    input_column->setContentsMargins(0, 0, 0, 0);
    input_column->addWidget(format_hint_);
    input_column->addWidget(touches_edit_, 1);
    input_column->addLayout(period_row);
    input_column->addLayout(buttons);
    input_column->addWidget(error_label_);
    input->setFixedWidth(320);

    // Chart
    delay_plot_ = new PlotView(delay_group_);
    delay_plot_->setObjectName(QStringLiteral("delay-plot"));
    delay_plot_->set_x_axis({PlotView::Scale::linear, {}, QStringLiteral("%g"), {}});
    delay_plot_->set_y_axis(PlotView::Side::left,
                            {PlotView::Scale::linear, {}, QStringLiteral("%g"), {}});
    delay_plot_->set_x_range(0.0, 1000.0);
    delay_plot_->set_y_range(PlotView::Side::left, 0.0, 100.0);

    // Results column
    tree_ = new QTreeWidget(delay_group_);
    tree_->setObjectName(QStringLiteral("delay-groups"));
    tree_->setColumnCount(col_count);
    tree_->setRootIsDecorated(true);
    tree_->setUniformRowHeights(true);
    tree_->setAlternatingRowColors(true);
    tree_->header()->setStretchLastSection(false);
    tree_->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    warnings_title_ = new QLabel(delay_group_);
    QFont bold = warnings_title_->font();
    bold.setBold(true);
    warnings_title_->setFont(bold);
    warnings_ = new LabWarningList;
    warnings_->setObjectName(QStringLiteral("delay-warnings"));
    auto* warnings_scroll = new QScrollArea(delay_group_);
    warnings_scroll->setWidget(warnings_);
    warnings_scroll->setWidgetResizable(true);
    warnings_scroll->setFrameShape(QFrame::NoFrame);
    warnings_scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto* results = new QWidget(delay_group_);
    auto* results_column = new QVBoxLayout(results);
    results_column->setContentsMargins(0, 0, 0, 0);
    results_column->addWidget(tree_, 3);
    results_column->addWidget(warnings_title_);
    results_column->addWidget(warnings_scroll, 2);
    results->setFixedWidth(450);

    // Apply row
    apply_label_ = new QLabel(delay_group_);
    apply_group_ = new QComboBox(delay_group_);
    apply_group_->setObjectName(QStringLiteral("apply-group"));
    apply_group_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    apply_label_->setBuddy(apply_group_);
    apply_breakdown_ = new QLabel(delay_group_);
    apply_breakdown_->setObjectName(QStringLiteral("apply-breakdown"));
    apply_breakdown_->setWordWrap(true);
    apply_breakdown_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    apply_button_ = new QPushButton(delay_group_);
    apply_button_->setObjectName(QStringLiteral("apply-to-scenario"));
    apply_button_->setEnabled(false);
    auto* apply_row = new QHBoxLayout;
    apply_row->addWidget(apply_label_);
    apply_row->addWidget(apply_group_);
    apply_row->addSpacing(8);
    apply_row->addWidget(apply_breakdown_, 1);
    apply_row->addWidget(apply_button_);

    auto* top = new QHBoxLayout;
    top->addWidget(input);
    top->addWidget(delay_plot_, 1);
    top->addWidget(results);
    auto* column = new QVBoxLayout(delay_group_);
    column->addLayout(top, 1);
    column->addLayout(apply_row);

    connect(fit_button_, &QPushButton::clicked, this, [this] { fit(); });
    connect(import_button_, &QPushButton::clicked, this, &LatencyTab::import_dialog);
    connect(period_, &QDoubleSpinBox::valueChanged, this, &LatencyTab::apply_period);
    connect(apply_group_, &QComboBox::currentIndexChanged, this, [this] { update_apply(); });
    connect(apply_button_, &QPushButton::clicked, this, [this] { apply_to_scenario(); });
}

void LatencyTab::build_compensation_section() {
    compensation_group_ = new QGroupBox(this);
    const CompensationInputs defaults;
    feed_ = new UnitSpinBox(1.0, 100000.0, 0, defaults.feed_mm_min, compensation_group_);
    feed_->setObjectName(QStringLiteral("compensation-feed"));
    feed_->set_unit(unit_mm_min);
    ipo_period_ =
        new UnitSpinBox(1e-5, 0.1, 3, defaults.interpolation_period_s, compensation_group_, 1000.0);
    ipo_period_->setObjectName(QStringLiteral("compensation-period"));
    ipo_period_->set_unit(unit_ms);
    lag_cycles_ = new QSpinBox(compensation_group_);
    lag_cycles_->setObjectName(QStringLiteral("compensation-lag"));
    lag_cycles_->setRange(0, static_cast<int>(IncrementRing::kCapacity) - 1);
    lag_cycles_->setValue(defaults.lag_cycles);
    lag_cycles_->setKeyboardTracking(false);
    lag_cycles_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    touch_ = new QComboBox(compensation_group_);
    touch_->setObjectName(QStringLiteral("compensation-touch"));
    touch_->addItem(QString(), static_cast<int>(TouchMotion::constant_speed));
    touch_->addItem(QString(), static_cast<int>(TouchMotion::braking));
    touch_->setCurrentIndex(defaults.touch == TouchMotion::braking ? 1 : 0);
    speed_fraction_ =
        new UnitSpinBox(0.001, 1.0, 1, defaults.speed_fraction, compensation_group_, 100.0);
    speed_fraction_->setObjectName(QStringLiteral("compensation-speed-fraction"));
    speed_fraction_->set_unit([] { return QStringLiteral("%"); });
    lag_from_fit_ = new QPushButton(compensation_group_);
    lag_from_fit_->setObjectName(QStringLiteral("lag-from-fit"));
    lag_from_fit_->setEnabled(false);
    compensation_form_ = new QFormLayout;
    compensation_form_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    // QFormLayout makes no label for an empty text; retranslate() fills these.
    for (QWidget* field : {static_cast<QWidget*>(feed_), static_cast<QWidget*>(ipo_period_),
                           static_cast<QWidget*>(lag_cycles_), static_cast<QWidget*>(touch_),
                           static_cast<QWidget*>(speed_fraction_)}) {
        auto* label = new QLabel(compensation_group_);
        label->setBuddy(field);
        compensation_form_->addRow(label, field);
    }
    compensation_note_ = new QLabel(compensation_group_);
    compensation_note_->setWordWrap(true);
    compensation_note_->setStyleSheet(QStringLiteral("color: #555555;"));
    compensation_error_ = new QLabel(compensation_group_);
    compensation_error_->setWordWrap(true);
    compensation_error_->hide();
    auto* input = new QWidget(compensation_group_);
    auto* input_column = new QVBoxLayout(input);
    input_column->setContentsMargins(0, 0, 0, 0);
    input_column->addLayout(compensation_form_);
    input_column->addWidget(lag_from_fit_, 0, Qt::AlignRight);
    input_column->addWidget(compensation_error_);
    input_column->addStretch(1);
    input->setFixedWidth(320);

    comparison_plot_ = new PlotView(compensation_group_);
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

    methods_table_ =
        new QTableWidget(static_cast<int>(kCompensationMethodCount), 3, compensation_group_);
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
    trigger_summary_ = new QLabel(compensation_group_);
    trigger_summary_->setObjectName(QStringLiteral("compensation-summary"));
    trigger_summary_->setWordWrap(true);
    trigger_summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* table = new QWidget(compensation_group_);
    auto* table_column = new QVBoxLayout(table);
    table_column->setContentsMargins(0, 0, 0, 0);
    table_column->addWidget(methods_table_);
    table_column->addWidget(trigger_summary_);
    table_column->addWidget(compensation_note_);
    table_column->addStretch(1);
    table->setFixedWidth(380);

    auto* row = new QHBoxLayout(compensation_group_);
    row->addWidget(input);
    row->addWidget(comparison_plot_, 1);
    row->addWidget(table);

    for (UnitSpinBox* box : {feed_, ipo_period_, speed_fraction_}) {
        connect(box, &QDoubleSpinBox::valueChanged, this, &LatencyTab::schedule_comparison);
    }
    connect(lag_cycles_, &QSpinBox::valueChanged, this, &LatencyTab::schedule_comparison);
    connect(touch_, &QComboBox::currentIndexChanged, this, [this] {
        speed_fraction_->setEnabled(compensation_inputs().touch == TouchMotion::braking);
        schedule_comparison();
    });
    connect(lag_from_fit_, &QPushButton::clicked, this, &LatencyTab::take_lag_from_fit);
}

void LatencyTab::retranslate() {
    delay_group_->setTitle(tr("Delay from touches at several feeds (delay-stability test)"));
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
    import_button_->setText(tr("Import CSV…"));
    fit_button_->setText(tr("Fit"));
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
    apply_label_->setText(tr("Delay to apply:"));
    apply_button_->setText(tr("Apply to scenario"));
    apply_button_->setToolTip(
        tr("Sets machine.controller_latency_s to the fitted delay less the probe's interface "
           "delay and half the scan period (none with a latched input)."));

    compensation_group_->setTitle(tr("Compensation of the trigger position"));
    const auto set_label = [this](QWidget* field, const QString& text, const QString& tip) {
        if (auto* label = qobject_cast<QLabel*>(compensation_form_->labelForField(field))) {
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
    set_label(touch_, tr("Touch"), tr("At constant speed, or while the axis is braking."));
    touch_->setItemText(0, tr("At constant speed"));
    touch_->setItemText(1, tr("While braking"));
    set_label(speed_fraction_, tr("Speed at the trigger"),
              tr("While braking: the speed at the trigger, in % of the feed."));
    lag_from_fit_->setText(tr("Take period and lag from the fit"));
    compensation_note_->setText(
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

    for (UnitSpinBox* box : {period_, feed_, ipo_period_, speed_fraction_}) box->retranslate();
    show_fit();
    show_comparison();
}

void LatencyTab::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void LatencyTab::set_scenario(const probecycle::Scenario& scenario) {
    scenario_ = scenario;
    update_apply();
    schedule_comparison();
}

// --- Delay from touches ---

void LatencyTab::set_touches_text(const QString& csv) {
    touches_edit_->setPlainText(csv);
}

QString LatencyTab::touches_text() const {
    return touches_edit_->toPlainText();
}

void LatencyTab::set_interpolation_period_s(double period_s) {
    {
        const QSignalBlocker block(period_);
        period_->set_internal_value(period_s);
    }
    apply_period();
}

void LatencyTab::apply_period() {
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
    } catch (const std::exception& e) {
        set_error(lab_error_text(e));
        return;
    }
    show_fit();
}

bool LatencyTab::fit() {
    return fit_text(touches_edit_->toPlainText(), QString());
}

bool LatencyTab::import_file(const QString& path) {
    QString error;
    const std::optional<QString> text = import_csv_into(touches_edit_, path, error);
    if (!text) {
        set_error(error);
        return false;
    }
    last_dir_ = QFileInfo(path).absolutePath();
    return fit_text(*text, QFileInfo(path).fileName());
}

bool LatencyTab::fit_text(const QString& text, const QString& source) {
    DelayFitOptions options = fit_options_;
    const double period_s = period_->internal_value();
    options.interpolation_period_s =
        period_s > 0.0 ? std::optional<double>(period_s) : std::nullopt;
    std::vector<DelayTouch> touches;
    DelayFit fit;
    try {
        touches = parse_delay_csv(text.toStdString());
        fit = fit_delay(touches, options);
    } catch (const std::exception& e) {
        const QString message = lab_error_text(e);
        set_error(source.isEmpty() ? message : tr("%1: %2").arg(source, message));
        return false;
    }
    touches_ = std::move(touches);
    fit_options_ = options;
    fit_ = std::move(fit);
    set_error({});
    show_fit();
    return true;
}

void LatencyTab::set_error(const QString& text) {
    last_error_ = text;
    QString shown = text;
    if (!text.isEmpty() && fit_) {
        shown += QLatin1Char('\n') + tr("The result shown is still that of the previous fit.");
    }
    show_error(error_label_, shown);
}

void LatencyTab::show_fit() {
    tree_->clear();
    std::vector<LabWarningList::Item> items;
    if (fit_) {
        for (const DelayGroup& g : fit_->groups) {
            const QString name = QString::fromStdString(g.name());
            auto* top = new QTreeWidgetItem(tree_);
            top->setText(col_name, name);
            top->setText(col_delay, lab_ms(g.delay_s));
            top->setText(col_lag, g.lag_cycles ? number(*g.lag_cycles, 2) : QStringLiteral("—"));
            top->setText(col_position, lab_mm(g.zero_speed_position_mm));
            top->setText(col_stability,
                         g.residual_2sigma_mm
                             ? lab_signed_um(*g.residual_2sigma_mm).remove(QLatin1Char('+'))
                             : QStringLiteral("—"));
            std::size_t n = 0;
            for (const FeedScatter& f : g.feeds) n += f.n;
            top->setText(col_n, QString::number(n));
            QFont bold = top->font(col_name);
            bold.setBold(true);
            for (int c = 0; c < col_count; ++c) top->setFont(c, bold);
            for (const FeedScatter& f : g.feeds) {
                auto* child = new QTreeWidgetItem(top);
                child->setText(col_name, format_feed(f.feed_mm_min));
                child->setText(col_position, lab_signed_um(f.mean_mm - g.zero_speed_position_mm));
                child->setText(col_stability, lab_signed_um(f.range_mm).remove(QLatin1Char('+')));
                child->setText(col_n, QString::number(f.n));
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
    warnings_->show_items(items);

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

void LatencyTab::draw_fit() {
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

QStringList LatencyTab::warning_codes() const {
    return warnings_->codes();
}

QStringList LatencyTab::results_text() const {
    QStringList out;
    for (int i = 0; i < tree_->topLevelItemCount(); ++i) {
        const QTreeWidgetItem* item = tree_->topLevelItem(i);
        QStringList cells;
        for (int c = 0; c < col_count; ++c) cells << item->text(c);
        out << cells.join(QStringLiteral(" | "));
    }
    return out;
}

QList<QPointF> LatencyTab::plotted_touches(int group) const {
    if (group < 0 || static_cast<std::size_t>(group) >= group_curves_.size()) return {};
    return delay_plot_->points(group_curves_[static_cast<std::size_t>(group)].touches);
}

QList<QPointF> LatencyTab::plotted_line(int group) const {
    if (group < 0 || static_cast<std::size_t>(group) >= group_curves_.size()) return {};
    return delay_plot_->points(group_curves_[static_cast<std::size_t>(group)].line);
}

void LatencyTab::import_dialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Import touches"), last_dir_,
                                                      tr("CSV files (*.csv);;All files (*)"));
    if (!path.isEmpty()) import_file(path);
}

// --- Apply ---

void LatencyTab::set_applied_group(const QString& name) {
    const int index = name.isEmpty() ? 0 : apply_group_->findData(name.toUpper());
    if (index >= 0) apply_group_->setCurrentIndex(index);
}

std::optional<std::string> LatencyTab::chosen_group() const {
    const QString name = apply_group_->currentData().toString();
    if (name.isEmpty()) return std::nullopt;
    return name.toStdString();
}

LatencyTab::ApplyState LatencyTab::evaluate_apply() const {
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
        AppliedDelay applied = controller_latency_from_fit(*fit_, *scenario_, chosen_group());
        // The result must be a valid scenario (the key's range).
        apply_delay(*scenario_, applied);
        state.applied = std::move(applied);
    } catch (const std::exception& e) {
        // LabError from the rule, ScenarioError from the key's range.
        state.problem = lab_error_text(e);
    }
    return state;
}

std::optional<AppliedDelay> LatencyTab::pending_application() const {
    return evaluate_apply().applied;
}

QString LatencyTab::apply_problem() const {
    return evaluate_apply().problem;
}

void LatencyTab::update_apply() {
    const ApplyState state = evaluate_apply();
    if (state.applied) {
        const AppliedDelay& a = *state.applied;
        const QString half_scan =
            scenario_->machine.latched_input ? tr("0 (latched input)") : lab_ms(a.half_scan_s);
        //: %1 group, %2 its delay, %3 interface delay, %4 half scan period, %5 result, %6 now
        apply_breakdown_->setText(
            tr("Controller latency = %1 delay %2 − interface %3 − half scan %4 = <b>%5</b> "
               "(now %6)")
                .arg(QString::fromStdString(a.group), lab_ms(a.total_delay_s),
                     lab_ms(a.interface_delay_s), half_scan, lab_ms(a.controller_latency_s),
                     lab_ms(a.previous_s)));
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
    lag_from_fit_->setEnabled(fit_ && fit_options_.interpolation_period_s && !fit_->groups.empty());
}

bool LatencyTab::apply_to_scenario() {
    const ApplyState state = evaluate_apply();
    if (!state.applied) {
        last_error_ = state.problem;
        return false;
    }
    last_error_.clear();
    emit controller_latency_applied(state.applied->controller_latency_s);
    return true;
}

void LatencyTab::take_lag_from_fit() {
    if (!fit_ || fit_->groups.empty() || !fit_options_.interpolation_period_s) return;
    // The group "Apply" uses (core choose_group), and the lag rule the
    // simulator assumes (core lag_cycles_for_delay).
    const DelayGroup* chosen = nullptr;
    try {
        chosen = choose_group(*fit_, chosen_group()).group;
    } catch (const std::invalid_argument&) {
        return;  // a name no longer in the fit: nothing to take
    }
    const double period_s = *fit_options_.interpolation_period_s;
    CompensationInputs inputs = compensation_inputs();
    inputs.interpolation_period_s = period_s;
    inputs.lag_cycles = lag_cycles_for_delay(chosen->delay_s, period_s);
    set_compensation_inputs(inputs);
}

// --- Compensation comparison ---

void LatencyTab::set_compensation_inputs(const CompensationInputs& inputs) {
    feed_->set_internal_value(inputs.feed_mm_min);
    ipo_period_->set_internal_value(inputs.interpolation_period_s);
    lag_cycles_->setValue(inputs.lag_cycles);
    touch_->setCurrentIndex(touch_->findData(static_cast<int>(inputs.touch)));
    speed_fraction_->set_internal_value(inputs.speed_fraction);
    update_comparison_now();
}

LatencyTab::CompensationInputs LatencyTab::compensation_inputs() const {
    CompensationInputs inputs;
    inputs.feed_mm_min = feed_->internal_value();
    inputs.interpolation_period_s = ipo_period_->internal_value();
    inputs.lag_cycles = lag_cycles_->value();
    inputs.touch = static_cast<TouchMotion>(touch_->currentData().toInt());
    inputs.speed_fraction = speed_fraction_->internal_value();
    return inputs;
}

void LatencyTab::schedule_comparison() {
    // The window hands every scenario edit over; a hidden tab (the user is
    // dragging sliders on the Cycle tab) defers the simulation to its showing.
    if (!isVisible()) {
        comparison_stale_ = true;
        return;
    }
    if (!comparison_timer_.isActive()) comparison_timer_.start();
}

void LatencyTab::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (comparison_stale_) {
        comparison_stale_ = false;
        schedule_comparison();
    }
}

void LatencyTab::update_comparison_now() {
    comparison_timer_.stop();
    comparison_stale_ = false;
    const CompensationInputs inputs = compensation_inputs();
    CompensationSetup setup;
    // The machine's dynamics; the defaults while the scenario is invalid
    // (its editors may hold a half-typed value).
    const Scenario machine = scenario_ && validate(*scenario_).empty() ? *scenario_ : Scenario{};
    setup.limits = machine.motion_limits();
    setup.feed_mm_min = inputs.feed_mm_min;
    setup.interpolation_period_s = inputs.interpolation_period_s;
    setup.lag_cycles = inputs.lag_cycles;
    setup.touch = inputs.touch;
    setup.braking_speed_fraction = inputs.speed_fraction;

    comparison_error_.clear();
    if (const auto errors = validate(setup); !errors.empty()) {
        QStringList messages;
        for (const FieldError& e : errors) messages << setup_error_text(e);
        comparison_error_ = messages.join(QLatin1Char('\n'));
        comparison_.reset();
        sweep_.clear();
    } else {
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

void LatencyTab::show_comparison() {
    show_error(compensation_error_, comparison_error_);
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
    const CompensationInputs inputs = compensation_inputs();
    const bool braking = inputs.touch == TouchMotion::braking && comparison_;
    comparison_plot_->set_points(current_fraction_curve_,
                                 braking ? QList<QPointF>{{inputs.speed_fraction * 100.0, lo - pad},
                                                          {inputs.speed_fraction * 100.0, hi + pad}}
                                         : QList<QPointF>{});
    comparison_plot_->set_visible(current_fraction_curve_, braking);

    for (std::size_t m = 0; m < kCompensationMethodCount; ++m) {
        const int row = static_cast<int>(m);
        if (comparison_) {
            const MethodResult& r = comparison_->methods[m];
            methods_table_->item(row, 1)->setText(number(r.position_mm, 4));
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
                           .arg(number(c.trigger_speed_mm_s, 1))
                           .arg(inputs.lag_cycles)
                           .arg(number(c.recorded_speed_mm_s, 1), lab_ms(c.naive_delay_s));
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

QList<QPointF> LatencyTab::comparison_curve(CompensationMethod method) const {
    return comparison_plot_->points(method_curves_[static_cast<std::size_t>(method)]);
}

}  // namespace probecycle::ui
