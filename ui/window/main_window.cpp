#include "ui/window/main_window.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QBuffer>
#include <QCloseEvent>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontMetrics>
#include <QImage>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPainter>
#include <QPixmap>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QStyle>
#include <QTabWidget>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>
#include <algorithm>
#include <exception>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <utility>

#include "core/common/file_io.h"
#include "core/cycle/cycle_report.h"
#include "core/program/linuxcnc_ini.h"
#include "ui/common/app_icon.h"
#include "ui/common/file_write.h"
#include "ui/common/language.h"
#include "ui/common/page.h"
#include "ui/common/parameter_info.h"
#include "ui/common/text_format.h"
#include "ui/comparison/comparison_tab.h"
#include "ui/cycle/cycle_charts.h"
#include "ui/cycle/optimise_panel.h"
#include "ui/cycle/parameter_panel.h"
#include "ui/lab/calibration_tab.h"
#include "ui/lab/latency_tab.h"
#include "ui/program/program_dialog.h"
#include "ui/window/document.h"
#include "ui/window/help_guide.h"
#include "ui/window/preset_list.h"
#include "ui/window/report_details_dialog.h"
#include "ui/window/scenario_command.h"

namespace probecycle::ui {

namespace {

constexpr int kMaxRecentFiles = 8;
// The property that holds a tab's key ("cycle", "calibration", ...).
constexpr const char* kTabKeyProperty = "probecycle_tab_key";

// A scenario key's label in the interface language.
QString key_label(const QString& key) {
    const KeyInfo* info = find_any_key(key.toStdString());
    return info != nullptr ? QCoreApplication::translate("Parameter", info->label) : key;
}

// Every problem of a refused scenario, one a line, in the interface language.
QString error_list(const FileContentError& error) {
    QStringList lines;
    for (const FieldError& e : error.errors()) lines << translate(e.to_message());
    return lines.join(QLatin1Char('\n'));
}

// A word or flag key's value as the window shows it.
QString shown_word(const Scenario& s, const KeyInfo& key) {
    const std::string_view name = key.key;
    if (name == "machine.accel_model") return accel_model_label(s.machine.accel_model);
    if (name == "machine.filter") return filter_label(s.machine.filter);
    if (name == "cycle.strategy") return strategy_label(s.cycle.strategy);
    if (name == "cycle.feature") return feature_label(s.cycle.feature);
    if (name == "cycle.backoff_from") return backoff_from_label(s.cycle.backoff_from);
    if (name == "cycle.tolerance_action") return tolerance_action_label(s.cycle.tolerance_action);
    if (key.kind == KeyKind::flag) {
        return value_text(s, key) == "true" ? MainWindow::tr("on") : MainWindow::tr("off");
    }
    return QString::fromStdString(value_text(s, key));
}

// What a preset overwrote, "label: old -> new" per key it changed,
// in the editors' units.
QStringList changed_keys(const Scenario& before, const Scenario& after) {
    QStringList out;
    for (const KeyInfo& key : scenario_keys()) {
        if (value_text(before, key) == value_text(after, key)) continue;
        if (key.kind != KeyKind::number) {
            out << QStringLiteral("%1: %2 \u2192 %3")
                       .arg(QCoreApplication::translate("Parameter", key.label),
                            shown_word(before, key), shown_word(after, key));
            continue;
        }
        const ParameterView view = parameter_view(key);
        const auto shown = [&](const Scenario& s) {
            return QLocale().toString(*get_number(s, key.key) * view.factor, 'f', view.decimals) +
                   QLatin1Char(' ') + view.unit;
        };
        out << QStringLiteral("%1: %2 \u2192 %3").arg(view.label, shown(before), shown(after));
    }
    return out;
}

// A divider whose place follows the window (the panel's width, the warnings
// pane's height) until the user drags it: kept for the next start only then,
// so an untouched one follows the window there too.
void save_chosen_split(QSettings& settings, const QString& key, const QSplitter& splitter,
                       bool chosen) {
    if (chosen) {
        settings.setValue(key, splitter.saveState());
    } else {
        settings.remove(key);
    }
}

}  // namespace

MainWindow::MainWindow(const MainWindowOptions& options, QWidget* parent)
    : QMainWindow(parent), options_(options), computation_(options.points_per_curve) {
    setObjectName(QStringLiteral("MainWindow"));
    setWindowIcon(app_icon());
    document_ = new Document(this);
    undo_ = document_->undo_stack();
    recompute_timer_.setSingleShot(true);
    recompute_timer_.setInterval(0);  // one recompute per pass of the event loop
    connect(&recompute_timer_, &QTimer::timeout, this, &MainWindow::recompute);

    build_ui();
    build_actions();
    build_menus();
    retranslate();
    for (Page* page : {static_cast<Page*>(calibration_tab_), static_cast<Page*>(latency_tab_),
                       static_cast<Page*>(comparison_tab_)}) {
        document_->add_page(page);
    }
    connect(document_, &Document::scenario_changed, this, &MainWindow::show_scenario);
    connect(document_, &Document::modified_changed, this, &MainWindow::update_title);
    if (options_.persistent) {
        restore_settings();
        // The first start opens the guide on "Getting started", once.
        QSettings settings;
        if (!settings.value(QStringLiteral("view/guide_shown")).toBool()) {
            settings.setValue(QStringLiteral("view/guide_shown"), true);
            QTimer::singleShot(0, this, &MainWindow::show_guide);
        }
    }
    show_scenario();
    update_title();
}

MainWindow::~MainWindow() {
    // The document is a child, destroyed after this window's members: its
    // last signals must not reach update_title() (which reads them and the
    // tabs). Found by valgrind as a use after free, intermittent in ctest.
    document_->disconnect(this);
    undo_->disconnect(this);
    tabs_->disconnect(this);
}

// --- construction ---------------------------------------------------------

void MainWindow::build_ui() {
    panel_ = new ParameterPanel;
    panel_->setObjectName(QStringLiteral("parameters"));
    connect(panel_, &ParameterPanel::edited, this, &MainWindow::on_panel_edit);
    panel_scroll_ = new QScrollArea;
    panel_scroll_->setWidget(panel_);
    panel_scroll_->setWidgetResizable(true);
    panel_scroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    panel_scroll_->setFrameShape(QFrame::NoFrame);
    panel_scroll_->setMinimumWidth(260);

    readouts_ = new Readouts;
    charts_ = new CycleCharts;
    warnings_ = new WarningsPanel;
    connect(warnings_, &WarningsPanel::fix_requested, this,
            [this](const QString& code) { apply_fix_for(code); });
    connect(warnings_, &WarningsPanel::counts_changed, this, &MainWindow::update_warning_counts);
    warnings_scroll_ = new QScrollArea;
    warnings_scroll_->setWidget(warnings_);
    warnings_scroll_->setWidgetResizable(true);
    warnings_scroll_->setFrameShape(QFrame::NoFrame);
    warnings_title_ = new QLabel;
    warnings_title_->setObjectName(QStringLiteral("warnings-title"));
    QFont bold = warnings_title_->font();
    bold.setBold(true);
    warnings_title_->setFont(bold);
    auto* warnings_box = new QWidget;
    warnings_box->setObjectName(QStringLiteral("warnings-box"));
    auto* warnings_layout = new QVBoxLayout(warnings_box);
    warnings_layout->setContentsMargins(0, 0, 0, 0);
    warnings_layout->setSpacing(2);
    warnings_layout->addWidget(warnings_title_);
    warnings_layout->addWidget(warnings_scroll_, 1);

    right_splitter_ = new QSplitter(Qt::Vertical);
    right_splitter_->setChildrenCollapsible(false);
    right_splitter_->addWidget(charts_);
    right_splitter_->addWidget(warnings_box);
    right_splitter_->setStretchFactor(0, 3);
    right_splitter_->setStretchFactor(1, 1);
    // Once the user drags the divider, the panel keeps the height they chose.
    connect(right_splitter_, &QSplitter::splitterMoved, this,
            [this] { warnings_sized_by_user_ = true; });
    // After the layout has placed the new rows: their height is known then.
    connect(warnings_, &WarningsPanel::counts_changed, this,
            [this] { QTimer::singleShot(0, this, &MainWindow::fit_warnings_pane); });
    // Room for about three problems, and charts that stay readable
    // however far the user drags the panel up.
    const int line = fontMetrics().height();
    warnings_box->setMinimumHeight(8 * line);
    charts_->setMinimumHeight(20 * line);

    auto* right = new QWidget;
    auto* right_layout = new QVBoxLayout(right);
    right_layout->setContentsMargins(0, 6, 6, 0);
    right_layout->setSpacing(6);
    right_layout->addWidget(readouts_);
    right_layout->addWidget(right_splitter_, 1);

    main_splitter_ = new QSplitter(Qt::Horizontal);
    main_splitter_->setObjectName(QStringLiteral("main-splitter"));
    main_splitter_->addWidget(panel_scroll_);
    main_splitter_->addWidget(right);
    main_splitter_->setStretchFactor(0, 0);
    main_splitter_->setStretchFactor(1, 1);
    main_splitter_->setChildrenCollapsible(false);
    main_splitter_->setSizes({ParameterPanel::one_column_width(), 960});
    // The panel's width follows the window's until the user drags the divider.
    main_splitter_->installEventFilter(this);
    connect(main_splitter_, &QSplitter::splitterMoved, this,
            [this] { panel_sized_by_user_ = true; });

    // The lab: calibration and latency from the user's own touches.
    calibration_tab_ = new CalibrationTab;
    latency_tab_ = new LatencyTab;
    connect(latency_tab_, &LatencyTab::delay_applied, this,
            [this](const QString& key, double value_s) {
                Scenario s = scenario();
                if (!set_number(s, key.toStdString(), value_s)) return;
                edit_scenario(s, [] { return tr("apply the measured delay"); });
            });
    tabs_ = new QTabWidget;
    tabs_->setObjectName(QStringLiteral("tabs"));
    tabs_->setDocumentMode(true);
    comparison_tab_ = new ComparisonTab;
    // "What should I change?": the optimiser's tab.
    optimise_ = new OptimisePanel;
    // The tabs in their order, each with the key `--tab` and tab_keys() name
    // it by.
    const std::pair<const char*, QWidget*> pages[] = {{"cycle", main_splitter_},
                                                      {"calibration", calibration_tab_},
                                                      {"latency", latency_tab_},
                                                      {"comparison", comparison_tab_},
                                                      {"optimise", optimise_}};
    for (const auto& [key, page] : pages) {
        page->setProperty(kTabKeyProperty, QString::fromLatin1(key));
        tabs_->addTab(page, QString());
    }
    connect(optimise_, &OptimisePanel::requirement_edited, this,
            [this](const QString& key, double value) {
                Scenario s = scenario();
                if (!set_number(s, key.toStdString(), value)) return;
                on_panel_edit(s, key);
            });
    connect(optimise_, &OptimisePanel::options_changed, this, &MainWindow::refresh_optimise);
    connect(optimise_, &OptimisePanel::apply_requested, this, [this](const Scenario& best) {
        edit_scenario(best, [] { return tr("apply the best settings"); });
    });
    connect(tabs_, &QTabWidget::currentChanged, this, [this] {
        if (tabs_->currentWidget() != optimise_) return;
        recompute_now();  // optimises too when a recompute was pending
        if (optimise_stale_) refresh_optimise();
    });
    setCentralWidget(tabs_);

    statusBar();  // file and preset messages
    // A message's whole text (show_status_text) goes with the message.
    connect(statusBar(), &QStatusBar::messageChanged, this, [this](const QString& message) {
        if (message.isEmpty()) statusBar()->setToolTip(QString());
    });
    resize(1280, 800);
}

void MainWindow::build_actions() {
    const auto icon = [this](QStyle::StandardPixmap pixmap) {
        return style()->standardIcon(pixmap);
    };
    new_ = new QAction(icon(QStyle::SP_FileIcon), {}, this);
    new_->setShortcut(QKeySequence::New);
    connect(new_, &QAction::triggered, this, &MainWindow::new_scenario);
    open_ = new QAction(icon(QStyle::SP_DialogOpenButton), {}, this);
    open_->setShortcut(QKeySequence::Open);
    connect(open_, &QAction::triggered, this, &MainWindow::open_dialog);
    save_ = new QAction(icon(QStyle::SP_DialogSaveButton), {}, this);
    save_->setShortcut(QKeySequence::Save);
    connect(save_, &QAction::triggered, this, &MainWindow::save_action);
    save_as_ = new QAction(this);
    save_as_->setShortcut(QKeySequence::SaveAs);
    connect(save_as_, &QAction::triggered, this, [this] { save_as_dialog(project_expected()); });
    export_csv_ = new QAction(icon(QStyle::SP_FileDialogDetailedView), {}, this);
    export_csv_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    connect(export_csv_, &QAction::triggered, this, &MainWindow::export_csv_dialog);
    export_png_ = new QAction(icon(QStyle::SP_DesktopIcon), {}, this);
    export_png_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
    connect(export_png_, &QAction::triggered, this, &MainWindow::export_png_dialog);
    export_pdf_ = new QAction(icon(QStyle::SP_FileIcon), {}, this);
    export_pdf_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_P));
    connect(export_pdf_, &QAction::triggered, this, &MainWindow::export_pdf_dialog);
    report_details_ = new QAction(this);
    connect(report_details_, &QAction::triggered, this, [this] { open_report_details_dialog(); });
    export_program_ = new QAction(this);
    connect(export_program_, &QAction::triggered, this, [this] { open_cycle_program_dialog(); });
    import_linuxcnc_ = new QAction(this);
    import_linuxcnc_->setObjectName(QStringLiteral("action-import-linuxcnc"));
    connect(import_linuxcnc_, &QAction::triggered, this, &MainWindow::import_linuxcnc_dialog);
    quit_ = new QAction(this);
    quit_->setShortcut(QKeySequence::Quit);
    quit_->setMenuRole(QAction::QuitRole);
    connect(quit_, &QAction::triggered, this, &QWidget::close);

    // Own actions rather than QUndoStack's, so their prefix follows the language.
    undo_action_ = new QAction(icon(QStyle::SP_ArrowBack), {}, this);
    undo_action_->setShortcut(QKeySequence::Undo);
    undo_action_->setEnabled(false);
    // Undo and redo jump (a slider's drag is one step): the charts fit anew.
    connect(undo_action_, &QAction::triggered, charts_, &CycleCharts::refit_ranges);
    connect(undo_action_, &QAction::triggered, undo_, &QUndoStack::undo);
    connect(undo_, &QUndoStack::canUndoChanged, undo_action_, &QAction::setEnabled);
    redo_action_ = new QAction(icon(QStyle::SP_ArrowForward), {}, this);
    redo_action_->setShortcut(QKeySequence::Redo);
    redo_action_->setEnabled(false);
    connect(redo_action_, &QAction::triggered, charts_, &CycleCharts::refit_ranges);
    connect(redo_action_, &QAction::triggered, undo_, &QUndoStack::redo);
    connect(undo_, &QUndoStack::canRedoChanged, redo_action_, &QAction::setEnabled);
    connect(undo_, &QUndoStack::indexChanged, this, &MainWindow::update_undo_texts);

    pin_ = new QAction(icon(QStyle::SP_DialogApplyButton), {}, this);
    pin_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    connect(pin_, &QAction::triggered, this, &MainWindow::pin_baseline);
    unpin_ = new QAction(icon(QStyle::SP_DialogDiscardButton), {}, this);
    unpin_->setEnabled(false);
    connect(unpin_, &QAction::triggered, this, &MainWindow::clear_baseline);

    guide_ = new QAction(this);
    guide_->setObjectName(QStringLiteral("action-guide"));
    guide_->setShortcut(QKeySequence::HelpContents);
    connect(guide_, &QAction::triggered, this, [this] { show_guide(); });
    about_ = new QAction(this);
    about_->setMenuRole(QAction::AboutRole);
    connect(about_, &QAction::triggered, this, [this] {
        QMessageBox::about(
            this, tr("About ProbeCycle"),
            tr("<p><b>ProbeCycle</b> %1</p><p>Cycle time, overtravel and uncertainty of "
               "touch-trigger probing cycles on CNC machine tools.</p><p>Every value in the model "
               "is a typical one until you replace it with your measured value.</p>")
                .arg(QCoreApplication::applicationVersion()));
    });

    for (const PresetEntry& entry : preset_list()) {
        auto* action = new QAction(this);
        const QString path = entry.path;
        connect(action, &QAction::triggered, this, [this, path] { apply_preset(path); });
        preset_actions_.append({action, &entry.preset});
    }
    presets_note_ = new QAction(this);
    presets_note_->setEnabled(false);

    language_group_ = new QActionGroup(this);
    language_group_->setExclusive(true);
    QStringList codes{QString()};
    codes.append(available_languages());
    for (const QString& code : codes) {
        auto* action = new QAction(this);
        action->setCheckable(true);
        action->setData(code);
        language_group_->addAction(action);
        language_actions_.append(action);
        connect(action, &QAction::triggered, this, [this, code] { set_language(code); });
    }
}

