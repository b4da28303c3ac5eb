#include "ui/common/bezier_exact_html.h"

#include "core/curves/bezier/bernstein.h"
#include "core/curves/bezier/bernstein_properties.h"
#include "core/curves/bezier/hodograph.h"
#include "core/exact/polynomial.h"
#include "core/exact/polynomial_text.h"
#include "core/exact/rational.h"
#include "core/exact/rational_approximation.h"
#include "ui/common/exact_panel.h"
#include "ui/common/number_text.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {

using RPoly = Polynomial<Rational>;

constexpr long kExactTDenominator = 16;      ///< t = p/q with q ≤ 16 gives the triangle in fractions
constexpr long kMaxShownDenominator = 10000; ///< larger denominators: the triangle at t in decimals
constexpr int kLevelsPerTable = 3;           ///< symbolic table columns per block, as the thesis prints them
constexpr int kNumericLevelsPerTable = 5;
constexpr long kExactCurvatureDenominator = 1000000; ///< κ in fractions while they stay this small


template <class P> QString joinPanelPoints(const std::vector<P>& points)
{
    QStringList parts;
    for (const P& p : points)
        parts << panelPointText(p);
    return parts.join(QStringLiteral(", "));
}

/// A polynomial pair in one unbroken line (the panel scrolls sideways instead).
QString unbrokenPolynomial(const std::string& text)
{
    return QStringLiteral("<span style=\"white-space:nowrap\">%1</span>").arg(ExactPanel::polynomialHtml(text));
}

/// The triangle laid out as the thesis does: one row per i, one column per level r, in
/// blocks of `perTable` levels; `cell(r, i)` gives the HTML of P_i^r.
template <class Cell> QString triangleHtml(int n, int lastLevel, int perTable, Cell cell)
{
    // The cells never break inside (white-space: nowrap): a wide table scrolls sideways.
    QString html;
    for (int r0 = 0; r0 <= lastLevel; r0 += perTable) {
        const int r1 = std::min(lastLevel, r0 + perTable - 1);
        html += QStringLiteral("<table border=\"1\" cellspacing=\"0\"><tr><th></th>");
        for (int r = r0; r <= r1; ++r)
            html += QStringLiteral("<th>%1</th>").arg(levelHtml(QStringLiteral("i"), QString::number(r)));
        html += QStringLiteral("</tr>");
        for (int i = 0; i <= n - r0; ++i) {
            html += QStringLiteral("<tr><td style=\"white-space:nowrap\">i = %1</td>").arg(i);
            for (int r = r0; r <= r1; ++r)
                html += QStringLiteral("<td style=\"white-space:nowrap\">%1</td>").arg(i <= n - r ? cell(r, i) : QString());
            html += QStringLiteral("</tr>");
        }
        html += QStringLiteral("</table><p></p>");
    }
    return html;
}

/// Arc length and curvature at t: κ exact as k/(d√d) for small fractions at a small rational t.
QString exactCurvatureHtml(const DeCasteljauPanelInput& in)
{
    const auto& points = in.points;
    if (points.empty() || !in.arcLength)
        return QString();
    QString html = ExactPanel::heading(
        QCoreApplication::translate("granota::ui::DeCasteljauTab", "Arc length and curvature at t"));
    html += QStringLiteral("<p>%1</p>")
                .arg(QCoreApplication::translate("granota::ui::DeCasteljauTab", "s(t) = %1, L = %2")
                         .arg(panelNumber(*in.arcLength), panelNumber(in.totalLength)));
    // κ = (x′y″ − y′x″)/|c′|³: exact as k/(d√d) with k and d = |c′|² fractions, for rational points and t.
    const int n = static_cast<int>(points.size()) - 1;
    const auto& exactPoints = in.exactPoints;
    const auto exactT = smallRational(in.t, kExactTDenominator);
    std::optional<QString> exact;
    if (exactPoints && exactT && n >= 1 && n <= kMaxExactBezierDegree) {
        const auto H = hodograph(*exactPoints);
        const RPoint d1 = deCasteljauPoint(H, *exactT), d2 = deCasteljauPoint(hodograph(H), *exactT);
        const ExactCurvature k = exactCurvatureAt(*exactPoints, *exactT);
        const auto small = [](const Rational& q) {
            return abs(q.get_num()) <= kExactCurvatureDenominator && q.get_den() <= kExactCurvatureDenominator;
        };
        const auto text = [](const Rational& q) { return QString::fromStdString(toString(q)); };
        if (k.speedSquared == 0)
            exact = QCoreApplication::translate("granota::ui::DeCasteljauTab",
                                                "κ(t) is undefined: c′(t) = 0 (a cusp, or coincident control points), so "
                                                "there is no normal and no osculating circle.");
        else if (small(k.numerator) && small(k.speedSquared))
            if (const auto value = exactCurvatureText(k))
                exact = QCoreApplication::translate("granota::ui::DeCasteljauTab",
                                                    "c′(t) = %1, c″(t) = %2<br>x′y″ − y′x″ = %3, |c′(t)|² = %4<br>κ(t) = "
                                                    "(x′y″ − y′x″)/|c′|³ = %5 ≈ %6")
                            .arg(panelPointText(d1), panelPointText(d2), text(k.numerator), text(k.speedSquared),
                                 QString::fromStdString(*value),
                                 panelNumber(k.numerator.get_d() / std::pow(k.speedSquared.get_d(), 1.5)));
    }
    if (exact)
        html += QStringLiteral("<p>%1</p>").arg(*exact);
    else
        html += QStringLiteral("<p>%1</p>").arg(in.curvatureReadout);
    return html;
}

} // namespace

