#include "ui/window/preset_list.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <algorithm>

namespace probecycle::ui {

namespace {

QList<PresetEntry> read_presets() {
    QList<PresetEntry> list;
    const QDir dir(QStringLiteral(":/presets"));
    for (const QString& name : dir.entryList({QStringLiteral("*.json")}, QDir::Files)) {
        QFile file(dir.filePath(name));
        if (!file.open(QIODevice::ReadOnly)) continue;
        try {
            list.append({file.fileName(), parse_preset(file.readAll().toStdString())});
        } catch (const PresetError&) {
            continue;
        }
    }
    std::stable_sort(list.begin(), list.end(), [](const PresetEntry& a, const PresetEntry& b) {
        if (a.preset.machine != b.preset.machine) return a.preset.machine;
        return a.preset.order < b.preset.order;
    });
    return list;
}

}  // namespace

const QList<PresetEntry>& preset_list() {
    static const QList<PresetEntry> list = read_presets();
    return list;
}

const PresetEntry* find_preset(const QString& path) {
    for (const PresetEntry& entry : preset_list()) {
        if (entry.path == path) return &entry;
    }
    return nullptr;
}

QString preset_title(const Preset& preset) {
    return QCoreApplication::translate("Preset", preset.title.c_str());
}

QString preset_description(const Preset& preset) {
    return QCoreApplication::translate("Preset", preset.description.c_str());
}

}  // namespace probecycle::ui
