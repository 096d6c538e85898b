#pragma once

// A tab's CSV report (the CLI's bytes, English keys for machines) as the PDF
// report's tables, for a reader: headings, column titles and quantities in
// the interface language with their units, the date and version left to the
// report's title line, and the tab's warnings as the window shows them
// (translated) instead of the CSV's English messages.

#include <QString>
#include <vector>

#include "ui/common/warning_list.h"

namespace probecycle::ui {

class PdfReport;

// A CSV word in the interface language: a section ("ring"), a column
// ("center_x_mm": "Centre X [mm]"), a quantity ("effective_radius"), a unit
// or a value ("yes"). A word it does not know (a symbol such as "ex", a group
// such as "X+") is returned as it is.
QString report_word(const QString& word);

void add_report_csv(PdfReport& report, const QString& csv,
                    const std::vector<WarningList::Item>& warnings);

}  // namespace probecycle::ui
