#pragma once
/// \file exact_panel.h
/// The side panel that shows the thesis's exact results (docs/tabs.md): polynomials,
/// tables and matrices as fractions, typeset in HTML (t⁴ as t<sup>4</sup>, fractions as
/// p/q). It only formats: the values come from the core. Tests read plainText() and
/// compare with the thesis text (“2 - 12t - 6t^2 + 52t^3 - 43t^4”).

#include <QString>
#include <QStringList>
#include <QTextBrowser>

#include <string>
#include <vector>

namespace granota::ui {

class ExactPanel : public QTextBrowser {
    Q_OBJECT
public:
    explicit ExactPanel(QWidget* parent = nullptr);

    /// Replaces the content by `html` (built with the helpers below) and keeps the scroll position.
    void setContent(const QString& html);
    /// The content as plain text in the core's notation ("t^2"), for tests and CSV.
    QString plainText() const { return m_plain; }
    /// Presentation mode: larger type.
    void setPresentation(bool on);

    /// "3 + 20t - 96t^2" → HTML with superscripts; the text stays searchable as "t^2" in plainText().
    static QString polynomialHtml(const std::string& text);
    /// A heading.
    static QString heading(const QString& text);
    /// A table: one row per entry of `rows`, cells already HTML; `header` may be empty.
    static QString table(const QStringList& header, const std::vector<QStringList>& rows);
    /// A matrix of texts (fractions), in brackets.
    static QString matrix(const QString& name, const std::vector<std::vector<std::string>>& entries);
    /// A note (a slip of the thesis, a warning), set apart.
    static QString note(const QString& text);
    /// `name` with the subscript `index` (Q<sub>2</sub>).
    static QString subscripted(const QString& name, int index);
    /// A check's result: a green ✓ or a red ✗.
    static QString checkMark(bool ok);

protected:
    /// The accessible name, again in the new language.
    void changeEvent(QEvent* event) override;

private:
    QString m_plain;
    bool m_presentation = false;
};

} // namespace granota::ui
