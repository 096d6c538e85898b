#pragma once

// The Calibration tab of the lab (docs/cli.md, "The calibration and latency
// lab"): touches in a ring gauge at spindle orientations 0 and 180
// degrees, pasted or imported as CSV, give the gauge centre, the stylus runout
// and the effective ball radius; the two fitted circles are drawn with the
// points. A small group computes the effective length from a surface of known
// Z. The physics is the core's (core/calibration.h); this widget only edits
// the input and shows the result.
//
// The public functions below the constructor are the tab's behaviour as tests
// drive it; the buttons call the same functions.

#include <QList>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QStringList>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/common/report_summary.h"
#include "core/cycle/scenario.h"
#include "core/lab/calibration.h"
#include "core/project/project_file.h"
#include "ui/common/page.h"
#include "ui/lab/lab_widgets.h"
#include "ui/program/machine_log_import.h"

class QComboBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QLayout;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;

namespace probecycle::ui {

class FitInput;
class PlotView;
class ProgramDialog;
class UnitSpinBox;
class WarningList;

class CalibrationTab : public Page {
    Q_OBJECT

  public:
    explicit CalibrationTab(QWidget* parent = nullptr);
    ~CalibrationTab() override;

    // The window's current scenario: the strategy and feeds of the ring
    // gauge's program.
    void set_scenario(const probecycle::Scenario& scenario);

    // --- Ring gauge ---
    // The paste box: CSV `orientation_deg,x_mm,y_mm`.
    void set_points_text(const QString& csv);
    QString points_text() const;
    // Changing the diameter (or a limit) refits the points of the current result.
    void set_gauge_diameter_mm(double diameter_mm);
    double gauge_diameter_mm() const;
    // Fits the pasted points. On bad input: false, last_error() names the line,
    // and the previous result stays on screen.
    bool fit();
    // "Example data": touches simulated for the scenario's probe in a gauge of
    // the diameter set (core/lab/lab_examples.h), pasted and fitted.
    bool load_example();
    // Reads a CSV file into the paste box and fits it; false as fit(), or when
    // the file cannot be read.
    bool import_file(const QString& path);
    // "Program…": the ring-gauge calibration's program for the scenario set
    // and this tab's gauge, in a window-modal dialog.
    ProgramDialog* open_program_dialog();
    // "Import machine log…": the control's record of a ring program, read
    // with its plan into the paste box and fitted. False with last_error()
    // (the file and line named) and the paste box and the result as they were.
    bool import_machine_log(const MachineLogChoice& choice);
    // The CSV report (calibration_report.h), written atomically; false with
    // last_error() when there is nothing to export or the file cannot be written.
    // A summary (report_summary.h) is the PDF report's.
    bool export_report(const QString& path, ReportRows rows = ReportRows::all);
    // The report's save dialog, then export_report() (the tab's button and
    // the window's "Export CSV Report" on this tab).
    void export_dialog() override;
    std::optional<std::string> report_csv(ReportRows rows) override;
    // The fitted ring points.
    std::size_t report_points() const override { return result_ ? points_.size() : 0; }

    const std::optional<RingCalibration>& result() const { return result_; }
    // The points behind result().
    const std::vector<RingPoint>& fitted_points() const { return points_; }
    QString last_error() const override { return last_error_; }
    // Ring and length warnings shown, by core code ("large_runout", ...).
    QStringList warning_codes() const;
    // The same warnings as shown, "title: message", in the interface language.
    QStringList warning_texts() const;
    // Every result line shown, "label: value", for tests and the clipboard.
    QStringList results_text() const;

    // --- Drawing ---
    // Radial deviations from the mean circle are drawn magnified by this
    // factor, one of the box's: 0 (chosen from the data), 1 (true scale), 10,
    // 100, 1000, 10000. Other values are ignored.
    void set_deviation_magnification(double factor);
    double deviation_magnification() const { return magnification_used_; }
    // What is drawn, orientation 0 (0 deg) or 1 (180 deg), in drawing
    // coordinates (machine X/Y at true scale).
    QList<QPointF> plotted_points(int orientation) const;
    QList<QPointF> plotted_circle(int orientation) const;
    PlotView* plot() const { return plot_; }

