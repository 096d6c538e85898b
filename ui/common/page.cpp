#include "ui/common/page.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QSpinBox>

namespace probecycle::ui {

void Page::watch_inputs() {
    // A spin box's own line edit is set with its signals blocked: the box reports.
    for (auto* box : findChildren<QDoubleSpinBox*>()) {
        connect(box, &QDoubleSpinBox::valueChanged, this, &Page::changed);
    }
    for (auto* box : findChildren<QSpinBox*>()) {
        connect(box, &QSpinBox::valueChanged, this, &Page::changed);
    }
    for (auto* edit : findChildren<QLineEdit*>()) {
        connect(edit, &QLineEdit::textChanged, this, &Page::changed);
    }
    for (auto* edit : findChildren<QPlainTextEdit*>()) {
        connect(edit, &QPlainTextEdit::textChanged, this, &Page::changed);
    }
    for (auto* box : findChildren<QComboBox*>()) {
        connect(box, &QComboBox::currentIndexChanged, this, &Page::changed);
    }
    for (auto* button : findChildren<QAbstractButton*>()) {
        if (button->isCheckable()) connect(button, &QAbstractButton::toggled, this, &Page::changed);
    }
}

}  // namespace probecycle::ui
