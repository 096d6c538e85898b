#include "ui/lab/calibration_tab.h"

#include <QComboBox>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/common/file_io.h"
#include "core/cycle/cycle_report.h"
#include "core/lab/calibration_report.h"
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

const QColor kColour0{0x1f, 0x77, 0xb4};    // orientation 0 deg
const QColor kColour180{0xe6, 0x7e, 0x22};  // orientation 180 deg
const QColor kGaugeColour{0x33, 0x33, 0x33};

constexpr int kCirclePoints = 181;
// Choices of the magnification box (0 = automatic): the project file's.
constexpr const auto& kMagnifications = kRingMagnifications;

enum ResultRow {
    row_centre,
    row_runout,
    row_radius,
    row_by_direction,
    row_residual,
    row_circle_0,
    row_circle_180,
    row_points,
    row_count
};

std::size_t orientation_of(const RingPoint& p) {
    return std::abs(p.orientation_deg) < 90.0 ? 0 : 1;
}

// Radial deviations about `centre` from a circle of radius `reference`, scaled
// by `k`: a point on the reference circle stays put, one 1 µm outside moves k µm.
QPointF magnified(double x, double y, double cx, double cy, double reference, double k) {
    const double dx = x - cx;
    const double dy = y - cy;
    const double distance = std::hypot(dx, dy);
    if (distance == 0.0 || k == 1.0) return {x, y};
    const double shown = std::max(reference + k * (distance - reference), 0.0);
    return {cx + dx / distance * shown, cy + dy / distance * shown};
}

std::optional<double> parse_number(const QString& text) {
    bool ok = false;
    double value = QLocale().toDouble(text, &ok);
    if (!ok) value = QLocale::c().toDouble(text, &ok);
    if (!ok || !std::isfinite(value)) return std::nullopt;
    return value;
}

}  // namespace

CalibrationTab::CalibrationTab(QWidget* parent) : Page(parent) {
    setObjectName(QStringLiteral("lab-calibration"));
    auto* input_column = new QVBoxLayout;
    input_column->setContentsMargins(0, 0, 0, 0);
    input_column->addWidget(build_ring_group(), 1);
    input_column->addWidget(build_length_group());
    auto* input_widget = new QWidget(this);
    input_widget->setLayout(input_column);
    input_widget->setFixedWidth(350);

    auto* root = new QHBoxLayout(this);
    root->addWidget(input_widget);
    root->addLayout(build_plot_column(), 1);
    root->addWidget(build_result_group());
    connect_inputs();
    retranslate();  // also shows the (empty) result and the length
    watch_inputs();
}

// The paste box of ring-gauge touches, the gauge and the warning limits.
QGroupBox* CalibrationTab::build_ring_group() {
    ring_group_ = new QGroupBox(this);
    format_hint_ = new QLabel(ring_group_);
    format_hint_->setWordWrap(true);
    input_ = new FitInput(ProgramKind::ring,
                          {"ring-points", "ring-program", "ring-import-log", "ring-error"}, this,
                          last_error_, [this] { return result_.has_value(); });
    input_->set_fit_text(
        [this](const QString& text, const QString& source) { return fit_text(text, source); });
    input_->set_example_text([this] {
        return QString::fromStdString(example_ring_csv(scenario_, diameter_->internal_value()));
    });
    points_edit_ = input_->make_editor(ring_group_);
    diameter_ = new UnitSpinBox(0.1, 2000.0, 4, 50.0, ring_group_);
    diameter_->setObjectName(QStringLiteral("gauge-diameter"));
    diameter_->set_unit(unit_mm);
    // Limits are shown in µm: they are a few micrometres.
    runout_limit_ = new UnitSpinBox(0.0, 10.0, 1, RingCalibrationOptions{}.runout_limit_mm,
                                    ring_group_, 1000.0);
    runout_limit_->set_unit(unit_um);
    residual_limit_ = new UnitSpinBox(0.0, 10.0, 1, RingCalibrationOptions{}.residual_limit_mm,
                                      ring_group_, 1000.0);
    residual_limit_->set_unit(unit_um);
    diameter_label_ = new QLabel(ring_group_);
    diameter_label_->setBuddy(diameter_);
    runout_limit_label_ = new QLabel(ring_group_);
    runout_limit_label_->setBuddy(runout_limit_);
    residual_limit_label_ = new QLabel(ring_group_);
    residual_limit_label_->setBuddy(residual_limit_);
    input_->make_buttons(ring_group_);
    input_->fit_button()->setDefault(true);

    auto* ring_form = new QFormLayout;
    ring_form->setFieldGrowthPolicy(QFormLayout::FieldsStayAtSizeHint);
    ring_form->addRow(diameter_label_, diameter_);
    ring_form->addRow(runout_limit_label_, runout_limit_);
    ring_form->addRow(residual_limit_label_, residual_limit_);
    auto* ring_column = new QVBoxLayout(ring_group_);
    ring_column->addWidget(format_hint_);
    ring_column->addWidget(points_edit_, 1);
    ring_column->addLayout(ring_form);
    input_->add_buttons_to(ring_column);
    return ring_group_;
}

