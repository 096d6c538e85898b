// Rows of warnings, an "all clear" line when there are none.

#include "ui/common/warning_list.h"

#include <gtest/gtest.h>

#include <QLabel>

namespace probecycle::ui {
namespace {

TEST(WarningList, ShowsItsItemsAndTheEmptyLineWhenThereAreNone) {
    WarningList list;
    list.set_empty_text(QStringLiteral("No warnings."));
    list.show_items({});
    list.show();
    const auto visible_texts = [&list] {
        QStringList texts;
        for (const QLabel* label : list.findChildren<QLabel*>()) {
            if (label->isVisible()) texts << label->text();
        }
        return texts;
    };
    EXPECT_EQ(visible_texts(), QStringList{QStringLiteral("No warnings.")});

    list.show_items({{QStringLiteral("a_code"), Severity::warning, QStringLiteral("Title"),
                      QStringLiteral("what <happened>")},
                     {QStringLiteral("b_code"), Severity::info, QStringLiteral("Other"),
                      QStringLiteral("more")}});
    EXPECT_EQ(list.codes(), (QStringList{QStringLiteral("a_code"), QStringLiteral("b_code")}));
    EXPECT_EQ(list.texts(), (QStringList{QStringLiteral("Title: what <happened>"),
                                         QStringLiteral("Other: more")}));
    const QStringList shown = visible_texts();
    ASSERT_EQ(shown.size(), 2);
    EXPECT_TRUE(shown[0].contains(QStringLiteral("what &lt;happened&gt;")))
        << shown[0].toStdString();

    // Fewer items hide the rows left over.
    list.show_items({{QStringLiteral("b_code"), Severity::info, QStringLiteral("Other"),
                      QStringLiteral("more")}});
    EXPECT_EQ(visible_texts().size(), 1);
    EXPECT_EQ(list.codes(), QStringList{QStringLiteral("b_code")});
}

}  // namespace
}  // namespace probecycle::ui
