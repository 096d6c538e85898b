#pragma once

// The ProbeCycle window: parameter panel, readouts, live charts, warnings,
// files, presets, compare and languages. What is open (the scenario, its
// undo, the file, unsaved work) is its Document (document.h); the tabs with
// data of their own are Pages (ui/common/page.h), which exports, the PDF
// report and project files loop over. It edits the document's scenario and
// draws what the core computes from it; edits are coalesced into one
// recompute per pass of the event loop.
//
// The public functions below the constructor are the window's behaviour as
// tests, the benchmark and `--screenshot` drive it.

#include <QByteArray>
#include <QImage>
#include <QList>
#include <QMainWindow>
#include <QPixmap>
#include <QPointF>
#include <QString>
#include <QStringList>
#include <QTimer>
#include <functional>
#include <optional>
#include <string>

#include "core/common/report_header.h"
#include "core/cycle/preset.h"
#include "core/project/project_file.h"
#include "ui/cycle/computation.h"
#include "ui/cycle/readouts.h"
#include "ui/cycle/warnings_panel.h"

class QAction;
class QActionGroup;
class QLabel;
class QMenu;
class QScrollArea;
class QSplitter;
class QTabWidget;
class QUndoStack;

namespace probecycle::ui {

class CalibrationTab;
class HelpGuide;
class CycleCharts;
class Document;
class OptimisePanel;
class LatencyTab;
class ComparisonTab;
class ParameterPanel;
class ProgramDialog;
class ReportDetailsDialog;

// What to do with unsaved edits before they would be lost.
enum class UnsavedAnswer { save, discard, cancel };

struct MainWindowOptions {
    // Restore and save geometry, the last scenario and recent files (QSettings).
    bool persistent{true};
    // Errors in modal-free message boxes; off in tests, which read last_error().
    bool show_dialogs{true};
    // Without dialogs (tests): the answer to "save the changes?".
    UnsavedAnswer unsaved_answer{UnsavedAnswer::discard};
    std::size_t points_per_curve{500};
};

class MainWindow : public QMainWindow {
    Q_OBJECT

  public:
    explicit MainWindow(const MainWindowOptions& options = {}, QWidget* parent = nullptr);
    ~MainWindow() override;

    const Scenario& scenario() const;
    const Computed& computed() const { return computation_.result(); }
    // An undoable change of the whole scenario; `describe` builds its text in
    // the language in effect (the undo step's text follows a language switch).
    void edit_scenario(const Scenario& scenario, std::function<QString()> describe);
    void edit_scenario(const Scenario& scenario, const QString& description);

    // Files. Each returns false and reports through last_error() on failure;
    // a file that does not load leaves the current scenario untouched.
    // Asks first when unsaved edits would be lost; false when the user cancels.
    // The lab's data stays: it is the session's, not the scenario's.
    bool new_scenario();
    // Without dialogs: the answer the next questions about unsaved edits get.
    void set_unsaved_answer(UnsavedAnswer answer) { options_.unsaved_answer = answer; }
    // A scenario file (the scenario only; the lab keeps its data) or a
    // project file (everything, docs/files.md, "The project file"), told apart by
    // content. Does not ask about unsaved edits: open_asking() does.
    bool open_scenario(const QString& path);
    // Asks first when unsaved work would be lost (a project replaces the
    // lab's data too), then opens; false when cancelled or refused.
    bool open_asking(const QString& path);
    bool save_scenario(const QString& path);
    // The whole session: scenario, baseline, lab, comparison (atomic).
    bool save_project(const QString& path);
    bool current_is_project() const;
    // Edits not in the current file: the scenario's, and for a project the
    // lab's and the comparison's too.
    bool has_unsaved_changes() const;
    // The tabs' keys in their order: cycle, calibration, latency,
    // comparison, optimise (the window's `--tab` words).
    QStringList tab_keys() const;
    // Shows the tab of `key`; false for a key that names none.
    bool select_tab(const QString& key);
    // The current tab's CSV report: the cycle's, or the Calibration, Latency
    // or Comparison tab's own.
    bool export_csv_report(const QString& path);
    // The header of the cycle report: today's date (SOURCE_DATE_EPOCH's when
    // set, as the CLI) and the scenario's file name, or "untitled".
    ReportHeader report_header() const;
    // The current tab's charts at `width` pixels under a title line.
    bool export_charts_png(const QString& path, int width = 1920);
    // `titled`: under the title line (the PNG export); the PDF report has its own.
    QImage export_image(int width, bool titled = true);
    // The report to hand over, of the current tab: A4 pages in the
    // interface's language (main_window_pdf.cpp). Written atomically.
    bool export_pdf_report(const QString& path);
    QByteArray pdf_report_bytes();
    // File > "Program for the Control…" (docs/programs.md): the tuned cycle, the
    // scenario's cycle as plain probing moves, in the control's dialect.
    ProgramDialog* open_cycle_program_dialog();
    // File > "Report Details…": the PDF report's title block; OK stores it
    // in the document.
    ReportDetailsDialog* open_report_details_dialog();
    // The Cycle tab's four charts at `width` pixels, whichever tab is shown.
    QImage charts_image(int width);
    // A preset from resources/ (":/presets/..."): its machine or probe section
    // replaces the current one, as an undoable edit.
    bool apply_preset(const QString& resource_path);
    // What the last preset overwrote, "label: old -> new" per key.
    QStringList last_preset_changes() const { return last_preset_changes_; }
    // File > Import Machine > LinuxCNC INI: the machine a LinuxCNC 2.9 INI
    // file describes (core/program/linuxcnc_ini.h) replaces the scenario's,
    // as one undoable edit. A file that cannot be read or is refused changes
    // nothing and is reported through last_error(), every problem named.
    bool import_linuxcnc_machine(const QString& path);
    QString current_file() const;
    QString last_error() const { return last_error_; }

