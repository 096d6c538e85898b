#pragma once

// File > "Report Details…": the PDF report's title block (customer, machine,
// part, author, notes), which the project file keeps (core/project/
// project_file.h, ReportDetails) and the report shows at the top of its first
// page. The fields are plain text, kept as typed.

#include <QDialog>
#include <QList>
#include <QStringList>

#include "core/project/project_file.h"

class QDialogButtonBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QPlainTextEdit;

namespace probecycle::ui {

class ReportDetailsDialog : public QDialog {
    Q_OBJECT

  public:
    explicit ReportDetailsDialog(const ReportDetails& details, QWidget* parent = nullptr);

    void set_details(const ReportDetails& details);
    ReportDetails details() const;

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslate();

    QLabel* note_{nullptr};
    QFormLayout* form_{nullptr};
    QLineEdit* customer_{nullptr};
    QLineEdit* machine_{nullptr};
    QLineEdit* part_{nullptr};
    QLineEdit* author_{nullptr};
    QPlainTextEdit* notes_{nullptr};
    QDialogButtonBox* buttons_{nullptr};
};

// The title block's fields that are filled in, as {label, value} pairs in
// the interface's language, in the dialog's order.
QList<QStringList> report_detail_rows(const ReportDetails& details);

}  // namespace probecycle::ui
