#include "ui/program/machine_log_import.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>
#include <string>
#include <utility>

#include "core/common/file_io.h"
#include "core/cycle/scenario.h"
#include "core/program/machine_log.h"
#include "ui/common/file_write.h"
#include "ui/program/program_dialog.h"

namespace probecycle::ui {

namespace {

QString tr_log(const char* text) {
    return QCoreApplication::translate("probecycle::ui::MachineLogDialog", text);
}

QString kind_title(ProgramKind kind) {
    switch (kind) {
        case ProgramKind::delay:
            return tr_log(
                QT_TRANSLATE_NOOP("probecycle::ui::MachineLogDialog", "delay-stability test"));
        case ProgramKind::ring:
            return tr_log(
                QT_TRANSLATE_NOOP("probecycle::ui::MachineLogDialog", "ring-gauge calibration"));
        case ProgramKind::cycle:
            return tr_log(QT_TRANSLATE_NOOP("probecycle::ui::MachineLogDialog", "tuned cycle"));
    }
    return {};
}

// A file's text by core's reader (the CLI's size limit and reasons).
std::string read_file(const QString& path) {
    return read_text_file(core_path(path));
}

}  // namespace

std::optional<QString> machine_log_csv(const MachineLogChoice& choice, ProgramKind kind,
                                       LiveText& error) {
    const QString plan_name = QFileInfo(choice.plan_path).fileName();
    const QString log_name = QFileInfo(choice.log_path).fileName();
    ProbingPlan plan;
    try {
        plan = parse_probing_plan(read_file(choice.plan_path));
    } catch (const PlanError&) {
        error = [plan_name, text = current_error_text()] {
            //: %1 the plan file, %2 what is wrong in it (one problem a line)
            return tr_log(QT_TRANSLATE_NOOP("probecycle::ui::MachineLogDialog",
                                            "%1 is not a probing plan:\n%2"))
                .arg(plan_name, text());
        };
        return std::nullopt;
    } catch (const std::exception&) {
        error = current_error_text();
        return std::nullopt;
    }
    if (plan.kind != kind) {
        error = [plan_name, planned = plan.kind, kind] {
            //: %1 the plan file, %2 its program ("ring-gauge calibration"), %3 this tab's
            return tr_log(QT_TRANSLATE_NOOP("probecycle::ui::MachineLogDialog",
                                            "%1 is the plan of a %2 program; this tab reads the "
                                            "log of a %3 program."))
                .arg(plan_name, kind_title(planned), kind_title(kind));
        };
        return std::nullopt;
    }
    try {
        return QString::fromStdString(
            import_machine_log(plan, choice.dialect, read_file(choice.log_path)));
    } catch (const FileError&) {
        error = current_error_text();
    } catch (const std::exception&) {
        // The core names the line; the file is named here.
        error = [log_name, text = current_error_text()] {
            //: %1 the machine log's file, %2 the problem with its line
            return tr_log(QT_TRANSLATE_NOOP("probecycle::ui::MachineLogDialog", "%1: %2"))
                .arg(log_name, text());
        };
    }
    return std::nullopt;
}

bool import_machine_log_into(QPlainTextEdit* editor, const MachineLogChoice& choice,
                             ProgramKind kind, std::optional<ImportedText>& imported,
                             const std::function<bool(const QString&, const QString&)>& fit_text,
                             const std::function<void(LiveText)>& show_error) {
    LiveText error;
    const std::optional<QString> csv = machine_log_csv(choice, kind, error);
    if (!csv) {
        show_error(std::move(error));
        return false;
    }
    const QString name = QFileInfo(choice.log_path).fileName();
    // Fitted before the paste box changes: a CSV that does not fit leaves it as it was.
    std::optional<ImportedText> previous = std::exchange(imported, ImportedText{name, *csv});
    if (!fit_text(*csv, name)) {
        imported = std::move(previous);
        return false;
    }
    replace_text_undoably(editor, *csv);
    remember_folder_of(choice.log_path);
    return true;
}

ProgramDialog* open_program_dialog(QWidget* tab, ProgramKind kind, const Scenario& scenario,
                                   MachineLogChoice& next_import) {
    auto* dialog = new ProgramDialog(kind, scenario, tab);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->set_dialect(next_import.dialect);
    QObject::connect(dialog, &ProgramDialog::saved, tab,
                     [&next_import](const QString&, const QString& plan_path, DialectId id) {
                         next_import.dialect = id;
                         next_import.plan_path = plan_path;
                         next_import.log_path.clear();  // the old log is not of this plan
                     });
    dialog->open();
    return dialog;
}

void open_machine_log_dialog(QWidget* tab, ProgramKind kind, MachineLogChoice& last,
                             std::function<bool(const MachineLogChoice&)> import) {
    auto* dialog = new MachineLogDialog(kind, tab);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->set_choice(last);
    QObject::connect(dialog, &QDialog::accepted, tab, [dialog, &last, import = std::move(import)] {
        last = dialog->choice();
        import(last);
    });
    dialog->open();
}

MachineLogDialog::MachineLogDialog(ProgramKind kind, QWidget* parent)
    : QDialog(parent), kind_(kind) {
    setObjectName(QStringLiteral("machine-log-dialog"));
    intro_ = new QLabel(this);
    intro_->setWordWrap(true);
    dialect_ = new QComboBox(this);
    dialect_->setObjectName(QStringLiteral("log-dialect"));
    for (DialectId id : program_dialects()) {
        dialect_->addItem(QString::fromUtf8(dialect(id).title), static_cast<int>(id));
    }
    dialect_label_ = new QLabel(this);
    dialect_label_->setBuddy(dialect_);
    dialect_hint_ = new QLabel(this);
    dialect_hint_->setWordWrap(true);
    plan_path_ = new QLineEdit(this);
    plan_path_->setObjectName(QStringLiteral("log-plan"));
    plan_label_ = new QLabel(this);
    plan_label_->setBuddy(plan_path_);
    plan_browse_ = new QPushButton(this);
    log_path_ = new QLineEdit(this);
    log_path_->setObjectName(QStringLiteral("log-file"));
    log_label_ = new QLabel(this);
    log_label_->setBuddy(log_path_);
    log_browse_ = new QPushButton(this);

    auto* grid = new QGridLayout;
    grid->addWidget(dialect_label_, 0, 0);
    grid->addWidget(dialect_, 0, 1, Qt::AlignLeft);
    grid->addWidget(dialect_hint_, 1, 1, 1, 2);
    grid->addWidget(plan_label_, 2, 0);
    grid->addWidget(plan_path_, 2, 1);
    grid->addWidget(plan_browse_, 2, 2);
    grid->addWidget(log_label_, 3, 0);
    grid->addWidget(log_path_, 3, 1);
    grid->addWidget(log_browse_, 3, 2);
    grid->setColumnStretch(1, 1);

    import_button_ = new QPushButton(this);
    import_button_->setObjectName(QStringLiteral("log-import"));
    import_button_->setDefault(true);
    cancel_button_ = new QPushButton(this);
    auto* buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(import_button_);
    buttons->addWidget(cancel_button_);

    auto* root = new QVBoxLayout(this);
    root->addWidget(intro_);
    root->addLayout(grid);
    root->addStretch(1);
    root->addLayout(buttons);
    resize(640, 280);

    connect(dialect_, &QComboBox::currentIndexChanged, this, &MachineLogDialog::retranslate);
    connect(plan_path_, &QLineEdit::textChanged, this, &MachineLogDialog::update_buttons);
    connect(log_path_, &QLineEdit::textChanged, this, &MachineLogDialog::update_buttons);
    connect(plan_browse_, &QPushButton::clicked, this, &MachineLogDialog::browse_plan);
    connect(log_browse_, &QPushButton::clicked, this, &MachineLogDialog::browse_log);
    connect(import_button_, &QPushButton::clicked, this, &QDialog::accept);
    connect(cancel_button_, &QPushButton::clicked, this, &QDialog::reject);
    retranslate();
    update_buttons();
}

void MachineLogDialog::retranslate() {
    setWindowTitle(tr("Import machine log"));
    //: %1 the program ("delay-stability test")
    intro_->setText(tr("What the control recorded while it ran a %1 program of ProbeCycle's, "
                       "with the plan saved beside the program. The positions fill the paste "
                       "box and are fitted; on any problem nothing changes.")
                        .arg(kind_title(kind_)));
    dialect_label_->setText(tr("Control"));
    // A dialect the core adds later shows no hint until one is written here.
    const auto chosen = static_cast<DialectId>(dialect_->currentData().toInt());
    dialect_hint_->setText(
        chosen == DialectId::linuxcnc
            ? tr("The log the program writes: probecycle_log.txt in LinuxCNC's working "
                 "directory.")
        : chosen == DialectId::grbl
            ? tr("The sender's console saved to a file: grbl answers [PRB:x,y,z:1] after each "
                 "probe (set $13=0 for mm).")
        : chosen == DialectId::fanuc || chosen == DialectId::haas
            ? tr("The program's DPRNT output as the control sent it (a serial terminal, a memory "
                 "card or a file): the lines from PROBECYCLE PLAN on.")
        : chosen == DialectId::siemens
            ? tr("The file PROBECYCLE_LOG that the program's WRITE appends to, copied from the "
                 "control: its last run is read.")
        : chosen == DialectId::mitsubishi
            ? tr("The common variables #500 to #999 after the program ended, as the control "
                 "outputs them or copied from its variable screen: one line \"#n value\" each.")
            : QString());
    plan_label_->setText(tr("Plan"));
    plan_path_->setPlaceholderText(tr("NAME.plan.json, saved with the program"));
    plan_browse_->setText(tr("Browse…"));
    log_label_->setText(tr("Log"));
    log_browse_->setText(tr("Browse…"));
    import_button_->setText(tr("Import"));
    cancel_button_->setText(tr("Cancel"));
}

void MachineLogDialog::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QDialog::changeEvent(event);
}