ReportDetailsDialog* MainWindow::open_report_details_dialog() {
    auto* dialog = new ReportDetailsDialog(document_->report_details(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this,
            [this, dialog] { document_->set_report_details(dialog->details()); });
    dialog->open();
    return dialog;
}

ProgramDialog* MainWindow::open_cycle_program_dialog() {
    auto* dialog = new ProgramDialog(ProgramKind::cycle, scenario(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
    return dialog;
}

void MainWindow::build_menus() {
    file_menu_ = menuBar()->addMenu(QString());
    file_menu_->addAction(new_);
    file_menu_->addAction(open_);
    recent_menu_ = file_menu_->addMenu(QString());
    connect(recent_menu_, &QMenu::aboutToShow, this, &MainWindow::update_recent_menu);
    file_menu_->addAction(save_);
    file_menu_->addAction(save_as_);
    file_menu_->addSeparator();
    import_machine_menu_ = file_menu_->addMenu(QString());
    import_machine_menu_->addAction(import_linuxcnc_);
    import_machine_menu_->setToolTipsVisible(true);
    file_menu_->addSeparator();
    file_menu_->addAction(export_csv_);
    file_menu_->addAction(export_png_);
    file_menu_->addAction(export_pdf_);
    file_menu_->addAction(report_details_);
    file_menu_->addAction(export_program_);
    file_menu_->addSeparator();
    file_menu_->addAction(quit_);

    edit_menu_ = menuBar()->addMenu(QString());
    edit_menu_->addAction(undo_action_);
    edit_menu_->addAction(redo_action_);

    presets_menu_ = menuBar()->addMenu(QString());
    presets_menu_->addAction(presets_note_);
    presets_menu_->addSeparator();
    machine_presets_menu_ = presets_menu_->addMenu(QString());
    probe_presets_menu_ = presets_menu_->addMenu(QString());
    for (const PresetAction& preset : preset_actions_) {
        (preset.preset->machine ? machine_presets_menu_ : probe_presets_menu_)
            ->addAction(preset.action);
    }
    presets_menu_->setToolTipsVisible(true);
    machine_presets_menu_->setToolTipsVisible(true);
    probe_presets_menu_->setToolTipsVisible(true);

    compare_menu_ = menuBar()->addMenu(QString());
    compare_menu_->addAction(pin_);
    compare_menu_->addAction(unpin_);

    view_menu_ = menuBar()->addMenu(QString());
    language_menu_ = view_menu_->addMenu(QString());
    language_menu_->addActions(language_actions_);

    help_menu_ = menuBar()->addMenu(QString());
    help_menu_->addAction(guide_);
    help_menu_->addSeparator();
    help_menu_->addAction(about_);

    auto* toolbar = addToolBar(QString());
    toolbar->setObjectName(QStringLiteral("main-toolbar"));
    toolbar->setMovable(false);
    toolbar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    toolbar->setIconSize(QSize(16, 16));
    toolbar->addAction(open_);
    toolbar->addAction(save_);
    toolbar->addSeparator();
    toolbar->addAction(undo_action_);
    toolbar->addAction(redo_action_);
    toolbar->addSeparator();
    toolbar->addAction(pin_);
    toolbar->addAction(unpin_);
    toolbar->addSeparator();
    toolbar->addAction(export_csv_);
    toolbar->addAction(export_png_);
    toolbar->addAction(export_pdf_);
}

void MainWindow::retranslate() {
    update_warning_counts();
    tabs_->setTabText(tabs_->indexOf(calibration_tab_), tr("Calibration"));
    tabs_->setTabText(tabs_->indexOf(latency_tab_), tr("Latency"));
    tabs_->setTabText(tabs_->indexOf(comparison_tab_), tr("Comparison"));
    tabs_->setTabText(tabs_->indexOf(optimise_), tr("Optimise"));
    new_->setText(tr("&New"));
    new_->setToolTip(tr("Start from the default scenario (typical values)"));
    open_->setText(tr("&Open…"));
    open_->setToolTip(tr("Open a scenario file (the JSON the command-line tool reads)"));
    save_->setText(tr("&Save"));
    save_->setToolTip(tr("Save the scenario as JSON"));
    save_as_->setText(tr("Save &As…"));
    export_csv_->setText(tr("Export CSV &Report…"));
    export_csv_->setToolTip(
        tr("Scenario, summary, phases, warnings and a feed sweep as CSV, the same as the "
           "command-line tool writes"));
    export_png_->setText(tr("Export Charts as &PNG…"));
    export_png_->setToolTip(tr("Save the four charts as one PNG image"));
    export_pdf_->setText(tr("Export P&DF Report…"));
    export_pdf_->setToolTip(
        tr("A4 pages to hand over: the current tab's results, charts, warnings with their fixes "
           "and the inputs, in the interface's language"));
    report_details_->setText(tr("Report De&tails…"));
    report_details_->setToolTip(
        tr("Customer, machine, part, author and notes for the top of the PDF report"));
    export_program_->setText(tr("Program for the &Control…"));
    export_program_->setToolTip(
        tr("The cycle as a probing program for your control (LinuxCNC, grbl, Fanuc, Haas, "
           "Mitsubishi, Siemens), "
           "with the values set here"));
    import_linuxcnc_->setText(tr("&LinuxCNC INI…"));
    import_linuxcnc_->setToolTip(
        tr("The machine from a LinuxCNC 2.9 configuration: the axes' acceleration and speed "
           "limits and the servo period, as ProbeCycle's LinuxCNC programs (exact stop) meet "
           "them. The drives' lag is not in the file and is set to none."));
    quit_->setText(tr("&Quit"));
    update_undo_texts();
    pin_->setText(tr("&Pin Baseline"));
    pin_->setToolTip(
        tr("Keep the current scenario as a baseline: its curves stay drawn dashed and the readouts "
           "show the difference"));
    unpin_->setText(tr("&Clear Baseline"));
    guide_->setText(tr("&Guide"));
    about_->setText(tr("&About ProbeCycle"));
    presets_note_->setText(tr("Presets hold typical values: replace them with measured ones"));
    for (const PresetAction& preset : preset_actions_) {
        preset.action->setText(preset_title(*preset.preset));
        preset.action->setToolTip(preset_description(*preset.preset));
        preset.action->setStatusTip(preset_description(*preset.preset));
    }
    for (QAction* action : language_actions_) {
        const QString code = action->data().toString();
        action->setText(code.isEmpty() ? tr("System language") : native_language_name(code));
    }

    file_menu_->setTitle(tr("&File"));
    recent_menu_->setTitle(tr("Open &Recent"));
    import_machine_menu_->setTitle(tr("&Import Machine"));
    edit_menu_->setTitle(tr("&Edit"));
    presets_menu_->setTitle(tr("&Presets"));
    machine_presets_menu_->setTitle(tr("&Machine (skip input, control)"));
    probe_presets_menu_->setTitle(tr("P&robe class"));
    compare_menu_->setTitle(tr("&Compare"));
    view_menu_->setTitle(tr("&View"));
    language_menu_->setTitle(tr("&Language"));
    help_menu_->setTitle(tr("&Help"));
    if (auto* toolbar = findChild<QToolBar*>(QStringLiteral("main-toolbar"))) {
        toolbar->setWindowTitle(tr("Main toolbar"));
    }
    update_title();
}

void MainWindow::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        // Texts built at run time: the undo steps' and the status bar's.
        for (int i = 0; i < undo_->count(); ++i) {
            // The stack holds ScenarioCommands only, and hands them out const.
            const auto* command = static_cast<const ScenarioCommand*>(undo_->command(i));
            const_cast<ScenarioCommand*>(command)->retranslate();
        }
        if (status_.make && !statusBar()->currentMessage().isEmpty()) show_status_text();
        retranslate();
        if (recompute_count_ > 0) schedule_recompute();  // texts built from numbers
    }
    QMainWindow::changeEvent(event);
}

// --- settings -------------------------------------------------------------

void MainWindow::restore_settings() {
    QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    panel_sized_by_user_ = main_splitter_->restoreState(
        settings.value(QStringLiteral("window/splitter")).toByteArray());
    warnings_sized_by_user_ = right_splitter_->restoreState(
        settings.value(QStringLiteral("window/right_splitter")).toByteArray());
    recent_files_ = settings.value(QStringLiteral("files/recent")).toStringList();
    set_remembered_folder(settings.value(QStringLiteral("files/last_dir")).toString());
    language_choice_ = settings.value(QStringLiteral("view/language")).toString();
    for (QAction* action : language_actions_) {
        action->setChecked(action->data().toString() == language_choice_);
    }
    const QString json = settings.value(QStringLiteral("scenario/last")).toString();
    const QString file = settings.value(QStringLiteral("scenario/file")).toString();
    const QString lab = settings.value(QStringLiteral("lab/last")).toString();
    Scenario scenario;
    QString current_file;
    bool is_project = false;
    try {
        if (!json.isEmpty()) {
            scenario = scenario_from_json(json.toStdString());
            current_file = file;
        } else if (!file.isEmpty()) {
            // Edits were discarded at the last quit: the file as saved.
            const std::string text = read_text_file(core_path(file));
            if (is_project_text(text)) {
                const Project project = parse_project(text);
                scenario = project.scenario;
                restore_session(project, QFileInfo(file).absolutePath());
                is_project = true;
            } else {
                scenario = scenario_from_json(text);
            }
            current_file = file;
        }
    } catch (const std::exception&) {
        // A stale or foreign entry, or a file gone: start from the defaults.
        scenario = Scenario{};
        current_file.clear();
        is_project = false;
    }
    if (!json.isEmpty() || !is_project) {
        // The lab as it was at the last quit (kept with the paths absolute).
        try {
            if (!lab.isEmpty()) restore_session(parse_project(lab.toStdString()), QString());
        } catch (const std::exception&) {
            // A stale entry: the lab starts empty.
        }
        is_project = !current_file.isEmpty() &&
                     settings.value(QStringLiteral("scenario/file_is_project")).toBool();
    }
    document_->reset(scenario, current_file, is_project);
    // A file name is only restored with its own content, so the lab shown is the file's.
    if (is_project) {
        document_->mark_session_saved();
    } else {
        document_->mark_session_unsaved();
    }
}

void MainWindow::save_settings(bool with_scenario) const {
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    save_chosen_split(settings, QStringLiteral("window/splitter"), *main_splitter_,
                      panel_sized_by_user_);
    save_chosen_split(settings, QStringLiteral("window/right_splitter"), *right_splitter_,
                      warnings_sized_by_user_);
    settings.setValue(QStringLiteral("files/recent"), recent_files_);
    settings.setValue(QStringLiteral("files/last_dir"), remembered_folder());
    settings.setValue(QStringLiteral("view/language"), language_choice_);
    settings.setValue(QStringLiteral("scenario/file_is_project"), document_->is_project());
    if (!with_scenario) {
        // Discarded edits: the file is opened again from disk at the next
        // start. Outside a project the lab's data is not the file's, and stays.
        settings.remove(QStringLiteral("scenario/last"));
        settings.setValue(QStringLiteral("scenario/file"), current_file());
        if (document_->is_project()) {
            settings.remove(QStringLiteral("lab/last"));
        } else {
            settings.setValue(QStringLiteral("lab/last"),
                              QString::fromStdString(project_json(document_->project(QString()))));
        }
        return;
    }
    settings.setValue(QStringLiteral("scenario/last"),
                      QString::fromStdString(scenario_to_json(scenario())));
    settings.setValue(QStringLiteral("lab/last"),
                      QString::fromStdString(project_json(document_->project(QString()))));
    // A file name is restored only with the file's own content.
    settings.setValue(QStringLiteral("scenario/file"),
                      has_unsaved_changes() ? QString() : current_file());
}

const Scenario& MainWindow::scenario() const {
    return document_->scenario();
}

QString MainWindow::current_file() const {
    return document_->file();
}

bool MainWindow::current_is_project() const {
    return document_->is_project();
}

bool MainWindow::has_unsaved_changes() const {
    return document_->has_unsaved_changes();
}

bool MainWindow::project_expected() const {
    return document_->is_project() || document_->session_has_data();
}

bool MainWindow::settle_unsaved_changes(bool replaces_lab) {
    // Outside a project the lab's data is the session's: it outlives New, a
    // scenario's Open and Quit, and only opening a project replaces it.
    const bool is_project = document_->is_project();
    const bool lab_at_stake = (is_project || replaces_lab) && document_->session_unsaved();
    if (undo_->isClean() && !lab_at_stake) return true;
    // The lab's data only fits in a project file.
    const bool as_project = is_project || lab_at_stake;
    UnsavedAnswer answer = options_.unsaved_answer;
    if (options_.show_dialogs) {
        const QString name = document_->display_name();
        const QString question =
            !is_project && lab_at_stake
                ? tr("The project you open replaces the lab's data (touches, fits, comparison "
                     "settings), which is in no project file yet. Save everything as a project "
                     "first?")
                : tr("Save the changes to %1?").arg(name);
        const auto button = QMessageBox::question(
            this, tr("Unsaved changes"), question,
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
        answer = button == QMessageBox::Save      ? UnsavedAnswer::save
                 : button == QMessageBox::Discard ? UnsavedAnswer::discard
                                                  : UnsavedAnswer::cancel;
    }
    switch (answer) {
        case UnsavedAnswer::save:
            if (as_project && !is_project) {
                // A scenario file cannot hold the lab: a new project file.
                return options_.show_dialogs && save_as_dialog(/*as_project=*/true);
            }
            // Without dialogs there is no file dialog to name an untitled one.
            return (options_.show_dialogs || !current_file().isEmpty()) && save_action();
        case UnsavedAnswer::discard:
            return true;
        case UnsavedAnswer::cancel:
            break;
    }
    return false;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!settle_unsaved_changes()) {
        event->ignore();
        return;
    }
    // Discard means discard (the edits are still unsaved here). The
    // next start shows the file as it was saved, or the defaults.
    if (options_.persistent) save_settings(/*with_scenario=*/!has_unsaved_changes());
    event->accept();
}

void MainWindow::set_language(const QString& code) {
    language_choice_ = code;
    for (QAction* action : language_actions_) action->setChecked(action->data().toString() == code);
    apply_language(code);  // LanguageChange events retranslate every widget
    if (options_.persistent) QSettings().setValue(QStringLiteral("view/language"), code);
}

// --- editing --------------------------------------------------------------

void MainWindow::show_scenario() {
    const Scenario& s = scenario();
    panel_->set_scenario(s);
    latency_tab_->set_scenario(s);
    calibration_tab_->set_scenario(s);
    schedule_recompute();
}

void MainWindow::on_panel_edit(const Scenario& scenario, const QString& key) {
    document_->edit(
        scenario, [key] { return tr("change %1").arg(key_label(key)); },
        ScenarioCommand::merge_id_for(key));
}

void MainWindow::edit_scenario(const Scenario& scenario, const QString& description) {
    edit_scenario(scenario, [description] { return description; });
}

void MainWindow::edit_scenario(const Scenario& scenario, std::function<QString()> describe) {
    charts_->refit_ranges();  // a preset, a fix, an import: a jump, not a drag
    document_->edit(scenario, std::move(describe));
}

void MainWindow::refresh_optimise() {
    optimise_stale_ = false;
    // The optimiser assumes a scenario that validates; the warnings panel
    // says what is wrong with one that does not.
    if (!validate(scenario()).empty()) return;
    optimise_->show_scenario(scenario());
}

OptimisePanel* MainWindow::optimise_panel() {
    recompute_now();
    if (optimise_stale_) refresh_optimise();
    return optimise_;
}

void MainWindow::schedule_recompute() {
    if (!recompute_timer_.isActive()) recompute_timer_.start();
}

void MainWindow::recompute_now() {
    if (recompute_timer_.isActive()) {
        recompute_timer_.stop();
        recompute();
    }
}

void MainWindow::recompute() {
    const Computed& c = computation_.run(scenario());
    const Computed* baseline = baseline_ ? &*baseline_ : nullptr;
    charts_->show_result(c);
    readouts_->show_result(c, baseline);
    warnings_->show_result(c);
    optimise_stale_ = true;
    if (tabs_ != nullptr && tabs_->currentWidget() == optimise_) refresh_optimise();
    ++recompute_count_;
    emit recomputed();
}

// --- files ----------------------------------------------------------------

void MainWindow::report_error(const char* title, const QString& text) {
    last_error_ = text;
    show_status([title] { return tr(title); }, 8000);
    if (!options_.show_dialogs) return;
    auto* box = new QMessageBox(QMessageBox::Warning, tr(title), text, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

bool MainWindow::new_scenario() {
    if (!settle_unsaved_changes()) return false;
    // The lab's data stays, outside any file.
    charts_->refit_ranges();
    document_->reset(Scenario{}, QString(), /*is_project=*/false);
    show_status(
        [] { return tr("Default scenario: typical values, to be replaced with measured ones"); },
        6000);
    return true;
}

std::optional<std::string> MainWindow::read_or_report(const QString& path, const char* title) {
    try {
        return read_text_file(core_path(path));
    } catch (const FileError& e) {
        report_error(title, tr("%1 could not be read: %2")
                                .arg(QDir::toNativeSeparators(path), translate(e.reason())));
        return std::nullopt;
    }
}

bool MainWindow::open_scenario(const QString& path) {
    const std::optional<std::string> read =
        read_or_report(path, QT_TR_NOOP("Could not open the scenario"));
    if (!read) return false;
    const std::string& text = *read;
    const bool project = is_project_text(text);
    Project loaded;
    try {
        if (project) {
            loaded = parse_project(text);
        } else {
            loaded.scenario = scenario_from_json(text);
        }
    } catch (const FileContentError& e) {
        // Each line names the key, the value and what is allowed, translated.
        report_error(
            project ? QT_TR_NOOP("Could not open the project")
                    : QT_TR_NOOP("Could not open the scenario"),
            (project ? tr("%1 is not a valid project:\n%2") : tr("%1 is not a valid scenario:\n%2"))
                .arg(QDir::toNativeSeparators(path), error_list(e)));
        return false;
    }
    // Nothing has changed yet: the file is whole and valid.
    const QString absolute = QFileInfo(path).absoluteFilePath();
    if (project) restore_session(loaded, QFileInfo(absolute).absolutePath());
    charts_->refit_ranges();
    document_->reset(loaded.scenario, absolute, project);
    if (project) document_->mark_session_saved();
    remember_recent(absolute);
    remember_folder_of(path);
    show_status([path] { return tr("Opened %1").arg(QDir::toNativeSeparators(path)); }, 4000);
    return true;
}

bool MainWindow::open_asking(const QString& path) {
    std::string text;
    try {
        text = read_text_file(core_path(path));
    } catch (const FileError&) {
        return open_scenario(path);  // says why it cannot be read, and changes nothing
    }
    if (!settle_unsaved_changes(/*replaces_lab=*/is_project_text(text))) return false;
    return open_scenario(path);
}

bool MainWindow::save_scenario(const QString& path) {
    QString error;
    if (!write_file(path, QByteArray::fromStdString(scenario_to_json(scenario())), error)) {
        report_error(QT_TR_NOOP("Could not save the scenario"),
                     tr("%1 could not be written: %2").arg(QDir::toNativeSeparators(path), error));
        return false;
    }
    document_->mark_saved(QFileInfo(path).absoluteFilePath(), /*is_project=*/false);
    remember_recent(current_file());
    remember_folder_of(path);
    show_status([path] { return tr("Saved %1").arg(QDir::toNativeSeparators(path)); }, 4000);
    return true;
}

bool MainWindow::save_project(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    QString error;
    const std::string text = project_json(document_->project(QFileInfo(absolute).absolutePath()));
    if (!write_file(path, QByteArray::fromStdString(text), error)) {
        report_error(QT_TR_NOOP("Could not save the project"),
                     tr("%1 could not be written: %2").arg(QDir::toNativeSeparators(path), error));
        return false;
    }
    document_->mark_saved(absolute, /*is_project=*/true);
    document_->mark_session_saved();
    remember_recent(absolute);
    remember_folder_of(path);
    show_status([path] { return tr("Saved %1").arg(QDir::toNativeSeparators(path)); }, 4000);
    return true;
}

void MainWindow::restore_session(const Project& project, const QString& base_folder) {
    document_->restore_pages(project, base_folder);
    if (!project.baseline || !pin_baseline_of(*project.baseline)) clear_baseline();
}

std::optional<std::string> MainWindow::current_report_csv(QString& why_none) {
    // A page's own report, or the cycle's.
    if (auto* page = qobject_cast<Page*>(tabs_->currentWidget())) {
        std::optional<std::string> csv = page->report_csv(ReportRows::all);
        if (!csv) why_none = page->last_error();
        return csv;
    }
    recompute_now();
    const Computed& c = computation_.result();
    if (!c.valid()) {
        why_none = tr("The scenario is not valid; see the warnings panel.");
        return std::nullopt;
    }
    const std::vector<double> feeds = report_feeds(c.scenario, c.analysis);
    return csv_report(c.scenario, c.analysis, feeds, report_header());
}

bool MainWindow::export_csv_report(const QString& path) {
    QString error;
    const std::optional<std::string> csv = current_report_csv(error);
    if (!csv) {
        report_error(QT_TR_NOOP("Could not export the report"), error);
        return false;
    }
    if (!write_file(path, QByteArray::fromStdString(*csv), error)) {
        report_error(QT_TR_NOOP("Could not export the report"),
                     tr("%1 could not be written: %2").arg(QDir::toNativeSeparators(path), error));
        return false;
    }
    remember_folder_of(path);
    show_status([path] { return tr("Report written to %1").arg(QDir::toNativeSeparators(path)); },
                4000);
    return true;
}

// The reports' header: today (as the CLI: SOURCE_DATE_EPOCH's day when set)
// and the scenario's file name, as the CLI names it.
ReportHeader MainWindow::report_header() const {
    ReportHeader header;
    header.date = report_date();
    if (!current_file().isEmpty()) {
        header.subject = QFileInfo(current_file()).fileName().toStdString();
    }
    return header;
}

// The current tab (the Cycle tab's charts, or the whole lab or
// comparison tab), drawn at `width` pixels (the widgets are vector-drawn, so
// no upscaled pixels), under a title line naming the scenario, the tab, the
// date and the program version.
QPixmap MainWindow::render_widget(QWidget* source, int width) const {
    const double scale = std::max(1.0, static_cast<double>(width) / std::max(1, source->width()));
    QPixmap content(source->size() * scale);
    content.setDevicePixelRatio(scale);
    content.fill(palette().color(QPalette::Window));
    source->render(&content);
    return content;
}

QImage MainWindow::charts_image(int width) {
    recompute_now();
    return render_widget(charts_, width).toImage();
}

QImage MainWindow::export_image(int width, bool titled) {
    recompute_now();
    QWidget* source =
        tabs_->currentIndex() == 0 ? static_cast<QWidget*>(charts_) : tabs_->currentWidget();
    const QPixmap content = render_widget(source, width);
    if (!titled) return content.toImage();
    const double scale = content.devicePixelRatio();

    const QString name = document_->display_name();
    const QString title =
        tr("%1 - %2 - %3 - ProbeCycle %4")
            .arg(name, tabs_->tabText(tabs_->currentIndex()),
                 QLocale().toString(QDateTime::currentDateTime(), QLocale::ShortFormat),
                 QCoreApplication::applicationVersion());
    QFont font = this->font();
    font.setPointSizeF(font.pointSizeF() * 1.4);
    const int band = static_cast<int>(QFontMetrics(font).height() * 2.0);
    const QSize logical = source->size();
    QImage image(QSize(logical.width(), logical.height() + band) * scale, QImage::Format_RGB32);
    image.setDevicePixelRatio(scale);
    image.fill(palette().color(QPalette::Window));
    QPainter painter(&image);
    painter.setFont(font);
    painter.setPen(palette().color(QPalette::WindowText));
    painter.drawText(QRect(12, 0, logical.width() - 24, band), Qt::AlignVCenter | Qt::AlignLeft,
                     title);
    painter.drawPixmap(0, band, content);
    painter.end();
    return image;
}

bool MainWindow::export_charts_png(const QString& path, int width) {
    const QImage image = export_image(width);
    QByteArray png;
    QBuffer buffer(&png);
    QString error;
    if (!buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, "PNG")) {
        error = tr("the image could not be encoded as PNG");
    }
    if (!error.isEmpty() || !write_file(path, png, error)) {
        report_error(QT_TR_NOOP("Could not export the charts"),
                     tr("%1 could not be written: %2").arg(QDir::toNativeSeparators(path), error));
        return false;
    }
    remember_folder_of(path);
    show_status([path] { return tr("Charts written to %1").arg(QDir::toNativeSeparators(path)); },
                4000);
    return true;
}

bool MainWindow::apply_preset(const QString& resource_path) {
    // The presets were read and checked once, at start (preset_list.h).
    const PresetEntry* entry = find_preset(resource_path);
    if (entry == nullptr) {
        report_error(QT_TR_NOOP("Could not apply the preset"),
                     tr("There is no preset %1.").arg(resource_path));
        return false;
    }
    // Only the keys the preset names change; everything else stays as the user set it.
    const Scenario before = scenario();
    Scenario next;
    try {
        next = merge_json(before, entry->preset.scenario_json);
    } catch (const ScenarioError& e) {
        report_error(QT_TR_NOOP("Could not apply the preset"), error_list(e));
        return false;
    }
    last_preset_changes_ = changed_keys(before, next);
    edit_scenario(next,
                  [resource_path] { return tr("preset %1").arg(preset_name(resource_path)); });
    // Say what it overwrote (a measured latency, say): Undo brings it back.
    show_status(
        [resource_path, before, next] {
            const QString name = preset_name(resource_path);
            const QStringList changes = changed_keys(before, next);
            return changes.isEmpty()
                       ? tr("%1: nothing to change, the values are already the preset's").arg(name)
                       : tr("%1: typical values applied (Undo restores): %2")
                             .arg(name, changes.join(QStringLiteral("; ")));
        },
        20000);
    return true;
}

bool MainWindow::import_linuxcnc_machine(const QString& path) {
    const std::optional<std::string> text =
        read_or_report(path, QT_TR_NOOP("Could not import the machine"));
    if (!text) return false;
    Scenario next = scenario();
    try {
        next.machine = machine_from_linuxcnc_ini(*text);
    } catch (const LinuxCncIniError& e) {
        QStringList problems;
        for (const IniProblem& problem : e.problems()) problems << translate(problem.to_message());
        report_error(QT_TR_NOOP("Could not import the machine"),
                     tr("%1 is not a valid LinuxCNC configuration:\n%2")
                         .arg(QDir::toNativeSeparators(path), problems.join(QLatin1Char('\n'))));
        return false;
    }
    const QString name = QFileInfo(path).fileName();
    const Scenario before = scenario();
    edit_scenario(next, [name] { return tr("import the machine from %1").arg(name); });
    remember_folder_of(path);
    // Say what it overwrote, as a preset does: Undo brings it back.
    show_status(
        [name, before, next] {
            const QStringList changes = changed_keys(before, next);
            return changes.isEmpty()
                       ? tr("%1: nothing to change, the machine is already this one").arg(name)
                       : tr("%1: machine imported (Undo restores): %2")
                             .arg(name, changes.join(QStringLiteral("; ")));
        },
        20000);
    return true;
}

void MainWindow::import_linuxcnc_dialog() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Import the machine from a LinuxCNC INI file"), dialog_start(),
        tr("LinuxCNC configuration (*.ini *.expanded);;All files (*)"));
    if (!path.isEmpty()) import_linuxcnc_machine(path);
}

