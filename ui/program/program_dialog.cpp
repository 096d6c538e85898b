#include "ui/program/program_dialog.h"

#include <QComboBox>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>
#include <utility>

#include "core/common/input_error.h"
#include "core/common/report_header.h"
#include "core/program/program_writer.h"
#include "ui/common/file_write.h"
#include "ui/common/language.h"
#include "ui/common/parameter_info.h"
#include "ui/common/status_text.h"
#include "ui/common/text_format.h"
#include "ui/common/unit_spin_box.h"

namespace probecycle::ui {

namespace {

const AxisDirection kAxes[] = {{'X', 1}, {'X', -1}, {'Y', 1}, {'Y', -1}, {'Z', 1}, {'Z', -1}};

// A feed as the feeds box shows it: the locale's decimal sign, no grouping
// (a group separator would read as a separator of feeds).
QString feed_text(double feed_mm_min) {
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale.toString(feed_mm_min, 'g', 12);
}

}  // namespace

std::vector<DialectId> program_dialects() {
    // The core's list, in the CLI's order.
    return {all_dialects().begin(), all_dialects().end()};
}

QString plan_path_for(const QString& program_path) {
    const QFileInfo info(program_path);
    return info.dir().filePath(info.completeBaseName() + QStringLiteral(".plan.json"));
}

ProgramDialog::ProgramDialog(ProgramKind kind, const Scenario& scenario, QWidget* parent)
    : QDialog(parent), kind_(kind), scenario_(scenario), date_(report_date()) {
    setObjectName(QStringLiteral("program-dialog"));
    update_timer_ = new QTimer(this);
    update_timer_->setSingleShot(true);
    update_timer_->setInterval(0);  // one update per pass of the event loop
    connect(update_timer_, &QTimer::timeout, this, &ProgramDialog::update_now);
    intro_ = new QLabel(this);
    intro_->setWordWrap(true);
    dialect_ = new QComboBox(this);
    dialect_->setObjectName(QStringLiteral("program-dialect"));
    for (DialectId id : program_dialects()) {
        dialect_->addItem(QString::fromUtf8(dialect(id).title), static_cast<int>(id));
    }
    dialect_label_ = new QLabel(this);
    dialect_label_->setBuddy(dialect_);

    auto* form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->addRow(dialect_label_, dialect_);
    probe_input_ = new QComboBox(this);
    probe_input_->setObjectName(QStringLiteral("program-probe-input"));
    for (const int input : {1, -1, 2, -2}) probe_input_->addItem(QString(), input);
    probe_input_label_ = new QLabel(this);
    probe_input_label_->setBuddy(probe_input_);
    form->addRow(probe_input_label_, probe_input_);
    if (kind_ == ProgramKind::ring) {
        build_ring_options(form);
    } else if (kind_ == ProgramKind::cycle) {
        build_cycle_options(form);
    } else {
        build_delay_options(form);
    }
    problem_label_ = new QLabel(this);
    problem_label_->setObjectName(QStringLiteral("program-problem"));
    problem_label_->setWordWrap(true);
    problem_label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    problem_label_->hide();
    auto* options = new QWidget(this);
    auto* options_column = new QVBoxLayout(options);
    options_column->setContentsMargins(0, 0, 0, 0);
    options_column->addLayout(form);
    options_column->addWidget(problem_label_);
    options_column->addStretch(1);
    options->setFixedWidth(380);

    preview_label_ = new QLabel(this);
    preview_ = new QPlainTextEdit(this);
    preview_->setObjectName(QStringLiteral("program-preview"));
    preview_->setReadOnly(true);
    preview_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    preview_->setLineWrapMode(QPlainTextEdit::NoWrap);
    preview_label_->setBuddy(preview_);
    auto* preview_column = new QVBoxLayout;
    preview_column->addWidget(preview_label_);
    preview_column->addWidget(preview_, 1);

    auto* body = new QHBoxLayout;
    body->addWidget(options);
    body->addLayout(preview_column, 1);

    status_ = new QLabel(this);
    status_->setObjectName(QStringLiteral("program-status"));
    status_->setWordWrap(true);
    status_->hide();
    save_button_ = new QPushButton(this);
    save_button_->setObjectName(QStringLiteral("program-save"));
    save_button_->setDefault(true);
    close_button_ = new QPushButton(this);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(status_, 1);
    buttons->addStretch(1);  // the buttons keep their size while the status is hidden
    buttons->addWidget(save_button_);
    buttons->addWidget(close_button_);

    auto* root = new QVBoxLayout(this);
    root->addWidget(intro_);
    root->addLayout(body, 1);
    root->addLayout(buttons);
    resize(1000, 640);

    connect(dialect_, &QComboBox::currentIndexChanged, this, &ProgramDialog::schedule_update);
    connect(probe_input_, &QComboBox::currentIndexChanged, this, &ProgramDialog::schedule_update);
    connect(save_button_, &QPushButton::clicked, this, &ProgramDialog::save_dialog);
    connect(close_button_, &QPushButton::clicked, this, &QDialog::reject);
    retranslate();
    update_now();
}

ProgramDialog::~ProgramDialog() = default;

void ProgramDialog::build_axis(QFormLayout* form, const AxisDirection& touch) {
    axis_ = new QComboBox(this);
    axis_->setObjectName(QStringLiteral("program-axis"));
    for (const AxisDirection& at : kAxes) {
        const QString name = QString::fromStdString(to_string(at));
        axis_->addItem(name, name);
    }
    set_axis(touch);
    axis_label_ = new QLabel(this);
    axis_label_->setBuddy(axis_);
    form->addRow(axis_label_, axis_);
    connect(axis_, &QComboBox::currentIndexChanged, this, &ProgramDialog::schedule_update);
}

void ProgramDialog::set_axis(const AxisDirection& touch) {
    axis_->setCurrentIndex(std::max(axis_->findData(QString::fromStdString(to_string(touch))), 0));
}

AxisDirection ProgramDialog::axis() const {
    return *axis_direction_from_string(axis_->currentData().toString().toStdString());
}

void ProgramDialog::build_cycle_options(QFormLayout* form) {
    build_axis(form, CyclePlanOptions{}.touch);
    // A bore or boss is touched at X+, X-, Y+ and Y- whatever the axis.
    const Feature feature = scenario_.cycle.feature;
    const bool used = feature != Feature::bore && feature != Feature::boss;
    axis_->setEnabled(used);
    axis_label_->setEnabled(used);
}

void ProgramDialog::build_delay_options(QFormLayout* form) {
    const DelayPlanOptions defaults;
    build_axis(form, defaults.touch);
    feeds_ = new QLineEdit(this);
    feeds_->setObjectName(QStringLiteral("program-feeds"));
    repeats_ = new QSpinBox(this);
    repeats_->setObjectName(QStringLiteral("program-repeats"));
    repeats_->setRange(1, kMaxPlanRepeats);
    repeats_->setValue(defaults.repeats);
    repeats_->setKeyboardTracking(false);
    margin_ = new UnitSpinBox(0.0, 100.0, 3, defaults.margin_mm, this);
    margin_->set_unit(unit_mm);
    placement_ = new UnitSpinBox(0.1, kMaxPlanDistance_mm, 3, defaults.placement_mm, this);
    placement_->set_unit(unit_mm);
    feeds_label_ = new QLabel(this);
    repeats_label_ = new QLabel(this);
    margin_label_ = new QLabel(this);
    placement_label_ = new QLabel(this);
    form->addRow(feeds_label_, feeds_);
    form->addRow(repeats_label_, repeats_);
    form->addRow(margin_label_, margin_);
    form->addRow(placement_label_, placement_);
    feeds_label_->setBuddy(feeds_);
    repeats_label_->setBuddy(repeats_);
    margin_label_->setBuddy(margin_);
    placement_label_->setBuddy(placement_);
    set_delay_options(defaults);

    connect(feeds_, &QLineEdit::textChanged, this, &ProgramDialog::schedule_update);
    connect(repeats_, &QSpinBox::valueChanged, this, &ProgramDialog::schedule_update);
    for (UnitSpinBox* box : {margin_, placement_}) {
        connect(box, &QDoubleSpinBox::valueChanged, this, &ProgramDialog::schedule_update);
    }
}

void ProgramDialog::build_ring_options(QFormLayout* form) {
    const RingPlanOptions defaults;
    gauge_ = new UnitSpinBox(0.1, 2000.0, 4, defaults.gauge_diameter_mm, this);
    gauge_->setObjectName(QStringLiteral("program-gauge-diameter"));
    gauge_->set_unit(unit_mm);
    ball_ = new UnitSpinBox(0.1, 100.0, 4, defaults.ball_diameter_mm, this);
    ball_->setObjectName(QStringLiteral("program-ball-diameter"));
    ball_->set_unit(unit_mm);
    tolerance_ = new UnitSpinBox(0.0, 100.0, 3, defaults.centre_tolerance_mm, this);
    tolerance_->setObjectName(QStringLiteral("program-centre-tolerance"));
    tolerance_->set_unit(unit_mm);
    gauge_label_ = new QLabel(this);
    ball_label_ = new QLabel(this);
    tolerance_label_ = new QLabel(this);
    form->addRow(gauge_label_, gauge_);
    form->addRow(ball_label_, ball_);
    form->addRow(tolerance_label_, tolerance_);
    orient_ = new QLineEdit(this);
    orient_->setObjectName(QStringLiteral("program-orient-180"));
    orient_label_ = new QLabel(this);
    orient_label_->setBuddy(orient_);
    form->addRow(orient_label_, orient_);
    connect(orient_, &QLineEdit::textChanged, this, &ProgramDialog::schedule_update);
    gauge_label_->setBuddy(gauge_);
    ball_label_->setBuddy(ball_);
    tolerance_label_->setBuddy(tolerance_);
    for (UnitSpinBox* box : {gauge_, ball_, tolerance_}) {
        connect(box, &QDoubleSpinBox::valueChanged, this, &ProgramDialog::schedule_update);
    }
}

void ProgramDialog::retranslate() {
    if (kind_ == ProgramKind::ring) {
        setWindowTitle(tr("Ring-gauge calibration program"));
        intro_->setText(
            tr("From the gauge centre: X+, X−, Y+, Y− with the spindle at 0°, a pause to turn it "
               "to 180°, the same four, each point with the scenario's strategy and feeds. Every "
               "move is incremental from where the probe stands. Save the plan with the program: "
               "\"Import machine log…\" needs it."));
        gauge_label_->setText(tr("Gauge diameter"));
        gauge_->setToolTip(tr("The calibrated diameter of the ring gauge, from its certificate."));
        ball_label_->setText(tr("Ball diameter"));
        ball_->setToolTip(
            tr("The stylus ball's diameter: the room to the wall is the gauge's "
               "radius less the ball's."));
        orient_label_->setText(tr("Spindle to 180°"));
        orient_->setPlaceholderText(tr("your control's block, from its manual"));
        orient_->setToolTip(
            tr("The block your control turns the spindle to 180° with. The Fanuc-type "
               "programs need it: M19 with an angle differs by maker and machine, and "
               "ProbeCycle does not guess it (the CLI's --orient-180)."));
        tolerance_label_->setText(tr("Centre tolerance"));
        tolerance_->setToolTip(
            tr("How far off the gauge centre the probe may start: each first touch searches "
               "this much further."));
        for (UnitSpinBox* box : {gauge_, ball_, tolerance_}) box->retranslate();
    } else if (kind_ == ProgramKind::cycle) {
        setWindowTitle(tr("Tuned cycle program"));
        const Feature feature = scenario_.cycle.feature;
        axis_label_->setText(tr("Axis and direction"));
        if (feature == Feature::surface) {
            intro_->setText(
                tr("The scenario's cycle on a surface, as plain probing moves: its strategy, "
                   "feeds, backoff and start distance, the values you tuned here, not a maker's "
                   "cycle call. The probe stands at the start distance in front of the surface. "
                   "Every move is incremental from where the probe stands. Every move runs at a "
                   "feed: prove it out at reduced feed override with the probe clear of the "
                   "part."));
            axis_->setToolTip(tr("The direction of travel of the touch."));
        } else {
            intro_->setText(
                tr("The scenario's cycle on its feature, as plain probing moves: its strategy, "
                   "feeds, backoff and start distance, the values you tuned here, not a maker's "
                   "cycle call. The probe starts at the feature's centre (over it for a boss or "
                   "web) and every move toward the part is protected: a touch on the way is an "
                   "obstruction. Every move is incremental from where the probe stands. Prove it "
                   "out at reduced feed override (a boss's or web's lifts are rapids: reduced "
                   "rapid override too) with the probe clear of the part."));
            axis_->setToolTip(feature == Feature::pocket || feature == Feature::web
                                  ? tr("The axis the two walls are touched along, X or Y (both "
                                       "directions, + first).")
                                  : tr("Not used: a bore or boss is touched at X+, X-, Y+ and "
                                       "Y-."));
        }
    } else {
        setWindowTitle(tr("Delay-stability test program"));
        intro_->setText(
            tr("Along one axis and direction: a locating touch, then the repeats at each feed, "
               "each from far enough out to touch at full speed, with a rapid retract between "
               "touches. Every move is incremental from where the probe stands. Save the plan "
               "with the program: \"Import machine log…\" needs it."));
        axis_label_->setText(tr("Axis and direction"));
        axis_->setToolTip(
            tr("The direction of travel of the touches. One per program: the control cannot "
               "jog to another surface at a pause; paste the imports of several programs "
               "together."));
        feeds_label_->setText(tr("Feeds"));
        feeds_->setToolTip(
            tr("The feeds of the touches, %1, separated by semicolons or spaces; at least two.")
                .arg(unit_mm_min()));
        repeats_label_->setText(tr("Touches per feed"));
        margin_label_->setText(tr("Start margin"));
        margin_->setToolTip(
            tr("Each touch starts this much farther out than the distance the axis needs to "
               "reach its feed."));
        placement_label_->setText(tr("Start at most"));
        placement_->setToolTip(
            tr("The probe stands at most this far from the surface when the program starts; "
               "the locating touch searches this far."));
        for (UnitSpinBox* box : {margin_, placement_}) box->retranslate();
    }
    dialect_label_->setText(tr("Control"));
    probe_input_label_->setText(tr("Probe input"));
    probe_input_->setItemText(0, tr("1, rising edge"));
    probe_input_->setItemText(1, tr("1, falling edge"));
    probe_input_->setItemText(2, tr("2, rising edge"));
    probe_input_->setItemText(3, tr("2, falling edge"));
    probe_input_->setToolTip(
        tr("Which probe input the measuring moves use (Siemens: MEAS=1, -1, 2 or -2), as the "
           "machine's builder wired it: falling edge for a probe whose signal falls when it "
           "triggers; the CLI's --probe-input."));
    dialect_->setToolTip(tr("The control's G-code dialect."));
    preview_label_->setText(tr("Program"));
    preview_->setPlaceholderText(tr("No program: the options are refused (see the message)."));
    save_button_->setText(tr("Save program…"));
    save_button_->setToolTip(
        tr("Writes the program and, beside it, its plan (NAME.plan.json), which the import of "
           "the machine's log needs."));
    close_button_->setText(tr("Close"));
}

void ProgramDialog::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QDialog::changeEvent(event);
}

