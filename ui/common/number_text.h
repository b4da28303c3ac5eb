#pragma once
/// \file number_text.h
/// Numbers for people, and numbers for files.
///
/// A number that goes to a file, a stream, the clipboard or the command line is written and
/// read without the locale: `formatDouble` and `parseRational` from the core, or
/// `QLocale::c()`. A `ca_ES.UTF-8` desktop sets LC_NUMERIC to a decimal comma, and anything
/// that follows it there writes CSV rows such as "0,005,0,015" that no reader can split.
///
/// A number that the window shows a person follows the interface language instead, the
/// same everywhere (spin boxes, tables, readouts, plot axes): a decimal comma in Catalan,
/// a point in English, never a group separator. In Catalan a typed number may use either
/// a comma or a point; a fraction such as 1/3 is read in both languages.

#include "core/base/vec2.h"
#include "core/exact/rational.h"

#include <QLocale>
#include <QString>

#include <optional>
#include <string>

namespace granota::ui {

/// The locale of the interface language ("ca" or "en"), without group separators.
QLocale displayLocale(const QString& language);
/// The locale of the language in use (currentLanguage()).
QLocale displayLocale();

/// The shortest text that reads back as `v`, with the interface's decimal sign ("0,1").
QString displayNumber(double v);
/// `decimals` digits after the decimal sign ("0,300").
QString displayFixed(double v, int decimals);
/// `digits` significant digits ("1,5e-08").
QString displaySignificant(double v, int digits);
/// A text of the core with the interface's decimal sign: "1.5 - 0.25t" → "1,5 - 0,25t" and
/// "(0.5, 2)" → "(0,5; 2)" in Catalan (the core's commas only ever separate). Texts without
/// decimals, such as the thesis's fractions "(1/2, 11/2)", are shown as printed.
QString displayText(const std::string& cText);
/// "(x, y)" of two shown numbers; "(x; y)" when one has a decimal comma ("(1,5; 2)").
QString displayPair(const QString& x, const QString& y);
/// displayPair of two doubles, each the shortest round-trip text.
QString displayPoint(double x, double y);
/// A double in an exact panel beside fractions: six significant digits, and 0 for zero and
/// for what is not finite.
QString panelNumber(double v);
/// A point of doubles in an exact panel, each coordinate a panelNumber.
QString panelPointText(const Point& p);
/// A fraction as the window shows it: "1/3", "-2" (displayText of the core's text).
QString rationalText(const Rational& q);
/// A point of fractions in an exact panel: "(1/2, 3)".
QString panelPointText(const Vec2<Rational>& p);

/// A whole number ≥ 0 in Unicode subscript or superscript digits, for names in plain text
/// (legends, readouts): "B" + subscriptDigits(2) + superscriptDigits(5) is B₂⁵.
QString subscriptDigits(int v);
QString superscriptDigits(int v);

/// A person's typed text with the number in the C form the core reads: in Catalan a
/// decimal comma becomes a point; the Unicode minus that the window shows becomes '-'.
QString typedToC(const QString& text);
/// A number as typed by a person: an integer, a decimal (with the interface's decimal sign
/// or a point) or a fraction. nullopt for anything else, including NaN and infinities.
std::optional<Rational> parseTypedRational(const QString& text);
std::optional<double> parseTypedNumber(const QString& text);

} // namespace granota::ui