QString MainWindow::preset_name(const QString& resource_path) {
    const PresetEntry* entry = find_preset(resource_path);
    return entry != nullptr ? preset_title(entry->preset) : QFileInfo(resource_path).baseName();
}

void MainWindow::show_status(std::function<QString()> make, int timeout_ms) {
    status_ = {std::move(make), timeout_ms};
    show_status_text();
}

void MainWindow::show_status_text() {
    QStatusBar* bar = statusBar();
    const QString text = status_.make();
    // QStatusBar draws a message a few pixels in from its left edge and
    // stops short of its size grip.
    const int grip = bar->isSizeGripEnabled()
                         ? bar->style()->pixelMetric(QStyle::PM_SizeGripSize, nullptr, bar)
                         : 0;
    const int room = std::max(0, bar->width() - grip - 24);
    const QString fitted = bar->fontMetrics().elidedText(text, Qt::ElideRight, room);
    bar->setToolTip(fitted == text ? QString() : text);
    bar->showMessage(fitted, status_.timeout_ms);
}

void MainWindow::resizeEvent(QResizeEvent* event) {
    QMainWindow::resizeEvent(event);
    if (status_.make && !statusBar()->currentMessage().isEmpty()) show_status_text();
}

void MainWindow::remember_recent(const QString& path) {
    recent_files_.removeAll(path);
    recent_files_.prepend(path);
    while (recent_files_.size() > kMaxRecentFiles) recent_files_.removeLast();
    if (options_.persistent) QSettings().setValue(QStringLiteral("files/recent"), recent_files_);
}

