#include "ui/common/number_text.h"

#include "core/base/number_format.h"
#include "ui/common/language.h"

#include <cmath>

namespace granota::ui {

QLocale displayLocale(const QString& language)
{
    QLocale locale = language == QLatin1String("ca") ? QLocale(QLocale::Catalan, QLocale::Spain)
                                                     : QLocale(QLocale::English, QLocale::UnitedStates);
    locale.setNumberOptions(QLocale::OmitGroupSeparator | QLocale::RejectGroupSeparator);
    return locale;
}

QLocale displayLocale() { return displayLocale(currentLanguage()); }

namespace {

/// The C text of the core with the interface's decimal sign. The core writes no decimal
/// commas, so each of its commas separates two things ("(1.5, 2)"): where a decimal comma
/// appears, the separator becomes a semicolon first ("(1,5; 2)"); "(1/2, 3)" stays.
QString localized(const std::string& cText)
{
    QString s = QString::fromStdString(cText);
    const QString point = displayLocale().decimalPoint();
    if (point != QLatin1String(".") && s.contains(QLatin1Char('.'))) {
        if (point == QLatin1String(","))
            s.replace(QLatin1Char(','), QLatin1Char(';'));
        s.replace(QLatin1Char('.'), point);
    }
    return s;
}

/// A number's C text without the minus of a zero: −0 and −0.0001 at one decimal read "-0",
/// "-0.0" ("-0,0 %" on the Frog canvas), and a person reads no sign on nothing.
std::string unsignedZero(std::string text)
{
    if (!text.empty() && text.front() == '-') {
        const std::size_t exponent = text.find_first_of("eE");
        if (text.find_first_of("123456789") >= exponent)
            text.erase(0, 1);
    }
    return text;
}

} // namespace

QString displayNumber(double v) { return localized(unsignedZero(formatDouble(v))); }
QString displayFixed(double v, int decimals) { return localized(unsignedZero(formatFixed(v, decimals))); }
QString displaySignificant(double v, int digits) { return localized(unsignedZero(formatSignificant(v, digits))); }
QString displayText(const std::string& cText) { return localized(cText); }

QString displayPair(const QString& x, const QString& y)
{
    const bool comma = x.contains(QLatin1Char(',')) || y.contains(QLatin1Char(','));
    return QLatin1Char('(') + x + (comma ? QStringLiteral("; ") : QStringLiteral(", ")) + y + QLatin1Char(')');
}

QString displayPoint(double x, double y) { return displayPair(displayNumber(x), displayNumber(y)); }

QString panelNumber(double v)
{
    if (v == 0.0 || !std::isfinite(v))
        return QStringLiteral("0");
    return displaySignificant(v, 6);
}

QString panelPointText(const Point& p) { return displayPair(panelNumber(p.x), panelNumber(p.y)); }

QString rationalText(const Rational& q) { return displayText(toString(q)); }

QString panelPointText(const Vec2<Rational>& p)
{
    return QStringLiteral("(%1, %2)").arg(QString::fromStdString(toString(p.x)), QString::fromStdString(toString(p.y)));
}

QString typedToC(const QString& text)
{
    QString s = text.trimmed();
    s.replace(QChar(0x2212), QLatin1Char('-'));
    if (displayLocale().decimalPoint() == QLatin1String(","))
        s.replace(QLatin1Char(','), QLatin1Char('.'));
    return s;
}

std::optional<Rational> parseTypedRational(const QString& text) { return parseRational(typedToC(text).toStdString()); }

std::optional<double> parseTypedNumber(const QString& text)
{
    const auto q = parseTypedRational(text);
    if (!q)
        return std::nullopt;
    const double v = toDouble(*q);
    if (!std::isfinite(v))
        return std::nullopt;
    return v;
}

namespace {

QString unicodeDigits(int v, const char* const* table)
{
    QString out;
    for (QChar c : QString::number(v))
        out += c.isDigit() ? QString::fromUtf8(table[c.digitValue()]) : QString(c);
    return out;
}

} // namespace

QString subscriptDigits(int v)
{
    static const char* const table[] = {"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
    return unicodeDigits(v, table);
}

QString superscriptDigits(int v)
{
    static const char* const table[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    return unicodeDigits(v, table);
}

} // namespace granota::ui
