#include "ui/cycle/parameter_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QResizeEvent>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <string_view>

#include "core/cycle/cycle.h"
#include "ui/common/parameter_info.h"
#include "ui/common/quantity_edit.h"

namespace probecycle::ui {

namespace {

QComboBox* make_combo(const QString& name, QWidget* parent) {
    auto* combo = new QComboBox(parent);
    combo->setObjectName(name);
    combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    combo->setMinimumContentsLength(12);
    return combo;
}

QHBoxLayout* labelled_row(QLabel* label, QWidget* editor) {
    auto* row = new QHBoxLayout;
    row->setContentsMargins(0, 0, 0, 0);
    // The box gets the larger share: its word is cut, a label wraps.
    row->addWidget(label, 1);
    row->addWidget(editor, 2);
    label->setWordWrap(true);
    label->setBuddy(editor);
    return row;
}

}  // namespace

ParameterPanel::ParameterPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 4, 6, 4);
    layout->setSpacing(4);

    note_ = new QLabel(this);
    note_->setWordWrap(true);
    note_->setObjectName(QStringLiteral("typical-values-note"));
    QFont note_font = note_->font();
    note_font.setItalic(true);
    note_->setFont(note_font);
    layout->addWidget(note_);

    machine_box_ = new QGroupBox(this);
    probe_box_ = new QGroupBox(this);
    cycle_box_ = new QGroupBox(this);
    auto* machine = new QVBoxLayout(machine_box_);
    auto* probe = new QVBoxLayout(probe_box_);
    auto* cycle = new QVBoxLayout(cycle_box_);
    for (QVBoxLayout* box : {machine, probe, cycle}) {
        box->setSpacing(3);
        box->setContentsMargins(6, 4, 6, 4);
    }

    accel_label_ = new QLabel(machine_box_);
    accel_model_ = make_combo(QStringLiteral("combo:machine.accel_model"), machine_box_);
    machine->addLayout(labelled_row(accel_label_, accel_model_));
    strategy_label_ = new QLabel(cycle_box_);
    strategy_ = make_combo(QStringLiteral("combo:cycle.strategy"), cycle_box_);
    cycle->addLayout(labelled_row(strategy_label_, strategy_));
    feature_label_ = new QLabel(cycle_box_);
    feature_ = make_combo(QStringLiteral("combo:cycle.feature"), cycle_box_);
    cycle->addLayout(labelled_row(feature_label_, feature_));

    // Every numeric key of the core, in file order, in its section.
    for (const KeyInfo& info : numeric_keys()) {
        const QString section = section_of(info.key);
        QGroupBox* box = section == QLatin1String("machine") ? machine_box_
                         : section == QLatin1String("probe") ? probe_box_
                                                             : cycle_box_;
        auto* edit = new QuantityEdit(info, box);
        qobject_cast<QVBoxLayout*>(box->layout())->addWidget(edit);
        edits_.push_back(edit);
        if (info.key == std::string_view("machine.max_jerk_mm_s3")) {
            // The filter after interpolation, after the plan's keys, before its own.
            filter_row_ = new QWidget(box);
            filter_label_ = new QLabel(filter_row_);
            filter_ = make_combo(QStringLiteral("combo:machine.filter"), filter_row_);
            filter_row_->setLayout(labelled_row(filter_label_, filter_));
            qobject_cast<QVBoxLayout*>(box->layout())->addWidget(filter_row_);
        }
        if (info.key == std::string_view("cycle.backoff_mm")) {
            // Where the backoff is measured from, right under it.
            backoff_from_row_ = new QWidget(box);
            backoff_from_label_ = new QLabel(backoff_from_row_);
            backoff_from_ =
                make_combo(QStringLiteral("combo:cycle.backoff_from"), backoff_from_row_);
            backoff_from_row_->setLayout(labelled_row(backoff_from_label_, backoff_from_));
            qobject_cast<QVBoxLayout*>(box->layout())->addWidget(backoff_from_row_);
        }
        if (info.key == std::string_view("cycle.size_tolerance_mm")) {
            // What the program does out of tolerance, right under it.
            tolerance_action_row_ = new QWidget(box);
            tolerance_action_label_ = new QLabel(tolerance_action_row_);
            tolerance_action_ =
                make_combo(QStringLiteral("combo:cycle.tolerance_action"), tolerance_action_row_);
            tolerance_action_row_->setLayout(
                labelled_row(tolerance_action_label_, tolerance_action_));
            qobject_cast<QVBoxLayout*>(box->layout())->addWidget(tolerance_action_row_);
        }
        connect(edit, &QuantityEdit::edited, this, [this, edit](double value) {
            set_number(scenario_, edit->key().toStdString(), value);
            emit_edit(edit->key());
        });
    }
    latched_ = new QCheckBox(machine_box_);
    latched_->setObjectName(QStringLiteral("check:machine.latched_input"));
    machine->addWidget(latched_);

    columns_ = new QHBoxLayout;
    columns_->setSpacing(0);
    first_column_ = new QVBoxLayout;
    second_column_ = new QVBoxLayout;
    for (QBoxLayout* column : {first_column_, second_column_}) {
        column->setSpacing(4);
        columns_->addLayout(column, column == first_column_ ? 1 : 0);
    }
    first_column_->addWidget(machine_box_);
    first_column_->addWidget(probe_box_);
    first_column_->addWidget(cycle_box_);
    first_column_->addStretch(1);
    second_column_->addStretch(1);
    layout->addLayout(columns_, 1);

    connect(accel_model_, &QComboBox::activated, this, [this](int index) {
        scenario_.machine.accel_model =
            static_cast<AccelModel>(accel_model_->itemData(index).toInt());
        emit_edit(QStringLiteral("machine.accel_model"));
    });
    connect(filter_, &QComboBox::activated, this, [this](int index) {
        scenario_.machine.filter = static_cast<FilterKind>(filter_->itemData(index).toInt());
        emit_edit(QStringLiteral("machine.filter"));
    });
    connect(strategy_, &QComboBox::activated, this, [this](int index) {
        scenario_.cycle.strategy = static_cast<Strategy>(strategy_->itemData(index).toInt());
        emit_edit(QStringLiteral("cycle.strategy"));
    });
    connect(feature_, &QComboBox::activated, this, [this](int index) {
        scenario_.cycle.feature = static_cast<Feature>(feature_->itemData(index).toInt());
        emit_edit(QStringLiteral("cycle.feature"));
    });
    connect(backoff_from_, &QComboBox::activated, this, [this](int index) {
        scenario_.cycle.backoff_from =
            static_cast<BackoffFrom>(backoff_from_->itemData(index).toInt());
        emit_edit(QStringLiteral("cycle.backoff_from"));
    });
    connect(tolerance_action_, &QComboBox::activated, this, [this](int index) {
        scenario_.cycle.tolerance_action =
            static_cast<ToleranceAction>(tolerance_action_->itemData(index).toInt());
        emit_edit(QStringLiteral("cycle.tolerance_action"));
    });
    connect(latched_, &QCheckBox::clicked, this, [this](bool checked) {
        scenario_.machine.latched_input = checked;
        emit_edit(QStringLiteral("machine.latched_input"));
    });

    retranslate();
    set_scenario(scenario_);
}

