// Every language, every size. At 1280x800, in English, Chinese and Russian,
// every tab shows its texts whole; after a language switch no text stays in the
// previous language; Russian numbers use its decimal comma everywhere in the
// window.

#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QFile>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QSpinBox>
#include <QStatusBar>
#include <QStyle>
#include <QStyleOptionComboBox>
#include <QTabBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QUndoStack>
#include <memory>

#include "tests/ui/lab/lab_test_data.h"
#include "ui/common/language.h"
#include "ui/common/plot_view.h"
#include "ui/comparison/comparison_tab.h"
#include "ui/cycle/parameter_panel.h"
#include "ui/lab/calibration_tab.h"
#include "ui/lab/latency_tab.h"
#include "ui/window/main_window.h"

namespace probecycle::ui {
namespace {

using lab_test::lab_data;

const QStringList kTabs = {QStringLiteral("cycle"), QStringLiteral("calibration"),
                           QStringLiteral("latency"), QStringLiteral("comparison"),
                           QStringLiteral("optimise")};

QString joined(const QStringList& list) {
    return list.join(QStringLiteral(" | "));
}

QString without_mnemonic(QString text) {
    return text.remove(QRegularExpression(QStringLiteral("&(?=[^&])")));
}

// The widest line of a text, as `metrics` lays it out.
int text_width(const QFontMetrics& metrics, const QString& text) {
    int widest = 0;
    for (const QString& line : text.split(QLatin1Char('\n'))) {
        widest = std::max(widest, metrics.horizontalAdvance(line));
    }
    return widest;
}

// Why `w` shows its text only in part, or "" when it shows it whole.
QStringList cut_in(const QWidget* w) {
    QStringList cut;
    const QString where = w->objectName().isEmpty()
                              ? QString::fromLatin1(w->metaObject()->className())
                              : w->objectName();
    if (const auto* label = qobject_cast<const QLabel*>(w)) {
        if (label->text().isEmpty()) return cut;
        const QRect room = label->contentsRect();
        const bool fits = label->wordWrap()
                              ? label->heightForWidth(room.width()) <= room.height() + 1
                              : label->sizeHint().width() <= label->width();
        if (!fits) cut << QStringLiteral("label %1: %2").arg(where, label->text());
    } else if (const auto* button = qobject_cast<const QAbstractButton*>(w)) {
        const QString text = without_mnemonic(button->text());
        if (text.isEmpty()) return cut;
        const int icon = button->icon().isNull() ? 0 : button->iconSize().width() + 4;
        if (text_width(button->fontMetrics(), text) + icon > button->width()) {
            cut << QStringLiteral("button %1: %2").arg(where, text);
        }
    } else if (const auto* header = qobject_cast<const QHeaderView*>(w)) {
        if (header->orientation() != Qt::Horizontal || header->model() == nullptr) return cut;
        const int margin = header->style()->pixelMetric(QStyle::PM_HeaderMargin);
        for (int i = 0; i < header->count(); ++i) {
            if (header->isSectionHidden(i)) continue;
            const QString text =
                header->model()->headerData(i, Qt::Horizontal, Qt::DisplayRole).toString();
            if (text_width(header->fontMetrics(), text) + 2 * margin > header->sectionSize(i)) {
                cut << QStringLiteral("column %1: %2").arg(where, text);
            }
        }
    } else if (const auto* plot = qobject_cast<const PlotView*>(w)) {
        for (const QString& text : plot->cut_texts()) {
            cut << QStringLiteral("chart %1: %2").arg(where, text);
        }
    } else if (const auto* combo = qobject_cast<const QComboBox*>(w)) {
        // The text shown and the arrow beside it.
        QStyleOptionComboBox option;
        option.initFrom(combo);
        const QRect text_room = combo->style()->subControlRect(QStyle::CC_ComboBox, &option,
                                                               QStyle::SC_ComboBoxEditField, combo);
        if (combo->fontMetrics().horizontalAdvance(combo->currentText()) > text_room.width()) {
            cut << QStringLiteral("combo box %1: %2").arg(where, combo->currentText());
        }
    } else if (const auto* bar = qobject_cast<const QTabBar*>(w)) {
        for (int i = 0; i < bar->count(); ++i) {
            const QString text = without_mnemonic(bar->tabText(i));
            if (text_width(bar->fontMetrics(), text) + 8 > bar->tabRect(i).width()) {
                cut << QStringLiteral("tab %1: %2").arg(where, text);
            }
        }
    } else if (qobject_cast<const QTableWidget*>(w) != nullptr ||
               qobject_cast<const QTreeWidget*>(w) != nullptr) {
        // A small table of results shows every column without scrolling.
        const auto* table = static_cast<const QAbstractScrollArea*>(w);
        if (table->horizontalScrollBar()->maximum() > 0) {
            cut << QStringLiteral("table %1 scrolls sideways").arg(where);
        }
    }
    return cut;
}

// Every text of the window the user can see now (the current tab), or can
// reach from it: menus, actions, tooltips, undo steps, the status bar.
QStringList window_texts(const MainWindow& window) {
    QStringList out{window.windowTitle(), window.statusBar()->currentMessage()};
    for (const QWidget* w : window.findChildren<QWidget*>()) {
        if (!w->isVisible()) continue;
        out << w->toolTip();
        if (const auto* label = qobject_cast<const QLabel*>(w)) out << label->text();
        if (const auto* button = qobject_cast<const QAbstractButton*>(w)) out << button->text();
        if (const auto* box = qobject_cast<const QGroupBox*>(w)) out << box->title();
        if (const auto* spin = qobject_cast<const QAbstractSpinBox*>(w)) out << spin->text();
        if (const auto* combo = qobject_cast<const QComboBox*>(w)) {
            for (int i = 0; i < combo->count(); ++i) out << combo->itemText(i);
        }
        if (const auto* tabs = qobject_cast<const QTabWidget*>(w)) {
            for (int i = 0; i < tabs->count(); ++i) out << tabs->tabText(i);
        }
        if (const auto* header = qobject_cast<const QHeaderView*>(w)) {
            for (int i = 0; header->model() != nullptr && i < header->count(); ++i) {
                out << header->model()->headerData(i, header->orientation()).toString()
                    << header->model()
                           ->headerData(i, header->orientation(), Qt::ToolTipRole)
                           .toString();
            }
        }
        if (const auto* view = qobject_cast<const QAbstractItemView*>(w)) {
            const QAbstractItemModel* model = view->model();
            for (int r = 0; model != nullptr && r < model->rowCount(); ++r) {
                for (int c = 0; c < model->columnCount(); ++c) {
                    out << model->index(r, c).data().toString();
                }
            }
        }
        if (const auto* plot = qobject_cast<const PlotView*>(w)) out << plot->texts();
    }
    for (const QMenu* menu : window.menuBar()->findChildren<QMenu*>()) out << menu->title();
    for (const QAction* action : window.findChildren<QAction*>()) {
        out << action->text() << action->toolTip() << action->statusTip();
    }
    const QUndoStack* undo = window.undo_stack();
    for (int i = 0; i < undo->count(); ++i) out << undo->text(i);
    out.removeAll(QString());
    return out;
}

// The language menu names each language in itself.
bool language_entry(const QString& text) {
    for (const QString& code : available_languages()) {
        if (text == native_language_name(code)) return true;
    }
    return false;
}

QStringList in_script(const QStringList& texts, const QRegularExpression& script) {
    QStringList found;
    for (const QString& text : texts) {
        if (!language_entry(text) && script.match(text).hasMatch()) found << text;
    }
    return found;
}

const QRegularExpression kCyrillic(QStringLiteral("[\\x{0400}-\\x{04FF}]"));
const QRegularExpression kChinese(QStringLiteral("[\\x{4E00}-\\x{9FFF}]"));

class WindowLanguageTest : public ::testing::Test {
  protected:
    void SetUp() override {
        apply_language(QStringLiteral("en"));
        MainWindowOptions options;
        options.persistent = false;
        options.show_dialogs = false;
        window_ = std::make_unique<MainWindow>(options);
        window_->resize(1280, 800);
        window_->show();
        ASSERT_TRUE(window_->open_scenario(
            QStringLiteral(PROBECYCLE_SOURCE_DIR "/resources/examples/bore_two_touch.json")))
            << window_->last_error().toStdString();
        settle();
    }
    void TearDown() override {
        window_.reset();
        apply_language(QStringLiteral("en"));
    }