// The effective length from a surface of known Z.
QGroupBox* CalibrationTab::build_length_group() {
    length_group_ = new QGroupBox(this);
    surface_z_ = new UnitSpinBox(-100000.0, 100000.0, 4, 0.0, length_group_);
    surface_z_->set_unit(unit_mm);
    trigger_z_ = new QLineEdit(length_group_);
    trigger_z_->setObjectName(QStringLiteral("trigger-z"));
    active_length_ = new UnitSpinBox(0.0, 2000.0, 4, 0.0, length_group_);
    active_length_->set_unit(unit_mm);
    nominal_length_ = new UnitSpinBox(0.0, 2000.0, 4, 0.0, length_group_);
    nominal_length_->set_unit(unit_mm);
    length_result_label_ = new QLabel(length_group_);
    length_result_label_->setObjectName(QStringLiteral("length-result"));
    length_result_label_->setWordWrap(true);
    length_result_label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    length_warnings_ = new WarningList(length_group_);
    length_form_ = new QFormLayout;
    length_form_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    // QFormLayout makes no label for an empty text; retranslate() fills these.
    for (QWidget* field :
         {static_cast<QWidget*>(surface_z_), static_cast<QWidget*>(trigger_z_),
          static_cast<QWidget*>(active_length_), static_cast<QWidget*>(nominal_length_)}) {
        auto* label = new QLabel(length_group_);
        label->setBuddy(field);
        length_form_->addRow(label, field);
    }
    auto* length_column = new QVBoxLayout(length_group_);
    length_column->addLayout(length_form_);
    length_column->addWidget(length_result_label_);
    length_column->addWidget(length_warnings_);
    return length_group_;
}

// The magnification box over the plot of the points and the fitted circles.
QLayout* CalibrationTab::build_plot_column() {
    magnification_label_ = new QLabel(this);
    magnification_ = new QComboBox(this);
    magnification_->setObjectName(QStringLiteral("magnification"));
    magnification_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    for (std::size_t i = 0; i < std::size(kMagnifications); ++i) magnification_->addItem(QString());
    magnification_label_->setBuddy(magnification_);
    plot_ = new PlotView(this);
    plot_->setObjectName(QStringLiteral("ring-plot"));
    plot_->set_x_axis({PlotView::Scale::linear, {}, QStringLiteral("%.4g"), {}});
    plot_->set_y_axis(PlotView::Side::left,
                      {PlotView::Scale::linear, {}, QStringLiteral("%.4g"), {}});
    // Named curves are in the legend (retranslate() sets the names): a circle
    // per orientation stands for its points and centre too, in its colour.
    const QString legend = QStringLiteral(" ");
    circle_curve_[0] = plot_->add_line({legend, kColour0, 1.5});
    circle_curve_[1] = plot_->add_line({legend, kColour180, 1.5, PlotView::Dash::dashed});
    points_curve_[0] = plot_->add_markers({{}, kColour0}, 10.0);
    points_curve_[1] = plot_->add_markers({{}, kColour180}, 10.0);
    centre_curve_[0] = plot_->add_markers({{}, kColour0}, 7.0);
    centre_curve_[1] = plot_->add_markers({{}, kColour180}, 7.0);
    gauge_centre_curve_ = plot_->add_markers({legend, kGaugeColour}, 8.0);
    auto* magnification_row = new QHBoxLayout;
    magnification_row->addStretch(1);
    magnification_row->addWidget(magnification_label_);
    magnification_row->addWidget(magnification_);
    auto* plot_column = new QVBoxLayout;
    plot_column->addLayout(magnification_row);
    plot_column->addWidget(plot_, 1);
    return plot_column;
}