void MainWindow::update_recent_menu() {
    recent_menu_->clear();
    for (const QString& path : recent_files_) {
        QAction* action = recent_menu_->addAction(QDir::toNativeSeparators(path));
        connect(action, &QAction::triggered, this, [this, path] { open_asking(path); });
    }
    if (recent_files_.isEmpty()) recent_menu_->addAction(tr("(none)"))->setEnabled(false);
}

void MainWindow::update_undo_texts() {
    const QString undo_text = undo_->undoText();
    const QString redo_text = undo_->redoText();
    undo_action_->setText(undo_text.isEmpty() ? tr("&Undo") : tr("&Undo %1").arg(undo_text));
    redo_action_->setText(redo_text.isEmpty() ? tr("&Redo") : tr("&Redo %1").arg(redo_text));
    undo_action_->setIconText(tr("Undo"));
    redo_action_->setIconText(tr("Redo"));
}

void MainWindow::update_title() {
    const QString name = document_->display_name();
    setWindowTitle(QStringLiteral("%1[*] - ProbeCycle").arg(name));
    setWindowModified(has_unsaved_changes());
}

void MainWindow::open_dialog() {
    // Asked once the file is chosen: a project replaces the lab's data too.
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open scenario or project"), dialog_start(),
        tr("Scenarios and projects (*.json *.probecycle);;Project (*.probecycle);;"
           "Scenario (*.json);;All files (*)"));
    if (!path.isEmpty()) open_asking(path);
}