    void settle() {
        for (int i = 0; i < 4; ++i) QApplication::processEvents();
        window_->recompute_now();
        for (int i = 0; i < 4; ++i) QApplication::processEvents();
    }

    void switch_to(const char* code) {
        window_->set_language(QLatin1String(code));
        settle();
        ASSERT_EQ(current_language(), QLatin1String(code));
    }

    QTabWidget* tabs() const { return window_->findChild<QTabWidget*>(QStringLiteral("tabs")); }
    void show_tab(qsizetype index) {
        tabs()->setCurrentIndex(static_cast<int>(index));
        settle();
    }

    // Results in every tab: fits, a comparison, an export, and errors.
    void fill_the_tabs() {
        auto* calibration = window_->findChild<CalibrationTab*>();
        auto* latency = window_->findChild<LatencyTab*>();
        auto* comparison = window_->findChild<ComparisonTab*>();
        ASSERT_NE(calibration, nullptr);
        calibration->set_gauge_diameter_mm(50.0);
        ASSERT_TRUE(calibration->import_file(lab_data("lab_ring.csv")))
            << calibration->last_error().toStdString();
        ASSERT_TRUE(latency->import_file(lab_data("lab_delay.csv")))
            << latency->last_error().toStdString();
        ASSERT_TRUE(latency->fit());
        ASSERT_TRUE(comparison->simulate_example(dir_.path()))
            << comparison->last_error().toStdString();
        ASSERT_TRUE(comparison->run()) << comparison->last_error().toStdString();
        settle();
    }

