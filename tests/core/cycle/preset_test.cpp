// core/cycle/preset.h: the presets' files, their "preset" block and what a
// malformed one is told.

#include "core/cycle/preset.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "core/cycle/scenario.h"

namespace probecycle {
namespace {

std::string slurp(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Every preset shipped: a title, a description, a place in its menu of its
// own; a machine preset sets machine keys and a probe preset probe keys, and
// each applies to the default scenario (two of them are the defaults).
TEST(Preset, EveryShippedPresetHasItsTextsAndApplies) {
    const auto dir = std::filesystem::path(PROBECYCLE_RESOURCES_DIR) / "presets";
    std::set<std::pair<bool, int>> places;
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        SCOPED_TRACE(entry.path().filename().string());
        const Preset preset = parse_preset(slurp(entry.path()));
        ++count;
        EXPECT_FALSE(preset.title.empty());
        EXPECT_GT(preset.description.size(), preset.title.size());
        EXPECT_EQ(preset.machine, entry.path().filename().string().rfind("machine_", 0) == 0);
        EXPECT_TRUE(places.insert({preset.machine, preset.order}).second) << "order taken twice";
        EXPECT_EQ(preset.scenario_json.find("\"preset\""), std::string::npos);
        const Scenario applied = merge_json(Scenario{}, preset.scenario_json);
        EXPECT_TRUE(validate(applied).empty());
        EXPECT_NE(preset.scenario_json.find(preset.machine ? "\"machine\"" : "\"probe\""),
                  std::string::npos);
    }
    EXPECT_GE(count, 11);
}

TEST(Preset, TheBlockIsTakenOutAndTheRestKept) {
    const Preset p =
        parse_preset(R"({"preset": {"title": "T", "description": "What it is", "order": 2},)"
                     R"( "probe": {"pretravel_mm": 0.01}})");
    EXPECT_EQ(p.title, "T");
    EXPECT_EQ(p.description, "What it is");
    EXPECT_EQ(p.order, 2);
    EXPECT_FALSE(p.machine);
    EXPECT_EQ(merge_json(Scenario{}, p.scenario_json).probe.pretravel_mm, 0.01);
}

TEST(Preset, AMalformedPresetIsRefusedWithTheKeyNamed) {
    const struct {
        const char* text;
        const char* names;
    } cases[] = {
        {"[1, 2]", "JSON object"},
        {"{not json", "JSON object"},
        {R"({"probe": {}})", "preset: a block"},
        {R"({"preset": 3})", "preset: a block"},
        {R"({"preset": {"description": "d", "order": 1}})", "preset.title"},
        {R"({"preset": {"title": "", "description": "d", "order": 1}})", "preset.title"},
        {R"({"preset": {"title": "t", "order": 1}})", "preset.description"},
        {R"({"preset": {"title": "t", "description": "d"}})", "preset.order"},
        {R"({"preset": {"title": "t", "description": "d", "order": 0}})", "1 to 99"},
        {R"({"preset": {"title": "t", "description": "d", "order": 1.5}})", "preset.order"},
        {R"({"preset": {"title": "t", "description": "d", "order": 100}})", "1 to 99"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.text);
        try {
            parse_preset(c.text);
            ADD_FAILURE() << "accepted";
        } catch (const PresetError& e) {
            EXPECT_NE(std::string(e.what()).find(c.names), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace probecycle
