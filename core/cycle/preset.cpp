#include "core/cycle/preset.h"

#include <nlohmann/json.hpp>

namespace probecycle {

namespace {

using Json = nlohmann::ordered_json;

std::string text_of(const Json& block, const char* key) {
    const auto it = block.find(key);
    if (it == block.end() || !it->is_string() || it->get<std::string>().empty()) {
        throw PresetError(std::string("preset.") + key + ": a text is required");
    }
    return it->get<std::string>();
}

}  // namespace

Preset parse_preset(std::string_view text) {
    Json json = Json::parse(text.begin(), text.end(), nullptr, false);
    if (json.is_discarded() || !json.is_object()) {
        throw PresetError("a preset is a JSON object of scenario sections and a \"preset\" block");
    }
    const auto block = json.find("preset");
    if (block == json.end() || !block->is_object()) {
        throw PresetError("preset: a block with title, description and order is required");
    }
    Preset preset;
    preset.title = text_of(*block, "title");
    preset.description = text_of(*block, "description");
    const auto order = block->find("order");
    if (order == block->end() || !order->is_number_integer() || order->get<int>() < 1 ||
        order->get<int>() > 99) {
        throw PresetError("preset.order: a whole number from 1 to 99 is required");
    }
    preset.order = order->get<int>();
    json.erase("preset");
    preset.machine = json.contains("machine");
    preset.scenario_json = json.dump(2);
    return preset;
}

}  // namespace probecycle
