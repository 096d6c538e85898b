#include "core/cycle/cycle_report.h"
#include "core/common/file_io.h"

#include <gtest/gtest.h>
#ifndef _WIN32
#include <unistd.h>
#endif

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/csv_writer.h"
#include "core/common/report_header.h"
#include "core/common/units.h"
#include "core/cycle/cycle.h"
#include "core/cycle/scenario.h"
#include "core/cycle/sweep.h"

namespace probecycle {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> out;
    std::string item;
    std::istringstream in(text);
    while (std::getline(in, item, sep)) out.push_back(item);
    return out;
}

// The fields of one CSV row, an empty last field included ("a,true," has three).
std::vector<std::string> fields_of(const std::string& row) {
    std::vector<std::string> out(1);
    for (char ch : row) {
        if (ch == ',') {
            out.emplace_back();
        } else {
            out.back() += ch;
        }
    }
    return out;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out = split(text, '\n');
    for (std::string& line : out) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
    }
    return out;
}

double to_number(const std::string& field) {
    std::size_t used = 0;
    const double value = std::stod(field, &used);
    EXPECT_EQ(used, field.size()) << "'" << field << "'";
    return value;
}

Scenario two_touch_with_warnings() {
    Scenario s;
    s.cycle.strategy = Strategy::two_touch;
    s.cycle.probe_feed_mm_min = 3000.0;
    s.cycle.backoff_mm = 5.0;                // backoff_excess
    s.cycle.target_uncertainty_mm = 0.0005;  // uncertainty_over_target
    return s;
}

// ---------------------------------------------------------------------------
// evaluate JSON

TEST(EvaluationJson, KeysAndValuesOfTheAnalysis) {
    const Scenario s = two_touch_with_warnings();
    const Analysis a = analyse(s);
    const nlohmann::json j = nlohmann::json::parse(evaluation_to_json(s, a));
    for (const char* key : {"cycle_time_s", "overtravel_mm", "trigger_speed_mm_min",
                            "uncertainty_mm", "recommended_backoff_mm"}) {
        ASSERT_TRUE(j.contains(key)) << key;
        ASSERT_TRUE(j[key].is_number()) << key;
    }
    const CycleResult& r = a.cycle;
    EXPECT_NEAR(j["cycle_time_s"].get<double>(), r.total(), 1e-9 * r.total());
    EXPECT_NEAR(j["overtravel_mm"].get<double>(), r.overtravel_mm(), 1e-9);
    EXPECT_NEAR(j["trigger_speed_mm_min"].get<double>(), mm_s_to_mm_min(r.trigger_speed_mm_s()),
                1e-9);
    EXPECT_NEAR(j["uncertainty_mm"].get<double>(), r.uncertainty_mm(), 1e-12);
    EXPECT_NEAR(j["recommended_backoff_mm"].get<double>(), r.recommended_backoff_mm(), 1e-9);

    ASSERT_TRUE(j["phases"].is_array());
    ASSERT_EQ(j["phases"].size(), r.phases().size());
    double sum = 0.0;
    for (std::size_t k = 0; k < r.phases().size(); ++k) {
        const nlohmann::json& p = j["phases"][k];
        EXPECT_EQ(p["name"], to_string(r.phases()[k].phase));
        EXPECT_NEAR(p["start_s"].get<double>(), r.phases()[k].start_s, 1e-9);
        EXPECT_NEAR(p["time_s"].get<double>(), r.phases()[k].time_s, 1e-9);
        EXPECT_NEAR(p["distance_mm"].get<double>(), r.phases()[k].distance_mm, 1e-9);
        sum += p["time_s"].get<double>();
    }
    EXPECT_NEAR(sum, j["cycle_time_s"].get<double>(), 1e-9);

    ASSERT_TRUE(j["warnings"].is_array());
    ASSERT_EQ(j["warnings"].size(), r.warnings().size());
    std::set<std::string> codes;
    for (std::size_t k = 0; k < r.warnings().size(); ++k) {
        const nlohmann::json& w = j["warnings"][k];
        EXPECT_EQ(w["code"], to_string(r.warnings()[k].code));
        EXPECT_EQ(w["severity"], to_string(r.warnings()[k].severity));
        EXPECT_EQ(w["message"], r.warnings()[k].message());
        codes.insert(w["code"].get<std::string>());
    }
    EXPECT_TRUE(codes.count("backoff_excess"));
    EXPECT_TRUE(codes.count("uncertainty_over_target"));
}

