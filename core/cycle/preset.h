#pragma once

// A preset: typical values for a kind of machine or probe, in a file of the
// scenario's format (resources/presets/*.json) that sets only the keys it
// names, plus a "preset" block that says what it is:
//   "preset": {"title": "...", "description": "...", "order": 3}
// The title and the description are English; the window translates them
// (context "Preset"). `order` places the preset in its menu (machine presets,
// the files with a "machine" section, first).

#include <stdexcept>
#include <string>
#include <string_view>

namespace probecycle {

struct Preset {
    std::string title;
    std::string description;
    int order{0};
    bool machine{false};        // sets machine keys (else probe keys)
    std::string scenario_json;  // the file without its "preset" block: merge_json() takes it
};

class PresetError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Reads a preset file; a file that is no JSON object, or whose "preset"
// block lacks a title, a description or an order from 1 to 99, is refused
// with a PresetError naming the key. The scenario keys are checked when the
// preset is applied (merge_json).
Preset parse_preset(std::string_view text);

}  // namespace probecycle
