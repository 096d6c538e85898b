#include "ui/common/report_tables.h"

#include <QCoreApplication>
#include <QLocale>
#include <QRegularExpression>
#include <QStringList>
#include <algorithm>
#include <array>
#include <utility>

#include "ui/common/parameter_info.h"
#include "ui/common/pdf_report.h"

namespace probecycle::ui {
namespace {

// The words of core/lab/calibration_report.cpp, delay_fit_report.cpp,
// core/comparison/comparison_report.cpp and core/common/report_summary.cpp.
struct Word {
    const char* key;
    const char* label;
};
constexpr std::array kWords = {
    // Sections.
    Word{"ring", QT_TRANSLATE_NOOP("ReportWord", "Ring gauge")},
    Word{"fits", QT_TRANSLATE_NOOP("ReportWord", "Circle fits by spindle orientation")},
    Word{"points", QT_TRANSLATE_NOOP("ReportWord", "Points")},
    Word{"length", QT_TRANSLATE_NOOP("ReportWord", "Length")},
    Word{"fit", QT_TRANSLATE_NOOP("ReportWord", "Fit")},
    Word{"groups", QT_TRANSLATE_NOOP("ReportWord", "Groups")},
    Word{"feeds", QT_TRANSLATE_NOOP("ReportWord", "Feeds")},
    Word{"touches", QT_TRANSLATE_NOOP("ReportWord", "Touches")},
    Word{"c_axis", QT_TRANSLATE_NOOP("ReportWord", "C axis")},
    Word{"summary", QT_TRANSLATE_NOOP("ReportWord", "Summary")},
    // Columns and quantities.
    Word{"quantity", QT_TRANSLATE_NOOP("ReportWord", "Quantity")},
    Word{"key", QT_TRANSLATE_NOOP("ReportWord", "Quantity")},
    Word{"value", QT_TRANSLATE_NOOP("ReportWord", "Value")},
    Word{"unit", QT_TRANSLATE_NOOP("ReportWord", "Unit")},
    Word{"uncertainty", QT_TRANSLATE_NOOP("ReportWord", "Uncertainty")},
    Word{"count", QT_TRANSLATE_NOOP("ReportWord", "Count")},
    Word{"min", QT_TRANSLATE_NOOP("ReportWord", "Min")},
    Word{"max", QT_TRANSLATE_NOOP("ReportWord", "Max")},
    Word{"mean", QT_TRANSLATE_NOOP("ReportWord", "Mean")},
    Word{"rms", QT_TRANSLATE_NOOP("ReportWord", "RMS")},
    Word{"std", QT_TRANSLATE_NOOP("ReportWord", "Std. deviation")},
    Word{"out_of_tolerance", QT_TRANSLATE_NOOP("ReportWord", "Out of tol.")},
    Word{"gauge_diameter", QT_TRANSLATE_NOOP("ReportWord", "Gauge diameter")},
    Word{"center_x", QT_TRANSLATE_NOOP("ReportWord", "Centre X")},
    Word{"center_y", QT_TRANSLATE_NOOP("ReportWord", "Centre Y")},
    Word{"runout_x", QT_TRANSLATE_NOOP("ReportWord", "Runout X")},
    Word{"runout_y", QT_TRANSLATE_NOOP("ReportWord", "Runout Y")},
    Word{"runout", QT_TRANSLATE_NOOP("ReportWord", "Runout")},
    Word{"effective_radius", QT_TRANSLATE_NOOP("ReportWord", "Effective radius")},
    Word{"radius_x_plus", QT_TRANSLATE_NOOP("ReportWord", "Radius X+")},
    Word{"radius_x_minus", QT_TRANSLATE_NOOP("ReportWord", "Radius X-")},
    Word{"radius_y_plus", QT_TRANSLATE_NOOP("ReportWord", "Radius Y+")},
    Word{"radius_y_minus", QT_TRANSLATE_NOOP("ReportWord", "Radius Y-")},
    Word{"residual_max", QT_TRANSLATE_NOOP("ReportWord", "Largest residual")},
    Word{"runout_limit", QT_TRANSLATE_NOOP("ReportWord", "Runout limit")},
    Word{"residual_limit", QT_TRANSLATE_NOOP("ReportWord", "Residual limit")},
    Word{"orientation", QT_TRANSLATE_NOOP("ReportWord", "Spindle orientation")},
    Word{"radius", QT_TRANSLATE_NOOP("ReportWord", "Radius")},
    Word{"line", QT_TRANSLATE_NOOP("ReportWord", "Line")},
    Word{"direction", QT_TRANSLATE_NOOP("ReportWord", "Direction")},
    Word{"residual", QT_TRANSLATE_NOOP("ReportWord", "Residual")},
    Word{"surface_z", QT_TRANSLATE_NOOP("ReportWord", "Surface Z")},
    Word{"active_length", QT_TRANSLATE_NOOP("ReportWord", "Active length")},
    Word{"nominal_length", QT_TRANSLATE_NOOP("ReportWord", "Nominal length")},
    Word{"trigger_z_mean", QT_TRANSLATE_NOOP("ReportWord", "Mean trigger Z")},
    Word{"trigger_z_range", QT_TRANSLATE_NOOP("ReportWord", "Range of trigger Z")},
    Word{"effective_length", QT_TRANSLATE_NOOP("ReportWord", "Effective length")},
    Word{"wear", QT_TRANSLATE_NOOP("ReportWord", "Wear")},
    Word{"interpolation_period", QT_TRANSLATE_NOOP("ReportWord", "Interpolation period")},
    Word{"group", QT_TRANSLATE_NOOP("ReportWord", "Group")},
    Word{"axis", QT_TRANSLATE_NOOP("ReportWord", "Axis")},
    Word{"delay", QT_TRANSLATE_NOOP("ReportWord", "Delay")},
    Word{"zero_speed_position", QT_TRANSLATE_NOOP("ReportWord", "Position at zero feed")},
    Word{"lag_cycles", QT_TRANSLATE_NOOP("ReportWord", "Lag [cycles]")},
    Word{"compensation_lag_cycles", QT_TRANSLATE_NOOP("ReportWord", "Compensation lag [cycles]")},
    Word{"residual_2sigma", QT_TRANSLATE_NOOP("ReportWord", "Residual (2σ)")},
    Word{"feed", QT_TRANSLATE_NOOP("ReportWord", "Feed")},
    Word{"mean_deviation", QT_TRANSLATE_NOOP("ReportWord", "Mean deviation")},
    Word{"fitted_deviation", QT_TRANSLATE_NOOP("ReportWord", "Fitted deviation")},
    Word{"range", QT_TRANSLATE_NOOP("ReportWord", "Range")},
    Word{"n", QT_TRANSLATE_NOOP("ReportWord", "Touches")},
    Word{"measured", QT_TRANSLATE_NOOP("ReportWord", "Measured")},
    Word{"identified", QT_TRANSLATE_NOOP("ReportWord", "C axis")},
    Word{"axis_x", QT_TRANSLATE_NOOP("ReportWord", "Axis X")},
    Word{"axis_y", QT_TRANSLATE_NOOP("ReportWord", "Axis Y")},
    Word{"angle", QT_TRANSLATE_NOOP("ReportWord", "Angle")},
    Word{"point", QT_TRANSLATE_NOOP("ReportWord", "Point")},
    Word{"deviation", QT_TRANSLATE_NOOP("ReportWord", "Deviation")},
    Word{"direct_deviation", QT_TRANSLATE_NOOP("ReportWord", "Direct deviation")},
    Word{"direct", QT_TRANSLATE_NOOP("ReportWord", "Direct deviation")},
    Word{"system_error", QT_TRANSLATE_NOOP("ReportWord", "System error")},
    Word{"c_axis_uncertainty", QT_TRANSLATE_NOOP("ReportWord", "C-axis uncertainty")},
    Word{"tolerance", QT_TRANSLATE_NOOP("ReportWord", "Tolerance")},
    Word{"test_omm", QT_TRANSLATE_NOOP("ReportWord", "Test part (on the machine)")},
    // Values (yes and no: only whether the C axis was identified).
    Word{"yes", QT_TRANSLATE_NOOP("ReportWord", "identified")},
    Word{"no", QT_TRANSLATE_NOOP("ReportWord", "not identified")},
    Word{"pasted", QT_TRANSLATE_NOOP("ReportWord", "pasted")},
    Word{"deg", QT_TRANSLATE_NOOP("ReportWord", "deg")},
    Word{"rad", QT_TRANSLATE_NOOP("ReportWord", "rad")},
};

QString known(const QString& word) {
    for (const Word& w : kWords) {
        if (word == QLatin1String(w.key)) return QCoreApplication::translate("ReportWord", w.label);
    }
    return {};
}

QString unit_word(const QString& unit) {
    if (unit == QLatin1String("mm")) return unit_mm();
    if (unit == QLatin1String("s")) return unit_s();
    if (unit == QLatin1String("mm_min")) return unit_mm_min();
    return known(unit);
}

// Statistics' sections ("points summary") and their largest rows ("points:
// the 10 largest |residual_mm| of 290000").
QString heading(const QString& text) {
    static const QRegularExpression summary(QStringLiteral("^(\\w+) summary$"));
    static const QRegularExpression largest(
        QStringLiteral("^(\\w+): the (\\d+) largest \\|(\\w+)\\| of (\\d+)$"));
    if (const QRegularExpressionMatch m = summary.match(text); m.hasMatch()) {
        //: %1 a section of the report, e.g. Points
        return QCoreApplication::translate("ReportWord", "%1: statistics")
            .arg(report_word(m.captured(1)));
    }
    if (const QRegularExpressionMatch m = largest.match(text); m.hasMatch()) {
        //: %1 a section (Points), %2 how many rows, %3 the column, %4 how many in all
        return QCoreApplication::translate("ReportWord", "%1: the %2 largest of %4 by |%3|")
            .arg(report_word(m.captured(1)), m.captured(2), report_word(m.captured(3)),
                 m.captured(4));
    }
    return report_word(text);
}

void add_warnings(PdfReport& report, const std::vector<WarningList::Item>& warnings) {
    report.add_heading(report_word(QStringLiteral("warnings")));
    if (warnings.empty()) {
        report.add_paragraph(QCoreApplication::translate("ReportWord", "No warnings."));
        return;
    }
    for (const WarningList::Item& item : warnings) {
        const QString severity = item.severity == Severity::error
                                     ? QCoreApplication::translate("ReportWord", "Error")
                                 : item.severity == Severity::warning
                                     ? QCoreApplication::translate("ReportWord", "Warning")
                                     : QCoreApplication::translate("ReportWord", "Note");
        //: %1 the severity (Error, Warning, Note), %2 the warning's title
        report.add_item(
            QCoreApplication::translate("ReportWord", "%1: %2").arg(severity, item.title),
            item.message);
    }
}

// One CSV line's fields (RFC 4180 quoting, as the reports write them).
QStringList fields(const QString& line) {
    QStringList fields;
    QString field;
    bool quoted = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (quoted) {
            if (c == QLatin1Char('"') && i + 1 < line.size() && line[i + 1] == QLatin1Char('"')) {
                field += c;
                ++i;
            } else if (c == QLatin1Char('"')) {
                quoted = false;
            } else {
                field += c;
            }
        } else if (c == QLatin1Char('"')) {
            quoted = true;
        } else if (c == QLatin1Char(',')) {
            fields.append(field);
            field.clear();
        } else {
            field += c;
        }
    }
    fields.append(field);
    return fields;
}

}  // namespace

