#include "core/comparison/comparison_files.h"

#include <utility>

#include "core/common/csv_reader.h"
#include "core/common/file_io.h"
#include "core/comparison/comparison_report.h"

namespace probecycle {

namespace {

// Reads the file whole and parses it; a refusal of its content names it.
template <typename Parse>
auto read_file(ComparisonFile which, const std::string& path, Parse parse) {
    const std::string text = read_text_file(path);
    try {
        return parse(text);
    } catch (const CsvError& e) {
        throw ComparisonFileError(ComparisonFileError::Problem::refused, which, path,
                                  std::current_exception(), path + ": " + e.what());
    } catch (const std::invalid_argument& e) {
        throw ComparisonFileError(ComparisonFileError::Problem::refused, which, path,
                                  std::current_exception(), path + ": " + e.what());
    }
}

}  // namespace

const char* to_string(ComparisonFile file) {
    switch (file) {
        case ComparisonFile::plan:
            return "plan";
        case ComparisonFile::reference_cmm:
            return "reference_cmm";
        case ComparisonFile::test_omm:
            return "test_omm";
        case ComparisonFile::reference_omm:
            return "reference_omm";
        case ComparisonFile::block_c0:
            return "block_c0";
        case ComparisonFile::block_c180:
            return "block_c180";
    }
    return "?";
}

const char* example_file_name(ComparisonFile file) {
    switch (file) {
        case ComparisonFile::plan:
            return "plan.csv";
        case ComparisonFile::reference_cmm:
            return "reference_cmm.csv";
        case ComparisonFile::test_omm:
            return "test_omm.csv";
        case ComparisonFile::reference_omm:
            return "reference_omm.csv";
        case ComparisonFile::block_c0:
            return "block_c0.csv";
        case ComparisonFile::block_c180:
            return "block_c180.csv";
    }
    return "?";
}

const std::string& ComparisonFiles::path(ComparisonFile file) const {
    switch (file) {
        case ComparisonFile::plan:
            return plan;
        case ComparisonFile::reference_cmm:
            return reference_cmm;
        case ComparisonFile::test_omm:
            return test_omm;
        case ComparisonFile::reference_omm:
            return reference_omm;
        case ComparisonFile::block_c0:
            return block_c0;
        case ComparisonFile::block_c180:
            break;
    }
    return block_c180;
}

ComparisonFileError::ComparisonFileError(Problem problem, ComparisonFile file, std::string path,
                                         std::exception_ptr cause, const std::string& what)
    : std::runtime_error(what),
      problem_(problem),
      file_(file),
      path_(std::move(path)),
      cause_(std::move(cause)) {}

bool blocks_paired(const ComparisonFiles& files) {
    return files.block_c0.empty() == files.block_c180.empty();
}

ComparisonInput read_comparison_files(const ComparisonFiles& files) {
    for (ComparisonFile which : {ComparisonFile::plan, ComparisonFile::reference_cmm,
                                 ComparisonFile::test_omm, ComparisonFile::reference_omm}) {
        if (files.path(which).empty()) {
            throw ComparisonFileError(ComparisonFileError::Problem::not_given, which, {}, {},
                                      std::string("no file given for ") + to_string(which));
        }
    }
    if (!blocks_paired(files)) {
        const ComparisonFile missing =
            files.block_c0.empty() ? ComparisonFile::block_c0 : ComparisonFile::block_c180;
        throw ComparisonFileError(
            ComparisonFileError::Problem::one_block, missing, {}, {},
            "the block is needed at both angles: give both block files, or neither");
    }
    ComparisonInput input;
    input.plan = read_file(ComparisonFile::plan, files.plan,
                           [](const std::string& text) { return parse_plan(text); });
    const auto points = [&input, &files](ComparisonFile which) {
        return read_file(which, files.path(which), [&input](const std::string& text) {
            return parse_points_for_plan(text, input.plan);
        });
    };
    input.reference_cmm = points(ComparisonFile::reference_cmm);
    input.test_omm = points(ComparisonFile::test_omm);
    input.reference_omm = points(ComparisonFile::reference_omm);
    if (!files.block_c0.empty()) {
        input.block_at_zero = read_block_file(ComparisonFile::block_c0, files.block_c0);
        input.block_turned = read_block_file(ComparisonFile::block_c180, files.block_c180);
    }
    return input;
}

std::vector<BlockTouch> read_block_file(ComparisonFile which, const std::string& path) {
    return read_file(which, path, [](const std::string& text) { return parse_block(text); });
}

std::vector<ComparisonExampleFile> comparison_example_files(const ComparisonDataSet& data) {
    const ComparisonInput& in = data.input;
    return {
        {example_file_name(ComparisonFile::plan), plan_csv(in.plan)},
        {example_file_name(ComparisonFile::reference_cmm), points_csv(in.reference_cmm)},
        {example_file_name(ComparisonFile::test_omm), points_csv(in.test_omm)},
        {example_file_name(ComparisonFile::reference_omm), points_csv(in.reference_omm)},
        {example_file_name(ComparisonFile::block_c0), block_csv(in.block_at_zero)},
        {example_file_name(ComparisonFile::block_c180), block_csv(in.block_turned)},
        {"truth.csv", truth_csv(in.plan, data.truth_mm)},
    };
}

}  // namespace probecycle
