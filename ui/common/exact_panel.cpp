#include "ui/common/exact_panel.h"
#include "ui/common/number_text.h"
#include "ui/common/presentation_scale.h"

#include <QEvent>
#include <QRegularExpression>
#include <QScrollBar>
#include <QTextDocument>

namespace granota::ui {

ExactPanel::ExactPanel(QWidget* parent) : QTextBrowser(parent)
{
    setOpenLinks(false);
    setTabChangesFocus(true); // Tab leaves the panel
    setAccessibleName(tr("Exact computation"));
    setMinimumWidth(280);
    document()->setDefaultStyleSheet(QStringLiteral("h3 { margin-top: 10px; margin-bottom: 4px; }"
                                                    "table { border-collapse: collapse; }"
                                                    "td, th { padding: 2px 8px; }"
                                                    "th { background: #eeeae0; }"
                                                    ".poly { font-family: 'DejaVu Serif', serif; }"
                                                    ".note { color: #8a3a00; }"));
}

void ExactPanel::setContent(const QString& html)
{
    const int scroll = verticalScrollBar()->value();
    setHtml(html);
    verticalScrollBar()->setValue(scroll);
    // The plain text keeps the core's notation: superscripts back to ^k.
    QString plain = html;
    plain.replace(QRegularExpression(QStringLiteral("<sup>([^<]*)</sup>")), QStringLiteral("^\\1"));
    plain.replace(QRegularExpression(QStringLiteral("<(br|/tr|/h3|/p|/div)[^>]*>")), QStringLiteral("\n"));
    plain.replace(QRegularExpression(QStringLiteral("</t[dh]>")), QStringLiteral("\t"));
    plain.remove(QRegularExpression(QStringLiteral("<[^>]*>")));
    plain.replace(QStringLiteral("&lt;"), QStringLiteral("<"));
    plain.replace(QStringLiteral("&gt;"), QStringLiteral(">"));
    plain.replace(QStringLiteral("&amp;"), QStringLiteral("&"));
    plain.replace(QStringLiteral("&nbsp;"), QStringLiteral(" "));
    m_plain = plain;
}

void ExactPanel::setPresentation(bool on)
{
    m_presentation = on;
    QFont f = font();
    f.setPointSizeF(QFont().pointSizeF() * presentationScale(on));
    document()->setDefaultFont(f);
}

QString ExactPanel::polynomialHtml(const std::string& text)
{
    QString html = displayText(text).toHtmlEscaped();
    html.replace(QRegularExpression(QStringLiteral("\\^(-?[0-9]+)")), QStringLiteral("<sup>\\1</sup>"));
    return QStringLiteral("<span class=\"poly\">%1</span>").arg(html);
}

QString ExactPanel::heading(const QString& text) { return QStringLiteral("<h3>%1</h3>").arg(text.toHtmlEscaped()); }

QString ExactPanel::table(const QStringList& header, const std::vector<QStringList>& rows)
{
    QString html = QStringLiteral("<table border=\"1\" cellspacing=\"0\">");
    if (!header.isEmpty()) {
        html += QStringLiteral("<tr>");
        for (const QString& h : header)
            html += QStringLiteral("<th>%1</th>").arg(h);
        html += QStringLiteral("</tr>");
    }
    for (const QStringList& row : rows) {
        html += QStringLiteral("<tr>");
        for (const QString& cell : row)
            html += QStringLiteral("<td>%1</td>").arg(cell);
        html += QStringLiteral("</tr>");
    }
    return html + QStringLiteral("</table>");
}

QString ExactPanel::matrix(const QString& name, const std::vector<std::vector<std::string>>& entries)
{
    QString html = QStringLiteral("<p><b>%1</b> =</p><table border=\"0\" cellspacing=\"0\">").arg(name.toHtmlEscaped());
    for (const auto& row : entries) {
        html += QStringLiteral("<tr><td>[</td>");
        for (const auto& e : row)
            // An entry never breaks over lines ("-1,234e-05" in 3 pieces): a wide matrix
            // scrolls sideways instead, as the De Casteljau triangle does.
            html += QStringLiteral("<td align=\"right\" style=\"white-space:nowrap; padding: 0 4px\">%1</td>")
                        .arg(QString::fromStdString(e).toHtmlEscaped());
        html += QStringLiteral("<td>]</td></tr>");
    }
    return html + QStringLiteral("</table>");
}

QString ExactPanel::note(const QString& text) { return QStringLiteral("<p class=\"note\">%1</p>").arg(text.toHtmlEscaped()); }

QString ExactPanel::subscripted(const QString& name, int index) { return QStringLiteral("%1<sub>%2</sub>").arg(name).arg(index); }

QString ExactPanel::checkMark(bool ok)
{
    return ok ? QStringLiteral("<span style=\"color:#1a7f37\">✓</span>")
              : QStringLiteral("<span style=\"color:#c62828\">✗</span>");
}

void ExactPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        setAccessibleName(tr("Exact computation"));
    QTextBrowser::changeEvent(event);
}

} // namespace granota::ui