QString report_word(const QString& word) {
    if (word == QLatin1String("warnings")) {
        return QCoreApplication::translate("ReportWord", "Warnings");
    }
    if (QString label = known(word); !label.isEmpty()) return label;
    // A column with its unit: "center_x_mm", "feed_mm_min", "delay_s".
    static const QRegularExpression with_unit(QStringLiteral("^(\\w+?)_(mm_min|mm|deg|rad|s)$"));
    if (const QRegularExpressionMatch m = with_unit.match(word); m.hasMatch()) {
        const QString base = known(m.captured(1));
        const QString unit = unit_word(m.captured(2));
        if (!base.isEmpty() && !unit.isEmpty()) return base + QStringLiteral(" [") + unit + ']';
        if (!unit.isEmpty()) return m.captured(1) + QStringLiteral(" [") + unit + ']';
    }
    // A quantity of a group: "residual X+".
    const qsizetype space = word.indexOf(QLatin1Char(' '));
    if (space > 0) {
        if (const QString label = known(word.left(space)); !label.isEmpty())
            return label + word.mid(space);
    }
    if (QString unit = unit_word(word); !unit.isEmpty()) return unit;
    return word;
}

void add_report_csv(PdfReport& report, const QString& csv,
                    const std::vector<WarningList::Item>& warnings) {
    QList<QStringList> rows;
    bool in_warnings = false;
    bool warnings_added = false;
    // The first column's words are names in a table of quantities.
    bool named_rows = false;
    const auto flush = [&] {
        if (!rows.isEmpty()) report.add_table(rows);
        rows.clear();
    };
    for (const QString& line : csv.split(QLatin1Char('\n'))) {
        if (line.trimmed().isEmpty()) {
            flush();
            continue;
        }
        if (line.startsWith(QLatin1Char('#'))) {
            flush();
            const QString text = line.mid(1).trimmed();
            in_warnings = text == QLatin1String("warnings");
            if (in_warnings) {
                add_warnings(report, warnings);
                warnings_added = true;
            } else if (text.contains(QLatin1Char(','))) {
                const QStringList meta = fields(text);
                // The date and the version are in the report's title line.
                if (meta.value(0) != QLatin1String("date") &&
                    meta.value(0) != QLatin1String("version")) {
                    report.add_paragraph(report_word(meta.value(0)) + QStringLiteral(": ") +
                                         report_word(meta.value(1)));
                }
            } else if (!text.startsWith(QLatin1String("ProbeCycle "))) {
                // (The report's own title: the report's title line names the tab.)
                report.add_heading(heading(text));
            }
            continue;
        }
        if (in_warnings) continue;  // the tab's own, translated, stand there instead
        QStringList cells = fields(line);
        if (rows.isEmpty()) {
            named_rows = cells.value(0) == QLatin1String("quantity") ||
                         cells.value(0) == QLatin1String("key");
            for (QString& cell : cells) cell = report_word(cell);
        } else {
            if (named_rows && !cells.isEmpty()) cells[0] = report_word(cells[0]);
            // Numbers in the interface's format (the CSV's digits, its
            // decimal point the language's), units and yes/no in any column.
            for (qsizetype i = 0; i < cells.size(); ++i) {
                QString& cell = cells[i];
                bool number = false;
                const double value = QLocale::c().toDouble(cell, &number);
                if (number) {
                    // A file's own digits (a plan's normals) to six significant ones.
                    const qsizetype digits = std::count_if(cell.begin(), cell.end(),
                                                           [](QChar c) { return c.isDigit(); });
                    QLocale locale;
                    locale.setNumberOptions(QLocale::OmitGroupSeparator);
                    cell = digits > 7 ? locale.toString(value, 'g', 6)
                                      : cell.replace(QLatin1Char('.'), QLocale().decimalPoint());
                    continue;
                }
                if (i == 0) continue;
                if (cell == QLatin1String("mm") || cell == QLatin1String("s") ||
                    cell == QLatin1String("deg") || cell == QLatin1String("rad") ||
                    cell == QLatin1String("yes") || cell == QLatin1String("no")) {
                    cells[i] = report_word(cell);
                }
            }
        }
        rows.append(cells);
    }
    flush();
    if (!warnings_added && !warnings.empty()) add_warnings(report, warnings);
}

}  // namespace probecycle::ui
