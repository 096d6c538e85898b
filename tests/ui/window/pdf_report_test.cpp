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
#include "ui/window/document.h"
#include "ui/window/main_window.h"
#include "ui/window/report_details_dialog.h"

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

QString first_page_text(const QString& path) {
    return run(QStringLiteral("pdftotext"),
               {QStringLiteral("-raw"), QStringLiteral("-f"), QStringLiteral("1"),
                QStringLiteral("-l"), QStringLiteral("1"), path, QStringLiteral("-")});
}

// The pictures in the PDF (pdfimages -list), each with the page it starts
// on and its "width x height" in pixels. A picture is listed once per page
// that draws any of it (a page clips the one before its top): each is
// counted once, by its object.
struct PdfImage {
    int page{0};
    QString size;
};
QList<PdfImage> pdf_images(const QString& path) {
    QList<PdfImage> images;
    QStringList objects;
    const QStringList lines =
        run(QStringLiteral("pdfimages"), {QStringLiteral("-list"), path}).split(QLatin1Char('\n'));
    for (const QString& line : lines.mid(2)) {
        const QStringList fields = line.simplified().split(QLatin1Char(' '));
        if (fields.size() > 10 && fields[2] == QLatin1String("image") &&
            !objects.contains(fields[10])) {
            objects << fields[10];
            images.append({fields[0].toInt(), fields[3] + QLatin1Char('x') + fields[4]});
        }
    }
    return images;
}

QStringList pdf_image_sizes(const QString& path) {
    QStringList sizes;
    for (const PdfImage& image : pdf_images(path)) sizes << image.size;
    return sizes;
}