void ParameterPanel::retranslate() {
    note_->setText(tr("Typical values: replace them with your measured ones."));
    note_->setToolTip(
        tr("The defaults and the presets are typical values for a machining centre "
           "and its probe. Replace them with the ones measured on your machine."));
    machine_box_->setTitle(section_label(QStringLiteral("machine")));
    probe_box_->setTitle(section_label(QStringLiteral("probe")));
    cycle_box_->setTitle(section_label(QStringLiteral("cycle")));
    // Labels and help of the word and flag keys: the core's key table.
    const auto label_of = [](const char* key) {
        return QCoreApplication::translate("Parameter", find_any_key(key)->label);
    };
    const auto help_of = [](const char* key) {
        return QCoreApplication::translate("Parameter", find_any_key(key)->description);
    };
    accel_label_->setText(label_of("machine.accel_model"));
    filter_label_->setText(label_of("machine.filter"));
    for (QWidget* w : {static_cast<QWidget*>(filter_label_), static_cast<QWidget*>(filter_)}) {
        w->setToolTip(help_of("machine.filter"));
    }
    strategy_label_->setText(label_of("cycle.strategy"));
    feature_label_->setText(label_of("cycle.feature"));
    backoff_from_label_->setText(label_of("cycle.backoff_from"));
    for (QWidget* w :
         {static_cast<QWidget*>(backoff_from_label_), static_cast<QWidget*>(backoff_from_)}) {
        w->setToolTip(help_of("cycle.backoff_from"));
    }
    tolerance_action_label_->setText(label_of("cycle.tolerance_action"));
    for (QWidget* w : {static_cast<QWidget*>(tolerance_action_label_),
                       static_cast<QWidget*>(tolerance_action_)}) {
        w->setToolTip(help_of("cycle.tolerance_action"));
    }
    latched_->setText(label_of("machine.latched_input"));
    for (QWidget* w : {static_cast<QWidget*>(accel_label_), static_cast<QWidget*>(accel_model_)}) {
        w->setToolTip(help_of("machine.accel_model"));
    }
    for (QWidget* w : {static_cast<QWidget*>(strategy_label_), static_cast<QWidget*>(strategy_)}) {
        w->setToolTip(help_of("cycle.strategy"));
    }
    for (QWidget* w : {static_cast<QWidget*>(feature_label_), static_cast<QWidget*>(feature_)}) {
        w->setToolTip(help_of("cycle.feature"));
    }
    latched_->setToolTip(help_of("machine.latched_input"));

    {
        const QSignalBlocker b1(accel_model_);
        const QSignalBlocker b2(strategy_);
        const QSignalBlocker b3(feature_);
        const QSignalBlocker b4(backoff_from_);
        const QSignalBlocker b5(filter_);
        const QSignalBlocker b6(tolerance_action_);
        tolerance_action_->clear();
        for (ToleranceAction a : {ToleranceAction::flag, ToleranceAction::stop}) {
            tolerance_action_->addItem(tolerance_action_label(a), static_cast<int>(a));
        }
        accel_model_->clear();
        for (AccelModel m : {AccelModel::time_constant, AccelModel::constant_accel,
                             AccelModel::jerk_limited, AccelModel::none}) {
            accel_model_->addItem(accel_model_label(m), static_cast<int>(m));
        }
        filter_->clear();
        for (FilterKind k :
             {FilterKind::none, FilterKind::linear, FilterKind::exponential, FilterKind::bell}) {
            filter_->addItem(filter_label(k), static_cast<int>(k));
        }
        strategy_->clear();
        for (Strategy s : {Strategy::single_touch, Strategy::two_touch}) {
            strategy_->addItem(strategy_label(s), static_cast<int>(s));
        }
        feature_->clear();
        for (Feature f :
             {Feature::surface, Feature::web, Feature::pocket, Feature::bore, Feature::boss}) {
            feature_->addItem(feature_label(f), static_cast<int>(f));
        }
        backoff_from_->clear();
        for (BackoffFrom f : {BackoffFrom::stop, BackoffFrom::trigger}) {
            backoff_from_->addItem(backoff_from_label(f), static_cast<int>(f));
        }
    }
    for (QuantityEdit* edit : edits_) edit->retranslate();
    set_scenario(scenario_);
}

void ParameterPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void ParameterPanel::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    set_two_columns(width() >= two_column_width());
}

void ParameterPanel::set_two_columns(bool two) {
    if (two == two_columns_) return;
    two_columns_ = two;
    if (two) {
        second_column_->insertWidget(0, cycle_box_);
    } else {
        first_column_->insertWidget(2, cycle_box_);
    }
    columns_->setStretch(1, two ? 1 : 0);
    columns_->setSpacing(two ? 6 : 0);
}

int ParameterPanel::one_column_height() const {
    const QMargins margins = layout()->contentsMargins();
    int height = margins.top() + margins.bottom() + note_->sizeHint().height();
    for (const QGroupBox* box : {machine_box_, probe_box_, cycle_box_}) {
        height += layout()->spacing() + box->sizeHint().height();
    }
    return height;
}

void ParameterPanel::set_scenario(const Scenario& scenario) {
    scenario_ = scenario;
    for (QuantityEdit* edit : edits_) {
        if (const auto value = get_number(scenario_, edit->key().toStdString())) {
            edit->set_value(*value);
        }
    }
    const QSignalBlocker b1(accel_model_);
    const QSignalBlocker b2(strategy_);
    const QSignalBlocker b3(feature_);
    const QSignalBlocker b4(latched_);
    const QSignalBlocker b5(backoff_from_);
    const QSignalBlocker b6(filter_);
    const QSignalBlocker b7(tolerance_action_);
    tolerance_action_->setCurrentIndex(
        tolerance_action_->findData(static_cast<int>(scenario_.cycle.tolerance_action)));
    filter_->setCurrentIndex(filter_->findData(static_cast<int>(scenario_.machine.filter)));
    accel_model_->setCurrentIndex(
        accel_model_->findData(static_cast<int>(scenario_.machine.accel_model)));
    strategy_->setCurrentIndex(strategy_->findData(static_cast<int>(scenario_.cycle.strategy)));
    feature_->setCurrentIndex(feature_->findData(static_cast<int>(scenario_.cycle.feature)));
    backoff_from_->setCurrentIndex(
        backoff_from_->findData(static_cast<int>(scenario_.cycle.backoff_from)));
    latched_->setChecked(scenario_.machine.latched_input);
    update_enabled();
}

void ParameterPanel::update_enabled() {
    // Keys the current model, strategy or feature does not use are hidden, so the
    // panel fits a 1280x800 screen; they come back with the model that uses them.
    for (QuantityEdit* edit : edits_) {
        edit->setVisible(key_applies(scenario_, edit->key().toStdString()));
    }
    tolerance_action_row_->setVisible(key_applies(scenario_, "cycle.tolerance_action"));
    backoff_from_row_->setVisible(key_applies(scenario_, "cycle.backoff_from"));
}

void ParameterPanel::emit_edit(const QString& key) {
    update_enabled();
    emit edited(scenario_, key);
}

}  // namespace probecycle::ui