// A warning with a one-click fix carries the keys the window's button sets;
// one without, none. A touch's number is a whole number.
TEST(EvaluationJson, AWarningWithAFixNamesTheKeysItSets) {
    const Scenario s = two_touch_with_warnings();  // 5 mm backoff: backoff_excess
    const Analysis a = analyse(s);
    const nlohmann::json j = nlohmann::json::parse(evaluation_to_json(s, a));
    bool seen = false;
    for (const nlohmann::json& w : j["warnings"]) {
        if (w["code"] == "backoff_excess") {
            ASSERT_TRUE(w.contains("fix")) << w.dump();
            EXPECT_EQ(w["fix"],
                      nlohmann::json({{"cycle.backoff_mm", a.cycle.recommended_backoff_mm()}}));
            seen = true;
        }
        if (w["code"] == "uncertainty_over_target") {
            EXPECT_FALSE(w.contains("fix"));
        }
    }
    EXPECT_TRUE(seen);
    Scenario faster = s;  // a second touch faster than the first: its number, 2
    faster.cycle.probe_feed_mm_min = 300.0;
    faster.cycle.measure_feed_mm_min = 3000.0;
    faster.cycle.backoff_mm = evaluate(faster).recommended_backoff_mm();
    faster.cycle.search_beyond_mm = 1.0;
    faster.cycle.feed_override_max_pct = 100.0;  // the touches at their programmed feeds
    faster.cycle.backoff_mm = evaluate(faster).recommended_backoff_mm();
    const nlohmann::json k = nlohmann::json::parse(evaluation_to_json(faster, analyse(faster)));
    bool numbered = false;
    for (const nlohmann::json& w : k["warnings"]) {
        if (w["code"] != "search_ends_too_soon") continue;
        EXPECT_TRUE(w["values"]["touch"].is_number_integer()) << w.dump();
        EXPECT_EQ(w["values"]["touch"], 2);
        EXPECT_EQ(w["fix"], nlohmann::json({{"cycle.search_beyond_mm", 1.91}}));
        numbered = true;
    }
    EXPECT_TRUE(numbered) << k.dump(2);
}

TEST(EvaluationJson, NoWarningsIsAnEmptyArray) {
    Scenario s;
    s.cycle.strategy = Strategy::single_touch;
    s.cycle.probe_feed_mm_min = 300.0;
    const Analysis a = analyse(s);
    ASSERT_TRUE(a.cycle.warnings().empty());
    const nlohmann::json j = nlohmann::json::parse(evaluation_to_json(s, a));
    ASSERT_TRUE(j["warnings"].is_array());
    EXPECT_TRUE(j["warnings"].empty());
}

TEST(EvaluationJson, ValidAndTheReasonsWhenNot) {
    Scenario s;  // two-touch, 2 mm backoff: enough at 2000 mm/min
    nlohmann::json j = nlohmann::json::parse(evaluation_to_json(s, analyse(s)));
    EXPECT_EQ(j["valid"], true);
    EXPECT_EQ(j["invalid_reasons"], nlohmann::json::array());
    s.cycle.backoff_mm = 0.5;
    j = nlohmann::json::parse(evaluation_to_json(s, analyse(s)));
    EXPECT_EQ(j["valid"], false);
    EXPECT_EQ(j["invalid_reasons"], nlohmann::json::array({"backoff_too_small"}));
    // The time is still given (what the model computes), but flagged.
    EXPECT_TRUE(j["cycle_time_s"].is_number());
    const std::string report = csv_report(s, ReportHeader{});
    EXPECT_NE(report.find("\nvalid,false,\ninvalid_reasons,backoff_too_small,\n"),
              std::string::npos);
}

// ---------------------------------------------------------------------------
// Sweep CSV

