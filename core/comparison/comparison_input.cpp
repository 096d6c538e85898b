#include "core/comparison/comparison_input.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>
#include <utility>

#include "core/common/csv_reader.h"
#include "core/comparison/comparison_message.h"

namespace probecycle {

namespace {

constexpr std::string_view kPtmeas = "PTMEAS/";

std::string upper(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return out;
}

std::string_view trim(std::string_view text) {
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    const auto last = text.find_last_not_of(" \t\r");
    return text.substr(first, last - first + 1);
}

// The file's lines, 1-based, without their ends.
template <typename Visit>
void for_each_line(std::string_view text, Visit visit) {
    std::size_t line = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        const auto end = text.find('\n', start);
        ++line;
        visit(line, trim(text.substr(start, end == std::string_view::npos ? end : end - start)));
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
}

bool is_dmis(std::string_view text) {
    bool found = false;
    for_each_line(text, [&found](std::size_t, std::string_view line) {
        found = found || upper(line.substr(0, kPtmeas.size())) == kPtmeas;
    });
    return found;
}

// The DMIS point statements as rows of x, y, z[, i, j, k]: the columns are
// named as in the CSV files so that messages read alike.
std::vector<CsvRow> dmis_rows(std::string_view text, bool need_normal) {
    std::vector<CsvRow> rows;
    for_each_line(text, [&](std::size_t line, std::string_view content) {
        const std::string head = upper(content.substr(0, kPtmeas.size() + 5));
        if (head.rfind(kPtmeas, 0) != 0) return;
        if (head != "PTMEAS/CART,") {
            throw CsvError(line, "",
                           comparison_message(
                               "dmis_not_cartesian",
                               QT_TRANSLATE_NOOP("Comparison",
                                                 "only PTMEAS/CART,x,y,z,i,j,k is read; got '%1'"),
                               {text_arg("value", std::string(content))}));
        }
        CsvRow row;
        row.line = line;
        std::string_view rest = content.substr(head.size());
        while (true) {
            const auto comma = rest.find(',');
            row.fields.emplace_back(trim(rest.substr(0, comma)));
            if (comma == std::string_view::npos) break;
            rest.remove_prefix(comma + 1);
        }
        const std::size_t count = row.fields.size();
        if (count != 6 && (need_normal || count != 3)) {
            throw CsvError(
                line, "",
                comparison_message(
                    "dmis_field_count",
                    need_normal
                        ? QT_TRANSLATE_NOOP("Comparison",
                                            "PTMEAS/CART has %1 numbers; the plan needs 6 "
                                            "(x, y, z, i, j, k)")
                        : QT_TRANSLATE_NOOP("Comparison",
                                            "PTMEAS/CART has %1 numbers; allowed: 3 (x, y, z) "
                                            "or 6 (x, y, z, i, j, k)"),
                    {arg("fields", ArgKind::integer, static_cast<double>(count))}));
        }
        rows.push_back(std::move(row));
    });
    return rows;
}

std::vector<CsvRow> point_rows(std::string_view text, bool plan) {
    if (is_dmis(text)) return dmis_rows(text, plan);
    if (plan) return read_csv_rows(text, {"x_mm", "y_mm", "z_mm", "i", "j", "k"});
    return read_csv_rows(text, {"x_mm", "y_mm", "z_mm"});
}

Eigen::Vector3d coordinates(const CsvRow& row) {
    return {csv_coordinate(row, 0, "x_mm"), csv_coordinate(row, 1, "y_mm"),
            csv_coordinate(row, 2, "z_mm")};
}

void check_enough(const std::vector<CsvRow>& rows) {
    if (rows.size() < kMinComparisonPoints) {
        throw CsvError(rows.empty() ? 0 : rows.back().line, "", too_few_points(rows.size()));
    }
}

}  // namespace

Message too_few_points(std::size_t points) {
    return comparison_message(
        "too_few_points",
        QT_TRANSLATE_NOOP("Comparison", "a comparison needs %2 points or more; got %1"),
        {arg("points", ArgKind::integer, static_cast<double>(points)),
         arg("required", ArgKind::integer, static_cast<double>(kMinComparisonPoints))});
}

void check_points_follow_plan(const std::vector<MeasuredPoint>& points,
                              const std::vector<PlanPoint>& plan) {
    if (plan.empty()) return;
    Eigen::Vector3d low = plan.front().nominal;
    Eigen::Vector3d high = low;
    for (const PlanPoint& p : plan) {
        low = low.cwiseMin(p.nominal);
        high = high.cwiseMax(p.nominal);
    }
    // A point of the part lies near its plan point: the part's deviations
    // are far smaller than the plan's extent.
    const double extent_mm = std::max((high - low).norm(), kMinPlanExtent_mm);
    for (std::size_t i = 0; i < points.size() && i < plan.size(); ++i) {
        const double distance_mm = (points[i].point - plan[i].nominal).norm();
        if (distance_mm <= extent_mm) continue;
        throw CsvError(
            points[i].line, "",
            comparison_message(
                "point_far_from_plan",
                QT_TRANSLATE_NOOP("Comparison",
                                  "this point lies %1 from its plan point (plan line %2); "
                                  "allowed: within the plan's extent, %3; the points follow "
                                  "the plan's order, one per plan point"),
                {arg("distance", ArgKind::length_mm, distance_mm),
                 arg("plan_line", ArgKind::integer, static_cast<double>(plan[i].line)),
                 arg("extent", ArgKind::length_mm, extent_mm)}));
    }
    // Out of order: a point much nearer another plan point than its own.
    // The plan points by x, so each point looks only at those within reach
    // in x (not every pair: a 16 MiB file holds 290,000 points).
    std::vector<std::size_t> by_x(plan.size());
    for (std::size_t j = 0; j < plan.size(); ++j) by_x[j] = j;
    std::sort(by_x.begin(), by_x.end(), [&plan](std::size_t a, std::size_t b) {
        return plan[a].nominal.x() < plan[b].nominal.x();
    });
    for (std::size_t i = 0; i < points.size() && i < plan.size(); ++i) {
        const double own_mm = (points[i].point - plan[i].nominal).norm();
        if (own_mm <= kOrderCheckFrom_mm) continue;
        const double reach_mm = own_mm / kOrderCheckRatio;
        const double x = points[i].point.x();
        auto it = std::lower_bound(
            by_x.begin(), by_x.end(), x - reach_mm,
            [&plan](std::size_t j, double value) { return plan[j].nominal.x() < value; });
        for (; it != by_x.end() && plan[*it].nominal.x() <= x + reach_mm; ++it) {
            const std::size_t j = *it;
            if (j == i) continue;
            const double other_mm = (points[i].point - plan[j].nominal).norm();
            if (other_mm * kOrderCheckRatio >= own_mm) continue;
            throw CsvError(
                points[i].line, "",
                comparison_message(
                    "point_out_of_order",
                    QT_TRANSLATE_NOOP("Comparison",
                                      "this point lies %1 from its plan point (plan line %2) "
                                      "but %3 from the plan point of line %4: the points must "
                                      "follow the plan's order, one per plan point"),
                    {arg("own", ArgKind::length_mm, own_mm),
                     arg("plan_line", ArgKind::integer, static_cast<double>(plan[i].line)),
                     arg("other", ArgKind::length_mm, other_mm),
                     arg("other_line", ArgKind::integer, static_cast<double>(plan[j].line))}));
        }
    }
}

std::vector<Eigen::Vector3d> parse_points_for_plan(std::string_view text,
                                                   const std::vector<PlanPoint>& plan) {
    const std::vector<MeasuredPoint> points = parse_points(text);
    check_point_count(points, plan.size());
    check_points_follow_plan(points, plan);
    std::vector<Eigen::Vector3d> out;
    out.reserve(points.size());
    for (const MeasuredPoint& p : points) out.push_back(p.point);
    return out;
}

const char* to_string(BlockFace face) {
    switch (face) {
        case BlockFace::a:
            return "A";
        case BlockFace::b:
            return "B";
        case BlockFace::c:
            return "C";
    }
    return "?";
}

std::vector<PlanPoint> parse_plan(std::string_view text) {
    const std::vector<CsvRow> rows = point_rows(text, true);
    std::vector<PlanPoint> plan;
    plan.reserve(rows.size());
    for (const CsvRow& row : rows) {
        PlanPoint point;
        point.line = row.line;
        point.nominal = coordinates(row);
        const Eigen::Vector3d normal(csv_number(row, 3, "i"), csv_number(row, 4, "j"),
                                     csv_number(row, 5, "k"));
        const double length = normal.norm();
        if (!(std::abs(length - 1.0) <= kNormalLengthTolerance)) {
            throw CsvError(
                row.line, "i",
                comparison_message(
                    "normal_not_unit",
                    QT_TRANSLATE_NOOP("Comparison",
                                      "the normal (i, j, k) has length %1; allowed: a unit "
                                      "vector, length 1 within %2"),
                    {significant_arg("length", ArgKind::number, length, 6),
                     arg("tolerance", ArgKind::number, kNormalLengthTolerance)}));
        }
        point.normal = normal / length;
        plan.push_back(point);
    }
    check_enough(rows);
    return plan;
}

std::vector<MeasuredPoint> parse_points(std::string_view text) {
    const std::vector<CsvRow> rows = point_rows(text, false);
    std::vector<MeasuredPoint> points;
    points.reserve(rows.size());
    for (const CsvRow& row : rows) points.push_back({coordinates(row), row.line});
    check_enough(rows);
    return points;
}

void check_point_count(const std::vector<MeasuredPoint>& points, std::size_t plan_count) {
    if (points.size() > plan_count) {
        throw CsvError(
            points[plan_count].line, "",
            comparison_message(
                "more_points_than_plan",
                QT_TRANSLATE_NOOP("Comparison",
                                  "point %1 has no plan point: the file has %2 points, the plan "
                                  "%3"),
                {arg("point", ArgKind::integer, static_cast<double>(plan_count + 1)),
                 arg("points", ArgKind::integer, static_cast<double>(points.size())),
                 arg("plan_points", ArgKind::integer, static_cast<double>(plan_count))}));
    }
    if (points.size() < plan_count) {
        throw CsvError(
            points.empty() ? 0 : points.back().line, "",
            comparison_message(
                "fewer_points_than_plan",
                QT_TRANSLATE_NOOP("Comparison",
                                  "the file ends after %1 points; the plan has %2 (one "
                                  "measured point per plan point, in the plan's order)"),
                {arg("points", ArgKind::integer, static_cast<double>(points.size())),
                 arg("plan_points", ArgKind::integer, static_cast<double>(plan_count))}));
    }
}

std::vector<BlockTouch> parse_block(std::string_view text) {
    const std::vector<CsvRow> rows = read_csv_rows(text, {"face", "x_mm", "y_mm", "z_mm"});
    std::vector<BlockTouch> touches;
    std::array<std::size_t, 3> count{};
    for (const CsvRow& row : rows) {
        const std::string face = upper(row.fields[0]);
        BlockTouch touch;
        touch.line = row.line;
        if (face == "A") {
            touch.face = BlockFace::a;
        } else if (face == "B") {
            touch.face = BlockFace::b;
        } else if (face == "C") {
            touch.face = BlockFace::c;
        } else {
            throw CsvError(row.line, "face",
                           comparison_message("unknown_face",
                                              QT_TRANSLATE_NOOP("Comparison",
                                                                "'%1' is not a face; allowed: A, "
                                                                "B, C"),
                                              {text_arg("value", row.fields[0])}));
        }
        touch.point = {csv_coordinate(row, 1, "x_mm"), csv_coordinate(row, 2, "y_mm"),
                       csv_coordinate(row, 3, "z_mm")};
        ++count[static_cast<std::size_t>(touch.face)];
        touches.push_back(touch);
    }
    for (const BlockFace face : {BlockFace::a, BlockFace::b, BlockFace::c}) {
        const std::size_t n = count[static_cast<std::size_t>(face)];
        if (n < kMinFaceTouches) {
            throw CsvError(
                rows.back().line, "face",
                comparison_message(
                    "face_too_few_touches",
                    QT_TRANSLATE_NOOP("Comparison",
                                      "touches on face %1: %2; each face needs %3 or "
                                      "more (typically 6)"),
                    {text_arg("face", to_string(face)),
                     arg("touches", ArgKind::integer, static_cast<double>(n)),
                     arg("required", ArgKind::integer, static_cast<double>(kMinFaceTouches))}));
        }
    }
    return touches;
}

}  // namespace probecycle