// The result rows, the warnings and the export button.
QGroupBox* CalibrationTab::build_result_group() {
    result_group_ = new QGroupBox(this);
    result_form_ = new QFormLayout;
    result_form_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    result_form_->setRowWrapPolicy(QFormLayout::DontWrapRows);
    for (int i = 0; i < row_count; ++i) {
        result_labels_[i] = new QLabel(result_group_);
        result_values_[i] = new QLabel(result_group_);
        result_values_[i]->setTextInteractionFlags(Qt::TextSelectableByMouse);
        result_values_[i]->setWordWrap(true);
        result_form_->addRow(result_labels_[i], result_values_[i]);
    }
    QFont bold = result_values_[row_radius]->font();
    bold.setBold(true);
    result_values_[row_radius]->setFont(bold);
    warnings_title_ = new QLabel(result_group_);
    warnings_title_->setFont(bold);
    warnings_ = new WarningList(result_group_);
    warnings_->setObjectName(QStringLiteral("ring-warnings"));
    export_button_ = new QPushButton(result_group_);
    export_button_->setEnabled(false);
    export_status_ = new QLabel(result_group_);
    export_status_->setWordWrap(true);
    export_status_->hide();
    auto* export_row = new QHBoxLayout;
    export_row->addStretch(1);
    export_row->addWidget(export_button_);
    auto* result_column = new QVBoxLayout(result_group_);
    result_column->addLayout(result_form_);
    result_column->addSpacing(6);
    result_column->addWidget(warnings_title_);
    result_column->addWidget(warnings_);
    result_column->addStretch(1);
    result_column->addWidget(export_status_);
    result_column->addLayout(export_row);
    result_group_->setFixedWidth(370);
    return result_group_;
}

// Edits refit the ring (with a result), redraw or recompute the length.
void CalibrationTab::connect_inputs() {
    connect(input_->import_button(), &QPushButton::clicked, this, &CalibrationTab::import_dialog);
    connect(input_->program_button(), &QPushButton::clicked, this,
            [this] { open_program_dialog(); });
    connect(export_button_, &QPushButton::clicked, this, &CalibrationTab::export_dialog);
    for (UnitSpinBox* box : {diameter_, runout_limit_, residual_limit_}) {
        connect(box, &QDoubleSpinBox::valueChanged, this, [this] {
            if (result_) refit();
        });
    }
    connect(magnification_, &QComboBox::currentIndexChanged, this, [this] { draw(); });
    for (UnitSpinBox* box : {surface_z_, active_length_, nominal_length_}) {
        connect(box, &QDoubleSpinBox::valueChanged, this, &CalibrationTab::compute_length);
    }
    connect(trigger_z_, &QLineEdit::textChanged, this, &CalibrationTab::compute_length);
}

CalibrationTab::~CalibrationTab() = default;

