#pragma once

// The summary readouts above the charts: cycle time, overtravel against the
// limit, trigger speed, uncertainty, recommended backoff and the knee, each
// with its difference from the pinned baseline.

#include <QString>
#include <QWidget>
#include <array>
#include <cstddef>

#include "ui/cycle/computation.h"

class QLabel;

namespace probecycle::ui {

enum class Readout {
    cycle_time,
    overtravel,
    trigger_speed,
    uncertainty,
    recommended_backoff,
    knee_feed,
};
constexpr std::size_t kReadoutCount = 6;

enum class Alert { none, caution, alarm };

class Readouts : public QWidget {
    Q_OBJECT

  public:
    explicit Readouts(QWidget* parent = nullptr);

    void show_result(const Computed& computed, const Computed* baseline);

    QString title_text(Readout readout) const;
    QString value_text(Readout readout) const;
    // The lines under the value: context, and the difference from the baseline.
    QString detail_text(Readout readout) const;
    Alert alert(Readout readout) const;

  protected:
    void changeEvent(QEvent* event) override;

  private:
    struct Card {
        QLabel* title{nullptr};
        QLabel* value{nullptr};
        QLabel* detail{nullptr};
        QLabel* delta{nullptr};  // difference from the baseline, when one is pinned
        Alert alert{Alert::none};
        int delta_sign{0};  // colour of the delta: -1 better, +1 worse, 0 neutral
    };
    void retranslate();
    void set_alert(Card& card, Alert alert);
    void set_delta(Card& card, const QString& text, int sign);

    std::array<Card, kReadoutCount> cards_{};
};

}  // namespace probecycle::ui