    // Compare.
    void pin_baseline();
    // Pins the baseline of another scenario (a project's); false when it is
    // not valid.
    bool pin_baseline_of(const Scenario& scenario);
    void clear_baseline();
    bool has_baseline() const { return baseline_.has_value(); }
    // The Optimise tab ("What should I change?"), optimised for the current scenario.
    OptimisePanel* optimise_panel();

    // Help > Guide (F1): the in-window guide, one window, shown and raised.
    HelpGuide* show_guide();

    // Fixes offered by the warnings panel.
    bool apply_fix_for(const QString& warning_code);

    // What the user sees.
    QString readout_text(Readout readout) const;
    QString readout_detail(Readout readout) const;
    Alert readout_alert(Readout readout) const;
    QStringList warning_codes() const;
    QStringList warning_texts() const;
    QList<QPointF> series_points(const QString& id) const;
    bool series_visible(const QString& id) const;
    QStringList series_ids() const;
    QWidget* charts_widget() const;

    QUndoStack* undo_stack() const { return undo_; }
    Document* document() const { return document_; }
    // Runs a pending recompute now (normally the event loop does).
    void recompute_now();
    int recompute_count() const { return recompute_count_; }
    bool recompute_pending() const { return recompute_timer_.isActive(); }

    void set_language(const QString& code);

  signals:
    void recomputed();

  protected:
    void closeEvent(QCloseEvent* event) override;
    void changeEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void build_ui();
    void build_actions();
    void build_menus();
    void retranslate();
    void restore_settings();
    // with_scenario false: the edits were discarded; only the file name is kept.
    void save_settings(bool with_scenario = true) const;

    // The document's scenario into the editors and tabs, and a recompute.
    void show_scenario();
    void on_panel_edit(const Scenario& scenario, const QString& key);
    void schedule_recompute();
    void recompute();
    // `title` untranslated (QT_TR_NOOP): the status bar shows it in the
    // language in effect, also after a switch.
    void report_error(const char* title, const QString& text);
    // The file's text as the core reads it (the CLI's size limit and
    // messages), or nullopt after saying under `title` why it cannot be read.
    std::optional<std::string> read_or_report(const QString& path, const char* title);
    // A status bar message that is built again after a language switch.
    void show_status(std::function<QString()> make, int timeout_ms);
    // The message as status_ makes it, cut with an ellipsis to the bar's
    // width (a long one would be cut at the window's edge), with the whole
    // text as the bar's tooltip.
    void show_status_text();
    static QString preset_name(const QString& resource_path);
    void remember_recent(const QString& path);
    void update_title();
    void update_warning_counts();
    void fit_warnings_pane();
    void fit_panel_width();
    // Optimises the current scenario into the Optimise tab (when it is valid).
    void refresh_optimise();
    void update_undo_texts();
    void update_recent_menu();