TEST(SweepCsv, HeaderThenOneRowPerFeed) {
    Scenario s;
    const std::vector<double> feeds = linear_feeds(100.0, 3000.0, 100.0);
    const SweepResult sweep = sweep_feeds(s, feeds);
    std::vector<std::string> lines = lines_of(sweep_to_csv(sweep));
    while (!lines.empty() && lines.back().empty()) lines.pop_back();
    ASSERT_EQ(lines.size(), feeds.size() + 1);

    const std::vector<std::string> header = fields_of(lines[0]);
    ASSERT_EQ(header.size(), 8 + kPhaseCount);
    EXPECT_EQ(header[7 + kPhaseCount], "feed_reached");
    EXPECT_EQ(header[5 + kPhaseCount], "valid");
    EXPECT_EQ(header[6 + kPhaseCount], "invalid_reasons");
    EXPECT_EQ(header[0], "feed_mm_min");
    EXPECT_EQ(header[1], "cycle_time_s");
    EXPECT_EQ(header[2], "overtravel_mm");
    EXPECT_EQ(header[3], "checked_overtravel_mm");
    EXPECT_EQ(header[4], "uncertainty_mm");
    // One column per phase, in canonical order, named after it.
    for (std::size_t k = 0; k < kPhaseCount; ++k) {
        const std::string name = to_string(all_phases()[k]);
        EXPECT_EQ(header[5 + k].rfind(name, 0), 0u) << header[5 + k] << " vs " << name;
    }

    for (std::size_t i = 0; i < feeds.size(); ++i) {
        const std::vector<std::string> fields = fields_of(lines[i + 1]);
        ASSERT_EQ(fields.size(), header.size()) << lines[i + 1];
        const SweepPoint& p = sweep.points[i];
        // Rounded to the reports' resolution (csv_writer.h): 0.1 mm/min, 1 us, 0.1 um.
        constexpr double half_feed = 0.05 + 1e-9;
        constexpr double half_time = 0.5e-6 + 1e-12;
        constexpr double half_length = 0.5e-4 + 1e-12;
        EXPECT_NEAR(to_number(fields[0]), p.feed_mm_min, half_feed);
        EXPECT_NEAR(to_number(fields[1]), p.cycle_time_s, half_time);
        EXPECT_NEAR(to_number(fields[2]), p.overtravel_mm, half_length);
        EXPECT_NEAR(to_number(fields[3]), p.checked_overtravel_mm, half_length);
        EXPECT_NEAR(to_number(fields[4]), p.uncertainty_mm, half_length);
        for (std::size_t k = 0; k < kPhaseCount; ++k) {
            EXPECT_NEAR(to_number(fields[5 + k]), p.phase_time_s[k], half_time);
        }
        EXPECT_EQ(fields[5 + kPhaseCount], p.valid() ? "true" : "false");
        EXPECT_EQ(fields[6 + kPhaseCount], invalid_codes_text(p.invalid_codes, ";"));
        EXPECT_EQ(fields[7 + kPhaseCount], p.feed_reached ? "true" : "false");
    }
    // The 2 mm backoff is too small from about 2850 mm/min on: those rows say so.
    EXPECT_EQ(fields_of(lines.back())[5 + kPhaseCount], "false");
    EXPECT_EQ(fields_of(lines.back())[6 + kPhaseCount], "backoff_too_small");
    EXPECT_EQ(fields_of(lines[1])[5 + kPhaseCount], "true");
}

TEST(SweepCsv, EmptySweepIsTheHeaderAlone) {
    std::vector<std::string> lines = lines_of(sweep_to_csv(SweepResult{}));
    while (!lines.empty() && lines.back().empty()) lines.pop_back();
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(
        lines[0].rfind(
            "feed_mm_min,cycle_time_s,overtravel_mm,checked_overtravel_mm,uncertainty_mm,", 0),
        0u);
}

TEST(SweepSummary, OneLineNamingTheKneeAndTheFeedMeetingTheTarget) {
    // Single touch, 4 ms scan: 1200 mm/min is the fastest within 0.05 mm.
    Scenario s;
    s.cycle.strategy = Strategy::single_touch;
    s.cycle.target_uncertainty_mm = 0.05;
    const SweepResult sweep = sweep_feeds(s, linear_feeds(100.0, 3000.0, 100.0));
    ASSERT_TRUE(sweep.knee_feed_mm_min.has_value());
    std::string summary = sweep_summary(sweep, s);
    while (!summary.empty() && summary.back() == '\n') summary.pop_back();
    EXPECT_FALSE(summary.empty());
    EXPECT_EQ(summary.find('\n'), std::string::npos) << summary;
    std::string lower = summary;
    for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    EXPECT_NE(lower.find("knee"), std::string::npos) << summary;
    EXPECT_NE(summary.find("1200"), std::string::npos) << summary;
    char knee[32];
    std::snprintf(knee, sizeof knee, "%.0f", *sweep.knee_feed_mm_min);
    EXPECT_NE(summary.find(knee), std::string::npos) << summary;
}