void ProgramDialog::set_dialect(DialectId id) {
    dialect_->setCurrentIndex(std::max(dialect_->findData(static_cast<int>(id)), 0));
}

DialectId ProgramDialog::dialect_id() const {
    return static_cast<DialectId>(dialect_->currentData().toInt());
}

void ProgramDialog::set_delay_options(const DelayPlanOptions& options) {
    if (!feeds_) return;
    set_axis(options.touch);
    const std::vector<double> feeds =
        options.feeds_mm_min.empty() ? default_delay_feeds(scenario_) : options.feeds_mm_min;
    QStringList texts;
    for (double feed : feeds) texts << feed_text(feed);
    feeds_->setText(texts.join(QStringLiteral("; ")));
    repeats_->setValue(options.repeats);
    margin_->set_internal_value(options.margin_mm);
    placement_->set_internal_value(options.placement_mm);
    schedule_update();
}

void ProgramDialog::set_feeds_text(const QString& text) {
    if (feeds_) feeds_->setText(text);
}

std::optional<std::vector<double>> ProgramDialog::parsed_feeds() const {
    const QLocale locale;
    const bool comma_decimal = locale.decimalPoint() == QStringLiteral(",");
    static const QRegularExpression kSpacesSemicolons(QStringLiteral("[;\\s]+"));
    static const QRegularExpression kAlsoCommas(QStringLiteral("[;,\\s]+"));
    std::vector<double> feeds;
    for (const QString& token : feeds_->text().split(
             comma_decimal ? kSpacesSemicolons : kAlsoCommas, Qt::SkipEmptyParts)) {
        bool ok = false;
        double value = locale.toDouble(token, &ok);
        if (!ok) value = QLocale::c().toDouble(token, &ok);
        if (!ok || !std::isfinite(value)) return std::nullopt;
        feeds.push_back(value);
    }
    return feeds;
}