void CalibrationTab::retranslate() {
    ring_group_->setTitle(tr("Ring gauge: touches at 0° and 180°"));
    format_hint_->setText(
        tr("Paste the trigger positions the control recorded, or import a CSV file. Columns "
           "<code>orientation_deg,x_mm,y_mm</code>; spindle oriented at 0° and at 180°, 3 or more "
           "points each (typically X+, X−, Y+, Y−)."));
    points_edit_->setPlaceholderText(
        QStringLiteral("orientation_deg,x_mm,y_mm\n0,122.002,-199.998\n0,77.992,-199.998\n"
                       "0,99.997,-177.993\n0,99.997,-222.003\n180,122.008,-200.002\n...") +
        QLatin1Char('\n') + tr("(example)"));
    diameter_label_->setText(tr("Gauge diameter"));
    diameter_->setToolTip(tr("The calibrated diameter of the ring gauge, from its certificate."));
    runout_limit_label_->setText(tr("Runout limit"));
    runout_limit_->setToolTip(tr("Warn when the stylus runout (eccentricity) is larger."));
    residual_limit_label_->setText(tr("Residual limit"));
    residual_limit_->setToolTip(
        tr("Warn when a point lies further than this off its fitted circle: dirt, a bad touch "
           "or a loose gauge."));
    input_->retranslate();
    input_->program_button()->setToolTip(
        tr("The ring-gauge calibration as a program for your control (LinuxCNC, grbl, Fanuc, Haas, "
           "Mitsubishi, Siemens), with the "
           "plan that the import of its log needs."));
    input_->log_button()->setToolTip(
        tr("What the control recorded while it ran the program, read with the program's plan "
           "into the points and fitted."));

    length_group_->setTitle(tr("Length from a surface of known Z"));
    const auto set_label = [this](QWidget* field, const QString& text, const QString& tip) {
        if (auto* label = qobject_cast<QLabel*>(length_form_->labelForField(field))) {
            label->setText(text);
        }
        field->setToolTip(tip);
    };
    set_label(surface_z_, tr("Surface Z"),
              tr("The known Z of the gauge top, sphere or block, set by a reference tool."));
    set_label(trigger_z_, tr("Trigger Z"),
              tr("The Z the control recorded at the touch; several touches separated by spaces "
                 "or semicolons."));
    // In the interface's number format, which the box reads.
    trigger_z_->setPlaceholderText(
        tr("e.g. %1; %2").arg(format_number(12.3456, 4), format_number(12.3459, 4)));
    set_label(active_length_, tr("Active length"),
              tr("The tool length offset active while probing (0 when none)."));
    set_label(nominal_length_, tr("Nominal length"),
              tr("The probe's nominal length, to express the result as wear (0 = none)."));
    nominal_length_->setSpecialValueText(tr("none"));
    length_warnings_->set_empty_text({});

    magnification_label_->setText(tr("Radial deviations:"));
    magnification_->setItemText(0, tr("Magnified, automatic"));
    magnification_->setItemText(1, tr("True scale"));
    for (std::size_t i = 2; i < std::size(kMagnifications); ++i) {
        //: the magnification of the radial deviations in the ring plot
        magnification_->setItemText(static_cast<int>(i),
                                    tr("× %1").arg(QLocale().toString(kMagnifications[i], 'f', 0)));
    }
    plot_->set_x_axis(
        {PlotView::Scale::linear, tr("X [%1]").arg(unit_mm()), QStringLiteral("%.4g"), {}});
    plot_->set_y_axis(
        PlotView::Side::left,
        {PlotView::Scale::linear, tr("Y [%1]").arg(unit_mm()), QStringLiteral("%.4g"), {}});
    plot_->set_name(circle_curve_[0], tr("Spindle at 0°"));
    plot_->set_name(circle_curve_[1], tr("Spindle at 180°"));
    plot_->set_name(gauge_centre_curve_, tr("Gauge centre"));

    result_group_->setTitle(tr("Result"));
    result_labels_[row_centre]->setText(tr("Gauge centre"));
    result_labels_[row_runout]->setText(tr("Stylus runout"));
    result_labels_[row_radius]->setText(tr("Effective ball radius"));
    result_labels_[row_by_direction]->setText(tr("Radius by direction"));
    result_labels_[row_residual]->setText(tr("Largest residual"));
    result_labels_[row_circle_0]->setText(tr("Circle at 0°"));
    result_labels_[row_circle_180]->setText(tr("Circle at 180°"));
    result_labels_[row_points]->setText(tr("Points"));
    warnings_title_->setText(tr("Warnings"));
    warnings_->set_empty_text(tr("No warnings."));
    export_button_->setText(tr("Export CSV report…"));

    for (UnitSpinBox* box :
         {diameter_, runout_limit_, residual_limit_, surface_z_, active_length_, nominal_length_}) {
        box->retranslate();
    }
    show_result();
    compute_length();
}

void CalibrationTab::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void CalibrationTab::set_scenario(const probecycle::Scenario& scenario) {
    scenario_ = scenario;
}

// --- Ring gauge ---

void CalibrationTab::set_points_text(const QString& csv) {
    points_edit_->setPlainText(csv);
}

QString CalibrationTab::points_text() const {
    return points_edit_->toPlainText();
}

void CalibrationTab::set_gauge_diameter_mm(double diameter_mm) {
    diameter_->set_internal_value(diameter_mm);
}

