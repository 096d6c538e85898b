#pragma once

// The presets the window offers: every resources/presets/*.json embedded as
// :/presets/, read once (core/cycle/preset.h). Their titles and descriptions
// live in the files; the build lists them for lupdate (context "Preset").

#include <QList>
#include <QString>
#include <string>

#include "core/cycle/preset.h"

namespace probecycle::ui {

struct PresetEntry {
    QString path;  // ":/presets/machine_linuxcnc.json"
    Preset preset;
};

// Machine presets first, then probe presets, each in its files' order. A
// file that cannot be read is left out (the tests read every one).
const QList<PresetEntry>& preset_list();

// The entry of `path`, or nullptr.
const PresetEntry* find_preset(const QString& path);

// A preset's title and description in the interface's language.
QString preset_title(const Preset& preset);
QString preset_description(const Preset& preset);

}  // namespace probecycle::ui
