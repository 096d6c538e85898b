#pragma once

// The window's whole session as one file, so that nothing the user made is lost
// (docs/files.md, "The project file"): the scenario, the pinned baseline, the
// lab's inputs and the fits on screen, the compensation setup and the
// Comparison tab's files and settings. JSON, versioned:
//   {"format": "probecycle-project", "version": 1,
//    "scenario": {...the scenario file's sections...},
//    "baseline": {...} or null,
//    "ring": {"points_csv": "...", "fitted_csv": "...", ...},
//    "length": {...}, "delay": {...}, "compensation": {...},
//    "comparison": {...the comparison project's keys...},
//    "report": {"customer": "...", "machine": "...", ...}}
// A fit is stored as the CSV text it was computed from (in the lab's CSV
// formats), not as its result: opening fits it again and shows what was on
// screen. The paste boxes are stored as typed, which may differ from what
// was fitted. Every key but format, version and scenario
// is optional (its default); an unknown key, a wrong type or a number out of
// range refuses the whole file, naming the dotted key and what is allowed.
// Plain scenario files stay what the CLI reads and writes; a project is
// recognised by its "format".

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/comparison/comparison_project.h"
#include "core/cycle/scenario.h"
#include "core/lab/calibration.h"
#include "core/lab/compensation.h"
#include "core/lab/delay_fit.h"

namespace probecycle {

// The Calibration tab's ring gauge.
struct RingSession {
    std::string points_csv;          // the paste box, as typed
    std::string fitted_csv;          // behind the fit on screen; empty: none
    RingCalibrationOptions options;  // the gauge and the warning limits
    double magnification{0.0};       // the drawing's: one of kRingMagnifications
};

// Deviations drawn magnified by one of these (0: chosen from the data).
constexpr double kRingMagnifications[] = {0.0, 1.0, 10.0, 100.0, 1000.0, 10000.0};

// The Calibration tab's length from a surface of known Z.
struct LengthSession {
    double surface_z_mm{0.0};
    std::string trigger_z;  // the box as typed: numbers separated by spaces or semicolons
    double active_length_mm{0.0};
    double nominal_length_mm{0.0};  // 0: none
};

// The Latency tab's delay fit.
struct DelaySession {
    std::string touches_csv;             // the paste box, as typed
    std::string fitted_csv;              // behind the fit on screen; empty: none
    double interpolation_period_s{0.0};  // 0: none
    std::string applied_group;           // "X+"; empty: the CLI's rule
};

// The Latency tab's compensation comparison (the window's inputs; the rest of
// CompensationSetup comes from the scenario).
struct CompensationSession {
    double feed_mm_min{2000.0};
    double interpolation_period_s{0.001};
    int lag_cycles{8};
    TouchMotion touch{TouchMotion::braking};
    double speed_fraction{0.5};  // braking: the speed at the trigger / the feed
    // The lag the real-increments method subtracts; -1: the lag itself.
    int compensated_lag_cycles{-1};
};

// The PDF report's title block: who it is for and who made it, as typed.
struct ReportDetails {
    std::string customer;
    std::string machine;
    std::string part;
    std::string author;
    std::string notes;  // may hold line breaks
    bool operator==(const ReportDetails&) const = default;
};

struct Project {
    Scenario scenario;
    std::optional<Scenario> baseline;  // the pinned baseline's scenario
    RingSession ring;
    LengthSession length;
    DelaySession delay;
    CompensationSession compensation;
    // Paths as stored: relative to the project file's folder (the window
    // resolves them), empty when not given.
    ComparisonProject comparison;
    ReportDetails report;
};

// The ranges the window's editors allow and a project file must keep to.
constexpr double kMinGaugeDiameter_mm = 0.1;
constexpr double kMaxGaugeDiameter_mm = 2000.0;
constexpr double kMaxLabLimit_mm = 10.0;  // runout and residual warning limits
constexpr double kMaxLength_mm = 2000.0;  // active and nominal length
constexpr double kMinCompensationFeed_mm_min = 1.0;
constexpr double kMaxCompensationFeed_mm_min = 100000.0;
constexpr double kMinInterpolationPeriod_s = 1e-5;
constexpr double kMaxInterpolationPeriod_s = 0.1;
constexpr double kMinSpeedFraction = 0.001;
constexpr int kMaxLagCycles = static_cast<int>(IncrementRing::kCapacity) - 1;

// The file's text (2-space JSON, "\n" at the end).
std::string project_json(const Project& project);
// A project file's problems.
class ProjectError : public FileContentError {
  public:
    explicit ProjectError(std::vector<FieldError> errors)
        : FileContentError(FileKind::project, std::move(errors)) {}
};

// Throws ProjectError listing every problem, each keyed by its dotted path in
// the file ("scenario.machine.scan_period_s", "delay.fitted_csv: line 3 ...").
Project parse_project(std::string_view text);
// True when the text names the project format ("probecycle-project"): a plain
// scenario or a comparison project gives false; a damaged project gives true,
// so that parse_project says what is wrong with it.
bool is_project_text(std::string_view text);

}  // namespace probecycle
