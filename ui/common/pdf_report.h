#pragma once

// A report to hand over (docs/window.md): A4 pages of headings, paragraphs, tables
// and pictures, with a footer on every page (what the figures are and are not,
// and the page number). Laid out by QTextDocument and written by QPdfWriter,
// which embeds the fonts it uses (DejaVu for Cyrillic, Noto CJK for Chinese),
// so the pages read the same on any machine.

#include <QByteArray>
#include <QImage>
#include <QList>
#include <QString>
#include <QStringList>
#include <vector>

namespace probecycle::ui {

class PdfReport {
  public:
    explicit PdfReport(QString title);

    void add_heading(const QString& text);
    // A smaller heading within a section (the scenario's machine, probe, cycle).
    void add_subheading(const QString& text);
    // Plain text (escaped); line breaks kept.
    void add_paragraph(const QString& text);
    // A bold first line and plain text under it (a warning and its fix): a
    // paragraph, which the layout never splits across pages mid-line as it
    // can a table's cell.
    void add_item(const QString& title, const QString& text);
    // The first row is the header, again at the top of each page the table
    // goes on to; cells are plain text. For rows of one line.
    void add_table(const QList<QStringList>& rows);
    // Label and value pairs without rules (the title block): bold labels
    // left, values beside them; line breaks kept.
    void add_fields(const QList<QStringList>& pairs);
    // A picture the page's width (at most its own size's aspect).
    void add_image(const QImage& image);
    // The next block starts a new page.
    void add_page_break();
    // The footer's text on every page, beside "page n of m".
    void set_footer(const QString& text) { footer_ = text; }

    // The PDF, A4 portrait, 15 mm margins. Where the text would split badly
    // it goes on on the next page: a heading is never left at a page's foot
    // without the start of what it heads, a short table is never split, and
    // a long one splits after a few rows at least.
    QByteArray render() const;

  private:
    enum class Kind { heading, subheading, paragraph, item, table, fields, image, page_break };
    struct Block {
        Kind kind{Kind::paragraph};
        QString text;
        QList<QStringList> rows;
        QImage image;
    };
    QString title_;
    QString footer_;
    std::vector<Block> blocks_;
};

}  // namespace probecycle::ui
