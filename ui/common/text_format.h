#pragma once

// Numbers and messages as the window shows them: in the interface language,
// with units, converted from the core's internal units at this edge only.

#include <QString>
#include <QStringList>
#include <vector>

#include "core/cycle/cycle.h"

namespace probecycle::ui {

// Every number the window shows goes through these, in the interface
// language's format (QLocale(), set by apply_language): "0,5" in Russian.
QString format_number(double value, int decimals);             // "-0.0" shown as "0.0"
QString with_unit(const QString& value, const QString& unit);  // no break between them
QString format_seconds(double seconds);                        // "4.93 s", "12.0 ms", "40 µs"
// Times that stand in one column: their numbers in one unit, given apart
// (ms for times under 10 s, µs under 0.1 ms, else s), each to two
// significant digits at least.
struct SecondsColumn {
    QStringList numbers;
    QString unit;
};
SecondsColumn format_seconds_column(const std::vector<double>& seconds);
QString format_mm(double mm);                   // "1.274 mm"
QString format_um(double mm);                   // "3.2 µm"
QString format_length(double mm);               // mm, or µm below 0.1 mm
QString format_feed(double mm_min);             // "1850 mm/min", "30 mm/min", "2.5 mm/min"
QString format_signed_seconds(double seconds);  // "+0.42 s" / "−0.42 s"
QString format_signed_length(double mm);

// A core message in the interface language: its template translated
// (QCoreApplication::translate with the message's context), each argument
// formatted for the locale with its unit. Every text that comes from core
// goes through here.
QString translate(const Message& message);
// One argument as the window writes it: "1.272 mm", "40 µs", "1,850 mm/min".
QString format_arg(const MessageArg& arg);
// A core warning in the interface language: translate(warning.to_message()).
QString warning_text(const Warning& warning);
// The colour of a severity, as "#rrggbb": the warnings panel and the lab's lists.
const char* severity_colour(Severity severity);
// A short title per warning code.
QString warning_title(WarningCode code);

// A phase's name as the timeline labels it.
QString phase_label(Phase phase);

}  // namespace probecycle::ui
