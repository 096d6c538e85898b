#pragma once

// The import of a cycle program's log (docs/programs.md, "What the cycle
// program measures"): the recorded touches matched to the plan, the feature's
// result computed from them (feature_result.h), checked against the result the
// program itself logged where it computes one, as text and as JSON. All or
// nothing: a log the lab's import refuses, or a result line that the touches do
// not give, is a CsvError naming the line.

#include <string>
#include <string_view>
#include <vector>

#include "core/program/dialect.h"
#include "core/program/feature_result.h"
#include "core/program/machine_log.h"
#include "core/program/plan.h"

namespace probecycle {

struct CycleImport {
    std::string plan_id;
    ResultSpec spec;
    std::vector<RecordedPosition> touches;
    FeatureResult result;
    // The program's own result line (line 0: none, as from grbl or a
    // LinuxCNC PROBEOPEN file).
    LoggedResult logged;
};

// How far the program's logged figures may differ from the import's: the
// digits the dialect prints (LinuxCNC 6 decimals, DPRNT 4), from touch
// positions printed to the same digits.
double logged_result_tolerance_mm(DialectId dialect);

// Throws InputError for a plan that is not a cycle's, CsvError for the log.
CycleImport import_cycle_log(const ProbingPlan& plan, DialectId dialect, std::string_view text);

// "bore diameter 50.0123 mm +- 0.0022 mm (k = 2)" ...: a few lines, "\n" at
// the end of each.
std::string cycle_import_text(const CycleImport& import);
// {"format": "probecycle-feature-result", "version": 1, ...}, 2-space JSON.
std::string cycle_import_json(const CycleImport& import);

}  // namespace probecycle
