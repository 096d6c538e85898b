#pragma once

// The comparison's input files (docs/comparison.md, "Files"):
// - the inspection plan, x_mm,y_mm,z_mm,i,j,k: a nominal point and its unit
//   outward normal (the side the probe comes from) per line;
// - measured points, x_mm,y_mm,z_mm, one per plan point in the plan's order
//   (the reference's CMM points, the test part's and the reference's OMM
//   points);
// - a block's touches, face,x_mm,y_mm,z_mm, faces A, B and C.
// Points also read from DMIS output: every `PTMEAS/CART,x,y,z[,i,j,k]` line
// is a point (other DMIS statements are skipped), the plan needs i, j, k.
// A file with a PTMEAS statement is read as DMIS, any other as CSV.
// Every error is a CsvError naming the line and the column.

#include <Eigen/Core>
#include <cstddef>
#include <string_view>
#include <vector>

#include "core/common/message.h"

namespace probecycle {

struct PlanPoint {
    Eigen::Vector3d nominal{Eigen::Vector3d::Zero()};
    Eigen::Vector3d normal{Eigen::Vector3d::UnitZ()};  // unit, outward
    std::size_t line{0};
};

struct MeasuredPoint {
    Eigen::Vector3d point{Eigen::Vector3d::Zero()};
    std::size_t line{0};
};

// Faces of the block's corner.
enum class BlockFace { a, b, c };
const char* to_string(BlockFace face);  // "A", "B", "C"

struct BlockTouch {
    BlockFace face{BlockFace::a};
    Eigen::Vector3d point{Eigen::Vector3d::Zero()};
    std::size_t line{0};
};

// A normal's length may differ from 1 by this much (then it is normalised).
constexpr double kNormalLengthTolerance = 1e-3;
// A comparison needs this many points (a bicubic surface's 16 controls).
constexpr std::size_t kMinComparisonPoints = 16;
// And each face of the block this many touches.
constexpr std::size_t kMinFaceTouches = 3;

// The plan; CsvError for a missing column, a bad number, a normal that is
// not a unit vector, or fewer than kMinComparisonPoints points.
std::vector<PlanPoint> parse_plan(std::string_view text);
// Measured points; CsvError as the plan (the normal, if DMIS gives one, is
// not used).
std::vector<MeasuredPoint> parse_points(std::string_view text);
// CsvError unless there is one point per plan point: naming the first line
// beyond the plan's count, or the count the file is short of.
void check_point_count(const std::vector<MeasuredPoint>& points, std::size_t plan_count);
// A plan smaller than this is taken as this large for the check below.
constexpr double kMinPlanExtent_mm = 1.0;
// A point farther than this from its plan point is checked for being another's.
constexpr double kOrderCheckFrom_mm = 0.1;
// ... and is refused when another plan point is this many times nearer.
constexpr double kOrderCheckRatio = 3.0;
// CsvError at the point's line unless each point lies near its plan point:
// within the plan's extent (the diagonal of its bounding box, at least
// kMinPlanExtent_mm; a point 100 m away made the surface fit singular with
// no line named), and not much nearer another plan point than its own (the
// points out of the plan's order).
void check_points_follow_plan(const std::vector<MeasuredPoint>& points,
                              const std::vector<PlanPoint>& plan);
// parse_points(), check_point_count() and check_points_follow_plan(): the
// coordinates, one per plan point.
std::vector<Eigen::Vector3d> parse_points_for_plan(std::string_view text,
                                                   const std::vector<PlanPoint>& plan);
// "a comparison needs %2 points or more; got %1".
Message too_few_points(std::size_t points);
// A block's touches; CsvError for an unknown face or a face with fewer than
// kMinFaceTouches touches.
std::vector<BlockTouch> parse_block(std::string_view text);

}  // namespace probecycle
