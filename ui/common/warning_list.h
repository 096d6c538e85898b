#pragma once

// A list of warnings with severity colours (the lab tabs', the comparison's).

#include <QString>
#include <QStringList>
#include <QWidget>
#include <vector>

#include "core/common/severity.h"

class QLabel;
class QVBoxLayout;

namespace probecycle::ui {

// Rows of "title: message", coloured by severity; an "all clear" line when empty.
class WarningList : public QWidget {
    Q_OBJECT

  public:
    explicit WarningList(QWidget* parent = nullptr);

    struct Item {
        QString code;
        Severity severity{Severity::info};
        QString title;
        QString message;
    };
    void show_items(const std::vector<Item>& items);
    void set_empty_text(const QString& text);

    QStringList codes() const;
    QStringList texts() const;
    const std::vector<Item>& items() const { return items_; }

  private:
    QVBoxLayout* layout_{nullptr};
    QLabel* empty_{nullptr};
    std::vector<QLabel*> rows_;
    std::vector<Item> items_;
};

}  // namespace probecycle::ui
