#include "ui/cycle/uncertainty_table.h"

#include <QCoreApplication>

#include "core/cycle/uncertainty.h"
#include "ui/common/text_format.h"

namespace probecycle::ui {

namespace {

constexpr const char* kContext = "UncertaintyBudget";

QString tr_budget(const char* text) {
    return QCoreApplication::translate(kContext, text);
}

QString term_name(BudgetTerm term) {
    switch (term) {
        case BudgetTerm::scan_wait:
            return tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "Scan wait of the skip input"));
        case BudgetTerm::probe_repeatability:
            return tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "Probe repeatability"));
        case BudgetTerm::probe_lobing:
            return tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "Probe lobing"));
        case BudgetTerm::calibration_artefact:
            return tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "Calibration artefact"));
        case BudgetTerm::machine_repeatability:
            return tr_budget(
                QT_TRANSLATE_NOOP("UncertaintyBudget", "Machine positioning repeatability"));
        case BudgetTerm::thermal_drift:
            return tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "Thermal drift"));
    }
    return {};
}

QString stated_as(const BudgetLine& line, int repeats) {
    QString text;
    switch (line.distribution) {
        case Distribution::uniform_range:
            text = tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "full range, ÷ √12"));
            break;
        case Distribution::uniform_half_width:
            text = tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "± half-width, ÷ √3"));
            break;
        case Distribution::normal_2sigma:
            text = tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "2σ or k = 2, ÷ 2"));
            break;
    }
    if (line.averaged && repeats > 1) {
        //: %1 how the value is stated, %2 the number of repeated touches averaged
        text = tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "%1, mean of %2"))
                   .arg(text)
                   .arg(repeats);
    }
    return text;
}

}  // namespace

QList<QStringList> uncertainty_budget_rows(const Scenario& scenario, const CycleResult& cycle) {
    const UncertaintyBudget b = uncertainty_budget(scenario, cycle.trigger_speed_mm_s());
    QList<QStringList> rows = {
        {tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "Term")),
         tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "Value")),
         tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "Stated as")),
         tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "Standard uncertainty")),
         tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "Share"))}};
    const double variance = b.combined_standard_mm * b.combined_standard_mm;
    for (const BudgetLine& line : b.lines) {
        const double share = variance > 0.0 ? line.standard_mm * line.standard_mm / variance : 0.0;
        rows.append({term_name(line.term), format_um(line.value_mm), stated_as(line, b.repeats),
                     format_um(line.standard_mm),
                     QStringLiteral("%1 %").arg(format_number(100.0 * share, 0))});
    }
    rows.append(
        {tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "Combined (root sum of squares)")),
         QString(), QString(), format_um(b.combined_standard_mm), QString()});
    rows.append({tr_budget(QT_TRANSLATE_NOOP("UncertaintyBudget", "Expanded uncertainty, k = 2")),
                 QString(), QString(), format_um(b.expanded_mm), QString()});
    return rows;
}

QString rows_to_html_table(const QList<QStringList>& rows) {
    QString html = QStringLiteral("<table cellspacing=\"0\" cellpadding=\"2\">");
    for (qsizetype r = 0; r < rows.size(); ++r) {
        html += QStringLiteral("<tr>");
        for (const QString& cell : rows[r]) {
            const QString tag = r == 0 ? QStringLiteral("th") : QStringLiteral("td");
            html += QStringLiteral("<%1 align=\"left\">%2</%1>").arg(tag, cell.toHtmlEscaped());
        }
        html += QStringLiteral("</tr>");
    }
    return html + QStringLiteral("</table>");
}

}  // namespace probecycle::ui