DelayPlanOptions ProgramDialog::delay_options() const {
    DelayPlanOptions options;
    if (!feeds_) return options;
    options.touch = axis();
    options.feeds_mm_min = parsed_feeds().value_or(std::vector<double>{});
    options.repeats = repeats_->value();
    options.margin_mm = margin_->internal_value();
    options.placement_mm = placement_->internal_value();
    return options;
}

void ProgramDialog::set_cycle_options(const CyclePlanOptions& options) {
    if (kind_ != ProgramKind::cycle) return;
    set_axis(options.touch);
    schedule_update();
}

CyclePlanOptions ProgramDialog::cycle_options() const {
    CyclePlanOptions options;
    if (kind_ == ProgramKind::cycle) options.touch = axis();
    return options;
}

void ProgramDialog::set_ring_options(const RingPlanOptions& options) {
    if (!gauge_) return;
    gauge_->set_internal_value(options.gauge_diameter_mm);
    ball_->set_internal_value(options.ball_diameter_mm);
    tolerance_->set_internal_value(options.centre_tolerance_mm);
    schedule_update();
}

RingPlanOptions ProgramDialog::ring_options() const {
    RingPlanOptions options;
    if (!gauge_) return options;
    options.gauge_diameter_mm = gauge_->internal_value();
    options.ball_diameter_mm = ball_->internal_value();
    options.centre_tolerance_mm = tolerance_->internal_value();
    return options;
}

