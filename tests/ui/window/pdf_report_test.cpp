// The PDF report to hand over (docs/window.md; MainWindow::export_pdf_report in
// ui/window/main_window.h): produced offscreen, with the pages and the texts
// the window shows, in the interface's language, written atomically. The
// texts are read back with pdftotext and the pages counted with pdfinfo
// (Debian's poppler-utils, which the test command installs).

#include <gtest/gtest.h>

#include <QApplication>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QThread>
#include <cmath>
#include <memory>
#include <numbers>

#include "core/cycle/cycle.h"
#include "core/cycle/scenario.h"
#include "tests/ui/window/test_window.h"
#include "ui/common/language.h"
#include "ui/cycle/optimise_panel.h"
#include "ui/cycle/uncertainty_table.h"
#include "ui/lab/calibration_tab.h"
#include "ui/lab/latency_tab.h"
#include "ui/window/main_window.h"

namespace probecycle::ui {
namespace {

const QString kLabData = QStringLiteral(PROBECYCLE_TEST_DATA_DIR);

// A bore with errors, warnings and fixes to report.
Scenario troubled_bore() {
    Scenario s;
    s.cycle.feature = Feature::bore;
    s.cycle.probe_feed_mm_min = 3500.0;
    s.cycle.repeats = 3.0;
    s.cycle.part_position_uncertainty_mm = 4.5;
    s.cycle.approach_mm = 4.0;  // inside the uncertainty
    s.probe.max_feed_mm_min = 3000.0;
    return s;
}

// What a program prints, or a failure naming it.
QString run(const QString& program, const QStringList& arguments) {
    QProcess process;
    process.start(program, arguments);
    if (!process.waitForFinished(60000) || process.exitCode() != 0) {
        ADD_FAILURE() << program.toStdString() << " failed (poppler-utils installed?): "
                      << process.readAllStandardError().toStdString();
        return {};
    }
    return QString::fromUtf8(process.readAllStandardOutput());
}

QString pdf_text(const QString& path) {
    // -raw: the text in the order it was drawn, so a table's cells stay whole.
    return run(QStringLiteral("pdftotext"), {QStringLiteral("-raw"), path, QStringLiteral("-")});
}

int pdf_pages(const QString& path) {
    const QString info = run(QStringLiteral("pdfinfo"), {path});
    const QRegularExpressionMatch m =
        QRegularExpression(QStringLiteral("Pages:\\s+(\\d+)")).match(info);
    return m.hasMatch() ? m.captured(1).toInt() : 0;
}

// pdftotext breaks lines where the layout did, and gives the font's
// ligatures ("ﬁ" in "filter"): compare compatibility-normalised text without
// white space.
QString squeezed(const QString& text) {
    return text.normalized(QString::NormalizationForm_KC)
        .remove(QRegularExpression(QStringLiteral("\\s+")));
}

TEST(PdfReport, TheCycleReportHasTheResultsTheWarningsTheirFixesAndEveryInput) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("report.pdf"));
    auto window = make_window();
    const Scenario s = troubled_bore();
    window->edit_scenario(s, QStringLiteral("edit"));
    window->recompute_now();
    ASSERT_TRUE(window->export_pdf_report(path)) << window->last_error().toStdString();

    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_TRUE(file.read(5) == "%PDF-");
    const int pages = pdf_pages(path);
    EXPECT_GE(pages, 3);
    EXPECT_LE(pages, 6);
    // A table row may go on on the next page: read past the footers.
    const QString text = squeezed(pdf_text(path).remove(
        QRegularExpression(QStringLiteral("Figures computed by.*?Page \\d+ of \\d+"),
                           QRegularExpression::DotMatchesEverythingOption)));
    const QString with_footers = squeezed(pdf_text(path));
    const auto has = [&](const QString& wanted) {
        EXPECT_TRUE(text.contains(squeezed(wanted))) << wanted.toStdString();
    };
    has(QStringLiteral("ProbeCycle report: Untitled"));
    // The readouts as the window shows them.
    for (Readout r :
         {Readout::cycle_time, Readout::overtravel, Readout::uncertainty, Readout::knee_feed}) {
        has(window->readout_text(r));
        has(window->readout_detail(r).section(QLatin1Char('\n'), 0, 0));
    }
    // The uncertainty budget, each term and the expanded figure
    // the readout shows.
    has(QStringLiteral("Uncertainty budget"));
    for (const QStringList& row :
         uncertainty_budget_rows(window->scenario(), evaluate(window->scenario()))) {
        has(row[0]);
        if (row.size() > 3 && !row[3].isEmpty()) has(row[3]);
    }
    has(QStringLiteral("Expanded uncertainty, k = 2 ") +
        window->readout_text(Readout::uncertainty));
    // Every warning, errors first, with its one-click fix.
    const QStringList warnings = window->warning_texts();
    ASSERT_GE(warnings.size(), 3);
    for (const QString& warning : warnings) has(warning);
    EXPECT_LT(
        text.indexOf(squeezed(QStringLiteral("Feed over the probe's rating"))),
        text.indexOf(squeezed(QStringLiteral("Start within the part's position uncertainty"))));
    has(QStringLiteral("One-click fix: Set backoff to"));
    has(QStringLiteral("Error: Backoff too small"));
    has(QStringLiteral("Start 6.250 mm out"));
    // The optimiser's recommendation, as its tab says it.
    has(QStringLiteral("The optimiser's recommendation"));
    has(window->optimise_panel()->saved_text());
    // Every input, by its key.
    for (const KeyInfo& key : scenario_keys()) has(QString::fromUtf8(key.key));
    has(QStringLiteral("3000 mm/min"));  // the probe's rating, as the editor shows it
    // What the figures are, on every page.
    EXPECT_EQ(with_footers.count(squeezed(QStringLiteral("not a calibration certificate"))), pages);
    EXPECT_TRUE(with_footers.contains(squeezed(QStringLiteral("Page %1 of %1").arg(pages))));
}

