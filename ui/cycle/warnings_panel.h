#pragma once

// Every core warning with a severity icon and colour, and a one-click fix
// where there is one. Problems that make the scenario invalid are listed too.

#include <QString>
#include <QStringList>
#include <QWidget>
#include <optional>
#include <vector>

#include "ui/cycle/computation.h"

class QFrame;
class QLabel;
class QPushButton;
class QVBoxLayout;

namespace probecycle::ui {

enum class Fix {
    none,
    backoff_to_recommended,  // set the backoff to the first touch's overtravel + reseat
    feed_to_knee,            // drop the probing feed to the knee
    approach_to_reach_feed,  // start far enough out to touch at full feed
};

// The scenario after applying a fix, with the value from the core's result
// rounded the safe way to what the editors show; nullopt when it does not apply.
std::optional<Scenario> apply_fix(const Computed& computed, Fix fix);

class WarningsPanel : public QWidget {
    Q_OBJECT

  public:
    explicit WarningsPanel(QWidget* parent = nullptr);

    void show_result(const Computed& computed);

    // Codes shown, in order ("overtravel_limit", ...; "invalid:<key>" for field errors).
    QStringList codes() const;
    QStringList texts() const;
    // The fix offered for a shown code, Fix::none if none.
    Fix fix_for(const QString& code) const;

  signals:
    void fix_requested(probecycle::ui::Fix fix);

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
        Fix fix{Fix::none};
        int severity{-1};
    };
    Row& row(std::size_t index);
    void show_row(std::size_t index, const QString& code, Severity severity, const QString& title,
                  const QString& text, Fix fix, const QString& fix_text);
    void retranslate();

    QVBoxLayout* rows_layout_{nullptr};
    QLabel* all_clear_{nullptr};
    std::vector<Row> rows_;
    std::size_t shown_{0};
};

}  // namespace probecycle::ui