bool triangleFitsInDoubles(const DeCasteljauTable<double>& table)
{
    for (const auto& level : table.levels)
        for (const Point& p : level)
            if (!isFinite(p))
                return false;
    return isFinite(table.tangent());
}

QString levelHtml(const QString& i, const QString& r) { return QStringLiteral("P<sub>%1</sub><sup>%2</sup>(t)").arg(i, r); }

QString basisHtml(const QString& i, const QString& n, const QString& arg)
{
    return QStringLiteral("B<sub>%1</sub><sup>%2</sup>(%3)").arg(i, n, arg);
}

QString deCasteljauSymbolicHtml(const std::vector<Point>& points, const std::optional<std::vector<RPoint>>& exact)
{
    const int n = static_cast<int>(points.size()) - 1;
    if (!exact)
        return ExactPanel::note(QCoreApplication::translate("granota::ui::DeCasteljauTab",
                                                            "The exact polynomials need control points that are small fractions: "
                                                            "type them in the table (1/3 is accepted) or turn on Snap to grid."));
    if (n > kMaxExactBezierDegree)
        return ExactPanel::note(QCoreApplication::translate("granota::ui::DeCasteljauTab",
                                                            "The levels in powers of t are shown up to degree %1; at degree "
                                                            "%2 their coefficients would no longer be readable.")
                                    .arg(kMaxExactBezierDegree)
                                    .arg(n));
    // Def 2.4 run on polynomials: t is the polynomial t, every P_i^r(t) comes out expanded.
    std::vector<Vec2<RPoly>> symbolic;
    for (const RPoint& p : *exact)
        symbolic.emplace_back(RPoly(p.x), RPoly(p.y));
    const auto table = deCasteljau(symbolic, RPoly::identity());
    QString html = QStringLiteral("<h3>%1</h3>")
                       .arg(QCoreApplication::translate("granota::ui::DeCasteljauTab", "The levels %1 in powers of t (Def 2.4)")
                                .arg(levelHtml(QStringLiteral("i"), QStringLiteral("r"))));
    if (n >= 1)
        html += triangleHtml(n, n - 1, kLevelsPerTable, [&table](int r, int i) {
            return unbrokenPolynomial(toText(table.levels[static_cast<std::size_t>(r)][static_cast<std::size_t>(i)]));
        });
    html += QStringLiteral("<p>%1 = c(t) = %2</p>")
                .arg(levelHtml(QStringLiteral("0"), QString::number(n)), unbrokenPolynomial(toText(table.point())));
    return html;
}

