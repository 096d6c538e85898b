#pragma once

// The comparison's files out: the CSV report (the CLI's --report and the
// Comparison tab's export, the same bytes), the CLI's JSON, and the
// simulator's data set in the input formats (comparison_input.h).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/common/report_header.h"
#include "core/common/report_summary.h"
#include "core/comparison/comparison.h"
#include "core/comparison/comparison_simulator.h"

namespace probecycle {

// The report header (report_header.h; its subject the test part's OMM file),
// then sections "# c_axis", "# summary", "# points" (plan order), "# warnings".
// A summary (report_summary.h) of more than kReportFullRows points has, in
// place of "# points", the 10 largest |deviation_mm| ("# summary" has the rest).
std::string comparison_report_csv(const ComparisonInput& input, const ComparisonResult& result,
                                  const ReportHeader& header, ReportRows rows = ReportRows::all);

// {"ex_rad", ..., "dz_mm", "uncertainty": {...}}: uncertainties null when
// unknown.
nlohmann::ordered_json c_axis_json(const CAxisErrors& errors,
                                   const std::optional<CAxisErrors>& uncertainty);
// compare run: c_axis, points, summary, warnings.
nlohmann::ordered_json comparison_json(const ComparisonResult& result);
// compare cerrors: c_axis, corners, planes, warnings.
nlohmann::ordered_json c_axis_identification_json(const CAxisIdentification& result,
                                                  const CAxisSetup& setup);

// The input formats, for the simulator's files.
std::string plan_csv(const std::vector<PlanPoint>& plan);
std::string points_csv(const std::vector<Eigen::Vector3d>& points);
std::string block_csv(const std::vector<BlockTouch>& touches);
// x_mm,y_mm,z_mm,deviation_mm: the plan point and the test part's true deviation.
std::string truth_csv(const std::vector<PlanPoint>& plan, const std::vector<double>& truth_mm);
// What the simulator applied: the C axis (position, angle, true errors) and
// the options.
nlohmann::ordered_json simulation_json(const ComparisonDataSet& data,
                                       const ComparisonSimulationOptions& options);

}  // namespace probecycle
