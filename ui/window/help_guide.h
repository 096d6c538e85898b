#pragma once

// The in-window guide (Help > Guide, F1): getting started (what to enter
// first, what the readouts mean, where the numbers come from), what each
// phase means, how to read the charts, how to measure the delay, with the formulas the
// tooltips show, in the interface language, and where the README says more.

#include <QDialog>
#include <QString>

class QTextBrowser;

namespace probecycle::ui {

// The guide as HTML in the current language. `readme_path`: the README to
// link to (no link when empty).
QString help_guide_html(const QString& readme_path);

class HelpGuide : public QDialog {
    Q_OBJECT

  public:
    explicit HelpGuide(QWidget* parent = nullptr);
    QString html() const;

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslate();
    QTextBrowser* text_{nullptr};
};

}  // namespace probecycle::ui