void ProgramDialog::schedule_update() {
    update_timer_->start();
}

void ProgramDialog::update_now() {
    update_timer_->stop();
    plan_.reset();
    program_.clear();
    refusal_.reset();
    bad_feed_.clear();
    try {
        if (kind_ == ProgramKind::ring) {
            plan_ = make_ring_plan(scenario_, ring_options());
        } else if (kind_ == ProgramKind::cycle) {
            plan_ = make_cycle_plan(scenario_, cycle_options());
        } else if (parsed_feeds()) {
            plan_ = make_delay_plan(scenario_, delay_options());
        } else {
            bad_feed_ = feeds_->text();
        }
        if (orient_ != nullptr) {
            const bool needed = dialect(dialect_id()).orient_from_user;
            orient_->setEnabled(needed);
            orient_label_->setEnabled(needed);
        }
        const bool input_needed = names_probe_input(dialect(dialect_id()));
        probe_input_->setEnabled(input_needed);
        probe_input_label_->setEnabled(input_needed);
        if (plan_) {
            ProgramOptions options;
            options.probe_input = probe_input_->currentData().toInt();
            if (orient_ != nullptr && orient_->isEnabled()) {
                options.orient_180_command = orient_->text().trimmed().toStdString();
            }
            program_ = QString::fromStdString(
                write_program(*plan_, dialect(dialect_id()), date_, options));
        }
    } catch (const InputError& e) {
        plan_.reset();
        refusal_ = e.to_message();
    }
    preview_->setPlainText(program_);
    save_button_->setEnabled(can_save());
    keep_translated(status_, [this] { status_->hide(); });  // "Saved" was of the old program
    show_problem();
}