void MachineLogDialog::set_choice(const MachineLogChoice& choice) {
    dialect_->setCurrentIndex(std::max(dialect_->findData(static_cast<int>(choice.dialect)), 0));
    plan_path_->setText(QDir::toNativeSeparators(choice.plan_path));
    log_path_->setText(QDir::toNativeSeparators(choice.log_path));
}

MachineLogChoice MachineLogDialog::choice() const {
    MachineLogChoice out;
    out.dialect = static_cast<DialectId>(dialect_->currentData().toInt());
    out.plan_path = QDir::fromNativeSeparators(plan_path_->text().trimmed());
    out.log_path = QDir::fromNativeSeparators(log_path_->text().trimmed());
    return out;
}

void MachineLogDialog::update_buttons() {
    const MachineLogChoice chosen = choice();
    import_button_->setEnabled(!chosen.plan_path.isEmpty() && !chosen.log_path.isEmpty());
}

void MachineLogDialog::browse_plan() {
    const QString start = plan_path_->text().isEmpty() ? dialog_start() : plan_path_->text();
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Choose the plan"), start,
                                     tr("Probing plans (*.plan.json *.json);;All files (*)"));
    if (path.isEmpty()) return;
    remember_folder_of(path);
    plan_path_->setText(QDir::toNativeSeparators(path));
}

void MachineLogDialog::browse_log() {
    const QString start = log_path_->text().isEmpty() ? dialog_start() : log_path_->text();
    const QString path = QFileDialog::getOpenFileName(this, tr("Choose the machine log"), start,
                                                      tr("Logs (*.txt *.log);;All files (*)"));
    if (path.isEmpty()) return;
    remember_folder_of(path);
    log_path_->setText(QDir::toNativeSeparators(path));
}

}  // namespace probecycle::ui