TEST(PdfReport, InTheInterfacesLanguage) {
    QTemporaryDir dir;
    auto window = make_window();
    window->edit_scenario(troubled_bore(), QStringLiteral("edit"));
    struct {
        const char* code;
        const char* title;
        const char* page;
    } languages[] = {{"ru", "Отчёт ProbeCycle", "Страница 1 из"},
                     {"zh_CN", "ProbeCycle 报告", "第 1 页"}};
    for (const auto& language : languages) {
        SCOPED_TRACE(language.code);
        window->set_language(QLatin1String(language.code));
        QCoreApplication::processEvents();
        const QString path = dir.filePath(QLatin1String(language.code) + QStringLiteral(".pdf"));
        ASSERT_TRUE(window->export_pdf_report(path)) << window->last_error().toStdString();
        const QString text = squeezed(pdf_text(path));
        EXPECT_TRUE(text.contains(squeezed(QString::fromUtf8(language.title))))
            << text.left(400).toStdString();
        // Qt's PDF text map gives 页 as the radical ⻚ that shares its
        // glyph (the page shows 页; pdftotext reads ⻚).
        EXPECT_TRUE(
            text.contains(squeezed(QString::fromUtf8(language.page))) ||
            text.contains(
                squeezed(QString::fromUtf8(language.page)).replace(QChar(0x9875), QChar(0x2EDA))));
        // Each warning (its start: a row may go on past a footer).
        for (const QString& warning : window->warning_texts()) {
            EXPECT_TRUE(text.contains(squeezed(warning.left(20)))) << warning.toStdString();
        }
    }
    window->set_language(QStringLiteral("en"));
    apply_language(QStringLiteral("en"));
}

TEST(PdfReport, ALabTabReportsItsOwnResults) {
    QTemporaryDir dir;
    auto window = make_window();
    auto* tabs = window->findChild<QTabWidget*>(QStringLiteral("tabs"));
    ASSERT_NE(tabs, nullptr);
    auto* lab = window->findChild<LatencyTab*>();
    ASSERT_NE(lab, nullptr);
    tabs->setCurrentWidget(lab);
    const QString empty = dir.filePath(QStringLiteral("empty.pdf"));
    ASSERT_TRUE(window->export_pdf_report(empty)) << window->last_error().toStdString();
    EXPECT_TRUE(squeezed(pdf_text(empty)).contains(squeezed(QStringLiteral("No results yet"))));

    ASSERT_TRUE(lab->import_file(kLabData + QStringLiteral("/lab_delay.csv")))
        << lab->last_error().toStdString();
    QCoreApplication::processEvents();
    const QString path = dir.filePath(QStringLiteral("latency.pdf"));
    ASSERT_TRUE(window->export_pdf_report(path)) << window->last_error().toStdString();
    const QString text = squeezed(pdf_text(path));
    // The fit's figures, as its CSV report names them.
    EXPECT_TRUE(text.contains(squeezed(QStringLiteral("delay_s")))) << text.toStdString();
    EXPECT_FALSE(text.contains(squeezed(QStringLiteral("No results yet"))));
    EXPECT_GE(pdf_pages(path), 2);
}

