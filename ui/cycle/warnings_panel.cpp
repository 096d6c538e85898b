#include "ui/cycle/warnings_panel.h"

#include <QEvent>
#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QStyle>
#include <QVBoxLayout>
#include <cmath>

#include "ui/common/text_format.h"

namespace probecycle::ui {

namespace {

QStyle::StandardPixmap severity_icon(Severity severity) {
    switch (severity) {
        case Severity::error:
            return QStyle::SP_MessageBoxCritical;
        case Severity::warning:
            return QStyle::SP_MessageBoxWarning;
        case Severity::info:
            break;
    }
    return QStyle::SP_MessageBoxInformation;
}

// Rounded so the editors show exactly the value set, and rounded the way that
// clears the warning (backoff up, feed down, start distance up).
double round_up(double value, double step) {
    return std::ceil(value / step - 1e-9) * step;
}
double round_down(double value, double step) {
    return std::floor(value / step + 1e-9) * step;
}

std::optional<Scenario> fixed_scenario(const Computed& c, Fix fix) {
    if (!c.valid()) return std::nullopt;
    Scenario s = c.scenario;
    switch (fix) {
        case Fix::backoff_to_recommended:
            if (s.cycle.strategy != Strategy::two_touch) return std::nullopt;
            s.cycle.backoff_mm = round_up(c.cycle().recommended_backoff_mm(), 0.001);
            return s;
        case Fix::feed_to_knee: {
            const auto& knee = c.analysis.knee_feed_mm_min;
            if (!knee || *knee >= s.cycle.probe_feed_mm_min) return std::nullopt;
            s.cycle.probe_feed_mm_min = std::max(round_down(*knee, 1.0), 1.0);
            return s;
        }
        case Fix::approach_to_reach_feed: {
            const double feed_mm_s = c.cycle().first_touch().programmed_feed_mm_s;
            s.cycle.approach_mm = round_up(approach_room_mm(s, feed_mm_s), 0.01);
            if (s.cycle.approach_mm <= c.scenario.cycle.approach_mm) return std::nullopt;
            return s;
        }
        case Fix::none:
            break;
    }
    return std::nullopt;
}

}  // namespace

std::optional<Scenario> apply_fix(const Computed& c, Fix fix) {
    std::optional<Scenario> fixed = fixed_scenario(c, fix);
    // A fix that breaks another rule (a bore too narrow for the longer
    // approach, a value beyond its range) is not offered.
    if (fixed && !validate(*fixed).empty()) return std::nullopt;
    return fixed;
}

WarningsPanel::WarningsPanel(QWidget* parent) : QWidget(parent) {
    rows_layout_ = new QVBoxLayout(this);
    rows_layout_->setContentsMargins(4, 4, 4, 4);
    rows_layout_->setSpacing(4);
    all_clear_ = new QLabel(this);
    all_clear_->setObjectName(QStringLiteral("warnings-all-clear"));
    rows_layout_->addWidget(all_clear_);
    rows_layout_->addStretch(1);
    retranslate();
}

void WarningsPanel::retranslate() {
    all_clear_->setText(tr("No warnings: the cycle is within the probe's limits."));
}

void WarningsPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

WarningsPanel::Row& WarningsPanel::row(std::size_t index) {
    while (rows_.size() <= index) {
        Row r;
        r.widget = new QWidget(this);
        auto* layout = new QHBoxLayout(r.widget);
        layout->setContentsMargins(0, 2, 6, 2);
        r.bar = new QFrame(r.widget);
        r.bar->setFixedWidth(4);
        r.bar->setAutoFillBackground(true);
        layout->addWidget(r.bar);
        r.icon = new QLabel(r.widget);
        r.icon->setAlignment(Qt::AlignTop);
        r.title = new QLabel(r.widget);
        QFont bold = r.title->font();
        bold.setBold(true);
        r.title->setFont(bold);
        r.title->setTextFormat(Qt::PlainText);
        r.text = new QLabel(r.widget);
        r.text->setWordWrap(true);
        r.text->setTextFormat(Qt::PlainText);  // updated on every slider step: keep it cheap
        r.text->setTextInteractionFlags(Qt::TextSelectableByMouse);
        auto* words = new QVBoxLayout;
        words->setContentsMargins(0, 0, 0, 0);
        words->setSpacing(0);
        words->addWidget(r.title);
        words->addWidget(r.text);
        r.button = new QPushButton(r.widget);
        r.button->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Fixed);
        layout->addWidget(r.icon, 0, Qt::AlignTop);
        layout->addLayout(words, 1);
        layout->addWidget(r.button, 0, Qt::AlignVCenter);
        const std::size_t i = rows_.size();
        connect(r.button, &QPushButton::clicked, this, [this, i] {
            if (i < shown_) emit fix_requested(rows_[i].fix);
        });
        // Before the stretch at the end.
        rows_layout_->insertWidget(rows_layout_->count() - 1, r.widget);
        rows_.push_back(r);
    }
    return rows_[index];
}

