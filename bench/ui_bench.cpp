// probecycle-ui-bench: the window's speed targets (docs/speed.md), offscreen.
//
// BM_SliderToCharts: from a slider value change to every chart updated and
// painted, 500 points per curve: the slider's signal, the undo command, the
// coalesced recompute (core analysis and two 500-point sweeps), the series
// replace()s, the chart layouts, and the event loop's paint of the window
// until each of the four charts has painted. Two sliders: the feed (the feed
// sweeps stay, markers, phases and motion move) and the time constant (every
// curve of every chart changes). BM_Recompute is the core's share alone;
// BM_Recompute_Fanuc the same on the Fanuc-type preset's machine (dynamics
// after interpolation), read from resources/presets.
// BM_OptimiseTabEdit: the Optimise tab's requirement edit to its charts
// painted (the optimiser runs again).
// BM_LaunchToFirstPaint runs `probecycle --time-startup` and times the
// process from spawn to exit (it exits right after its first paint); the
// counter first_paint_ms is the program's own figure from main() to paint.
// BM_LargeProject_*: with the project at the input limits that
// tools/make_large_project.py writes, named by PROBECYCLE_LARGE_PROJECT
// (skipped without it): opening it, moving from tab to tab until the new tab
// has painted, and the feed slider as above with the lab's data loaded.

#include <benchmark/benchmark.h>

#include <QAbstractScrollArea>
#include <QApplication>
#include <QDoubleSpinBox>
#include <QProcess>
#include <QSlider>
#include <QTabWidget>
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/common/file_io.h"
#include "core/cycle/preset.h"
#include "ui/common/plot_view.h"
#include "ui/cycle/computation.h"
#include "ui/cycle/optimise_panel.h"
#include "ui/window/main_window.h"

namespace {

using probecycle::ui::MainWindow;
using probecycle::ui::MainWindowOptions;

std::unique_ptr<MainWindow> make_window(int width, int height) {
    MainWindowOptions options;
    options.persistent = false;
    options.show_dialogs = false;
    options.points_per_curve = 500;
    auto window = std::make_unique<MainWindow>(options);
    window->resize(width, height);
    window->show();
    QCoreApplication::processEvents();
    window->recompute_now();
    window->repaint();
    return window;
}

// The benchmark's third argument: which slider moves. The feed moves the feed
// markers, the phases and the motion (the feed sweeps stay as they are); the
// time constant changes every curve of every chart.
const char* const kSliders[] = {"slider:cycle.probe_feed_mm_min", "slider:machine.time_constant_s"};

QSlider* slider_for(MainWindow& window, std::int64_t which) {
    return window.findChild<QSlider*>(QLatin1String(kSliders[which]));
}

// A drag back and forth over the middle 40 % of the slider, one stop per
// event, so every step really changes the scenario. The slider's positions
// are its round-number stops (quantity_edit.h), a few dozen to a few hundred
// of them, read from the slider itself: a fixed 300-700 of an assumed 1000
// once parked the slider at its end, and no chart changed again.
int next_position(const QSlider& slider, std::int64_t i) {
    const int span = slider.maximum() - slider.minimum();
    const int low = slider.minimum() + (3 * span) / 10;
    const int width = std::max(1, (4 * span) / 10);
    const auto phase = static_cast<int>(i % (2 * width));
    return low + (phase < width ? phase : 2 * width - phase);
}

// Counts paint events of the viewports of the charts shown under `parent`.
class PaintCounter : public QObject {
  public:
    explicit PaintCounter(QWidget* parent) {
        for (const probecycle::ui::PlotView* plot :
             parent->findChildren<probecycle::ui::PlotView*>()) {
            if (!plot->isVisible()) continue;
            for (QAbstractScrollArea* view : plot->findChildren<QAbstractScrollArea*>()) {
                view->viewport()->installEventFilter(this);
                painted_.emplace_back(view->viewport(), false);
            }
        }
    }
    void reset() {
        for (auto& entry : painted_) entry.second = false;
    }
    bool all_painted() const {
        return std::all_of(painted_.begin(), painted_.end(),
                           [](const auto& e) { return e.second; });
    }
    std::size_t count() const { return painted_.size(); }

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::Paint) {
            for (auto& entry : painted_) {
                if (entry.first == watched) entry.second = true;
            }
        }
        return false;
    }

  private:
    std::vector<std::pair<QObject*, bool>> painted_;
};

