#include "ui/window/scenario_command.h"

#include <QHash>

namespace probecycle::ui {

namespace {
// Edits of the same key further apart than this are separate undo steps.
constexpr qint64 kMergeWindow_ms = 1500;
}  // namespace

ScenarioCommand::ScenarioCommand(Apply apply, const Scenario& before, const Scenario& after,
                                 Describe describe, int merge_id)
    : apply_(std::move(apply)),
      describe_(std::move(describe)),
      before_(before),
      after_(after),
      merge_id_(merge_id) {
    retranslate();
    last_edit_.start();
}

bool ScenarioCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = static_cast<const ScenarioCommand*>(other);
    if (next->merge_id_ != merge_id_ || merge_id_ == kNoMerge) return false;
    if (last_edit_.elapsed() > kMergeWindow_ms) return false;
    after_ = next->after_;
    last_edit_.restart();
    return true;
}

int ScenarioCommand::merge_id_for(const QString& key) {
    // Non-negative and never kNoMerge.
    return static_cast<int>(qHash(key) & 0x3fffffffU);
}

}  // namespace probecycle::ui
