#pragma once

// Per-point tables in a report to read. The CSV export holds every row; the
// PDF report holds a table whole only while it stays a page or two, and
// beyond that what a reader needs: the count, the spread of the residuals and
// the rows that stand out (the largest residuals). Hundreds of thousands of
// rows are data to load into a spreadsheet, not pages to hand a customer.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace probecycle {

// Which rows a report's per-point tables hold.
enum class ReportRows {
    all,      // every row: the CSV export, the CLI's --report
    summary,  // whole up to kReportFullRows, else statistics and the largest residuals
};

// A per-point table up to this many rows stays whole in a summary.
inline constexpr std::size_t kReportFullRows = 50;
// Beyond it, the rows with the largest residuals, largest first.
inline constexpr std::size_t kReportLargestRows = 10;

// True when a table of `count` rows is summarised.
bool summarised(ReportRows rows, std::size_t count);

// Over the finite values (NaN stands for "no value" and is left out); a
// count of 0 leaves the rest 0. std_mm is the sample standard deviation
// (0 for one value).
struct ValueStats {
    std::size_t count{0};
    double min{0.0};
    double max{0.0};
    double mean{0.0};
    double std{0.0};
};

ValueStats value_stats(std::span<const double> values);

// The indices of the `n` finite values largest in magnitude, largest first;
// ties keep the earlier index first.
std::vector<std::size_t> largest_magnitudes(std::span<const double> values, std::size_t n);

// A statistics table of lengths: "quantity,count,min_mm,max_mm,mean_mm,std_mm"
// and one row per quantity, to 0.1 um (csv_writer.h).
std::string csv_stats_header();
std::string csv_stats_row(const std::string& quantity, const ValueStats& stats);

// The heading of the largest rows' table, "# <what>: the 10 largest |residual_mm| of 290000".
std::string csv_largest_heading(const std::string& what, const std::string& column,
                                std::size_t shown, std::size_t count);

}  // namespace probecycle
