#pragma once

// How the window presents each scenario key: translated label and help,
// display unit (the UI is an edge where units may be converted), decimals,
// and the slider a key gets, if any. Ranges come from the core's key table.

#include <QString>
#include <optional>
#include <string_view>

#include "core/cycle/scenario.h"

namespace probecycle::ui {

enum class SliderScale { none, linear, log };

struct ParameterView {
    QString key;         // dotted core key
    QString label;       // translated, short
    QString help;        // translated: what it is and how it enters the model
    QString unit;        // translated display unit
    double factor{1.0};  // display value = internal value * factor
    int decimals{3};
    double min{0.0};  // internal units, from the core's key table
    double max{0.0};
    SliderScale slider{SliderScale::none};
    double slider_min{0.0};  // internal units; within [min, max]
    double slider_max{0.0};
    QString zero_text;  // shown instead of 0 when 0 has a meaning ("none")
};

// Presentation of a numeric key (every key of numeric_keys() has one; keys
// this table does not know fall back to the core's unit and description).
ParameterView parameter_view(const KeyInfo& info);

// The section a dotted key belongs to: "machine", "probe" or "cycle".
QString section_of(std::string_view dotted_key);

// Translated names of the enum values and sections.
QString accel_model_label(AccelModel model);
QString filter_label(FilterKind kind);
QString strategy_label(Strategy strategy);
QString backoff_from_label(BackoffFrom from);
QString tolerance_action_label(ToleranceAction action);
QString feature_label(Feature feature);
QString section_label(const QString& section);

// Unit words used by readouts (so "mm" is translated in one place).
QString unit_mm();
QString unit_um();
QString unit_s();
QString unit_ms();
QString unit_mm_min();

}  // namespace probecycle::ui