// 10 000 ring points: a report of a few pages (their statistics and the
// largest residuals), not one row per point; the CSV export has them all.
TEST(PdfReport, ALabTabSummarisesManyPoints) {
    QTemporaryDir dir;
    auto window = make_window();
    auto* tabs = window->findChild<QTabWidget*>(QStringLiteral("tabs"));
    auto* lab = window->findChild<CalibrationTab*>();
    ASSERT_NE(lab, nullptr);
    tabs->setCurrentWidget(lab);
    QString csv = QStringLiteral("orientation_deg,x_mm,y_mm\n");
    constexpr int kPoints = 10000;
    for (int i = 0; i < kPoints; ++i) {
        const double angle = 2.0 * std::numbers::pi * (i / 2) / (kPoints / 2);
        const double r = 23.5 + 0.001 * std::sin(3.0 * angle);
        csv += QStringLiteral("%1,%2,%3\n")
                   .arg(i % 2 == 0 ? 0 : 180)
                   .arg(r * std::cos(angle), 0, 'f', 5)
                   .arg(r * std::sin(angle), 0, 'f', 5);
    }
    lab->set_points_text(csv);
    ASSERT_TRUE(lab->fit()) << lab->last_error().toStdString();
    const QString path = dir.filePath(QStringLiteral("ring.pdf"));
    ASSERT_TRUE(window->export_pdf_report(path)) << window->last_error().toStdString();
    EXPECT_LE(pdf_pages(path), 4);
    const QString text = squeezed(pdf_text(path));
    EXPECT_TRUE(text.contains(squeezed(QStringLiteral("10,000 points: the tables give their"))))
        << text.left(2000).toStdString();
    EXPECT_TRUE(text.contains(squeezed(QStringLiteral("points summary"))));

    const QString report = dir.filePath(QStringLiteral("ring.csv"));
    ASSERT_TRUE(lab->export_report(report));
    QFile file(report);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_GT(file.readAll().count('\n'), kPoints);
}

TEST(PdfReport, AFailedWriteSaysWhereAndLeavesNothing) {
    QTemporaryDir dir;
    auto window = make_window();
    const QString path = dir.filePath(QStringLiteral("missing/report.pdf"));
    EXPECT_FALSE(window->export_pdf_report(path));
    EXPECT_TRUE(window->last_error().contains(QStringLiteral("report.pdf")))
        << window->last_error().toStdString();
    EXPECT_FALSE(QFile::exists(path));
}

TEST(PdfReport, UnderSourceDateEpochTheSameReportIsTheSameBytes) {
    // The creation date was once the time of the export, so two exports of
    // one report differed.
    QTemporaryDir dir;
    auto window = make_window();
    qputenv("SOURCE_DATE_EPOCH", "1700000000");
    const QString first = dir.filePath(QStringLiteral("first.pdf"));
    const QString second = dir.filePath(QStringLiteral("second.pdf"));
    ASSERT_TRUE(window->export_pdf_report(first));
    QThread::msleep(1100);  // a second later: the clock's date would differ
    ASSERT_TRUE(window->export_pdf_report(second));
    qunsetenv("SOURCE_DATE_EPOCH");
    QFile a(first);
    QFile b(second);
    ASSERT_TRUE(a.open(QIODevice::ReadOnly));
    ASSERT_TRUE(b.open(QIODevice::ReadOnly));
    const QByteArray bytes = a.readAll();
    EXPECT_EQ(bytes, b.readAll());
    EXPECT_TRUE(bytes.contains("/CreationDate (D:20231114221320Z)"));
}

}  // namespace
}  // namespace probecycle::ui
