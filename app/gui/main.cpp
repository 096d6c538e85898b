// probecycle: the desktop window.
//
//   probecycle [SCENARIO.json]
//   probecycle --screenshot FILE.png [--scenario FILE.json] [--size WxH] [--language CODE]
//   probecycle --report-pdf FILE.pdf [--scenario FILE.json] [--tab NAME] [--language CODE]
//   probecycle --time-startup        prints the ms from main() to the first painted window
//
// --screenshot renders the window offscreen to a PNG and exits, --report-pdf
// writes the PDF report of a tab (File > Export PDF Report) and exits; without
// a display they select the offscreen platform themselves.

#include <QApplication>
#include <QBuffer>
#include <QByteArray>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QImage>
#include <QSettings>
#include <QSize>
#include <QStatusBar>
#include <QTimer>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>

#include "ui/common/app_icon.h"
#include "ui/common/file_write.h"
#include "ui/common/language.h"
#include "ui/window/main_window.h"

#ifndef PROBECYCLE_VERSION
#define PROBECYCLE_VERSION "0"
#endif

namespace {

using Clock = std::chrono::steady_clock;

bool has_flag(int argc, char** argv, const char* flag) {
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], flag, std::strlen(flag)) == 0) return true;  // also --flag=value
    }
    return false;
}

// Offscreen rendering (and --help, --version) needs no display; pick it before
// QApplication exists. The window without a display would only get Qt's
// "could not load the Qt platform plugin": say instead how to run it. False
// when the program should stop.
bool choose_platform(int argc, char** argv) {
    const bool headless_mode = has_flag(argc, argv, "--screenshot") ||
                               has_flag(argc, argv, "--report-pdf") ||
                               has_flag(argc, argv, "--time-startup") ||
                               has_flag(argc, argv, "--help") || has_flag(argc, argv, "-h") ||
                               has_flag(argc, argv, "--version") || has_flag(argc, argv, "-v");
    const bool has_display =
        std::getenv("DISPLAY") != nullptr || std::getenv("WAYLAND_DISPLAY") != nullptr;
    if (has_display || std::getenv("QT_QPA_PLATFORM") != nullptr) return true;
    if (headless_mode) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
        return true;
    }
    std::fprintf(stderr,
                 "probecycle: no display (DISPLAY and WAYLAND_DISPLAY are not set).\n"
                 "  Render the window to a PNG:  probecycle --screenshot probecycle.png "
                 "[--scenario FILE.json]\n"
                 "  Run it on a virtual display: xvfb-run probecycle\n"
                 "  The same computations on the command line: probecycle-cli --help\n");
    return false;
}

constexpr int kMinWidth = 400;
constexpr int kMinHeight = 300;
constexpr int kMaxSide = 8000;

std::optional<QSize> parse_size(const QString& text) {
    const QStringList parts = text.toLower().split(QLatin1Char('x'));
    if (parts.size() != 2) return std::nullopt;
    bool ok_w = false;
    bool ok_h = false;
    const int w = parts[0].toInt(&ok_w);
    const int h = parts[1].toInt(&ok_h);
    if (!ok_w || !ok_h || w < kMinWidth || h < kMinHeight || w > kMaxSide || h > kMaxSide)
        return std::nullopt;
    return QSize(w, h);
}

// Quits after the first paint of the window has been flushed, and prints the time.
class FirstPaintProbe : public QObject {
  public:
    FirstPaintProbe(Clock::time_point start, QWidget* window) : start_(start) {
        window->installEventFilter(this);
    }

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::Paint && !seen_) {
            seen_ = true;
            // The rest of this paint pass (all children) runs before the timer fires.
            QTimer::singleShot(0, this, [this] {
                const double ms =
                    std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
                std::printf("startup_ms %.1f\n", ms);
                std::fflush(stdout);
                QCoreApplication::quit();
            });
        }
        return QObject::eventFilter(watched, event);
    }

  private:
    Clock::time_point start_;
    bool seen_{false};
};

}  // namespace