void WarningsPanel::show_row(std::size_t index, const QString& code, Severity severity,
                             const QString& title, const QString& text, Fix fix,
                             const QString& fix_text) {
    Row& r = row(index);
    r.code = code;
    r.fix = fix;
    const int level = static_cast<int>(severity);
    if (r.severity != level) {
        r.severity = level;
        const int size = r.title->fontMetrics().height();
        r.icon->setPixmap(style()->standardIcon(severity_icon(severity)).pixmap(size, size));
        const QColor colour(QLatin1String(severity_colour(severity)));
        QPalette palette = r.bar->palette();
        palette.setColor(QPalette::Window, colour);
        r.bar->setPalette(palette);
        QPalette title_palette = r.title->palette();
        title_palette.setColor(QPalette::WindowText, colour);
        r.title->setPalette(title_palette);
    }
    r.widget->setObjectName(QStringLiteral("warning:") + code);
    r.title->setText(title);
    r.text->setText(text);
    r.button->setObjectName(QStringLiteral("fix:") + code);
    r.button->setVisible(fix != Fix::none);
    r.button->setText(fix_text);
    r.widget->setVisible(true);
}

void WarningsPanel::show_result(const Computed& c) {
    std::size_t n = 0;
    if (!c.valid()) {
        for (const FieldError& e : c.errors) {
            show_row(n++, QStringLiteral("invalid:") + QString::fromStdString(e.key),
                     Severity::error, tr("Invalid scenario"), translate(e.to_message()), Fix::none,
                     {});
        }
    } else {
        for (const Warning& w : c.cycle().warnings()) {
            Fix fix = Fix::none;
            switch (w.code) {
                case WarningCode::backoff_too_small:
                case WarningCode::backoff_excess:
                    fix = Fix::backoff_to_recommended;
                    break;
                case WarningCode::feed_beyond_knee:
                case WarningCode::overtravel_limit:
                    fix = Fix::feed_to_knee;
                    break;
                case WarningCode::touch_while_accelerating:
                    fix = w.d < 0.5 ? Fix::approach_to_reach_feed : Fix::none;
                    break;
                default:
                    break;
            }
            const std::optional<Scenario> fixed = apply_fix(c, fix);
            if (!fixed) fix = Fix::none;
            QString fix_text;
            switch (fix) {
                case Fix::backoff_to_recommended:
                    fix_text = tr("Set backoff to %1").arg(format_mm(fixed->cycle.backoff_mm));
                    break;
                case Fix::feed_to_knee:
                    fix_text = tr("Drop feed to the knee, %1")
                                   .arg(format_feed(fixed->cycle.probe_feed_mm_min));
                    break;
                case Fix::approach_to_reach_feed:
                    fix_text = tr("Start %1 out").arg(format_mm(fixed->cycle.approach_mm));
                    break;
                case Fix::none:
                    break;
            }
            show_row(n++, QString::fromUtf8(to_string(w.code)), w.severity, warning_title(w.code),
                     warning_text(w), fix, fix_text);
        }
    }
    for (std::size_t i = n; i < rows_.size(); ++i) {
        rows_[i].widget->setVisible(false);
        rows_[i].code.clear();
    }
    shown_ = n;
    all_clear_->setVisible(n == 0);
}

QStringList WarningsPanel::codes() const {
    QStringList out;
    for (std::size_t i = 0; i < shown_; ++i) out.append(rows_[i].code);
    return out;
}

QStringList WarningsPanel::texts() const {
    QStringList out;
    for (std::size_t i = 0; i < shown_; ++i) out.append(rows_[i].text->text());
    return out;
}

Fix WarningsPanel::fix_for(const QString& code) const {
    for (std::size_t i = 0; i < shown_; ++i) {
        if (rows_[i].code == code) return rows_[i].fix;
    }
    return Fix::none;
}

}  // namespace probecycle::ui