TEST(CsvReport, SectionsInOrder) {
    const Scenario s = two_touch_with_warnings();
    const Analysis a = analyse(s);
    const std::vector<double> feeds = linear_feeds(100.0, 3000.0, 100.0);
    const SweepResult sweep = sweep_feeds(s, feeds);
    const std::string report = csv_report(s, a, feeds, ReportHeader{.date = "2026-11-26"});
    EXPECT_EQ(report.rfind("# ProbeCycle cycle report\n# date,2026-11-26\n# version,", 0), 0U)
        << report.substr(0, 200);
    std::size_t at = 0;
    for (const char* section : {"# scenario", "# summary", "# phases", "# warnings", "# sweep"}) {
        const std::size_t found = report.find(section, at);
        ASSERT_NE(found, std::string::npos) << section;
        at = found;
    }
    // The sweep section is the sweep CSV, with the optimised curve of a
    // two-touch cycle beside it.
    ASSERT_EQ(s.cycle.strategy, Strategy::two_touch);
    const SweepResult optimised = sweep_feeds(s, feeds, {.recommended_backoff = true});
    EXPECT_NE(report.find(sweep_to_csv(sweep, &optimised)), std::string::npos);
    EXPECT_NE(report.find("backoff_excess"), std::string::npos);
    EXPECT_NE(report.find("machine.scan_period_s"), std::string::npos);
}

// The summary speaks evaluate's keys (docs/cli.md documents them), each value
// evaluate's rounded to the digits its unit gets in the reports.
TEST(CsvReport, SummaryHasEvaluatesKeysRoundedToTheModelsDigits) {
    for (Scenario s : {two_touch_with_warnings(), Scenario{}}) {
        if (s.cycle.backoff_mm < 3.0) s.cycle.backoff_mm = 0.5;  // invalid: backoff_too_small
        const Analysis a = analyse(s);
        const nlohmann::json j = nlohmann::json::parse(evaluation_to_json(s, a));
        const std::string report = csv_report(s, a, std::vector<double>{1000.0}, ReportHeader{});
        const std::size_t begin = report.find("# summary\nkey,value,unit\n");
        ASSERT_NE(begin, std::string::npos);
        const std::size_t end = report.find("\n\n", begin);
        const std::vector<std::string> rows = split(report.substr(begin, end - begin), '\n');
        std::set<std::string> keys;
        for (std::size_t i = 2; i < rows.size(); ++i) {
            const std::vector<std::string> f = fields_of(rows[i]);
            ASSERT_EQ(f.size(), 3U) << rows[i];
            keys.insert(f[0]);
            ASSERT_TRUE(j.contains(f[0])) << f[0] << " is not a key of evaluate";
            const nlohmann::json& v = j[f[0]];
            if (v.is_null()) {
                EXPECT_EQ(f[1], "") << f[0];
            } else if (v.is_boolean()) {
                EXPECT_EQ(f[1], v.get<bool>() ? "true" : "false") << f[0];
            } else if (v.is_string()) {
                EXPECT_EQ(f[1], v.get<std::string>()) << f[0];
            } else if (v.is_array()) {
                std::string joined;
                for (const auto& code : v)
                    joined += (joined.empty() ? "" : ";") + code.get<std::string>();
                EXPECT_EQ(f[1], joined) << f[0];
            } else {
                const double value = v.get<double>();
                const std::string want = f[2] == "s"    ? csv_time_s(value)
                                         : f[2] == "mm" ? csv_length_mm(value)
                                                        : csv_feed_mm_min(value);
                EXPECT_EQ(f[1], want) << f[0];
                // No more digits than the unit's resolution.
                const std::size_t dot = f[1].find('.');
                const std::size_t decimals = dot == std::string::npos ? 0 : f[1].size() - dot - 1;
                EXPECT_LE(decimals, f[2] == "s" ? 6U : f[2] == "mm" ? 4U : 1U) << f[0];
            }
        }
        std::set<std::string> want;
        for (const auto& [key, value] : j.items()) {
            // The phases, the warnings and the touches have tables of their own.
            if (key != "phases" && key != "warnings" && !value.is_object()) want.insert(key);
        }
        EXPECT_EQ(keys, want);
    }
}

