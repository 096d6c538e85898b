#pragma once

// The Comparison tab (docs/comparison.md):
// the plan, the reference part's CMM points, the two on-machine measurements
// and optionally the block touched at both angles, the C axis's position, the
// angle and the tolerance; one Run. It shows the C axis's errors, direct OMM
// against the comparison (min, max, RMS, out of tolerance), a deviation
// colour map of the points over the part with the tolerance band, a
// histogram, the points worst first and the warnings. The physics is the
// core's (core/comparison/); this widget edits the input and shows the
// result. "Simulate example data" writes the simulator's data set and runs
// it, so a new user sees the method work at once.
//
// The public functions below the constructor are the tab's behaviour as tests
// drive it; the buttons call the same functions.

#include <QString>
#include <QStringList>
#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "core/common/report_summary.h"
#include "core/comparison/comparison.h"
#include "core/comparison/comparison_files.h"
#include "core/comparison/comparison_project.h"
#include "ui/common/page.h"

class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableView;
class QTableWidget;
class QToolButton;

namespace probecycle::ui {

class PointTableModel;
class PlotView;
class UnitSpinBox;
class WarningList;

class ComparisonTab : public Page {
    Q_OBJECT

  public:
    using InputFile = ComparisonFile;
    static constexpr int kInputFiles = static_cast<int>(kComparisonFiles);

    explicit ComparisonTab(QWidget* parent = nullptr);
    ~ComparisonTab() override;

    void set_file(InputFile which, const QString& path);
    QString file(InputFile which) const;
    void set_c_axis(double x_mm, double y_mm);
    void set_angle_deg(double angle_deg);
    void set_tolerance_mm(double tolerance_mm);
    double tolerance_mm() const;

    // Reads every file and runs the comparison. On bad input: false,
    // last_error() names the file, the line and the column, and the previous
    // result stays on screen.
    bool run();
    // Writes the simulator's data set (noise-free, with the C axis's and the
    // machine's errors) into `folder` (by default the application's data
    // folder), fills the inputs with it and runs.
    bool simulate_example(const QString& folder = {});
    // The CSV report, the same bytes as `probecycle-cli compare run --report`;
    // a summary (report_summary.h) is the PDF report's.
    bool export_report(const QString& path, ReportRows rows = ReportRows::all);
    std::optional<std::string> report_csv(ReportRows rows) override;
    // The compared points.
    std::size_t report_points() const override { return result_ ? result_->points.size() : 0; }
    // The report's save dialog, then export_report() (the tab's button and
    // the window's "Export CSV Report" on this tab).
    void export_dialog() override;
    // The project file: the paths (relative to its folder) and settings.
    bool save_project(const QString& path);
    // Loads a project; on a bad file false with last_error(), and the inputs
    // stay as they were. Runs when the four point files are given.
    bool open_project(const QString& path);
    // The files and settings as a project holds them: paths relative to
    // `base_folder`, or absolute when it is empty (the window's project file
    // and its saved session).
    ComparisonProject settings(const QString& base_folder) const;
    // Takes them back (paths relative to `base_folder`, or absolute); runs
    // when the four point files are given, else clears the result shown.
    bool restore(const ComparisonProject& project, const QString& base_folder);
    void save_session(Project& project, const QString& base_folder) const override {
        project.comparison = settings(base_folder);
    }
    bool restore_session(const Project& project, const QString& base_folder) override {
        return restore(project.comparison, base_folder);
    }

    const std::optional<ComparisonResult>& result() const { return result_; }
    QString last_error() const override { return last_error_; }
    QStringList warning_codes() const;
    // The summary table as shown, one "row: min, max, RMS, out" per line.
    QStringList summary_text() const;
    // The C-axis rows as shown, "error: value (uncertainty)".
    QStringList c_axis_text() const;
    // The point table's first column (1-based plan index), top to bottom.
    QList<int> point_order() const;
    PlotView* map() const { return map_; }
    PlotView* histogram() const { return histogram_; }
    // Points drawn in the map, over every colour class.
    int map_point_count() const;

  protected:
    void changeEvent(QEvent* event) override;

  private:
    QGroupBox* build_input_group();
    QWidget* build_charts();
    QWidget* build_result_column();
    void retranslate();
    void set_error(const QString& text);
    void show_result();
    void clear_result();
    void draw_map();
    void draw_histogram();
    void fill_tables();
    void choose_file(InputFile which);
    void open_project_dialog();
    void save_project_dialog();
    void simulate_dialog();
    // Rerun with the current inputs when a result is on screen.
    void rerun_if_shown();
    // The files' content, read anew only when a path or a file's
    // modification time or size changed since the last read.
    ComparisonInput read_files();
    // The error in the interface language: the file's label, or its name and
    // what is wrong with its content.
    QString file_error_text(const ComparisonFileError& error) const;

    std::array<QLabel*, kInputFiles> file_labels_{};
    std::array<QLineEdit*, kInputFiles> file_edits_{};
    std::array<QToolButton*, kInputFiles> file_buttons_{};
    QGroupBox* input_group_{nullptr};
    QLabel* format_hint_{nullptr};
    QLabel* axis_x_label_{nullptr};
    UnitSpinBox* axis_x_{nullptr};
    QLabel* axis_y_label_{nullptr};
    UnitSpinBox* axis_y_{nullptr};
    QLabel* angle_label_{nullptr};
    UnitSpinBox* angle_{nullptr};
    QLabel* tolerance_label_{nullptr};
    UnitSpinBox* tolerance_{nullptr};
    QPushButton* run_button_{nullptr};
    QPushButton* simulate_button_{nullptr};
    QPushButton* open_button_{nullptr};
    QPushButton* save_button_{nullptr};
    QLabel* error_label_{nullptr};

    PlotView* map_{nullptr};
    PlotView* histogram_{nullptr};
    std::array<int, 7> class_curves_{};
    int direct_area_{-1};
    int deviation_area_{-1};
    int band_low_{-1};
    int band_high_{-1};

    QGroupBox* result_group_{nullptr};
    QLabel* c_axis_title_{nullptr};
    QTableWidget* c_axis_table_{nullptr};
    QLabel* summary_title_{nullptr};
    QTableWidget* summary_table_{nullptr};
    QLabel* warnings_title_{nullptr};
    WarningList* warnings_{nullptr};
    QLabel* points_title_{nullptr};
    QTableView* point_table_{nullptr};
    PointTableModel* point_model_{nullptr};
    QPushButton* export_button_{nullptr};
    QLabel* export_status_{nullptr};

    struct FileCache;
    std::unique_ptr<FileCache> file_cache_;
    ComparisonInput input_;  // of result_
    std::optional<ComparisonResult> result_;
    QString last_error_;
};

}  // namespace probecycle::ui