int main(int argc, char** argv) {
    const Clock::time_point start = Clock::now();
    if (!choose_platform(argc, argv)) return 2;
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("ProbeCycle"));
    QCoreApplication::setApplicationName(QStringLiteral("ProbeCycle"));
    QCoreApplication::setApplicationVersion(QStringLiteral(PROBECYCLE_VERSION));
    QApplication::setWindowIcon(probecycle::ui::app_icon());

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Cycle time, overtravel and uncertainty of touch-trigger probing cycles."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                        QStringLiteral("Render the window to a PNG and exit."),
                                        QStringLiteral("FILE"));
    const QCommandLineOption scenario(
        QStringLiteral("scenario"),
        QStringLiteral("Scenario JSON for --screenshot and --report-pdf."), QStringLiteral("FILE"));
    const QCommandLineOption size(
        QStringLiteral("size"), QStringLiteral("Window size for --screenshot (default 1280x800)."),
        QStringLiteral("WxH"), QStringLiteral("1280x800"));
    const QCommandLineOption language(QStringLiteral("language"),
                                      QStringLiteral("Interface language: en, zh_CN or ru."),
                                      QStringLiteral("CODE"));
    const QCommandLineOption time_startup(
        QStringLiteral("time-startup"),
        QStringLiteral("Print the ms from start to the first painted window, then exit."));
    const QCommandLineOption tab(
        QStringLiteral("tab"),
        QStringLiteral(
            "Tab for --screenshot and --report-pdf: cycle (default), calibration, latency, "
            "comparison or optimise."),
        QStringLiteral("NAME"), QStringLiteral("cycle"));
    const QCommandLineOption report_pdf(
        QStringLiteral("report-pdf"),
        QStringLiteral("Write the PDF report of the tab (--tab) to FILE and exit; no display "
                       "needed."),
        QStringLiteral("FILE"));
    parser.addOptions({screenshot, scenario, size, language, time_startup, tab, report_pdf});
    parser.addPositionalArgument(
        QStringLiteral("file"),
        QStringLiteral("Scenario (.json) or project (.probecycle) to open: the desktop entry "
                       "passes the file double-clicked."),
        QStringLiteral("[SCENARIO.json|PROJECT.probecycle]"));
    parser.process(app);

    const bool reporting = parser.isSet(report_pdf);
    const bool shooting = parser.isSet(screenshot) || reporting;
    const bool timing = parser.isSet(time_startup);
    const bool interactive = !shooting && !timing;
    const QString language_code =
        parser.isSet(language)
            ? parser.value(language)
            : (interactive ? QSettings().value(QStringLiteral("view/language")).toString()
                           : QStringLiteral("en"));
    probecycle::ui::apply_language(language_code);

    probecycle::ui::MainWindowOptions options;
    options.persistent = interactive;
    options.show_dialogs = interactive;
    probecycle::ui::MainWindow window(options);

    const QString file = shooting ? parser.value(scenario) : parser.positionalArguments().value(0);
    if (!file.isEmpty() && !window.open_scenario(file)) {
        if (!interactive) {
            std::fprintf(stderr, "probecycle: %s\n", qPrintable(window.last_error()));
            return 2;
        }
    }

    if (shooting) {
        const std::optional<QSize> wanted = parse_size(parser.value(size));
        if (!wanted) {
            std::fprintf(stderr,
                         "probecycle: --size: got '%s'; allowed: WxH, a width from %d to %d "
                         "and a height from %d to %d pixels, e.g. 1920x1080\n",
                         qPrintable(parser.value(size)), kMinWidth, kMaxSide, kMinHeight, kMaxSide);
            return 2;
        }
        // Any tab can be looked at offscreen.
        if (!window.select_tab(parser.value(tab))) {
            std::fprintf(stderr, "probecycle: --tab: got '%s'; allowed: %s\n",
                         qPrintable(parser.value(tab)),
                         qPrintable(window.tab_keys().join(QStringLiteral(", "))));
            return 2;
        }
        window.resize(*wanted);
        window.show();
        window.statusBar()->clearMessage();  // no "Opened ..." in the picture
        window.recompute_now();
        QCoreApplication::processEvents();
        window.recompute_now();
        QCoreApplication::processEvents();
        if (reporting) {
            if (!window.export_pdf_report(parser.value(report_pdf))) {
                std::fprintf(stderr, "probecycle: %s\n", qPrintable(window.last_error()));
                return 2;
            }
            if (!parser.isSet(screenshot)) return 0;
        }
        // Through the checked writer as every export: a FIFO, a device or a
        // folder is refused, not replaced.
        const QImage image = window.grab().toImage();
        QByteArray png;
        QBuffer buffer(&png);
        QString error;
        if (!buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, "PNG")) {
            error = QStringLiteral("cannot encode the PNG");
        }
        if (!error.isEmpty() || !probecycle::ui::write_file(parser.value(screenshot), png, error)) {
            std::fprintf(stderr, "probecycle: cannot write %s: %s\n",
                         qPrintable(parser.value(screenshot)), qPrintable(error));
            return 2;
        }
        return 0;
    }

    window.recompute_now();  // the first paint shows results, not empty charts
    std::optional<FirstPaintProbe> probe;
    if (timing) probe.emplace(start, &window);
    window.show();
    return QApplication::exec();
}