void run_slider(benchmark::State& state) {
    auto window = make_window(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    QSlider* slider = slider_for(*window, state.range(2));
    state.SetLabel(
        QString::fromLatin1(kSliders[state.range(2)]).section(QLatin1Char(':'), 1).toStdString());
    PaintCounter counter(window->charts_widget());
    if (counter.count() != 4) {
        state.SkipWithError("expected four chart views");
        return;
    }
    std::int64_t i = 0;
    const int before = window->recompute_count();
    for (auto _ : state) {
        counter.reset();
        const int done = window->recompute_count() + 1;
        slider->setValue(next_position(*slider, i++));
        // The event loop runs the coalesced recompute, then lays out and paints.
        for (int pass = 0; pass < 20; ++pass) {
            QCoreApplication::processEvents();
            if (window->recompute_count() >= done && counter.all_painted()) break;
        }
        if (!counter.all_painted()) {
            state.SkipWithError("a chart was not repainted");
            return;
        }
    }
    if (window->recompute_count() - before != state.iterations()) {
        state.SkipWithError("not exactly one recompute per slider change");
    }
    // Whatever is still queued belongs to no iteration.
    QCoreApplication::processEvents();
}

void BM_SliderToCharts(benchmark::State& state) {
    run_slider(state);
}

// The Optimise tab shown: one step of a requirement's spin box (the target
// uncertainty, as an arrow key or a held arrow gives it) to the optimiser
// run again and its charts painted. Its editors have no slider; each step
// re-runs the whole optimiser (best, binding, advice, Pareto front).
void BM_OptimiseTabEdit(benchmark::State& state) {
    auto window = make_window(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    window->select_tab(QStringLiteral("optimise"));
    probecycle::ui::OptimisePanel* panel = window->optimise_panel();
    QCoreApplication::processEvents();
    auto* spin = window->findChild<QDoubleSpinBox*>(
        QStringLiteral("optimise-spin:cycle.target_uncertainty_mm"));
    if (spin == nullptr) {
        state.SkipWithError("no target-uncertainty editor on the Optimise tab");
        return;
    }
    PaintCounter counter(panel);
    std::int64_t i = 0;
    for (auto _ : state) {
        counter.reset();
        const int done = panel->optimise_count() + 1;
        spin->stepBy((i++ % 2 == 0) ? 1 : -1);
        for (int pass = 0; pass < 20; ++pass) {
            QCoreApplication::processEvents();
            if (panel->optimise_count() >= done && counter.all_painted()) break;
        }
        if (panel->optimise_count() < done || !counter.all_painted()) {
            state.SkipWithError("the optimiser did not run, or a chart was not repainted");
            return;
        }
    }
    QCoreApplication::processEvents();
}

void run_recompute(benchmark::State& state, probecycle::Scenario scenario) {
    probecycle::ui::Computation computation(500);
    std::int64_t i = 0;
    for (auto _ : state) {
        scenario.cycle.probe_feed_mm_min = (i++ % 2 == 0) ? 1500.0 : 2500.0;
        benchmark::DoNotOptimize(computation.run(scenario).cycle().total());
    }
}

void BM_Recompute(benchmark::State& state) {
    run_recompute(state, probecycle::Scenario{});
}

void BM_Recompute_Fanuc(benchmark::State& state) {
    run_recompute(state, probecycle::merge_json(
                             probecycle::Scenario{},
                             probecycle::parse_preset(probecycle::read_text_file(std::string(
                                                          PROBECYCLE_PRESETS_DIR
                                                          "/machine_fanuc_exponential_servo.json")))
                                 .scenario_json));
}

void BM_LaunchToFirstPaint(benchmark::State& state) {
    double in_process_ms = 0.0;
    for (auto _ : state) {
        QProcess process;
        process.start(QStringLiteral(PROBECYCLE_GUI_PATH), {QStringLiteral("--time-startup")});
        if (!process.waitForFinished(10000) || process.exitCode() != 0) {
            state.SkipWithError("probecycle --time-startup failed");
            return;
        }
        const QString out = QString::fromUtf8(process.readAllStandardOutput());
        in_process_ms += out.section(QLatin1Char(' '), 1, 1).trimmed().toDouble();
    }
    state.counters["first_paint_ms"] = in_process_ms / static_cast<double>(state.iterations());
}

// The large project's path, or the benchmark skipped.
QString large_project(benchmark::State& state) {
    const char* path = std::getenv("PROBECYCLE_LARGE_PROJECT");
    if (path == nullptr) state.SkipWithError("PROBECYCLE_LARGE_PROJECT not set");
    return path == nullptr ? QString() : QString::fromLocal8Bit(path);
}

void BM_LargeProject_Open(benchmark::State& state) {
    const QString path = large_project(state);
    if (path.isEmpty()) return;
    for (auto _ : state) {
        auto window = make_window(1280, 800);
        if (!window->open_scenario(path)) {
            state.SkipWithError(window->last_error().toStdString().c_str());
            return;
        }
        window->recompute_now();
        window->repaint();
    }
}

// A window with the large project open; nullptr after skipping the benchmark.
std::unique_ptr<MainWindow> large_project_window(benchmark::State& state) {
    const QString path = large_project(state);
    if (path.isEmpty()) return nullptr;
    auto window = make_window(1280, 800);
    if (!window->open_scenario(path)) {
        state.SkipWithError(window->last_error().toStdString().c_str());
        return nullptr;
    }
    return window;
}

void BM_LargeProject_TabSwitch(benchmark::State& state) {
    const auto window = large_project_window(state);
    if (!window) return;
    auto* tabs = window->findChild<QTabWidget*>(QStringLiteral("tabs"));
    int i = 0;
    for (auto _ : state) {
        tabs->setCurrentIndex(++i % tabs->count());
        QCoreApplication::processEvents();
        tabs->currentWidget()->repaint();
    }
}

void BM_LargeProject_SliderToCharts(benchmark::State& state) {
    const auto window = large_project_window(state);
    if (!window) return;
    QSlider* slider = slider_for(*window, 0);
    std::int64_t i = 0;
    for (auto _ : state) {
        slider->setValue(next_position(*slider, i++));
        QCoreApplication::processEvents();
        window->recompute_now();
        window->charts_widget()->repaint();
    }
}

}  // namespace

BENCHMARK(BM_LargeProject_Open)->Iterations(3)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_LargeProject_TabSwitch)->Iterations(10)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_LargeProject_SliderToCharts)
    ->Iterations(20)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_SliderToCharts)
    ->ArgNames({"w", "h", "slider"})
    ->Args({1280, 800, 0})
    ->Args({1280, 800, 1})
    ->Args({1920, 1080, 0})
    ->Args({1920, 1080, 1})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OptimiseTabEdit)
    ->ArgNames({"w", "h"})
    ->Args({1280, 800})
    ->Args({1920, 1080})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Recompute)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Recompute_Fanuc)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LaunchToFirstPaint)->Iterations(10)->Unit(benchmark::kMillisecond)->UseRealTime();

int main(int argc, char** argv) {
    if (std::getenv("QT_QPA_PLATFORM") == nullptr) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
