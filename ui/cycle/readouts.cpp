#include "ui/cycle/readouts.h"

#include <QEvent>
#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "core/common/units.h"
#include "ui/common/parameter_info.h"
#include "ui/common/text_format.h"
#include "ui/cycle/uncertainty_table.h"

namespace probecycle::ui {

namespace {

// A readout's alert is the severity of the core's warning about it, so the
// thresholds (80 % of the overtravel limit, ...) live in core/cycle.cpp only.
Alert alert_for(const CycleResult& r, WarningCode code) {
    Alert alert = Alert::none;
    for (const Warning& w : r.warnings()) {
        if (w.code != code) continue;
        if (w.severity == Severity::error) return Alert::alarm;
        if (w.severity == Severity::warning) alert = Alert::caution;
    }
    return alert;
}

const char* const kAlarmColour = "#c0392b";
const char* const kCautionColour = "#b9770e";
const char* const kBetterColour = "#1e8449";

QString object_name(Readout readout) {
    static const char* names[] = {"cycle_time",  "overtravel",          "trigger_speed",
                                  "uncertainty", "recommended_backoff", "knee_feed"};
    return QString::fromLatin1(names[static_cast<std::size_t>(readout)]);
}

// Lower is better for time, overtravel and uncertainty; the rest are neutral.
bool lower_is_better(Readout readout) {
    return readout == Readout::cycle_time || readout == Readout::overtravel ||
           readout == Readout::uncertainty;
}

}  // namespace

Readouts::Readouts(QWidget* parent) : QWidget(parent) {
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    row->setSpacing(6);
    for (std::size_t i = 0; i < kReadoutCount; ++i) {
        auto* frame = new QFrame(this);
        frame->setFrameShape(QFrame::StyledPanel);
        frame->setObjectName(QStringLiteral("readout:") + object_name(static_cast<Readout>(i)));
        auto* column = new QVBoxLayout(frame);
        column->setContentsMargins(8, 4, 8, 4);
        column->setSpacing(0);
        Card& card = cards_[i];
        card.title = new QLabel(frame);
        card.value = new QLabel(frame);
        card.detail = new QLabel(frame);
        card.delta = new QLabel(frame);
        card.delta->setVisible(false);
        card.value->setObjectName(QStringLiteral("value"));
        card.value->setTextInteractionFlags(Qt::TextSelectableByMouse);
        QFont value_font = card.value->font();
        value_font.setPointSizeF(value_font.pointSizeF() * 1.45);
        value_font.setBold(true);
        card.value->setFont(value_font);
        QFont small = card.title->font();
        small.setPointSizeF(small.pointSizeF() * 0.9);
        card.title->setFont(small);
        card.detail->setFont(small);
        card.delta->setFont(small);
        // Plain text: these change on every slider step and rich text costs a document layout.
        card.detail->setTextFormat(Qt::PlainText);
        card.delta->setTextFormat(Qt::PlainText);
        // Long titles (Russian) wrap instead of widening the window past the screen;
        // the lines that change on every slider step are clipped rather than wrapped,
        // which would cost a height-for-width layout each time.
        card.title->setWordWrap(true);
        card.detail->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
        card.delta->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
        card.title->setForegroundRole(QPalette::PlaceholderText);
        column->addWidget(card.title);
        column->addWidget(card.value);
        column->addWidget(card.detail);
        column->addWidget(card.delta);
        row->addWidget(frame, 1);
    }
    retranslate();
}

void Readouts::retranslate() {
    cards_[0].title->setText(tr("Cycle time"));
    cards_[1].title->setText(tr("Overtravel"));
    cards_[2].title->setText(tr("Trigger speed"));
    cards_[3].title->setText(tr("Uncertainty (k = 2)"));
    cards_[4].title->setText(tr("Recommended backoff"));
    cards_[5].title->setText(tr("Knee of the curve"));
    cards_[0].title->setToolTip(
        tr("Total time of the probing cycle, all touches and moves. \"Invalid\" when the cycle "
           "cannot run as set (backoff too small, overtravel over the probe's limit): then it "
           "has no cycle time to compare."));
    cards_[1].title->setToolTip(
        tr("Worst distance beyond the surface where the axis stops: pretravel + trigger speed × "
           "(interface + controller + full scan period) + braking distance."));
    cards_[2].title->setToolTip(
        tr("Speed when the measuring touch triggers; lower than programmed "
           "if the touch happens while accelerating."));
    cards_[3].title->setToolTip(
        tr("Expanded (k = 2) uncertainty of the measured point: the trigger's part (the "
           "scan-period range and the probe's repeatability, averaged over repeats) combined "
           "with the probe's lobing, the calibration artefact, the machine's repeatability and "
           "the thermal drift. The value's tooltip shows the budget."));
    cards_[4].title->setToolTip(
        tr("Two-touch: from the backoff's reference (where the probe stopped, or the recorded "
           "trigger position) the larger of the reseat distance and the distance to reach the "
           "measuring feed. Less risks a probe that has not reseated; more is approached again "
           "at the slow measuring feed."));
    cards_[5].title->setToolTip(
        tr("The lowest probing feed whose cycle time is within the knee tolerance (1 % by "
           "default) of the best, among the valid cycles (overtravel under the probe's limit): "
           "faster buys almost no time."));
    for (Card& card : cards_) card.value->setToolTip(card.title->toolTip());
}

void Readouts::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void Readouts::set_alert(Card& card, Alert alert) {
    if (card.alert == alert) return;  // style sheets are costly to re-apply on every drag step
    card.alert = alert;
    const char* colour = alert == Alert::alarm     ? kAlarmColour
                         : alert == Alert::caution ? kCautionColour
                                                   : nullptr;
    card.value->setStyleSheet(
        colour != nullptr ? QStringLiteral("color: %1;").arg(QLatin1String(colour)) : QString());
}

void Readouts::set_delta(Card& card, const QString& text, int sign) {
    card.delta->setText(text);
    card.delta->setVisible(!text.isEmpty());
    if (card.delta_sign == sign) return;
    card.delta_sign = sign;
    QPalette palette = card.detail->palette();
    if (sign != 0) {
        palette.setColor(QPalette::WindowText,
                         QColor(QLatin1String(sign < 0 ? kBetterColour : kAlarmColour)));
    }
    card.delta->setPalette(palette);
}

void Readouts::show_result(const Computed& c, const Computed* baseline) {
    if (!c.valid()) {
        for (Card& card : cards_) {
            card.value->setText(QStringLiteral("—"));
            card.detail->setText(tr("invalid scenario"));
            set_alert(card, Alert::none);
            set_delta(card, {}, 0);
        }
        return;
    }
    const CycleResult& r = c.cycle();
    const Scenario& s = c.scenario;
    const QLocale locale;
    const bool two_touch = s.cycle.strategy == Strategy::two_touch;
    const bool compare = baseline != nullptr && baseline->valid();

    std::array<QString, kReadoutCount> detail;
    std::array<double, kReadoutCount> now{};
    std::array<double, kReadoutCount> base{};
    std::array<bool, kReadoutCount> has_delta{};

    // Cycle time; an invalid cycle shows no time, but what makes it invalid.
    now[0] = r.total();
    if (r.valid()) {
        cards_[0].value->setText(format_seconds(r.total()));
        detail[0] = strategy_label(s.cycle.strategy);
        set_alert(cards_[0], Alert::none);
    } else {
        cards_[0].value->setText(tr("Invalid"));
        QStringList why;
        for (const Warning& w : r.warnings()) {
            if (w.severity == Severity::error) why << warning_title(w.code);
        }
        detail[0] = why.join(QStringLiteral("; "));
        set_alert(cards_[0], Alert::alarm);
    }

    // Overtravel against the limit; the limit holds at the highest feed
    // override, whose figure the detail gives.
    const double limit = s.probe.overtravel_limit_mm;
    const double share = r.checked_overtravel_mm() / limit;
    now[1] = r.overtravel_mm();
    cards_[1].value->setText(format_mm(r.overtravel_mm()));
    const QString percent = locale.toString(100.0 * share, 'f', 0);
    if (s.cycle.feed_override_max_pct > 100.0) {
        // The share of the limit is the figure at the override; the tooltip
        // says that figure.
        const QString override_pct = locale.toString(s.cycle.feed_override_max_pct, 'f', 0);
        // (Short: the card is narrow; the tooltip names the limit.)
        detail[1] = r.overtravel_touch() == 2
                        ? tr("%1 % of limit at %2 %, 2nd touch").arg(percent, override_pct)
                        : tr("%1 % of limit at %2 %").arg(percent, override_pct);
        cards_[1].detail->setToolTip(
            tr("At %1 % feed override the probe stops %2 past the surface: %3 % of the probe's "
               "%4 limit. Every overtravel check holds at that override (Highest feed override).")
                .arg(override_pct, format_mm(r.checked_overtravel_mm()), percent,
                     format_mm(limit)));
    } else {
        detail[1] = r.overtravel_touch() == 2
                        ? tr("%1 % of %2, 2nd touch").arg(percent, format_mm(limit))
                        : tr("%1 % of %2").arg(percent, format_mm(limit));
        cards_[1].detail->setToolTip(QString());
    }
    set_alert(cards_[1], alert_for(r, WarningCode::overtravel_limit));

    // Trigger speed of the measuring touch
    const TouchResult& measuring = r.measuring_touch();
    now[2] = mm_s_to_mm_min(r.trigger_speed_mm_s());
    cards_[2].value->setText(format_feed(now[2]));
    // Lower than programmed: by how much, as a share (the two feeds can
    // round to one number, and the programmed one is in the editor).
    const bool slower =
        measuring.trigger_speed_mm_s < measuring.programmed_feed_mm_s * (1.0 - 1e-9);
    const double trigger_share = std::min(
        std::floor(1000.0 * measuring.trigger_speed_mm_s / measuring.programmed_feed_mm_s) / 10.0,
        99.9);
    detail[2] = slower ? tr("%1 % of programmed").arg(format_number(trigger_share, 1))
                       : tr("as programmed");
    set_alert(cards_[2], slower ? Alert::caution : Alert::none);

    // Uncertainty against the target
    const double target = s.cycle.target_uncertainty_mm;
    now[3] = r.uncertainty_mm();
    cards_[3].value->setText(format_length(r.uncertainty_mm()));
    // The figure is the whole budget; the detail names the trigger's part of
    // it, the tooltip shows the budget line by line.
    detail[3] = target > 0.0 ? tr("target %1").arg(format_length(target))
                             : tr("trigger %1").arg(format_length(r.trigger_uncertainty_mm()));
    const QString budget =
        tr("<p>The measurement's uncertainty budget: each term's standard uncertainty, combined "
           "as the root sum of squares and expanded with k = 2. Set the terms under Machine and "
           "Probe.</p>") +
        rows_to_html_table(uncertainty_budget_rows(s, r));
    cards_[3].value->setToolTip(budget);
    cards_[3].detail->setToolTip(budget);
    set_alert(cards_[3], alert_for(r, WarningCode::uncertainty_over_target));

    // Recommended backoff
    now[4] = r.recommended_backoff_mm();
    cards_[4].value->setText(format_mm(r.recommended_backoff_mm()));
    detail[4] = two_touch ? tr("set %1").arg(format_mm(s.cycle.backoff_mm)) : tr("for two-touch");
    set_alert(cards_[4], alert_for(r, WarningCode::backoff_too_small));

    // Knee
    const auto& knee = c.analysis.knee_feed_mm_min;
    now[5] = knee.value_or(0.0);
    cards_[5].value->setText(knee ? format_feed(*knee) : QStringLiteral("—"));
    detail[5] = c.analysis.knee_cycle_time_s
                    ? tr("cycle %1").arg(format_seconds(*c.analysis.knee_cycle_time_s))
                    : QString();
    set_alert(cards_[5], Alert::none);

    if (compare) {
        const CycleResult& b = baseline->cycle();
        base = {b.total(),
                b.overtravel_mm(),
                mm_s_to_mm_min(b.trigger_speed_mm_s()),
                b.uncertainty_mm(),
                b.recommended_backoff_mm(),
                baseline->analysis.knee_feed_mm_min.value_or(0.0)};
        has_delta.fill(true);
        // An invalid cycle's time is no time to compare.
        has_delta[0] = r.valid() && b.valid();
        has_delta[5] = knee.has_value() && baseline->analysis.knee_feed_mm_min.has_value();
    }

    for (std::size_t i = 0; i < kReadoutCount; ++i) {
        Card& card = cards_[i];
        card.detail->setText(detail[i]);
        if (!has_delta[i]) {
            set_delta(card, {}, 0);
            continue;
        }
        const double d = now[i] - base[i];
        QString delta;
        switch (static_cast<Readout>(i)) {
            case Readout::cycle_time:
                delta = format_signed_seconds(d);
                break;
            case Readout::trigger_speed:
            case Readout::knee_feed:
                delta = (d > 0   ? QStringLiteral("+")
                         : d < 0 ? QStringLiteral("\u2212")
                                 : QString()) +
                        format_feed(std::abs(d));
                break;
            default:
                delta = format_signed_length(d);
                break;
        }
        const double scale = std::max(std::abs(now[i]), std::abs(base[i]));
        const bool changed = std::abs(d) > 1e-9 * std::max(scale, 1e-12);
        const int sign =
            changed && lower_is_better(static_cast<Readout>(i)) ? (d < 0.0 ? -1 : 1) : 0;
        set_delta(card, tr("Δ %1 vs baseline").arg(delta), sign);
    }
}

QString Readouts::title_text(Readout readout) const {
    return cards_[static_cast<std::size_t>(readout)].title->text();
}

QString Readouts::value_text(Readout readout) const {
    return cards_[static_cast<std::size_t>(readout)].value->text();
}

QString Readouts::detail_text(Readout readout) const {
    const Card& card = cards_[static_cast<std::size_t>(readout)];
    return card.delta->text().isEmpty()
               ? card.detail->text()
               : card.detail->text() + QLatin1Char('\n') + card.delta->text();
}

Alert Readouts::alert(Readout readout) const {
    return cards_[static_cast<std::size_t>(readout)].alert;
}

}  // namespace probecycle::ui
