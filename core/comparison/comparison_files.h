#pragma once

// The comparison's input as files: the six files read into a
// ComparisonInput (`compare run` and the Comparison tab), a block file alone
// (`compare cerrors`), and the example data set as named files (`compare
// simulate` and the tab's "Simulate example data"). The parsing is
// comparison_input.h's; this adds the reading and names the file in every
// refusal.

#include <cstddef>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/comparison/comparison.h"
#include "core/comparison/comparison_input.h"
#include "core/comparison/comparison_simulator.h"

namespace probecycle {

// The input files, in the order they are read, listed and written.
enum class ComparisonFile { plan, reference_cmm, test_omm, reference_omm, block_c0, block_c180 };
constexpr std::size_t kComparisonFiles = 6;

// "plan", "reference_cmm", ... (the project file's keys).
const char* to_string(ComparisonFile file);
// "plan.csv", "reference_cmm.csv", ... (the example's files).
const char* example_file_name(ComparisonFile file);

// The files' paths; an empty path is a file not given. The four point files
// are needed, the two block files are optional: both or neither.
struct ComparisonFiles {
    std::string plan;
    std::string reference_cmm;
    std::string test_omm;
    std::string reference_omm;
    std::string block_c0;
    std::string block_c180;

    const std::string& path(ComparisonFile file) const;
};

// Why the files are not a comparison's input, naming the file:
// - not_given: a needed file's path is empty;
// - one_block: one block file without the other (file(): the one missing);
// - refused: the file's content was refused; cause() is the parser's
//   exception (a CsvError naming the line and the column, or a
//   std::invalid_argument), what() is "PATH: " and the cause's text.
class ComparisonFileError : public std::runtime_error {
  public:
    enum class Problem { not_given, one_block, refused };

    ComparisonFileError(Problem problem, ComparisonFile file, std::string path,
                        std::exception_ptr cause, const std::string& what);
    Problem problem() const { return problem_; }
    ComparisonFile file() const { return file_; }
    const std::string& path() const { return path_; }
    std::exception_ptr cause() const { return cause_; }

  private:
    Problem problem_;
    ComparisonFile file_;
    std::string path_;
    std::exception_ptr cause_;
};

// True when both block files are given or neither.
bool blocks_paired(const ComparisonFiles& files);

// Reads every file given, in ComparisonFile's order, and parses it: the plan
// (parse_plan), the three point files against it (parse_points_for_plan),
// the blocks (parse_block). The input's C axis and tolerance stay at their
// defaults. Before any file is opened, ComparisonFileError for a needed file
// not given or a lone block file; then FileError (it names the path) for a
// file that cannot be read, ComparisonFileError (refused) for one whose
// content is refused.
ComparisonInput read_comparison_files(const ComparisonFiles& files);
// One block file, read and refused as read_comparison_files does.
std::vector<BlockTouch> read_block_file(ComparisonFile which, const std::string& path);

// One file of the example data set.
struct ComparisonExampleFile {
    std::string name;  // example_file_name(), or "truth.csv"
    std::string text;
};
// The data set's six input files in ComparisonFile's order, then truth.csv
// (the test part's true deviation per plan point).
std::vector<ComparisonExampleFile> comparison_example_files(const ComparisonDataSet& data);

}  // namespace probecycle
