// What the core threw, in words for a label; errors in the error colour and
// "Saved FILE" (English: this test loads no translation).

#include "ui/common/status_text.h"

#include <gtest/gtest.h>

#include <QLabel>
#include <stdexcept>

#include "core/common/csv_reader.h"
#include "core/common/file_io.h"
#include "core/comparison/comparison_input.h"

namespace probecycle::ui {
namespace {

TEST(StatusText, TheCoresErrorsAreTheirMessagesAnythingElseIsUnexpected) {
    try {
        (void)parse_points("x_mm,y_mm,z_mm\n1,2,3\nabc,2,3\n");
        FAIL() << "no CsvError";
    } catch (const CsvError& e) {
        EXPECT_EQ(error_text(e), QString::fromStdString(e.what()));
        EXPECT_TRUE(error_text(e).startsWith(QStringLiteral("line 3, column x_mm:")))
            << error_text(e).toStdString();
    }
    try {
        (void)read_text_file("/nonexistent/probecycle/file.csv");
        FAIL() << "no FileError";
    } catch (const FileError& e) {
        EXPECT_TRUE(error_text(e).contains(QStringLiteral("file.csv")))
            << error_text(e).toStdString();
    }
    EXPECT_EQ(error_text(std::runtime_error("boom")), QStringLiteral("Unexpected error: boom"));
}

TEST(StatusText, TheCurrentErrorIsBuiltAtEachCall) {
    LiveText text;
    try {
        throw std::runtime_error("boom");
    } catch (...) {
        text = current_error_text();
    }
    EXPECT_EQ(text(), QStringLiteral("Unexpected error: boom"));
    EXPECT_EQ(text(), QStringLiteral("Unexpected error: boom"));
}

TEST(StatusText, ErrorsShowInTheErrorColourAndSavedNamesTheFile) {
    QLabel label;
    show_error(&label, QStringLiteral("wrong"));
    EXPECT_FALSE(label.isHidden());
    EXPECT_EQ(label.text(), QStringLiteral("wrong"));
    EXPECT_TRUE(label.styleSheet().contains(QStringLiteral("#c0392b")));
    show_error(&label, QString());
    EXPECT_TRUE(label.isHidden());

    show_live_error(&label, [] { return QStringLiteral("again"); });
    EXPECT_EQ(label.text(), QStringLiteral("again"));
    show_saved(&label, QStringLiteral("/some/folder/report.csv"));
    EXPECT_EQ(label.text(), QStringLiteral("Saved report.csv"));
    EXPECT_TRUE(label.styleSheet().isEmpty());
    EXPECT_FALSE(label.isHidden());
}

}  // namespace
}  // namespace probecycle::ui