double CalibrationTab::gauge_diameter_mm() const {
    return diameter_->internal_value();
}

RingCalibrationOptions CalibrationTab::options() const {
    RingCalibrationOptions options;
    options.gauge_diameter_mm = diameter_->internal_value();
    options.runout_limit_mm = runout_limit_->internal_value();
    options.residual_limit_mm = residual_limit_->internal_value();
    return options;
}

bool CalibrationTab::load_example() {
    return input_->load_example();
}

bool CalibrationTab::fit() {
    return input_->fit();
}

bool CalibrationTab::import_file(const QString& path) {
    return input_->import_file(path);
}

bool CalibrationTab::fit_text(const QString& text, const QString& source) {
    const RingCalibrationOptions options = this->options();
    std::vector<RingPoint> points;
    RingCalibration result;
    try {
        points = parse_ring_csv(text.toStdString());
        result = calibrate_ring(points, options);
    } catch (const std::exception&) {
        input_->show_fit_error(source);
        return false;
    }
    points_ = std::move(points);
    points_from_ = input_->source_of(text);
    options_ = options;
    result_ = std::move(result);
    fitted_text_ = text;
    set_error({});
    show_result();
    emit changed();  // the project keeps the CSV behind the fit
    return true;
}

bool CalibrationTab::refit() {
    const RingCalibrationOptions options = this->options();
    try {
        RingCalibration result = calibrate_ring(points_, options);
        options_ = options;
        result_ = std::move(result);
    } catch (const std::exception&) {
        set_error(current_error_text());
        return false;
    }
    set_error({});
    show_result();
    return true;
}

void CalibrationTab::set_error(LiveText text) {
    input_->set_error(std::move(text));
}

void CalibrationTab::show_result() {
    for (QLabel* value : result_values_) value->setText(result_ ? QString() : QStringLiteral("—"));
    std::vector<WarningList::Item> items;
    if (result_) {
        const RingCalibration& r = *result_;
        // One coordinate a line: a narrow column (and a long translation)
        // never parts a name from its value.
        const QChar gap = QLatin1Char('\n');
        result_values_[row_centre]->setText(tr("X %1").arg(lab_mm(r.center_x_mm)) + gap +
                                            tr("Y %1").arg(lab_mm(r.center_y_mm)));
        if (r.runout_x_mm && r.runout_y_mm) {
            result_values_[row_runout]->setText(
                tr("X %1").arg(lab_signed_um(*r.runout_x_mm)) + gap +
                tr("Y %1").arg(lab_signed_um(*r.runout_y_mm)) + QLatin1Char('\n') +
                tr("%1 in all")
                    .arg(lab_signed_um(std::hypot(*r.runout_x_mm, *r.runout_y_mm))
                             .remove(QLatin1Char('+'))));
        } else {
            result_values_[row_runout]->setText(tr("unknown: one orientation only"));
        }
        result_values_[row_radius]->setText(lab_mm(r.effective_radius_mm));
        const auto direction = [](const char* name, const std::optional<double>& radius) {
            return QString::fromUtf8(name) + QChar(0x00A0) +
                   (radius ? lab_mm(*radius) : QStringLiteral("—"));
        };
        const DirectionalRadius& d = r.radius_by_direction;
        result_values_[row_by_direction]->setText(direction("X+", d.x_plus_mm) + gap +
                                                  direction("X\u2212", d.x_minus_mm) +
                                                  QLatin1Char('\n') + direction("Y+", d.y_plus_mm) +
                                                  gap + direction("Y\u2212", d.y_minus_mm));
        result_values_[row_residual]->setText(lab_signed_um(r.residual_max_mm));
        for (int o = 0; o < 2; ++o) {
            QLabel* value = result_values_[o == 0 ? row_circle_0 : row_circle_180];
            if (const auto& fit = r.fits[static_cast<std::size_t>(o)]) {
                value->setText(tr("centre %1, %2; radius %3")
                                   .arg(QLocale().toString(fit->center_x_mm, 'f', 4),
                                        QLocale().toString(fit->center_y_mm, 'f', 4),
                                        lab_mm(fit->radius_mm)));
            } else {
                value->setText(tr("no points"));
            }
        }
        int count[2] = {0, 0};
        for (const RingPoint& p : points_) ++count[orientation_of(p)];
        result_values_[row_points]->setText(tr("%1 at 0°, %2 at 180°; gauge %3")
                                                .arg(count[0])
                                                .arg(count[1])
                                                .arg(lab_mm(options_.gauge_diameter_mm)));
        for (const CalibrationWarning& w : r.warnings) items.push_back(warning_item(w));
    }
    warnings_->show_items(items);
    export_button_->setEnabled(result_.has_value() || length_result_.has_value());
    draw();
}

