#include "ui/lab/fit_input.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>
#include <utility>

#include "ui/common/file_write.h"
#include "ui/common/status_text.h"

namespace probecycle::ui {

FitInput::FitInput(ProgramKind kind, Names names, QWidget* owner, QString& last_error,
                   std::function<bool()> has_result)
    : QObject(owner),
      kind_(kind),
      names_(names),
      owner_(owner),
      last_error_(last_error),
      has_result_(std::move(has_result)) {}

QPlainTextEdit* FitInput::make_editor(QWidget* parent) {
    editor_ = make_csv_editor(parent);
    editor_->setObjectName(QString::fromLatin1(names_.editor));
    return editor_;
}

void FitInput::make_buttons(QWidget* parent) {
    import_button_ = new QPushButton(parent);
    fit_button_ = new QPushButton(parent);
    example_button_ = new QPushButton(parent);
    program_button_ = new QPushButton(parent);
    program_button_->setObjectName(QString::fromLatin1(names_.program));
    log_button_ = new QPushButton(parent);
    log_button_->setObjectName(QString::fromLatin1(names_.log));
    error_label_ = new QLabel(parent);
    error_label_->setObjectName(QString::fromLatin1(names_.error));
    error_label_->setWordWrap(true);
    error_label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    error_label_->hide();
    connect(fit_button_, &QPushButton::clicked, this, [this] { fit(); });
    connect(example_button_, &QPushButton::clicked, this, [this] { load_example(); });
    connect(log_button_, &QPushButton::clicked, this, &FitInput::import_machine_log_dialog);
}

void FitInput::add_buttons_to(QVBoxLayout* column) {
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(import_button_);
    buttons->addWidget(example_button_);
    buttons->addStretch(1);
    buttons->addWidget(fit_button_);
    auto* machine_buttons = new QHBoxLayout;
    machine_buttons->addWidget(program_button_);
    machine_buttons->addWidget(log_button_);
    machine_buttons->addStretch(1);
    column->addLayout(buttons);
    column->addLayout(machine_buttons);
    column->addWidget(error_label_);
}

void FitInput::retranslate() {
    import_button_->setText(tr("Import CSV…"));
    fit_button_->setText(tr("Fit"));
    example_button_->setText(tr("Example data"));
    example_button_->setToolTip(
        tr("Touches simulated for the probe and machine of the scenario, with a known answer: "
           "to try the fit before measuring your own."));
    program_button_->setText(tr("Program…"));
    log_button_->setText(tr("Import machine log…"));
}

bool FitInput::fit() {
    return fit_text_(editor_->toPlainText(), QString());
}

bool FitInput::load_example() {
    if (!example_text_) return false;
    const QString text = example_text_();
    editor_->setPlainText(text);
    imported_ = ImportedText{QStringLiteral("example"), text};
    return fit_text_(text, QString());
}

bool FitInput::import_file(const QString& path) {
    LiveText error;
    const std::optional<QString> text = import_csv_into(editor_, path, error);
    if (!text) {
        set_error(error);
        return false;
    }
    remember_folder_of(path);
    imported_ = ImportedText{QFileInfo(path).fileName(), *text};
    return fit_text_(*text, QFileInfo(path).fileName());
}

void FitInput::import_dialog(const QString& title) {
    const QString path = QFileDialog::getOpenFileName(owner_, title, dialog_start(),
                                                      tr("CSV files (*.csv);;All files (*)"));
    if (!path.isEmpty()) import_file(path);
}

bool FitInput::import_machine_log(const MachineLogChoice& choice) {
    log_choice_ = choice;
    return import_machine_log_into(editor_, choice, kind_, imported_, fit_text_,
                                   [this](LiveText error) { set_error(std::move(error)); });
}

void FitInput::import_machine_log_dialog() {
    open_machine_log_dialog(owner_, kind_, log_choice_, [this](const MachineLogChoice& choice) {
        return import_machine_log(choice);
    });
}

ProgramDialog* FitInput::open_program_dialog(const Scenario& scenario) {
    return ui::open_program_dialog(owner_, kind_, scenario, log_choice_);
}

void FitInput::set_error(LiveText text) {
    // Built again after a language switch, with the note as it stood.
    const bool previous = text && has_result_();
    show_live_error(error_label_, [this, text = std::move(text), previous] {
        last_error_ = text ? text() : QString();
        return previous ? last_error_ + QLatin1Char('\n') +
                              tr("The result shown is still that of the previous fit.")
                        : last_error_;
    });
}

void FitInput::show_fit_error(const QString& source) {
    // CsvError names the line and column; InputError says what is wrong.
    LiveText message = current_error_text();
    if (!source.isEmpty()) {
        message = [source, message] { return tr("%1: %2").arg(source, message()); };
    }
    set_error(std::move(message));
}

std::string FitInput::source_of(const QString& text) const {
    return data_source_name(imported_, text);
}

}  // namespace probecycle::ui
