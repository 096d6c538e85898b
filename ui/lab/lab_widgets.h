#pragma once

// What the two lab tabs share: the translated titles of the lab's warning
// codes, the report's export and the lab's number formats.

#include <QString>
#include <string>

#include "core/lab/calibration.h"
#include "core/lab/delay_fit.h"
#include "ui/common/status_text.h"
#include "ui/common/warning_list.h"

class QLabel;
class QWidget;

namespace probecycle::ui {

WarningList::Item warning_item(const CalibrationWarning& warning);
WarningList::Item warning_item(const LatencyWarning& warning, const QString& group);

// A lab tab's report export: the save dialog, starting in the last
// folder used (dialog_start) with `file_name`, ".csv" added; empty when the
// user cancels.
QString ask_report_path(QWidget* parent, const QString& title, const QString& file_name);
// Writes the report atomically (write_file) and says where in `status`, or
// why not (then false, with `error`); remembers the folder.
bool write_report(const QString& path, const std::string& csv, QLabel* status, QString& error);

// Lengths and times at the resolution calibration needs (4 decimals in mm,
// 0.1 µm), in the interface language.
QString lab_mm(double mm, int decimals = 4);
QString lab_signed_um(double mm);
QString lab_signed_length(double mm);  // µm below 0.1 mm, else mm
QString lab_ms(double seconds);

}  // namespace probecycle::ui