QString ProgramDialog::program_text() const {
    return program_;
}

bool ProgramDialog::can_save() const {
    return plan_.has_value() && !program_.isEmpty();
}

// The option a refusal names ("feeds"), as this dialog labels it.
QString ProgramDialog::field_label(const std::string& key) const {
    const std::pair<const char*, QLabel*> labels[] = {{"feeds", feeds_label_},
                                                      {"repeats", repeats_label_},
                                                      {"margin_mm", margin_label_},
                                                      {"placement_mm", placement_label_},
                                                      {"gauge_diameter_mm", gauge_label_},
                                                      {"ball_diameter_mm", ball_label_},
                                                      {"centre_tolerance_mm", tolerance_label_},
                                                      {"--orient-180", orient_label_},
                                                      {"--probe-input", probe_input_label_},
                                                      {"axis", axis_label_}};
    for (const auto& [name, label] : labels) {
        if (key == name && label) return label->text();
    }
    return QString::fromStdString(key);
}

QString ProgramDialog::problem() const {
    if (!bad_feed_.isEmpty()) {
        //: %1 the label of the feeds box, %2 what it holds
        return tr("%1: “%2” are not numbers separated by semicolons or spaces")
            .arg(field_label("feeds"), bad_feed_);
    }
    if (!refusal_) return {};
    Message shown = *refusal_;
    // A refused option: the core's key ("margin_mm") in the dialog's words.
    if (!shown.args.empty() && shown.args.front().name == "key") {
        shown.args.front().text = field_label(shown.args.front().text).toStdString();
    }
    return translate(shown);
}