    void open_dialog();
    // Unsaved edits would be lost: Save, Discard or Cancel, asked once. True
    // to go on (saved, or discarded), false to keep the edits.
    // `replaces_lab`: the action also replaces the lab's data (opening a
    // project), so unsaved lab data counts even outside a project.
    bool settle_unsaved_changes(bool replaces_lab = false);
    // Takes a project's lab, comparison and baseline (not its scenario).
    void restore_session(const Project& project, const QString& base_folder);
    // Save As offers a project first: the document is one, or the lab holds data.
    bool project_expected() const;
    // `computed` as the pinned baseline, in the document and on the charts.
    void show_baseline(const Computed& computed);
    bool save_action();
    // A file dialog offering both kinds, `as_project` chosen first.
    bool save_as_dialog(bool as_project);
    // The current tab's CSV report, or nullopt with `why_none` in the
    // interface language.
    std::optional<std::string> current_report_csv(QString& why_none);
    void export_csv_dialog();
    void export_png_dialog();
    void export_pdf_dialog();
    void import_linuxcnc_dialog();
    // `source` drawn at `width` pixels (vector-drawn widgets: no upscaled pixels).
    QPixmap render_widget(QWidget* source, int width) const;

    MainWindowOptions options_;
    QStringList last_preset_changes_;
    Document* document_{nullptr};
    Computation computation_;
    std::optional<Computed> baseline_;
    QTimer recompute_timer_;
    int recompute_count_{0};
    QString last_error_;
    QStringList recent_files_;
    struct Status {
        std::function<QString()> make;
        int timeout_ms{0};
    };
    Status status_;

    QUndoStack* undo_{nullptr};
    ParameterPanel* panel_{nullptr};
    QScrollArea* panel_scroll_{nullptr};
    Readouts* readouts_{nullptr};
    CycleCharts* charts_{nullptr};
    WarningsPanel* warnings_{nullptr};
    QLabel* warnings_title_{nullptr};
    QScrollArea* warnings_scroll_{nullptr};
    bool warnings_sized_by_user_{false};
    int warnings_rows_fitted_{-1};
    int warnings_usual_height_{-1};
    QSplitter* main_splitter_{nullptr};
    bool panel_sized_by_user_{false};
    QTabWidget* tabs_{nullptr};
    CalibrationTab* calibration_tab_{nullptr};
    LatencyTab* latency_tab_{nullptr};
    ComparisonTab* comparison_tab_{nullptr};
    // Optimised when its tab is shown, again on every change while
    // it is; marked stale otherwise (the optimiser costs far more than a
    // recompute).
    OptimisePanel* optimise_{nullptr};
    bool optimise_stale_{true};
    QSplitter* right_splitter_{nullptr};

    QMenu* file_menu_{nullptr};
    QMenu* recent_menu_{nullptr};
    QMenu* import_machine_menu_{nullptr};
    QMenu* edit_menu_{nullptr};
    QMenu* presets_menu_{nullptr};
    QMenu* machine_presets_menu_{nullptr};
    QMenu* probe_presets_menu_{nullptr};
    QMenu* compare_menu_{nullptr};
    QMenu* view_menu_{nullptr};
    QMenu* language_menu_{nullptr};
    QMenu* help_menu_{nullptr};
    QAction* new_{nullptr};
    QAction* open_{nullptr};
    QAction* save_{nullptr};
    QAction* save_as_{nullptr};
    QAction* export_csv_{nullptr};
    QAction* export_png_{nullptr};
    QAction* export_pdf_{nullptr};
    QAction* report_details_{nullptr};
    QAction* export_program_{nullptr};
    QAction* import_linuxcnc_{nullptr};
    QAction* quit_{nullptr};
    QAction* undo_action_{nullptr};
    QAction* redo_action_{nullptr};
    QAction* pin_{nullptr};
    QAction* unpin_{nullptr};
    QAction* about_{nullptr};
    QAction* guide_{nullptr};
    HelpGuide* guide_window_{nullptr};
    QAction* presets_note_{nullptr};
    QActionGroup* language_group_{nullptr};
    QList<QAction*> language_actions_;
    struct PresetAction {
        QAction* action;
        const Preset* preset;  // in preset_list()
    };
    QList<PresetAction> preset_actions_;
    QString language_choice_;
};

}  // namespace probecycle::ui