QStringList CalibrationTab::warning_codes() const {
    return warnings_->codes() + length_warnings_->codes();
}

QStringList CalibrationTab::warning_texts() const {
    return warnings_->texts() + length_warnings_->texts();
}

QStringList CalibrationTab::results_text() const {
    QStringList out;
    for (int i = 0; i < row_count; ++i) {
        out << result_labels_[i]->text() + QStringLiteral(": ") + result_values_[i]->text();
    }
    if (length_result_) out << length_result_label_->text();
    return out;
}

// --- Drawing ---

void CalibrationTab::set_deviation_magnification(double factor) {
    const auto* found = std::find(std::begin(kMagnifications), std::end(kMagnifications), factor);
    if (found != std::end(kMagnifications)) {
        magnification_->setCurrentIndex(static_cast<int>(found - std::begin(kMagnifications)));
    }
    draw();
}

void CalibrationTab::draw() {
    QList<QPointF> points[2];
    QList<QPointF> circles[2];
    QList<QPointF> centres[2];
    QList<QPointF> gauge_centre;
    magnification_used_ = 1.0;
    if (result_) {
        const RingCalibration& r = *result_;
        const double cx = r.center_x_mm;
        const double cy = r.center_y_mm;
        // The reference circle: the mean fitted radius.
        double reference = 0.0;
        int fits = 0;
        for (const auto& fit : r.fits) {
            if (fit) {
                reference += fit->radius_mm;
                ++fits;
            }
        }
        reference /= std::max(fits, 1);

        double k =
            kMagnifications[static_cast<std::size_t>(std::max(magnification_->currentIndex(), 0))];
        if (k == 0.0) {
            // Automatic: the largest power of ten that keeps the largest
            // deviation within 30 % of the radius, so the runout and the
            // residuals show while the circle stays a circle.
            double largest = 0.0;
            for (const RingPoint& p : points_) {
                largest =
                    std::max(largest, std::abs(std::hypot(p.x_mm - cx, p.y_mm - cy) - reference));
            }
            for (const auto& fit : r.fits) {
                if (!fit) continue;
                largest =
                    std::max(largest, std::hypot(fit->center_x_mm - cx, fit->center_y_mm - cy) +
                                          std::abs(fit->radius_mm - reference));
            }
            k = 1.0;
            for (const double candidate : {10000.0, 1000.0, 100.0, 10.0}) {
                if (largest > 0.0 && candidate * largest <= 0.3 * reference) {
                    k = candidate;
                    break;
                }
            }
        }
        magnification_used_ = k;

        for (const RingPoint& p : points_) {
            points[orientation_of(p)].append(magnified(p.x_mm, p.y_mm, cx, cy, reference, k));
        }
        for (std::size_t o = 0; o < 2; ++o) {
            const auto& fit = r.fits[o];
            if (!fit) continue;
            circles[o].reserve(kCirclePoints);
            for (int i = 0; i < kCirclePoints; ++i) {
                const double angle = 2.0 * std::numbers::pi * i / (kCirclePoints - 1);
                circles[o].append(magnified(fit->center_x_mm + fit->radius_mm * std::cos(angle),
                                            fit->center_y_mm + fit->radius_mm * std::sin(angle), cx,
                                            cy, reference, k));
            }
            // A centre is drawn where its offset from the gauge centre, magnified, puts it.
            centres[o].append({cx + k * (fit->center_x_mm - cx), cy + k * (fit->center_y_mm - cy)});
        }
        gauge_centre.append({cx, cy});
        plot_->set_title(
            k == 1.0 ? tr("True scale")
                     : tr("Radial deviations magnified × %1").arg(QLocale().toString(k, 'f', 0)));
    } else {
        plot_->set_title(tr("No fit yet"));
    }
    // QRectF::united drops empty rectangles, so the bounds are taken by hand.
    double lo_x = qInf(), hi_x = -qInf(), lo_y = qInf(), hi_y = -qInf();
    for (int o = 0; o < 2; ++o) {
        plot_->set_points(points_curve_[o], points[o]);
        plot_->set_points(circle_curve_[o], circles[o]);
        plot_->set_points(centre_curve_[o], centres[o]);
        for (const QList<QPointF>* list : {&points[o], &circles[o]}) {
            for (const QPointF& p : *list) {
                lo_x = std::min(lo_x, p.x());
                hi_x = std::max(hi_x, p.x());
                lo_y = std::min(lo_y, p.y());
                hi_y = std::max(hi_y, p.y());
            }
        }
    }
    data_bounds_ = lo_x <= hi_x ? QRectF(QPointF(lo_x, lo_y), QPointF(hi_x, hi_y)) : QRectF();
    plot_->set_points(gauge_centre_curve_, gauge_centre);
    for (int o = 0; o < 2; ++o) plot_->set_visible(circle_curve_[o], !circles[o].isEmpty());
    update_plot_ranges();
}