void ProgramDialog::show_problem() {
    const bool refused = !bad_feed_.isEmpty() || refusal_.has_value();
    show_live_error(problem_label_, refused ? LiveText([this] { return problem(); }) : LiveText());
}

bool ProgramDialog::save(const QString& path) {
    if (update_timer_->isActive()) update_now();
    if (!can_save()) {
        last_error_ = problem();
        return false;
    }
    const QString plan_path = plan_path_for(path);
    // The plan first: a program without its plan cannot be imported.
    const std::pair<QString, QByteArray> files[] = {
        {plan_path, QByteArray::fromStdString(probing_plan_json(*plan_))},
        {path, program_.toUtf8()}};
    for (const auto& file : files) {
        QString reason;
        if (!write_file(file.first, file.second, reason)) {
            const auto message = [name = file.first, reason] {
                return tr("%1 could not be written: %2")
                    .arg(QDir::toNativeSeparators(name), reason);
            };
            last_error_ = message();
            show_live_error(status_, message);
            return false;
        }
    }
    remember_folder_of(path);
    last_error_.clear();
    keep_translated(status_, [this, program = QFileInfo(path).fileName(),
                              plan = QFileInfo(plan_path).fileName()] {
        status_->setStyleSheet({});
        //: %1 the program's file, %2 its plan's
        status_->setText(tr("Saved %1 and its plan %2").arg(program, plan));
        status_->show();
    });
    emit saved(path, plan_path, dialect_id());
    return true;
}

void ProgramDialog::save_dialog() {
    const Dialect& chosen = dialect(dialect_id());
    const QString extension = QString::fromUtf8(chosen.extension);
    const QString name = QString::fromUtf8(to_string(kind_)) + QLatin1Char('.') + extension;
    //: %1 the control ("LinuxCNC"), %2 the program's extension ("ngc")
    const QString filter =
        tr("%1 programs (*.%2);;All files (*)").arg(QString::fromUtf8(chosen.title), extension);
    QString path =
        QFileDialog::getSaveFileName(this, tr("Save program"), dialog_start(name), filter);
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QLatin1Char('.') + extension;
    save(path);
}

}  // namespace probecycle::ui