bool MainWindow::save_action() {
    if (current_file().isEmpty()) return save_as_dialog(project_expected());
    return document_->is_project() ? save_project(current_file()) : save_scenario(current_file());
}

bool MainWindow::save_as_dialog(bool as_project) {
    const QString project_filter =
        tr("ProbeCycle project: scenario, lab and comparison (*.probecycle)");
    const QString scenario_filter = tr("Scenario only (*.json)");
    QString chosen = as_project ? project_filter : scenario_filter;
    QString start = current_file();
    if (start.isEmpty() || document_->is_project() != as_project) {
        const QString stem = current_file().isEmpty()
                                 ? QStringLiteral("scenario")
                                 : QFileInfo(current_file()).completeBaseName();
        start = dialog_start(
            stem + (as_project ? QStringLiteral(".probecycle") : QStringLiteral(".json")));
    }
    QString path = QFileDialog::getSaveFileName(
        this, tr("Save as"), start, project_filter + QStringLiteral(";;") + scenario_filter,
        &chosen);
    if (path.isEmpty()) return false;
    const bool project = chosen == project_filter;
    if (QFileInfo(path).suffix().isEmpty()) {
        path += project ? QStringLiteral(".probecycle") : QStringLiteral(".json");
    }
    return project ? save_project(path) : save_scenario(path);
}