    // --- Length ---
    struct LengthInputs {
        double surface_z_mm{0.0};
        QString trigger_z;  // one or more numbers, separated by spaces or semicolons
        double active_length_mm{0.0};
        double nominal_length_mm{0.0};  // 0 = none
    };
    void set_length_inputs(const LengthInputs& inputs);

    // --- Project ---
    // The inputs as the project file holds them: the paste box as typed, the
    // CSV behind the fit on screen, the gauge, the limits and the drawing.
    RingSession ring_session() const;
    LengthSession length_session() const;
    // Takes them back and fits the stored CSV; false (with last_error())
    // when that no longer fits.
    bool restore(const RingSession& ring, const LengthSession& length);
    void save_session(Project& project, const QString& base_folder) const override;
    bool restore_session(const Project& project, const QString& base_folder) override;
    const std::optional<LengthCalibration>& length_result() const { return length_result_; }
    QString length_error() const { return length_error_; }

  protected:
    void changeEvent(QEvent* event) override;

  private:
    QGroupBox* build_ring_group();
    QGroupBox* build_length_group();
    QLayout* build_plot_column();
    QGroupBox* build_result_group();
    void connect_inputs();
    bool fit_text(const QString& text, const QString& source);
    bool refit();
    void set_error(std::function<QString()> text);
    RingCalibrationOptions options() const;
    void show_result();
    void draw();
    void update_plot_ranges();
    void compute_length();
    void retranslate();
    void import_dialog();

    Scenario scenario_;

    // Input
    QGroupBox* ring_group_{nullptr};
    QLabel* format_hint_{nullptr};
    FitInput* input_{nullptr};
    QPlainTextEdit* points_edit_{nullptr};  // input_'s
    QLabel* diameter_label_{nullptr};
    UnitSpinBox* diameter_{nullptr};
    QLabel* runout_limit_label_{nullptr};
    UnitSpinBox* runout_limit_{nullptr};
    QLabel* residual_limit_label_{nullptr};
    UnitSpinBox* residual_limit_{nullptr};

    // Length
    QGroupBox* length_group_{nullptr};
    QFormLayout* length_form_{nullptr};
    UnitSpinBox* surface_z_{nullptr};
    QLineEdit* trigger_z_{nullptr};
    UnitSpinBox* active_length_{nullptr};
    UnitSpinBox* nominal_length_{nullptr};
    QLabel* length_result_label_{nullptr};
    WarningList* length_warnings_{nullptr};

    // Drawing
    QLabel* magnification_label_{nullptr};
    QComboBox* magnification_{nullptr};
    PlotView* plot_{nullptr};
    int points_curve_[2]{-1, -1};
    int circle_curve_[2]{-1, -1};
    int centre_curve_[2]{-1, -1};
    int gauge_centre_curve_{-1};
    double magnification_used_{1.0};
    QRectF data_bounds_;

    // Result
    QGroupBox* result_group_{nullptr};
    QFormLayout* result_form_{nullptr};
    QLabel* result_labels_[8]{};
    QLabel* result_values_[8]{};
    QLabel* warnings_title_{nullptr};
    WarningList* warnings_{nullptr};
    QPushButton* export_button_{nullptr};
    QLabel* export_status_{nullptr};

    std::vector<RingPoint> points_;
    QString fitted_text_;                // the CSV behind result_
    std::string points_from_{"pasted"};  // the report's subject: points_' file, or "pasted"
    RingCalibrationOptions options_;     // of result_
    std::optional<RingCalibration> result_;
    QString last_error_;

    std::optional<LengthCalibrationInput> length_input_;
    std::optional<LengthCalibration> length_result_;
    QString length_error_;
};

}  // namespace probecycle::ui