QString deCasteljauPanelHtml(const DeCasteljauPanelInput& in)
{
    const auto& points = in.points;
    if (points.empty() || in.levels.levels.empty())
        return QString();
    const int n = static_cast<int>(points.size()) - 1;
    const auto& exactPoints = in.exactPoints;
    const auto exactT = smallRational(in.t, kExactTDenominator);
    const QString triangleTitle = QCoreApplication::translate("granota::ui::DeCasteljauTab",
                                                              "De Casteljau's triangle at t = %1 (Def 2.4)");
    const QString splitText = QCoreApplication::translate("granota::ui::DeCasteljauTab",
                                                          "Split at t: [0, t] has control points %1; [t, 1] has %2.");
    QString html;
    std::optional<DeCasteljauTable<Rational>> exactTable;
    if (exactPoints && exactT && n <= kMaxExactBezierDegree) {
        exactTable = deCasteljau(*exactPoints, *exactT);
        // Fractions only while they stay readable; decimals otherwise.
        bool readable = true;
        for (const auto& level : exactTable->levels)
            for (const RPoint& q : level)
                readable = readable && q.x.get_den() <= kMaxShownDenominator && q.y.get_den() <= kMaxShownDenominator;
        if (!readable)
            exactTable.reset();
    }
    if (exactTable) {
        // Rational points at a rational t: the triangle in fractions.
        const auto& table = *exactTable;
        html += ExactPanel::heading(triangleTitle.arg(QString::fromStdString(toString(*exactT))));
        html += triangleHtml(n, n, kNumericLevelsPerTable, [&table](int r, int i) {
            return panelPointText(table.levels[static_cast<std::size_t>(r)][static_cast<std::size_t>(i)]);
        });
        html += QStringLiteral("<p>c(t) = %1 = %2<br>c′(t) = %3</p>")
                    .arg(levelHtml(QStringLiteral("0"), QString::number(n)), panelPointText(table.point()),
                         panelPointText(table.tangent()));
        if (in.showSplit)
            html += QStringLiteral("<p>%1</p>")
                        .arg(splitText.arg(joinPanelPoints(table.leftHalf()), joinPanelPoints(table.rightHalf())));
    } else {
        const QString tText = exactT ? QString::fromStdString(toString(*exactT)) : panelNumber(in.t);
        html += ExactPanel::heading(triangleTitle.arg(tText));
        if (!triangleFitsInDoubles(in.levels)) {
            // No wrong number: the values themselves do not exist in double precision.
            html += ExactPanel::note(QCoreApplication::translate(
                "granota::ui::DeCasteljauTab", "The values are too large for a double (beyond ±1.8e308): a level of the "
                                               "triangle or c′(t) overflows. Move the control points closer to the origin."));
            return html + in.symbolicHtml;
        }
        const auto& levels = in.levels;
        if (n <= kMaxTriangleDegree)
            html += triangleHtml(n, n, kNumericLevelsPerTable, [&levels](int r, int i) {
                return panelPointText(levels.levels[static_cast<std::size_t>(r)][static_cast<std::size_t>(i)]);
            });
        else
            html += ExactPanel::note(
                QCoreApplication::translate("granota::ui::DeCasteljauTab",
                                            "The triangle is shown up to degree %1; this curve has degree %2.")
                    .arg(kMaxTriangleDegree)
                    .arg(n));
        // c′(t) from the triangle, unless its doubles could not tell it from 0 and the exact
        // control points gave it (curvature.h: near ±1e308 the triangle says (0, 0) for (21/4, 0)).
        html += QStringLiteral("<p>c(t) = %1 = %2<br>c′(t) = %3</p>")
                    .arg(levelHtml(QStringLiteral("0"), QString::number(n)), panelPointText(levels.point()),
                         panelPointText(in.curvature.exact ? in.curvature.tangent : levels.tangent()));
        if (in.showSplit && n <= kMaxTriangleDegree)
            html += QStringLiteral("<p>%1</p>")
                        .arg(splitText.arg(joinPanelPoints(levels.leftHalf()), joinPanelPoints(levels.rightHalf())));
    }
    html += exactCurvatureHtml(in);
    html += in.symbolicHtml;
    if (!in.warning.isEmpty())
        html += ExactPanel::note(in.warning);
    return html;
}

QString bernsteinPanelHtml(int degree, bool allDegrees, const std::vector<Point>& points,
                           const std::optional<std::vector<RPoint>>& exact)
{
    QString html;
    // Ex 2.4: B_i^n expanded in powers of t.
    for (int n = allDegrees ? 0 : degree; n <= degree; ++n) {
        html += ExactPanel::heading(
            QCoreApplication::translate("granota::ui::BernsteinTab", "Bernstein polynomials of degree %1 (Def 2.5)").arg(n));
        html += QStringLiteral("<p>");
        for (int i = 0; i <= n; ++i)
            html += QStringLiteral("%1 = %2<br>")
                        .arg(basisHtml(QString::number(i), QString::number(n)),
                             ExactPanel::polynomialHtml(toText(bernsteinPolynomial(i, n))));
        html += QStringLiteral("</p>");
    }
    // Ex 2.5, Ex 2.6: the De Casteljau tab's curve written with Def 2.6, term by term.
    const int n = static_cast<int>(points.size()) - 1;
    html += ExactPanel::heading(QCoreApplication::translate("granota::ui::BernsteinTab",
                                                            "The De Casteljau tab's curve in the Bernstein basis (Def 2.6)"));
    if (!exact) {
        html += ExactPanel::note(QCoreApplication::translate(
            "granota::ui::BernsteinTab", "The control points are not small fractions, so the curve is not expanded exactly."));
    } else if (n > kMaxExactBezierDegree) {
        html += ExactPanel::note(QCoreApplication::translate("granota::ui::BernsteinTab",
                                                             "The expansion is shown up to degree %1; the curve has degree %2.")
                                     .arg(kMaxExactBezierDegree)
                                     .arg(n));
    } else {
        const QString nText = QString::number(n);
        html += QStringLiteral("<p>α(t) = Σ<sub>k=0</sub><sup>%1</sup> %2 P<sub>k</sub></p><p>")
                    .arg(nText, basisHtml(QStringLiteral("k"), nText));
        const auto terms = bernsteinTerms(*exact);
        for (int k = 0; k <= n; ++k)
            html += QStringLiteral("%1 P<sub>%2</sub> = (%3) · %4 = %5<br>")
                        .arg(basisHtml(QString::number(k), nText))
                        .arg(k)
                        .arg(ExactPanel::polynomialHtml(toText(bernsteinPolynomial(k, n))),
                             panelPointText((*exact)[static_cast<std::size_t>(k)]),
                             ExactPanel::polynomialHtml(toText(terms[static_cast<std::size_t>(k)])));
        html += QStringLiteral("</p><p><b>α(t) = %1</b></p>").arg(ExactPanel::polynomialHtml(toText(bernsteinSum(*exact))));
    }
    return html;
}

} // namespace granota::ui
