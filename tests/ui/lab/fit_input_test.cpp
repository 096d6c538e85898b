// The input both lab fits share, with a fit of its own: Fit and Import CSV
// hand the text to the owner's fit, a refusal is shown under the buttons
// with the file's name, and with the note while a previous result stays.

#include "ui/lab/fit_input.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QLabel>
#include <QPlainTextEdit>
#include <QTemporaryDir>
#include <QVBoxLayout>
#include <QWidget>
#include <stdexcept>

namespace probecycle::ui {
namespace {

class FitInputTest : public testing::Test {
  protected:
    void SetUp() override {
        input_ = new FitInput(ProgramKind::delay, {"touches", "program", "log", "error"}, &owner_,
                              last_error_, [this] { return has_result_; });
        input_->make_editor(&owner_);
        input_->make_buttons(&owner_);
        auto* column = new QVBoxLayout(&owner_);
        input_->add_buttons_to(column);
        input_->retranslate();
        // Fits "ok", refuses anything else.
        input_->set_fit_text([this](const QString& text, const QString& source) {
            fitted_ << text;
            try {
                if (text != QStringLiteral("ok")) throw std::runtime_error("refused");
            } catch (const std::exception&) {
                input_->show_fit_error(source);
                return false;
            }
            input_->set_error({});
            return true;
        });
    }

    QString error_shown() const {
        const auto* label = owner_.findChild<QLabel*>(QStringLiteral("error"));
        return label && !label->isHidden() ? label->text() : QString();
    }

    QWidget owner_;
    FitInput* input_{nullptr};
    QString last_error_;
    bool has_result_{false};
    QStringList fitted_;
};

TEST_F(FitInputTest, FitHandsThePasteBoxToTheOwnersFit) {
    input_->editor()->setPlainText(QStringLiteral("ok"));
    EXPECT_TRUE(input_->fit());
    EXPECT_EQ(fitted_, QStringList{QStringLiteral("ok")});
    EXPECT_TRUE(last_error_.isEmpty());
    EXPECT_TRUE(error_shown().isEmpty());
    EXPECT_EQ(input_->source_of(QStringLiteral("ok")), "pasted");
}

TEST_F(FitInputTest, ARefusalIsShownWithTheNoteWhileAResultStays) {
    input_->editor()->setPlainText(QStringLiteral("bad"));
    EXPECT_FALSE(input_->fit());
    EXPECT_EQ(last_error_, QStringLiteral("Unexpected error: refused"));
    EXPECT_EQ(error_shown(), last_error_);
    has_result_ = true;
    EXPECT_FALSE(input_->fit());
    EXPECT_EQ(
        error_shown(),
        last_error_ + QStringLiteral("\nThe result shown is still that of the previous fit."));
}

TEST_F(FitInputTest, AnImportedFileIsFittedAndNamed) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const auto write = [&dir](const QString& name, const QByteArray& text) {
        QFile file(dir.filePath(name));
        EXPECT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(text);
        return file.fileName();
    };
    EXPECT_TRUE(input_->import_file(write(QStringLiteral("good.csv"), "ok")));
    EXPECT_EQ(input_->editor()->toPlainText(), QStringLiteral("ok"));
    EXPECT_EQ(input_->source_of(QStringLiteral("ok")), "good.csv");
    EXPECT_EQ(input_->source_of(QStringLiteral("edited")), "pasted");

    EXPECT_FALSE(input_->import_file(write(QStringLiteral("bad.csv"), "bad")));
    EXPECT_EQ(last_error_, QStringLiteral("bad.csv: Unexpected error: refused"));

    fitted_.clear();
    EXPECT_FALSE(input_->import_file(dir.filePath(QStringLiteral("missing.csv"))));
    EXPECT_TRUE(fitted_.isEmpty());
    EXPECT_TRUE(last_error_.startsWith(QStringLiteral("missing.csv could not be read:")))
        << last_error_.toStdString();
}

}  // namespace
}  // namespace probecycle::ui