void MainWindow::export_csv_dialog() {
    if (auto* page = qobject_cast<Page*>(tabs_->currentWidget())) return page->export_dialog();
    QString path = QFileDialog::getSaveFileName(
        this, tr("Export CSV report"), dialog_start(QStringLiteral("probecycle-report.csv")),
        tr("CSV (*.csv)"));
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".csv");
    export_csv_report(path);
}

void MainWindow::export_pdf_dialog() {
    QString path = QFileDialog::getSaveFileName(
        this, tr("Export PDF report"), dialog_start(QStringLiteral("probecycle-report.pdf")),
        tr("PDF (*.pdf)"));
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".pdf");
    export_pdf_report(path);
}

void MainWindow::export_png_dialog() {
    QString path = QFileDialog::getSaveFileName(
        this, tr("Export charts as PNG"), dialog_start(QStringLiteral("probecycle-charts.png")),
        tr("PNG image (*.png)"));
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".png");
    export_charts_png(path);
}

// --- compare and fixes ----------------------------------------------------

void MainWindow::pin_baseline() {
    recompute_now();
    if (!computation_.result().valid()) return;
    show_baseline(computation_.result());
    show_status([] { return tr("Baseline pinned: change parameters to compare against it"); },
                6000);
}

bool MainWindow::pin_baseline_of(const Scenario& scenario) {
    Computation computation(options_.points_per_curve);
    const Computed& computed = computation.run(scenario);
    if (!computed.valid()) return false;
    show_baseline(computed);
    return true;
}