    std::unique_ptr<MainWindow> window_;
    QTemporaryDir dir_;
};

// No text is cut short on any tab, in any language, at 1280x800 and at
// 1920x1080: labels, buttons, column headers, charts, combo boxes, tab bars,
// and small result tables that would scroll sideways.
TEST_F(WindowLanguageTest, EveryTabShowsItsTextsWholeInEveryLanguageAndSize) {
    fill_the_tabs();
    for (const QSize size : {QSize(1280, 800), QSize(1920, 1080)}) {
        window_->resize(size);
        for (const char* code : {"en", "zh_CN", "ru"}) {
            switch_to(code);
            const auto expect_whole = [&](const std::string& what) {
                QStringList cut;
                for (const QWidget* w : window_->findChildren<QWidget*>()) {
                    if (w->isVisible()) cut << cut_in(w);
                }
                EXPECT_TRUE(cut.isEmpty())
                    << code << ", " << size.width() << "x" << size.height() << ", " << what << ":\n"
                    << cut.join(QLatin1Char('\n')).toStdString();
            };
            for (qsizetype t = 0; t < kTabs.size(); ++t) {
                show_tab(t);
                expect_whole(kTabs[t].toStdString());
            }
            // A machine with a filter after interpolation: the panel's longest
            // words, and a trigger slower than programmed in the readouts.
            show_tab(0);
            ASSERT_TRUE(window_->apply_preset(
                QStringLiteral(":/presets/machine_linear_after_interpolation.json")));
            settle();
            expect_whole("cycle with the linear-filter preset");
            window_->undo_stack()->undo();
            settle();
        }
    }
}

// A window started in `code` at `size`, shown and laid out, as at start.
std::unique_ptr<MainWindow> started_window(const char* code, QSize size) {
    apply_language(QLatin1String(code));
    MainWindowOptions options;
    options.persistent = false;
    options.show_dialogs = false;
    auto window = std::make_unique<MainWindow>(options);
    window->resize(size);
    window->show();
    for (int i = 0; i < 4; ++i) QApplication::processEvents();
    return window;
}

// A tab shown for the first time after the window started lays its charts
// out at their real size: no axis title drawn small (in a real X window a
// tab hidden at start once drew them at about 5 pixels; offscreen too).
TEST(WindowFirstShow, EveryTabDrawsReadableAxisTitlesInEveryLanguageAndSize) {
    for (const char* code : {"en", "zh_CN", "ru"}) {
        for (const QSize size : {QSize(1280, 800), QSize(1920, 1080)}) {
            const std::unique_ptr<MainWindow> started = started_window(code, size);
            MainWindow& window = *started;
            auto* tabs = window.findChild<QTabWidget*>(QStringLiteral("tabs"));
            for (int t = 0; t < tabs->count(); ++t) {
                tabs->setCurrentIndex(t);
                for (int i = 0; i < 4; ++i) QApplication::processEvents();
                for (const PlotView* plot : tabs->currentWidget()->findChildren<PlotView*>()) {
                    if (!plot->isVisible()) continue;
                    const int px = plot->smallest_axis_title_px();
                    EXPECT_TRUE(px == 0 || px >= 9)
                        << code << ' ' << size.width() << "x" << size.height() << ", tab " << t
                        << ", " << plot->objectName().toStdString() << ": " << px << " px";
                    // The phases chart's rows (a second touch's phases on
                    // the first's rows) leave its labels readable.
                    const int category_px = plot->category_label_px();
                    EXPECT_TRUE(category_px == 0 || category_px >= 9)
                        << code << ' ' << size.width() << "x" << size.height() << ", tab " << t
                        << ", " << plot->objectName().toStdString() << " rows: " << category_px
                        << " px";
                }
            }
        }
    }
    apply_language(QStringLiteral("en"));
}

// At 1920x1080 the parameter panel stands in two columns and shows every
// editor without scrolling, in every language; at 1280x800 it keeps one
// column (the charts need the width) and scrolls.
TEST(WindowFirstShow, TheParameterPanelShowsEveryEditorAt1920x1080InEveryLanguage) {
    for (const char* code : {"en", "zh_CN", "ru"}) {
        for (const QSize size : {QSize(1280, 800), QSize(1920, 1080)}) {
            const std::unique_ptr<MainWindow> started = started_window(code, size);
            MainWindow& window = *started;
            auto* panel = window.findChild<QWidget*>(QStringLiteral("parameters"));
            ASSERT_NE(panel, nullptr);
            auto* scroll = qobject_cast<QScrollArea*>(panel->parentWidget()->parentWidget());
            ASSERT_NE(scroll, nullptr);
            const bool scrolls = scroll->verticalScrollBar()->isVisible();
            const bool large = size.width() == 1920;
            EXPECT_EQ(scrolls, !large) << code << ' ' << size.width() << "x" << size.height();
            EXPECT_EQ(panel->width() >= ParameterPanel::two_column_width(), large)
                << code << ' ' << size.width() << ": " << panel->width() << " px";
        }
    }
    apply_language(QStringLiteral("en"));
}

// After a switch no text is left in the language before: menus, actions,
// undo steps, the status bar, every tab's labels, results, errors and charts.
TEST_F(WindowLanguageTest, NoTextStaysInThePreviousLanguageAfterASwitch) {
    // Texts built at run time, made in Russian: undo steps, a status message,
    // lab results, errors and exports.
    switch_to("ru");
    fill_the_tabs();
    auto* latency = window_->findChild<LatencyTab*>();
    auto* calibration = window_->findChild<CalibrationTab*>();
    EXPECT_FALSE(latency->import_file(dir_.filePath(QStringLiteral("missing.csv"))));
    EXPECT_TRUE(calibration->export_report(dir_.filePath(QStringLiteral("calibration.csv"))));
    Scenario edited = window_->scenario();
    edited.cycle.backoff_mm = 3.5;  // over the recommended 2.485 mm by more than 10 %
    window_->edit_scenario(edited, QStringLiteral("edit"));
    settle();
    ASSERT_TRUE(window_->apply_fix_for(QStringLiteral("backoff_excess")))
        << window_->warning_codes().join(QStringLiteral(",")).toStdString();
    ASSERT_TRUE(window_->apply_preset(QStringLiteral(":/presets/probe_kinematic_radio.json")));
    window_->undo_stack()->undo();  // a redo text too
    settle();

    const auto check = [&](const char* code, const QRegularExpression& gone,
                           const QRegularExpression& expected) {
        switch_to(code);
        QStringList texts;
        for (qsizetype t = 0; t < kTabs.size(); ++t) {
            show_tab(t);
            texts << window_texts(*window_);
        }
        const QStringList left = in_script(texts, gone);
        EXPECT_TRUE(left.isEmpty()) << "in " << code << ":\n"
                                    << left.join(QLatin1Char('\n')).toStdString();
        if (expected.pattern().isEmpty()) return;
        EXPECT_FALSE(in_script(texts, expected).isEmpty()) << code;
    };
    check("ru", kChinese, kCyrillic);
    check("en", kCyrillic, {});
    check("en", kChinese, {});
    check("zh_CN", kCyrillic, kChinese);
}

// Russian numbers: a decimal comma in every number the window shows (the
// CSV paste boxes and their hints show the file format, which keeps '.'),
// and one quantity written alike wherever it is shown.
TEST_F(WindowLanguageTest, RussianNumbersUseTheDecimalCommaEverywhere) {
    fill_the_tabs();
    switch_to("ru");
    const QRegularExpression decimal_point(QStringLiteral("\\d\\.\\d"));
    for (qsizetype t = 0; t < kTabs.size(); ++t) {
        show_tab(t);
        QStringList found;
        for (const QWidget* w : window_->findChildren<QWidget*>()) {
            if (!w->isVisible() || qobject_cast<const QPlainTextEdit*>(w) != nullptr) continue;
            if (w->objectName() == QLatin1String("format-hint")) continue;
            QStringList shown;
            if (const auto* label = qobject_cast<const QLabel*>(w)) shown << label->text();
            if (const auto* spin = qobject_cast<const QAbstractSpinBox*>(w)) shown << spin->text();
            if (const auto* plot = qobject_cast<const PlotView*>(w)) {
                shown << plot->texts() << plot->x_labels() << plot->y_labels(PlotView::Side::left)
                      << plot->y_labels(PlotView::Side::right);
            }
            if (const auto* view = qobject_cast<const QAbstractItemView*>(w)) {
                for (int r = 0; view->model() != nullptr && r < view->model()->rowCount(); ++r) {
                    for (int c = 0; c < view->model()->columnCount(); ++c) {
                        shown << view->model()->index(r, c).data().toString();
                    }
                }
            }
            for (const QString& text : shown) {
                if (decimal_point.match(text).hasMatch()) found << text;
            }
        }
        EXPECT_TRUE(found.isEmpty()) << kTabs[t].toStdString() << ":\n"
                                     << found.join(QLatin1Char('\n')).toStdString();
    }
    show_tab(0);
    // The cycle time in the readout and in the phases chart's title; the
    // recommended backoff in the readout and on the fix's button.
    const QString cycle_time = window_->readout_text(Readout::cycle_time);
    EXPECT_TRUE(cycle_time.contains(QLatin1Char(','))) << cycle_time.toStdString();
    auto* phases = window_->findChild<PlotView*>(QStringLiteral("chart:phases"));
    ASSERT_NE(phases, nullptr);
    EXPECT_TRUE(phases->texts().first().contains(cycle_time))
        << joined(phases->texts()).toStdString();
    const QString backoff = window_->readout_text(Readout::recommended_backoff);
    auto* fix = window_->findChild<QPushButton*>(QStringLiteral("fix:backoff_excess"));
    ASSERT_NE(fix, nullptr);
    EXPECT_TRUE(fix->text().contains(backoff)) << fix->text().toStdString();
}

}  // namespace
}  // namespace probecycle::ui