void CalibrationTab::update_plot_ranges() {
    if (!result_ || !(data_bounds_.width() > 0.0 || data_bounds_.height() > 0.0)) {
        plot_->set_equal_scales({});
        plot_->set_x_range(-1.0, 1.0);
        plot_->set_y_range(PlotView::Side::left, -1.0, 1.0);
        return;
    }
    // Equal scales on both axes, so the circles look round.
    plot_->set_equal_scales(data_bounds_.adjusted(-1e-4, -1e-4, 1e-4, 1e-4));
}

QList<QPointF> CalibrationTab::plotted_points(int orientation) const {
    return plot_->points(points_curve_[orientation == 0 ? 0 : 1]);
}

QList<QPointF> CalibrationTab::plotted_circle(int orientation) const {
    return plot_->points(circle_curve_[orientation == 0 ? 0 : 1]);
}

// --- Project ---

RingSession CalibrationTab::ring_session() const {
    RingSession session;
    session.points_csv = points_edit_->toPlainText().toStdString();
    if (result_) session.fitted_csv = fitted_text_.toStdString();
    session.options = options();
    session.magnification =
        kMagnifications[static_cast<std::size_t>(std::max(magnification_->currentIndex(), 0))];
    return session;
}

LengthSession CalibrationTab::length_session() const {
    LengthSession session;
    session.surface_z_mm = surface_z_->internal_value();
    session.trigger_z = trigger_z_->text().toStdString();
    session.active_length_mm = active_length_->internal_value();
    session.nominal_length_mm = nominal_length_->internal_value();
    return session;
}

bool CalibrationTab::restore(const RingSession& ring, const LengthSession& length) {
    {
        // The old fit is not refitted with the new settings on the way.
        const QSignalBlocker block_diameter(diameter_);
        const QSignalBlocker block_runout(runout_limit_);
        const QSignalBlocker block_residual(residual_limit_);
        diameter_->set_internal_value(ring.options.gauge_diameter_mm);
        runout_limit_->set_internal_value(ring.options.runout_limit_mm);
        residual_limit_->set_internal_value(ring.options.residual_limit_mm);
    }
    {
        const QSignalBlocker block(magnification_);
        set_deviation_magnification(ring.magnification);
    }
    result_.reset();
    points_.clear();
    fitted_text_.clear();
    set_error({});
    bool fitted = true;
    if (!ring.fitted_csv.empty()) {
        fitted = fit_text(QString::fromStdString(ring.fitted_csv), QString());
    } else {
        show_result();
    }
    set_points_text(QString::fromStdString(ring.points_csv));
    set_length_inputs({length.surface_z_mm, QString::fromStdString(length.trigger_z),
                       length.active_length_mm, length.nominal_length_mm});
    return fitted;
}

void CalibrationTab::save_session(Project& project, const QString& /*base_folder*/) const {
    project.ring = ring_session();
    project.length = length_session();
}

bool CalibrationTab::restore_session(const Project& project, const QString& /*base_folder*/) {
    return restore(project.ring, project.length);
}

// --- Length ---

