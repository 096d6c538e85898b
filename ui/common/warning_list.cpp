#include "ui/common/warning_list.h"

#include <QLabel>
#include <QVBoxLayout>

#include "ui/common/text_format.h"

namespace probecycle::ui {

WarningList::WarningList(QWidget* parent) : QWidget(parent) {
    layout_ = new QVBoxLayout(this);
    layout_->setContentsMargins(0, 0, 0, 0);
    layout_->setSpacing(4);
    empty_ = new QLabel(this);
    empty_->setWordWrap(true);
    empty_->setStyleSheet(QStringLiteral("color: #1e8449;"));
    layout_->addWidget(empty_);
    layout_->addStretch(1);  // rows stay at the top
}

void WarningList::set_empty_text(const QString& text) {
    empty_->setText(text);
}

void WarningList::show_items(const std::vector<Item>& items) {
    items_ = items;
    while (rows_.size() < items.size()) {
        auto* label = new QLabel(this);
        label->setWordWrap(true);
        label->setTextFormat(Qt::RichText);
        label->setTextInteractionFlags(Qt::TextSelectableByMouse);
        layout_->insertWidget(layout_->count() - 1, label);  // before the stretch
        rows_.push_back(label);
    }
    for (std::size_t i = 0; i < rows_.size(); ++i) {
        QLabel* label = rows_[i];
        if (i >= items.size()) {
            label->hide();
            continue;
        }
        const Item& item = items[i];
        const QString colour = QLatin1String(severity_colour(item.severity));
        label->setStyleSheet(
            QStringLiteral("QLabel { border-style: solid; border-color: %1; border-width: 0px 0px "
                           "0px 4px; padding-left: 6px; }")
                .arg(colour));
        label->setText(QStringLiteral("<b style=\"color:%1\">%2</b><br>%3")
                           .arg(colour, item.title.toHtmlEscaped(), item.message.toHtmlEscaped()));
        label->setToolTip(item.code);
        label->show();
    }
    empty_->setVisible(items.empty());
}

QStringList WarningList::codes() const {
    QStringList out;
    for (const Item& item : items_) out << item.code;
    return out;
}

QStringList WarningList::texts() const {
    QStringList out;
    for (const Item& item : items_) out << item.title + QStringLiteral(": ") + item.message;
    return out;
}

}  // namespace probecycle::ui
