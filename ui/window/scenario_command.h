#pragma once

// One undoable change of the scenario: the whole scenario before and after
// (a few hundred bytes), so every kind of edit undoes the same way. A slider
// drag is many edits of one key in a row; they merge into one step. Its text
// is built by a function, so that it can be built again in another language.

#include <QElapsedTimer>
#include <QString>
#include <QUndoCommand>
#include <functional>

#include "core/cycle/scenario.h"

namespace probecycle::ui {

class ScenarioCommand : public QUndoCommand {
  public:
    using Apply = std::function<void(const Scenario&)>;
    using Describe = std::function<QString()>;
    static constexpr int kNoMerge = -1;

    ScenarioCommand(Apply apply, const Scenario& before, const Scenario& after, Describe describe,
                    int merge_id = kNoMerge);

    // Builds the text again, in the language now in effect.
    void retranslate() { setText(describe_()); }

    void undo() override { apply_(before_); }
    void redo() override { apply_(after_); }
    int id() const override { return merge_id_; }
    bool mergeWith(const QUndoCommand* other) override;

    // A merge id per edited key, so edits of different keys stay separate steps.
    static int merge_id_for(const QString& key);

  private:
    Apply apply_;
    Describe describe_;
    Scenario before_;
    Scenario after_;
    int merge_id_;
    QElapsedTimer last_edit_;
};

}  // namespace probecycle::ui
