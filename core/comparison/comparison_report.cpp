#include "core/comparison/comparison_report.h"

#include <cstdio>
#include <sstream>

#include "core/common/csv_writer.h"
#include "core/common/message_json.h"
#include "core/common/number_format.h"
#include "core/common/report_summary.h"

namespace probecycle {

namespace {

using Json = nlohmann::ordered_json;

Json optional_json(const std::optional<double>& value) {
    return value ? Json(*value) : Json(nullptr);
}

Json optional_json(const std::optional<std::size_t>& value) {
    return value ? Json(*value) : Json(nullptr);
}

Json summary_json(const DeviationSummary& s) {
    return {
        {"min_mm", s.min_mm}, {"max_mm", s.max_mm}, {"mean_mm", s.mean_mm}, {"rms_mm", s.rms_mm}};
}

std::string code_of(const std::string& code) {
    return code;
}
std::string code_of(CAxisWarningCode code) {
    return to_string(code);
}

std::string row(std::initializer_list<std::string> fields) {
    std::string out;
    for (const std::string& f : fields) out += (out.empty() ? "" : ",") + f;
    return out + "\n";
}

// The digits the method supports (csv_writer.h). Lengths and
// deviations to 0.1 um; the C axis's angles to 0.01 urad (its uncertainty on
// a part is tens of urad); the inputs (the plan's points and normals, the
// C axis's position, the angle, the tolerance) exactly as given.
std::string mm(double value) {
    return csv_length_mm(value);
}
std::string mm(const std::optional<double>& value) {
    return csv_length_mm(value);
}
std::string rad(double value) {
    return format_fixed(value, 8);
}
std::string rad(const std::optional<double>& value) {
    return value ? rad(*value) : std::string();
}
std::string exact(double value) {
    return csv_exact(value);
}
std::string exact(const std::optional<double>& value) {
    return value ? csv_exact(*value) : std::string();
}

// The simulator's data files: 9 significant digits, as a CMM's export.
std::string n(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", value);
    return buffer;
}

}  // namespace

Json c_axis_json(const CAxisErrors& e, const std::optional<CAxisErrors>& u) {
    const auto six = [](const CAxisErrors& v) {
        return Json{{"ex_rad", v.ex_rad}, {"ey_rad", v.ey_rad}, {"ez_rad", v.ez_rad},
                    {"dx_mm", v.dx_mm},   {"dy_mm", v.dy_mm},   {"dz_mm", v.dz_mm}};
    };
    Json out = six(e);
    if (u) {
        out["uncertainty"] = six(*u);
    } else {
        out["uncertainty"] = {{"ex_rad", nullptr}, {"ey_rad", nullptr}, {"ez_rad", nullptr},
                              {"dx_mm", nullptr},  {"dy_mm", nullptr},  {"dz_mm", nullptr}};
    }
    return out;
}

Json comparison_json(const ComparisonResult& result) {
    Json out = Json::object();
    out["c_axis"] = c_axis_json(result.c_axis.errors, result.c_axis.uncertainty);
    out["c_axis"]["identified"] = result.c_axis_identified;
    Json points = Json::array();
    for (const ComparisonPoint& p : result.points) {
        points.push_back({{"x_mm", p.nominal.x()},
                          {"y_mm", p.nominal.y()},
                          {"z_mm", p.nominal.z()},
                          {"deviation_mm", p.deviation_mm},
                          {"direct_deviation_mm", p.direct_deviation_mm},
                          {"system_error_mm", p.system_error_mm},
                          {"c_axis_uncertainty_mm", optional_json(p.c_axis_uncertainty_mm)}});
    }
    out["points"] = points;
    out["summary"] = {{"deviation", summary_json(result.deviation)},
                      {"direct", summary_json(result.direct)},
                      {"system_error", summary_json(result.system_error)},
                      {"out_of_tolerance", optional_json(result.out_of_tolerance)}};
    out["surfaces"] = {{"cmm_residual_max_mm", result.cmm_fit.max_mm},
                       {"design_residual_max_mm", result.design_fit.max_mm},
                       {"calibrated_residual_max_mm", result.calibrated_fit.max_mm}};
    out["warnings"] =
        warnings_json(result.warnings, [](const auto& code) { return code_of(code); });
    return out;
}

Json c_axis_identification_json(const CAxisIdentification& result, const CAxisSetup& setup) {
    Json out = Json::object();
    out["c_axis"] = c_axis_json(result.errors, result.uncertainty);
    out["axis_x_mm"] = setup.x_mm;
    out["axis_y_mm"] = setup.y_mm;
    out["angle_deg"] = setup.angle_deg;
    Json poses = Json::array();
    for (const auto& [angle, pose] :
         {std::pair{0.0, &result.at_zero}, std::pair{setup.angle_deg, &result.turned}}) {
        Json planes = Json::array();
        for (const FacePlane& f : pose->faces) {
            planes.push_back({{"face", to_string(f.face)},
                              {"touches", f.touches},
                              {"normal", {f.normal.x(), f.normal.y(), f.normal.z()}},
                              {"residual_rms_mm", f.rms_mm},
                              {"residual_max_mm", f.max_mm},
                              {"sigma_mm", optional_json(f.sigma_mm)}});
        }
        poses.push_back({{"angle_deg", angle},
                         {"corner_mm", {pose->corner.x(), pose->corner.y(), pose->corner.z()}},
                         {"planes", planes}});
    }
    out["blocks"] = poses;
    out["warnings"] =
        warnings_json(result.warnings, [](const auto& code) { return code_of(code); });
    return out;
}

std::string comparison_report_csv(const ComparisonInput& input, const ComparisonResult& result,
                                  const ReportHeader& header, ReportRows rows) {
    std::ostringstream out;
    out << report_header_csv("comparison report", "test_omm", header);
    out << "# c_axis\nquantity,value,uncertainty,unit\n";
    const CAxisErrors& e = result.c_axis.errors;
    const std::optional<CAxisErrors>& u = result.c_axis.uncertainty;
    const auto err = [&](const char* name, double value, double CAxisErrors::*member,
                         const char* unit) {
        const std::optional<double> uncertainty =
            u ? std::optional<double>((*u).*member) : std::nullopt;
        const bool angle = std::string_view(unit) == "rad";
        out << row({name, angle ? rad(value) : mm(value),
                    angle ? rad(uncertainty) : mm(uncertainty), unit});
    };
    out << row({"identified", result.c_axis_identified ? "yes" : "no", "", ""});
    out << row({"axis_x", exact(input.c_axis.x_mm), "", "mm"});
    out << row({"axis_y", exact(input.c_axis.y_mm), "", "mm"});
    out << row({"angle", exact(input.c_axis.angle_deg), "", "deg"});
    err("ex", e.ex_rad, &CAxisErrors::ex_rad, "rad");
    err("ey", e.ey_rad, &CAxisErrors::ey_rad, "rad");
    err("ez", e.ez_rad, &CAxisErrors::ez_rad, "rad");
    err("dx", e.dx_mm, &CAxisErrors::dx_mm, "mm");
    err("dy", e.dy_mm, &CAxisErrors::dy_mm, "mm");
    err("dz", e.dz_mm, &CAxisErrors::dz_mm, "mm");

    out << "\n# summary\nquantity,min_mm,max_mm,mean_mm,rms_mm,out_of_tolerance\n";
    const auto count = [](const std::optional<std::size_t>& c) {
        return c ? std::to_string(*c) : std::string();
    };
    const auto summary = [&](const char* name, const DeviationSummary& s,
                             const std::string& beyond) {
        out << row({name, mm(s.min_mm), mm(s.max_mm), mm(s.mean_mm), mm(s.rms_mm), beyond});
    };
    summary("deviation", result.deviation, count(result.out_of_tolerance));
    summary("direct", result.direct, count(result.direct_out_of_tolerance));
    summary("system_error", result.system_error, "");
    out << row({"tolerance", exact(input.tolerance_mm), "", "", "", ""});

    const std::vector<ComparisonPoint>& points = result.points;
    const auto point_row = [&](std::size_t k) {
        const ComparisonPoint& p = points[k];
        out << row({std::to_string(k + 1), exact(p.nominal.x()), exact(p.nominal.y()),
                    exact(p.nominal.z()), exact(p.normal.x()), exact(p.normal.y()),
                    exact(p.normal.z()), mm(p.deviation_mm), mm(p.direct_deviation_mm),
                    mm(p.system_error_mm), mm(p.c_axis_uncertainty_mm)});
    };
    const char* columns =
        "point,x_mm,y_mm,z_mm,i,j,k,deviation_mm,direct_deviation_mm,system_error_mm,"
        "c_axis_uncertainty_mm\n";
    if (summarised(rows, points.size())) {
        // "# summary" above has the statistics.
        std::vector<double> deviation_mm(points.size());
        for (std::size_t k = 0; k < points.size(); ++k) deviation_mm[k] = points[k].deviation_mm;
        const std::vector<std::size_t> largest =
            largest_magnitudes(deviation_mm, kReportLargestRows);
        out << '\n'
            << csv_largest_heading("points", "deviation_mm", largest.size(), points.size())
            << columns;
        for (const std::size_t k : largest) point_row(k);
    } else {
        out << "\n# points\n" << columns;
        for (std::size_t k = 0; k < points.size(); ++k) point_row(k);
    }
    out << "\n# warnings\ncode,severity,message\n";
    for (const ComparisonWarning& w : result.warnings) {
        out << row({w.code, to_string(w.severity), csv_quote(render(w.message))});
    }
    return out.str();
}

std::string plan_csv(const std::vector<PlanPoint>& plan) {
    std::string out = "x_mm,y_mm,z_mm,i,j,k\n";
    for (const PlanPoint& p : plan) {
        out += row({n(p.nominal.x()), n(p.nominal.y()), n(p.nominal.z()), n(p.normal.x()),
                    n(p.normal.y()), n(p.normal.z())});
    }
    return out;
}

std::string points_csv(const std::vector<Eigen::Vector3d>& points) {
    std::string out = "x_mm,y_mm,z_mm\n";
    for (const Eigen::Vector3d& p : points) out += row({n(p.x()), n(p.y()), n(p.z())});
    return out;
}

std::string block_csv(const std::vector<BlockTouch>& touches) {
    std::string out = "face,x_mm,y_mm,z_mm\n";
    for (const BlockTouch& t : touches) {
        out += row({to_string(t.face), n(t.point.x()), n(t.point.y()), n(t.point.z())});
    }
    return out;
}

std::string truth_csv(const std::vector<PlanPoint>& plan, const std::vector<double>& truth_mm) {
    std::string out = "x_mm,y_mm,z_mm,deviation_mm\n";
    for (std::size_t k = 0; k < plan.size() && k < truth_mm.size(); ++k) {
        const Eigen::Vector3d& p = plan[k].nominal;
        out += row({n(p.x()), n(p.y()), n(p.z()), n(truth_mm[k])});
    }
    return out;
}

Json simulation_json(const ComparisonDataSet& data, const ComparisonSimulationOptions& options) {
    Json out = Json::object();
    out["seed"] = options.seed;
    out["noise_mm"] = options.omm_noise_mm;
    out["cmm_noise_mm"] = options.cmm_noise_mm;
    out["points"] = data.input.plan.size();
    out["axis_x_mm"] = data.input.c_axis.x_mm;
    out["axis_y_mm"] = data.input.c_axis.y_mm;
    out["angle_deg"] = data.input.c_axis.angle_deg;
    out["true_c_axis"] = c_axis_json(data.true_c_axis, CAxisErrors{});
    out["true_c_axis"].erase("uncertainty");
    return out;
}

}  // namespace probecycle