// ---------------------------------------------------------------------------
// Files

class AtomicFile : public testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("probecycle_report_test_" + std::to_string(std::random_device{}()) + "_" +
                testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    static std::string slurp(const fs::path& path) {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream out;
        out << in.rdbuf();
        return out.str();
    }
    std::vector<std::string> listing() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir_)) {
            names.push_back(entry.path().filename().string());
        }
        std::sort(names.begin(), names.end());
        return names;
    }

    fs::path dir_;
};

TEST_F(AtomicFile, WritesTheCompleteContent) {
    std::string big;
    for (int i = 0; i < 200000; ++i) big += "line " + std::to_string(i) + ",1.5\n";
    big.push_back('\0');  // binary-safe
    big += "tail";
    const fs::path path = dir_ / "out.csv";
    write_file_atomically(path.string(), big);
    EXPECT_EQ(slurp(path), big);
    EXPECT_EQ(read_text_file(path.string()), big);
    EXPECT_EQ(listing(), std::vector<std::string>{"out.csv"});  // no temporary left behind
}

TEST_F(AtomicFile, ReplacesAnExistingFile) {
    const fs::path path = dir_ / "out.csv";
    write_file_atomically(path.string(), "old content that is longer than the new\n");
    write_file_atomically(path.string(), "new\n");
    EXPECT_EQ(slurp(path), "new\n");
    write_file_atomically(path.string(), "");
    EXPECT_EQ(slurp(path), "");
    EXPECT_EQ(listing(), std::vector<std::string>{"out.csv"});
}

TEST_F(AtomicFile, MissingDirectoryThrowsAndCreatesNothing) {
    const fs::path path = dir_ / "missing" / "out.csv";
    EXPECT_THROW(write_file_atomically(path.string(), "content"), std::runtime_error);
    EXPECT_FALSE(fs::exists(dir_ / "missing"));
    EXPECT_TRUE(listing().empty());
}

TEST_F(AtomicFile, TargetThatCannotBeReplacedKeepsItsOldContent) {
    // A directory in the way of the target: the rename fails.
    const fs::path target = dir_ / "out.csv";
    fs::create_directories(target);
    std::ofstream(target / "keep.txt") << "old";
    EXPECT_THROW(write_file_atomically(target.string(), "new"), std::runtime_error);
    EXPECT_TRUE(fs::is_directory(target));
    EXPECT_EQ(slurp(target / "keep.txt"), "old");
    EXPECT_EQ(listing(), std::vector<std::string>{"out.csv"});  // the temporary is cleaned up
}

#ifndef _WIN32  // POSIX permissions
TEST_F(AtomicFile, ReadOnlyDirectoryKeepsTheOldFile) {
    if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
    const fs::path path = dir_ / "out.csv";
    write_file_atomically(path.string(), "old");
    fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec);
    EXPECT_THROW(write_file_atomically(path.string(), "new"), std::runtime_error);
    fs::permissions(dir_, fs::perms::owner_all);
    EXPECT_EQ(slurp(path), "old");
}
#endif

#ifndef _WIN32  // POSIX permissions
TEST_F(AtomicFile, KeepsTheModeOfTheFileItReplaces) {
    const fs::path path = dir_ / "out.csv";
    write_file_atomically(path.string(), "old\n");
    EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                  fs::perms::others_read);  // 0644 for a new file
    fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
    write_file_atomically(path.string(), "new\n");
    EXPECT_EQ(slurp(path), "new\n");
    EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write);
}
#endif

#ifndef _WIN32  // symbolic links need privileges on Windows
TEST_F(AtomicFile, WritesThroughASymbolicLink) {
    const fs::path target = dir_ / "real.json";
    const fs::path link = dir_ / "link.json";
    write_file_atomically(target.string(), "old\n");
    fs::create_symlink(target, link);
    write_file_atomically(link.string(), "new\n");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(slurp(target), "new\n");
    EXPECT_EQ(listing(), (std::vector<std::string>{"link.json", "real.json"}));
}
#endif

TEST_F(AtomicFile, ReadTextFileOfAMissingFileNamesThePath) {
    const fs::path path = dir_ / "nope.json";
    try {
        read_text_file(path.string());
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace probecycle