void MainWindow::show_baseline(const Computed& computed) {
    baseline_ = computed;
    document_->set_baseline(computed.scenario);
    charts_->set_baseline(&*baseline_);
    unpin_->setEnabled(true);
    schedule_recompute();
}

void MainWindow::clear_baseline() {
    baseline_.reset();
    document_->set_baseline(std::nullopt);
    charts_->set_baseline(nullptr);
    unpin_->setEnabled(false);
    schedule_recompute();
}

// Room for every problem shown, as far as the charts can spare it, whenever
// their number changes, until the user drags the divider; back to the usual
// height when fewer are left.
void MainWindow::fit_warnings_pane() {
    const int rows = warnings_->count(Severity::error) + warnings_->count(Severity::warning) +
                     warnings_->count(Severity::info);
    if (warnings_sized_by_user_ || rows == warnings_rows_fitted_) return;
    const QList<int> sizes = right_splitter_->sizes();
    const int total = sizes.value(0) + sizes.value(1);
    const int viewport = warnings_scroll_->viewport()->height();
    if (!right_splitter_->isVisible() || total <= 0 || viewport <= 0) return;
    warnings_rows_fitted_ = rows;
    // The panel's height as the layout first gave it: it never gets smaller.
    if (warnings_usual_height_ < 0) warnings_usual_height_ = sizes.value(1);
    const int width = warnings_scroll_->viewport()->width();
    const int content = warnings_->hasHeightForWidth() ? warnings_->heightForWidth(width)
                                                       : warnings_->sizeHint().height();
    const int chrome = sizes.value(1) - viewport;  // the title and margins
    // The charts keep 60 % and at least 30 lines, so that their axis titles
    // stay full size; a smaller window keeps the panel's usual height and
    // scrolls it.
    const int charts_keep = std::max(total * 3 / 5, 30 * fontMetrics().height());
    const int most = std::max(warnings_usual_height_, total - charts_keep);
    const int wanted = std::clamp(content + chrome, warnings_usual_height_, most);
    if (wanted != sizes.value(1)) right_splitter_->setSizes({total - wanted, wanted});
}