QList<int> pdf_image_pages(const QString& path) {
    QList<int> pages;
    for (const PdfImage& image : pdf_images(path)) pages << image.page;
    return pages;
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
    // What a customer reads: a suggested change, not the window's button.
    has(QStringLiteral("Suggested change: Set backoff to"));
    EXPECT_FALSE(with_footers.contains(squeezed(QStringLiteral("One-click fix"))));
    has(QStringLiteral("Error: Backoff too small"));
    has(QStringLiteral("Start 6.250 mm out"));
    // The optimiser's recommendation, as its tab says it.
    has(QStringLiteral("The optimiser's recommendation"));
    has(window->optimise_panel()->saved_text());
    // Every input the model uses, by its key; the others are left out.
    for (const KeyInfo& key : scenario_keys()) {
        if (key_applies(s, key.key)) {
            has(QString::fromUtf8(key.key));
        } else {
            EXPECT_FALSE(text.contains(QString::fromUtf8(key.key))) << key.key;
        }
    }
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
    // The fit's figures under the words a reader reads (the CSV's keys are
    // for machines), the tab's warnings as the tab shows them.
    EXPECT_TRUE(text.contains(squeezed(QStringLiteral("Delay [s]")))) << text.toStdString();
    EXPECT_FALSE(text.contains(squeezed(QStringLiteral("delay_s")))) << text.toStdString();
    EXPECT_FALSE(text.contains(squeezed(QStringLiteral("code,severity"))));
    EXPECT_FALSE(text.contains(squeezed(QStringLiteral("No results yet"))));
    EXPECT_GE(pdf_pages(path), 2);

    // In Russian: the tables' words and numbers too.
    window->set_language(QStringLiteral("ru"));
    QCoreApplication::processEvents();
    const QString ru = dir.filePath(QStringLiteral("latency_ru.pdf"));
    ASSERT_TRUE(window->export_pdf_report(ru)) << window->last_error().toStdString();
    const QString ru_text = squeezed(pdf_text(ru));
    EXPECT_TRUE(ru_text.contains(squeezed(QStringLiteral("Время задержки [с]"))))
        << ru_text.toStdString();
    EXPECT_TRUE(ru_text.contains(squeezed(QStringLiteral("Группа")))) << ru_text.toStdString();
    for (const char* english : {"Delay", "group", "interpolation_period", "0.00"}) {
        EXPECT_FALSE(ru_text.contains(squeezed(QLatin1String(english)))) << english;
    }
    window->set_language(QStringLiteral("en"));
    apply_language(QStringLiteral("en"));
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
    EXPECT_TRUE(text.contains(squeezed(QStringLiteral("Points: statistics"))));

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

// The scenario table lists what the model uses: the jerk only under the
// jerk-limited model, the filter times only with a filter.
TEST(PdfReport, TheScenarioTableLeavesOutInputsThatDoNotApply) {
    QTemporaryDir dir;
    auto window = make_window();
    Scenario s;
    s.machine.accel_model = AccelModel::time_constant;
    s.machine.filter = FilterKind::none;
    window->edit_scenario(s, QStringLiteral("edit"));
    const QString plain = dir.filePath(QStringLiteral("plain.pdf"));
    ASSERT_TRUE(window->export_pdf_report(plain)) << window->last_error().toStdString();
    const QString text = squeezed(pdf_text(plain));
    EXPECT_TRUE(text.contains(QStringLiteral("machine.time_constant_s")));
    for (const char* key : {"machine.max_jerk_mm_s3", "machine.max_accel_mm_s2",
                            "machine.filter_time_s", "machine.filter2_time_s"}) {
        EXPECT_FALSE(text.contains(QLatin1String(key))) << key;
    }

    s.machine.accel_model = AccelModel::jerk_limited;
    s.machine.filter = FilterKind::bell;
    window->edit_scenario(s, QStringLiteral("edit"));
    const QString jerk = dir.filePath(QStringLiteral("jerk.pdf"));
    ASSERT_TRUE(window->export_pdf_report(jerk)) << window->last_error().toStdString();
    const QString jerk_text = squeezed(pdf_text(jerk));
    EXPECT_FALSE(jerk_text.contains(QStringLiteral("machine.time_constant_s")));
    for (const char* key : {"machine.max_jerk_mm_s3", "machine.max_accel_mm_s2",
                            "machine.filter_time_s", "machine.filter2_time_s"}) {
        EXPECT_TRUE(jerk_text.contains(QLatin1String(key))) << key;
    }
}

// The title block: the report's details as the project keeps them, with the
// date and the program's version, at the top of the first page.
TEST(PdfReport, TheFirstPageStartsWithTheTitleBlock) {
    QTemporaryDir dir;
    auto window = make_window();
    // File > Report Details…, filled in and accepted.
    ReportDetailsDialog* dialog = window->open_report_details_dialog();
    dialog->set_details(
        {"Acme Präzision GmbH", "DMU 50", "Housing 4711-B", "J. Engineer", "Probe OMP40-2."});
    dialog->accept();
    EXPECT_EQ(window->document()->report_details().part, "Housing 4711-B");
    qputenv("SOURCE_DATE_EPOCH", "1700000000");
    const QString path = dir.filePath(QStringLiteral("titled.pdf"));
    const bool written = window->export_pdf_report(path);
    qunsetenv("SOURCE_DATE_EPOCH");
    ASSERT_TRUE(written) << window->last_error().toStdString();
    const QString first = squeezed(first_page_text(path));
    for (const char* wanted : {"CustomerAcme Präzision GmbH", "MachineDMU 50", "PartHousing 4711-B",
                               "AuthorJ. Engineer", "NotesProbe OMP40-2.", "2023-11-14"}) {
        EXPECT_TRUE(first.contains(squeezed(QString::fromUtf8(wanted))))
            << wanted << "\n"
            << first.left(600).toStdString();
    }
    EXPECT_TRUE(first.contains(
        squeezed(QStringLiteral("ProbeCycle ") + QCoreApplication::applicationVersion())));
    // Before the results.
    EXPECT_LT(first.indexOf(QStringLiteral("Customer")), first.indexOf(QStringLiteral("Results")));

    // Fields left empty are left out.
    window->document()->set_report_details({"Acme", "", "", "", ""});
    ASSERT_TRUE(window->export_pdf_report(path));
    const QString only = squeezed(first_page_text(path));
    EXPECT_TRUE(only.contains(QStringLiteral("CustomerAcme")));
    EXPECT_FALSE(only.contains(QStringLiteral("Author")));
}

// The charts are drawn for the page, each alone at one size whatever the
// window's (no picture of the tab with its inputs and buttons), also from a
// tab whose charts were never shown, and in every language.
TEST(PdfReport, EachChartIsDrawnForThePageWhateverTheWindowsSize) {
    QTemporaryDir dir;
    auto window = make_window();
    const QString chart = QStringLiteral("1520x660");
    struct Case {
        const char* tab;
        QSize window;
        const char* language;
        int charts;
    } cases[] = {{"cycle", {1280, 800}, "en", 4},
                 {"cycle", {1920, 1080}, "ru", 4},
                 {"optimise", {1280, 800}, "zh_CN", 5}};
    for (const Case& c : cases) {
        SCOPED_TRACE(std::string(c.tab) + " " + c.language);
        window->resize(c.window);
        window->set_language(QLatin1String(c.language));
        ASSERT_TRUE(window->select_tab(QLatin1String(c.tab)));
        QCoreApplication::processEvents();
        const QString path =
            dir.filePath(QLatin1String(c.tab) + QLatin1String(c.language) + QStringLiteral(".pdf"));
        ASSERT_TRUE(window->export_pdf_report(path)) << window->last_error().toStdString();
        const QStringList sizes = pdf_image_sizes(path);
        EXPECT_EQ(sizes.size(), c.charts) << sizes.join(QLatin1Char(' ')).toStdString();
        EXPECT_EQ(sizes.count(chart), sizes.size()) << sizes.join(QLatin1Char(' ')).toStdString();
        // Three charts to a page: the cycle's four take the end of the
        // first page and the next, with no third page for the last one
        // (the page before it left a quarter empty).
        if (QLatin1String(c.tab) == QLatin1String("cycle")) {
            const QList<int> pages = pdf_image_pages(path);
            ASSERT_EQ(pages.size(), 4);
            EXPECT_LE(pages[3] - pages[0], 1) << pages[0] << pages[1] << pages[2] << pages[3];
        }
    }
    window->set_language(QStringLiteral("en"));
    apply_language(QStringLiteral("en"));

    // A lab tab: its charts, not the tab.
    auto* lab = window->findChild<LatencyTab*>();
    ASSERT_NE(lab, nullptr);
    ASSERT_TRUE(window->select_tab(QStringLiteral("latency")));
    ASSERT_TRUE(lab->import_file(kLabData + QStringLiteral("/lab_delay.csv")))
        << lab->last_error().toStdString();
    QCoreApplication::processEvents();
    const QString latency = dir.filePath(QStringLiteral("latency.pdf"));
    ASSERT_TRUE(window->export_pdf_report(latency)) << window->last_error().toStdString();
    EXPECT_EQ(pdf_image_sizes(latency), QStringList({chart, chart}));
}

// A section's heading never ends a page without what it heads.
TEST(PdfReport, NoHeadingIsLeftAtTheFootOfAPage) {
    QTemporaryDir dir;
    auto window = make_window();
    window->edit_scenario(troubled_bore(), QStringLiteral("edit"));
    ASSERT_TRUE(window->select_tab(QStringLiteral("optimise")));
    const QString path = dir.filePath(QStringLiteral("report.pdf"));
    ASSERT_TRUE(window->export_pdf_report(path)) << window->last_error().toStdString();
    const int pages = pdf_pages(path);
    for (int page = 1; page <= pages; ++page) {
        const QStringList lines =
            run(QStringLiteral("pdftotext"),
                {QStringLiteral("-raw"), QStringLiteral("-f"), QString::number(page),
                 QStringLiteral("-l"), QString::number(page), path, QStringLiteral("-")})
                .split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        // The last line of text before the footer (pictures have none: the
        // charts' heading is left out, and a page of charts only is passed).
        const qsizetype footer = lines.indexOf(QRegularExpression(QStringLiteral("^Figures.*")));
        ASSERT_GE(footer, 0) << page;
        if (footer == 0) continue;
        const QString last = lines[footer - 1].trimmed();
        for (const char* heading :
             {"Results", "Uncertainty budget", "Warnings and what to change",
              "The optimiser's recommendation", "The scenario", "Machine", "Probe", "Cycle"}) {
            EXPECT_NE(last, QLatin1String(heading)) << "page " << page;
        }
    }
}

}  // namespace
}  // namespace probecycle::ui
