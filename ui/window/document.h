#pragma once

// What the window has open: the scenario with its undo history, the file it
// came from (a scenario file or a project file), the pinned baseline's
// scenario, the pages that keep data of their own (the lab's and the
// comparison's, ui/common/page.h) and the PDF report's title block. It tells
// unsaved work: edits of the scenario since the file was saved, and for a
// project the pages' and the baseline's too, compared with what the file
// holds when a page says it changed.
//
// It knows nothing of widgets beyond the pages' interface: the window shows
// the scenario when scenario_changed() says so, and its title when
// modified_changed() does.

#include <QList>
#include <QObject>
#include <QString>
#include <QTimer>
#include <functional>
#include <optional>
#include <string>

#include "core/cycle/scenario.h"
#include "core/project/project_file.h"

class QUndoStack;

namespace probecycle::ui {

class Page;

class Document : public QObject {
    Q_OBJECT

  public:
    explicit Document(QObject* parent = nullptr);

    // --- The scenario ---
    const Scenario& scenario() const { return scenario_; }
    QUndoStack* undo_stack() const { return undo_; }
    // An undoable change of the whole scenario. `describe` builds the undo
    // step's text in the language in effect; edits with one `merge_id`
    // (ScenarioCommand::merge_id_for(key)) in a row are one step.
    void edit(const Scenario& scenario, std::function<QString()> describe, int merge_id = -1);

    // --- The file ---
    // Absolute path, or empty for a document never saved.
    const QString& file() const { return file_; }
    bool is_project() const { return is_project_; }
    // The file's name, or "Untitled".
    QString display_name() const;
    // A new content from a file (or the defaults, `file` empty): the undo
    // history starts again, clean.
    void reset(const Scenario& scenario, const QString& file, bool is_project);
    // The scenario is now in `file` as it is.
    void mark_saved(const QString& file, bool is_project);
    // The pages and the baseline as they are now are the file's (a project
    // saved or opened)...
    void mark_session_saved();
    // ... or no file holds them: any data in them is unsaved work.
    void mark_session_unsaved();

    // --- The session: pages and baseline ---
    // Called once per page, in tab order, before the first mark_session_*.
    void add_page(Page* page);
    const QList<Page*>& pages() const { return pages_; }
    const std::optional<Scenario>& baseline() const { return baseline_; }
    void set_baseline(const std::optional<Scenario>& baseline);
    // The PDF report's title block: session data, as the pages' (a project
    // keeps it; outside one it outlives New and a scenario's Open).
    const ReportDetails& report_details() const { return report_details_; }
    // Changed details are unsaved work of a project (the title's "*").
    void set_report_details(const ReportDetails& details);
    // Everything a project file holds: the scenario, the baseline, each
    // page's part, with paths relative to `base_folder` (absolute when
    // empty), and the report's details.
    Project project(const QString& base_folder) const;
    // Each page takes its part of `project`, and the document the report's
    // details (not the scenario or baseline).
    void restore_pages(const Project& project, const QString& base_folder);

    // --- Unsaved work ---
    // The session differs from the file's (or, outside a project, holds data).
    bool session_unsaved() const;
    // The session holds anything at all (a fit, touches, a baseline...).
    bool session_has_data() const;
    // Edits not in the current file: the scenario's, and for a project the
    // session's too.
    bool has_unsaved_changes() const;

  signals:
    // The scenario changed (an edit, undo, redo or reset): show it.
    void scenario_changed();
    // has_unsaved_changes() may have changed: the title's "*".
    void modified_changed();

  private:
    void apply(const Scenario& scenario);
    // The session as the comparisons see it: the project without its
    // scenario, large texts as their length and hash.
    std::string session_snapshot() const;

    Scenario scenario_;
    QUndoStack* undo_{nullptr};
    QString file_;
    bool is_project_{false};
    QList<Page*> pages_;
    std::optional<Scenario> baseline_;
    ReportDetails report_details_;
    std::string saved_session_;
    std::string empty_session_;
    // A page's changed() is looked at once per pass of the event loop.
    QTimer session_check_;
    bool last_modified_{false};
};

}  // namespace probecycle::ui
