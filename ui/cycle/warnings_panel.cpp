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

}  // namespace

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
            if (i < shown_) emit fix_requested(rows_[i].code);
        });
        // Before the stretch at the end.
        rows_layout_->insertWidget(rows_layout_->count() - 1, r.widget);
        rows_.push_back(r);
    }
    return rows_[index];
}

void WarningsPanel::show_row(std::size_t index, const QString& code, Severity severity,
                             const QString& title, const QString& text,
                             const std::optional<Fix>& fix, const QString& fix_text) {
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
    r.button->setVisible(fix.has_value());
    r.button->setText(fix_text);
    r.widget->setVisible(true);
}

namespace {

// The button's words: what the fix sets, with the value.
QString fix_kind_text(const Fix& fix) {
    const Cycle& c = fix.scenario.cycle;
    switch (fix.kind) {
        case FixKind::backoff_to_recommended:
            return WarningsPanel::tr("Set backoff to %1").arg(format_mm(c.backoff_mm));
        case FixKind::feed_to_knee:
            return WarningsPanel::tr("Drop feed to the knee, %1")
                .arg(format_feed(c.probe_feed_mm_min));
        case FixKind::feed_for_overtravel:
            return WarningsPanel::tr("Drop feed to %1").arg(format_feed(c.probe_feed_mm_min));
        case FixKind::approach_to_reach_feed:
            return WarningsPanel::tr("Start %1 out").arg(format_mm(c.approach_mm));
        case FixKind::search_past_stop:
            return WarningsPanel::tr("Search %1 past the surface")
                .arg(format_mm(c.search_beyond_mm));
        case FixKind::position_feed_for_overtravel:
            return WarningsPanel::tr("Position at %1").arg(format_feed(c.position_feed_mm_min));
        case FixKind::none:
            break;
    }
    return {};
}

// With the backoff the fixed cycle needs, when the fix sets it too.
QString fix_text(const Fix& fix) {
    QString text = fix_kind_text(fix);
    if (!fix.with_backoff || text.isEmpty()) return text;
    //: %1 what the fix sets ("Start 15.680 mm out"), %2 the backoff it needs with it
    return WarningsPanel::tr("%1, backoff %2").arg(text, format_mm(fix.scenario.cycle.backoff_mm));
}

}  // namespace

void WarningsPanel::show_result(const Computed& c) {
    std::size_t n = 0;
    if (!c.valid()) {
        for (const FieldError& e : c.errors) {
            show_row(n++, QStringLiteral("invalid:") + QString::fromStdString(e.key),
                     Severity::error, tr("Invalid scenario"), translate(e.to_message()),
                     std::nullopt, {});
        }
    } else {
        // In the core's order: errors first (order_by_severity).
        for (const Warning& w : c.cycle().warnings()) {
            const std::optional<Fix> fix = probecycle::fix_for(c.scenario, c.analysis, w);
            // Each row's code is unique: the second touch's acceleration
            // warning is told from the first's.
            QString code = QString::fromUtf8(to_string(w.code));
            if (accelerating_touch(w) == 2) {
                code += QStringLiteral(":second");
            }
            show_row(n++, code, w.severity, warning_title(w.code), warning_text(w), fix,
                     fix ? fix_text(*fix) : QString());
        }
    }
    for (std::size_t i = n; i < rows_.size(); ++i) {
        rows_[i].widget->setVisible(false);
        rows_[i].code.clear();
        rows_[i].fix.reset();
    }
    shown_ = n;
    all_clear_->setVisible(n == 0);
    emit counts_changed();
}

int WarningsPanel::count(Severity severity) const {
    int n = 0;
    for (std::size_t i = 0; i < shown_; ++i) n += rows_[i].severity == static_cast<int>(severity);
    return n;
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

QList<QStringList> WarningsPanel::rows_text() const {
    QList<QStringList> out;
    for (std::size_t i = 0; i < shown_; ++i) {
        const Row& r = rows_[i];
        const QString severity = r.severity == static_cast<int>(Severity::error)     ? tr("Error")
                                 : r.severity == static_cast<int>(Severity::warning) ? tr("Warning")
                                                                                     : tr("Note");
        out.append({severity, r.title->text(), r.text->text(),
                    r.fix.has_value() ? r.button->text() : QString()});
    }
    return out;
}

std::optional<Fix> WarningsPanel::fix_for(const QString& code) const {
    for (std::size_t i = 0; i < shown_; ++i) {
        if (rows_[i].code == code) return rows_[i].fix;
    }
    return std::nullopt;
}

}  // namespace probecycle::ui