void CalibrationTab::set_length_inputs(const LengthInputs& inputs) {
    surface_z_->set_internal_value(inputs.surface_z_mm);
    trigger_z_->setText(inputs.trigger_z);
    active_length_->set_internal_value(inputs.active_length_mm);
    nominal_length_->set_internal_value(inputs.nominal_length_mm);
    compute_length();
}

void CalibrationTab::compute_length() {
    length_result_.reset();
    length_input_.reset();
    length_error_.clear();
    std::vector<WarningList::Item> items;

    LengthCalibrationInput input;
    input.surface_z_mm = surface_z_->internal_value();
    input.active_length_mm = active_length_->internal_value();
    if (nominal_length_->internal_value() > 0.0) {
        input.nominal_length_mm = nominal_length_->internal_value();
    }
    static const QRegularExpression kSeparators(QStringLiteral("[\\s;]+"));
    const QStringList tokens = trigger_z_->text().split(kSeparators, Qt::SkipEmptyParts);
    for (const QString& token : tokens) {
        const auto value = parse_number(token);
        if (!value) {
            length_error_ = tr("Trigger Z: “%1” is not a number.").arg(token);
            break;
        }
        input.trigger_z_mm.push_back(*value);
    }
    if (length_error_.isEmpty() && !input.trigger_z_mm.empty()) {
        try {
            length_result_ = calibrate_length(input);
            length_input_ = input;
        } catch (const std::exception& e) {
            length_error_ = error_text(e);
        }
    }

    if (!length_error_.isEmpty()) {
        show_error(length_result_label_, length_error_);
        length_result_label_->show();
    } else if (length_result_) {
        const LengthCalibration& l = *length_result_;
        length_result_label_->setStyleSheet({});
        QString text = tr("Effective length: <b>%1</b>").arg(lab_mm(l.effective_length_mm));
        if (l.wear_mm)
            text += QStringLiteral("<br>") + tr("Wear: %1").arg(lab_signed_length(*l.wear_mm));
        text += QStringLiteral("<br>") +
                tr("Touches: %1, spread %2")
                    .arg(l.touches)
                    .arg(lab_signed_um(l.trigger_z_range_mm).remove(QLatin1Char('+')));
        length_result_label_->setText(text);
        length_result_label_->show();
        for (const CalibrationWarning& w : l.warnings) items.push_back(warning_item(w));
    } else {
        length_result_label_->setStyleSheet({});
        length_result_label_->setText(tr("Enter the trigger Z of one or more touches."));
        length_result_label_->show();
    }
    length_warnings_->show_items(items);
    export_button_->setEnabled(result_.has_value() || length_result_.has_value());
}

// --- Files ---

std::optional<std::string> CalibrationTab::report_csv(ReportRows rows) {
    if (!result_ && !length_result_) {
        show_live_error(export_status_, [this] {
            return last_error_ =
                       tr("Nothing to export: fit the ring points or enter a length first.");
        });
        return std::nullopt;
    }
    std::optional<RingReportInput> ring;
    if (result_) ring = RingReportInput{points_, options_, *result_};
    std::optional<LengthReportInput> length;
    if (length_result_ && length_input_)
        length = LengthReportInput{*length_input_, *length_result_};
    ReportHeader header;
    header.date = report_date();
    header.subject = result_ ? points_from_ : "none";
    return calibration_report_csv(ring, length, header, rows);
}

bool CalibrationTab::export_report(const QString& path, ReportRows rows) {
    const std::optional<std::string> csv = report_csv(rows);
    return csv && write_report(path, *csv, export_status_, last_error_);
}

void CalibrationTab::import_dialog() {
    input_->import_dialog(tr("Import ring gauge points"));
}

ProgramDialog* CalibrationTab::open_program_dialog() {
    ProgramDialog* dialog = input_->open_program_dialog(scenario_);
    RingPlanOptions options;
    options.gauge_diameter_mm = diameter_->internal_value();
    dialog->set_ring_options(options);
    return dialog;
}

bool CalibrationTab::import_machine_log(const MachineLogChoice& choice) {
    return input_->import_machine_log(choice);
}

void CalibrationTab::export_dialog() {
    const QString path = ask_report_path(this, tr("Export calibration report"),
                                         QStringLiteral("calibration-report.csv"));
    if (!path.isEmpty()) export_report(path);
}

}  // namespace probecycle::ui
