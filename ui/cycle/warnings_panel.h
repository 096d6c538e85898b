#pragma once

// Every core warning with a severity icon and colour, errors first, and a
// one-click fix where the core has one that clears it (core/cycle/fixes.h).
// Problems that make the scenario invalid are listed too.

#include <QList>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <optional>
#include <vector>

#include "core/cycle/fixes.h"
#include "ui/cycle/computation.h"

class QFrame;
class QLabel;
class QPushButton;
class QVBoxLayout;

namespace probecycle::ui {

class WarningsPanel : public QWidget {
    Q_OBJECT

  public:
    explicit WarningsPanel(QWidget* parent = nullptr);

    void show_result(const Computed& computed);

    // Codes shown, in order ("overtravel_limit", ...; "touch_while_accelerating:second"
    // for the second touch's; "invalid:<key>" for field errors).
    QStringList codes() const;
    QStringList texts() const;
    // Each shown row as the user reads it: severity, title, text and the fix
    // button's words (empty without a fix), for the PDF report.
    QList<QStringList> rows_text() const;
    // The fix offered for a shown code, nullopt if none.
    std::optional<Fix> fix_for(const QString& code) const;
    // Shown problems by severity, for the panel's title.
    int count(Severity severity) const;

  signals:
    // The user pressed the fix button of the row showing `code`.
    void fix_requested(const QString& code);
    // The rows changed (their number or severities).
    void counts_changed();

  protected:
    void changeEvent(QEvent* event) override;

  private:
    struct Row {
        QWidget* widget{nullptr};
        QFrame* bar{nullptr};  // severity colour
        QLabel* icon{nullptr};
        QLabel* title{nullptr};
        QLabel* text{nullptr};
        QPushButton* button{nullptr};
        QString code;
        std::optional<Fix> fix;
        int severity{-1};
    };
    Row& row(std::size_t index);
    void show_row(std::size_t index, const QString& code, Severity severity, const QString& title,
                  const QString& text, const std::optional<Fix>& fix, const QString& fix_text);
    void retranslate();

    QVBoxLayout* rows_layout_{nullptr};
    QLabel* all_clear_{nullptr};
    std::vector<Row> rows_;
    std::size_t shown_{0};
};

}  // namespace probecycle::ui
