#pragma once

// A tab of the window with data of its own, which a project file keeps: the
// Calibration, Latency and Comparison tabs. The window exports their
// reports, writes their part of the PDF report, saves and opens projects and
// tells unsaved work by looping over its pages, with no knowledge of any one.
// (The Cycle and Optimise tabs draw the scenario, which the window's
// Document holds: they have no data of their own.)

#include <QString>
#include <QWidget>
#include <cstddef>
#include <optional>
#include <string>

#include "core/common/report_summary.h"
#include "core/project/project_file.h"

namespace probecycle::ui {

class Page : public QWidget {
    Q_OBJECT

  public:
    using QWidget::QWidget;

    // The tab's CSV report (the same bytes as the CLI's), or nullopt when
    // there is nothing to report yet, with last_error() saying why.
    virtual std::optional<std::string> report_csv(ReportRows rows) = 0;
    // How many points the report covers: the PDF report says so when its
    // tables summarise them (report_summary.h).
    virtual std::size_t report_points() const = 0;
    virtual QString last_error() const = 0;
    // The report's save dialog, then the report written (the tab's button
    // and the window's "Export CSV Report" on this tab).
    virtual void export_dialog() = 0;

    // Its part of a project file: paths relative to `base_folder`, or
    // absolute when it is empty (the window's saved session).
    virtual void save_session(Project& project, const QString& base_folder) const = 0;
    // Takes its part back; false (with last_error(), shown in the tab) when
    // a part no longer loads. The rest is taken as stored.
    virtual bool restore_session(const Project& project, const QString& base_folder) = 0;

  signals:
    // What save_session() writes may have changed. Emitted freely (every
    // edit of an input, every fit): the window compares sessions to tell.
    void changed();

  protected:
    // Emits changed() on every edit of any input among this page's widgets
    // (spin boxes, line and text edits, combo boxes, check boxes); call at
    // the end of the constructor. A fit that changes the stored result
    // emits changed() itself.
    void watch_inputs();
};

}  // namespace probecycle::ui
