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
    // Plain text (escaped); line breaks kept.
    void add_paragraph(const QString& text);
    // A bold first line and plain text under it (a warning and its fix): a
    // paragraph, which the layout never splits across pages mid-line as it
    // can a table's cell.
    void add_item(const QString& title, const QString& text);
    // The first row is the header; cells are plain text. For rows of one line.
    void add_table(const QList<QStringList>& rows);
    // A picture the page's width (at most its own size's aspect).
    void add_image(const QImage& image);
    // The next block starts a new page.
    void add_page_break();
    // The footer's text on every page, beside "page n of m".
    void set_footer(const QString& text) { footer_ = text; }

    // The PDF, A4 portrait, 15 mm margins.
    QByteArray render() const;

  private:
    enum class Kind { heading, paragraph, item, table, image, page_break };
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
