#include "ui/window/report_details_dialog.h"

#include <QDialogButtonBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QVBoxLayout>
#include <string>

namespace probecycle::ui {

namespace {

QString from(const std::string& text) {
    return QString::fromStdString(text);
}

// The fields' names, one place for the dialog and the report.
QString customer_label() {
    return ReportDetailsDialog::tr("Customer");
}
QString machine_label() {
    return ReportDetailsDialog::tr("Machine");
}
QString part_label() {
    return ReportDetailsDialog::tr("Part");
}
QString author_label() {
    return ReportDetailsDialog::tr("Author");
}
QString notes_label() {
    return ReportDetailsDialog::tr("Notes");
}

}  // namespace

ReportDetailsDialog::ReportDetailsDialog(const ReportDetails& details, QWidget* parent)
    : QDialog(parent) {
    setObjectName(QStringLiteral("ReportDetailsDialog"));
    note_ = new QLabel(this);
    note_->setWordWrap(true);
    customer_ = new QLineEdit(this);
    machine_ = new QLineEdit(this);
    part_ = new QLineEdit(this);
    author_ = new QLineEdit(this);
    notes_ = new QPlainTextEdit(this);
    notes_->setTabChangesFocus(true);
    for (QLineEdit* edit : {customer_, machine_, part_, author_}) edit->setMinimumWidth(320);
    buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(note_);
    form_ = new QFormLayout;
    for (QWidget* field : {static_cast<QWidget*>(customer_), static_cast<QWidget*>(machine_),
                           static_cast<QWidget*>(part_), static_cast<QWidget*>(author_),
                           static_cast<QWidget*>(notes_)}) {
        form_->addRow(new QLabel(this), field);
    }
    layout->addLayout(form_);
    layout->addWidget(buttons_);
    set_details(details);
    retranslate();
}

void ReportDetailsDialog::set_details(const ReportDetails& details) {
    customer_->setText(from(details.customer));
    machine_->setText(from(details.machine));
    part_->setText(from(details.part));
    author_->setText(from(details.author));
    notes_->setPlainText(from(details.notes));
}

ReportDetails ReportDetailsDialog::details() const {
    return {customer_->text().toStdString(), machine_->text().toStdString(),
            part_->text().toStdString(), author_->text().toStdString(),
            notes_->toPlainText().toStdString()};
}

void ReportDetailsDialog::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QDialog::changeEvent(event);
}

void ReportDetailsDialog::retranslate() {
    setWindowTitle(tr("Report Details"));
    note_->setText(
        tr("Shown at the top of the PDF report's first page, with the date and the program's "
           "version. Saved in the project file."));
    const QStringList labels = {customer_label(), machine_label(), part_label(), author_label(),
                                notes_label()};
    for (int row = 0; row < form_->rowCount(); ++row) {
        if (auto* label =
                qobject_cast<QLabel*>(form_->itemAt(row, QFormLayout::LabelRole)->widget())) {
            label->setText(labels.value(row));
        }
    }
}

QList<QStringList> report_detail_rows(const ReportDetails& details) {
    QList<QStringList> rows;
    const auto add = [&rows](const QString& label, const std::string& value) {
        const QString text = from(value).trimmed();
        if (!text.isEmpty()) rows.append({label, text});
    };
    add(customer_label(), details.customer);
    add(machine_label(), details.machine);
    add(part_label(), details.part);
    add(author_label(), details.author);
    add(notes_label(), details.notes);
    return rows;
}

}  // namespace probecycle::ui