// The parameter panel in two columns when one would scroll and the window
// is wide enough to spare the charts the room (1920x1080: every editor in
// sight); one column otherwise.
void MainWindow::fit_panel_width() {
    // Called before the splitter lays its widgets out anew: its width is
    // new, their sizes are not yet.
    const int total = main_splitter_->width() - main_splitter_->handleWidth();
    if (panel_sized_by_user_ || total <= 0) return;
    const bool two = total >= 1500 && panel_->one_column_height() > main_splitter_->height();
    // Room for the scroll bar, which shows until the panel has its two columns.
    const int wanted = two ? ParameterPanel::two_column_width() +
                                 panel_scroll_->verticalScrollBar()->sizeHint().width()
                           : ParameterPanel::one_column_width();
    if (wanted != main_splitter_->sizes().value(0))
        main_splitter_->setSizes({wanted, total - wanted});
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
    if (watched == main_splitter_ && event->type() == QEvent::Resize) fit_panel_width();
    return QMainWindow::eventFilter(watched, event);
}

// The panel's title and the Cycle tab count the problems shown, so an error
// is seen from any tab and however small the panel is.
void MainWindow::update_warning_counts() {
    const int errors = warnings_->count(Severity::error);
    const int warnings = warnings_->count(Severity::warning);
    const int notes = warnings_->count(Severity::info);
    QStringList parts;
    if (errors > 0) parts << tr("Errors: %1").arg(errors);
    if (warnings > 0) parts << tr("Warnings: %1").arg(warnings);
    if (notes > 0) parts << tr("Notes: %1").arg(notes);
    warnings_title_->setText(parts.isEmpty() ? tr("Warnings")
                                             : parts.join(QStringLiteral("  \u00b7  ")));
    const int problems = errors + warnings;
    tabs_->setTabText(tabs_->indexOf(main_splitter_),
                      problems > 0 ? tr("Cycle (%1)").arg(problems) : tr("Cycle"));
    tabs_->setTabIcon(0, errors > 0     ? style()->standardIcon(QStyle::SP_MessageBoxCritical)
                         : warnings > 0 ? style()->standardIcon(QStyle::SP_MessageBoxWarning)
                                        : QIcon());
}

HelpGuide* MainWindow::show_guide() {
    if (guide_window_ == nullptr) guide_window_ = new HelpGuide(this);
    guide_window_->show();
    guide_window_->raise();
    return guide_window_;
}

bool MainWindow::apply_fix_for(const QString& warning_code) {
    recompute_now();
    const std::optional<Fix> fix = warnings_->fix_for(warning_code);
    if (!fix) return false;
    if (fix->kind == FixKind::none) return false;
    edit_scenario(fix->scenario, [kind = fix->kind] {
        switch (kind) {
            case FixKind::backoff_to_recommended:
                return tr("set backoff to recommended");
            case FixKind::feed_to_knee:
                return tr("drop feed to the knee");
            case FixKind::feed_for_overtravel:
                return tr("drop feed for the overtravel");
            case FixKind::approach_to_reach_feed:
                return tr("start far enough out to reach the feed");
            case FixKind::search_past_stop:
                return tr("search past the touch's stop");
            case FixKind::position_feed_for_overtravel:
                return tr("drop the positioning feed for the overtravel");
            case FixKind::none:
                break;
        }
        return QString();
    });
    return true;
}

// --- what the user sees ---------------------------------------------------

QString MainWindow::readout_text(Readout readout) const {
    return readouts_->value_text(readout);
}
QString MainWindow::readout_detail(Readout readout) const {
    return readouts_->detail_text(readout);
}
Alert MainWindow::readout_alert(Readout readout) const {
    return readouts_->alert(readout);
}
QStringList MainWindow::warning_codes() const {
    return warnings_->codes();
}
QStringList MainWindow::warning_texts() const {
    return warnings_->texts();
}
QList<QPointF> MainWindow::series_points(const QString& id) const {
    return charts_->series_points(id);
}
bool MainWindow::series_visible(const QString& id) const {
    return charts_->series_visible(id);
}
QStringList MainWindow::series_ids() const {
    return charts_->series_ids();
}
QWidget* MainWindow::charts_widget() const {
    return charts_;
}

QStringList MainWindow::tab_keys() const {
    QStringList keys;
    for (int i = 0; i < tabs_->count(); ++i) {
        keys.append(tabs_->widget(i)->property(kTabKeyProperty).toString());
    }
    return keys;
}

bool MainWindow::select_tab(const QString& key) {
    const int index = static_cast<int>(tab_keys().indexOf(key));
    if (index < 0) return false;
    tabs_->setCurrentIndex(index);
    return true;
}

}  // namespace probecycle::ui
