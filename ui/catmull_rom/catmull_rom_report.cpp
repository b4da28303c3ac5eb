#include "ui/catmull_rom/catmull_rom_report.h"

#include "core/curves/splines/bezier_segments.h"
#include "core/curves/splines/continuity_check.h"
#include "core/curves/splines/cubic_spline.h"
#include "core/curves/splines/function_spline_segments.h"
#include "core/curves/splines/knot_continuity.h"
#include "core/exact/polynomial_text.h"
#include "core/curves/splines/segment_joins.h"
#include "core/curves/splines/spline_offset_correction.h"
#include "core/io/worked_examples.h"
#include "ui/common/exact_panel.h"
#include "ui/common/number_text.h"

#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {

constexpr double kTolerance = 1e-9; ///< relative, for comparisons in doubles (continuity_check.h)
constexpr double kPi = 3.14159265358979323846;

QString text(const std::string& s) { return QString::fromStdString(s); }
QString tauText(const Rational& t) { return text(toString(t)); }
template <class S> QString poly(const Polynomial<S>& p, const char* var = "t")
{
    return ExactPanel::polynomialHtml(toText(p, var));
}
template <class S> QString vec(const Vec2<S>& v) { return text(detail::scalarText(v)).toHtmlEscaped(); }
QString para(const QString& html) { return QStringLiteral("<p>%1</p>").arg(html); }
/// Escapes `plain` and writes C^2 as C<sup>2</sup> (plainText() gives back "C^2").
QString esc(const QString& plain)
{
    QString html = plain.toHtmlEscaped();
    html.replace(QRegularExpression(QStringLiteral("\\^(\\d+|∞)")), QStringLiteral("<sup>\\1</sup>"));
    return html;
}

QString segmentName(int index, int count, CatmullRomEnds ends)
{
    if (ends == CatmullRomEnds::Segment && count == 1)
        return QStringLiteral("p(t)");
    return ExactPanel::subscripted(QStringLiteral("p"), index + 1 + firstSegmentStart(ends)) + QStringLiteral("(t)");
}

template <class S> QString segmentTable(const std::vector<Vec2<Polynomial<S>>>& segs, CatmullRomEnds ends)
{
    std::vector<QStringList> rows;
    const int count = static_cast<int>(segs.size());
    const int shown = std::min(count, CatmullRomReport::kMaxListedSegments);
    for (int i = 0; i < shown; ++i) {
        const auto& s = segs[static_cast<std::size_t>(i)];
        rows.push_back({segmentName(i, count, ends), poly(s.x), poly(s.y)});
    }
    QString html = ExactPanel::table({QString(), QStringLiteral("x(t)"), QStringLiteral("y(t)")}, rows);
    if (count > shown)
        html += ExactPanel::note(CatmullRomReport::tr("… and %n more segments.", nullptr, count - shown));
    return html;
}

template <class S> QString defectText(const ContinuityDefect<S>& d)
{
    const QString x = text(detail::scalarText(d.x));
    switch (d.kind) {
    case DefectKind::Jump:
        return CatmullRomReport::tr("%1 jumps at x = %2: left %3, right %4 (jump %5)")
            .arg(text(detail::derivativeName("s", d.order)), x, text(detail::scalarText(d.left)),
                 text(detail::scalarText(d.right)), text(detail::scalarText(d.jump())));
    case DefectKind::NotInterpolated:
        return CatmullRomReport::tr("%1 does not interpolate (%2, %3): %1(%2) = %4")
            .arg(QStringLiteral("s_%1").arg(d.piece + 1), x, text(detail::scalarText(d.expected)),
                 text(detail::scalarText(d.got)));
    case DefectKind::OutsideDomain:
        return CatmullRomReport::tr("The point (%1, %2) lies outside the domain.").arg(x, text(detail::scalarText(d.expected)));
    }
    return {};
}

/// "✓ C² at every knot; interpolates all 4 points" or the failures, one per line.
template <class S> QString continuitySummary(const ContinuityReport<S>& report, int checkedUpTo)
{
    QString html;
    const int order = report.continuityOrder();
    if (order < 0)
        html += ExactPanel::checkMark(false) + QLatin1Char(' ') + CatmullRomReport::tr("not continuous").toHtmlEscaped();
    else if (order >= checkedUpTo)
        html += ExactPanel::checkMark(true) + QLatin1Char(' ') + esc(CatmullRomReport::tr("C^%1 at every knot").arg(order));
    else
        html += ExactPanel::checkMark(order >= 2) + QLatin1Char(' ') +
                esc(CatmullRomReport::tr("C^%1, not C^%2").arg(order).arg(order + 1));
    html += QStringLiteral("; ");
    if (report.interpolates())
        html += ExactPanel::checkMark(true) + QLatin1Char(' ') +
                CatmullRomReport::tr("interpolates all %n points", nullptr, report.dataPoints).toHtmlEscaped();
    else
        html += ExactPanel::checkMark(false) + QLatin1Char(' ') +
                CatmullRomReport::tr("does not interpolate every point").toHtmlEscaped();
    html = para(html);
    QStringList lines;
    for (const auto& d : report.defects)
        if (d.kind != DefectKind::Jump || d.order <= std::max(order, 0) + 1)
            lines << defectText(d).toHtmlEscaped();
    if (!lines.isEmpty())
        html += para(lines.join(QStringLiteral("<br>")));
    return html;
}

/// The knot table of a function spline: x_i and, per derivative order, ✓ or ✗.
template <class S> QString knotTable(const PiecewisePolynomial<S>& spline, const ContinuityReport<S>& report)
{
    QStringList header{CatmullRomReport::tr("knot")};
    for (int k = 0; k <= report.maxOrder; ++k)
        header << text(detail::derivativeName("s", k)).toHtmlEscaped();
    std::vector<QStringList> rows;
    for (int i = 1; i < spline.pieceCount(); ++i) {
        QStringList row{QStringLiteral("x = %1").arg(text(detail::scalarText(spline.knots[static_cast<std::size_t>(i)])))};
        for (int k = 0; k <= report.maxOrder; ++k) {
            const bool bad = std::any_of(report.defects.begin(), report.defects.end(), [&](const auto& d) {
                return d.kind == DefectKind::Jump && d.knot == i && d.order == k;
            });
            row << ExactPanel::checkMark(!bad);
        }
        rows.push_back(row);
    }
    return ExactPanel::table(header, rows);
}

/// Prop 2.3 for one τ: a summary line, and for the selected τ the table knot by knot.
template <class S>
QString tangentSection(const std::vector<Vec2<Polynomial<S>>>& segs, const Rational& tau, CatmullRomEnds ends, int pointCount,
                       bool uniform, bool withTable)
{
    const bool closed = ends == CatmullRomEnds::Closed;
    const double tol = std::is_floating_point_v<S> ? kTolerance : 0.0;
    const auto joins = segmentJoinValues(segs, 1, closed, tol);
    const auto report = checkSegmentJoins(segs, 2, closed, tol);
    const bool allEqual = std::all_of(joins.begin(), joins.end(), [](const auto& j) { return j.equal; });
    const bool allParallel = std::all_of(joins.begin(), joins.end(), [](const auto& j) { return j.parallel; });
    QString line = QStringLiteral("<b>τ = %1</b>: ").arg(tauText(tau));
    if (joins.empty()) {
        line += CatmullRomReport::tr("no interior knot").toHtmlEscaped();
    } else if (allEqual) {
        line +=
            ExactPanel::checkMark(true) + QLatin1Char(' ') +
            CatmullRomReport::tr("equal tangents at all %n knots (C¹)", nullptr, static_cast<int>(joins.size())).toHtmlEscaped();
        line += QStringLiteral("; ") + (report.continuityOrder() >= 2 ? CatmullRomReport::tr("C² too (p″ matches)")
                                                                      : CatmullRomReport::tr("not C²: p″ jumps"))
                                           .toHtmlEscaped();
    } else if (allParallel && !uniform) {
        line += ExactPanel::checkMark(true) + QLatin1Char(' ') +
                CatmullRomReport::tr("parallel tangents at all %n knots (G¹), not equal ones (C¹) in the local "
                                     "parameters",
                                     nullptr, static_cast<int>(joins.size()))
                    .toHtmlEscaped();
    } else {
        line += ExactPanel::checkMark(false) + QLatin1Char(' ') +
                CatmullRomReport::tr("the tangents differ at some knots").toHtmlEscaped();
    }
    QString html = para(line);
    if (!withTable || joins.empty())
        return html;
    std::vector<QStringList> rows;
    const int shown = std::min(static_cast<int>(joins.size()), CatmullRomReport::kMaxListedSegments);
    for (int j = 0; j < shown; ++j) {
        const auto& v = joins[static_cast<std::size_t>(j)];
        const int knot = (v.fromSegment + firstSegmentStart(ends) + 1) % std::max(pointCount, 1);
        const int from = v.fromSegment + 1 + firstSegmentStart(ends), to = v.toSegment + 1 + firstSegmentStart(ends);
        QString verdict = ExactPanel::checkMark(v.equal);
        if (!v.equal && v.parallel)
            verdict += QStringLiteral(" G¹ ") + ExactPanel::checkMark(true);
        rows.push_back({ExactPanel::subscripted(QStringLiteral("q"), knot),
                        ExactPanel::subscripted(QStringLiteral("p"), from) + QStringLiteral("′(1) = ") + vec(v.left),
                        ExactPanel::subscripted(QStringLiteral("p"), to) + QStringLiteral("′(0) = ") + vec(v.right), verdict});
    }
    html += ExactPanel::table({CatmullRomReport::tr("knot"), CatmullRomReport::tr("end of the segment before"),
                               CatmullRomReport::tr("start of the segment after"), QString()},
                              rows);
    return html;
}

/// A point as the panel shows it: exact fractions, or six significant digits, in the interface's decimals.
QString shownPoint(const Vec2<Rational>& v) { return displayText(detail::scalarText(v)).toHtmlEscaped(); }
QString shownPoint(const Vec2<double>& v)
{
    return displayPair(displaySignificant(v.x, 6), displaySignificant(v.y, 6)).toHtmlEscaped();
}

/// The control points b_0..b_3 of each segment (bezier_segments.h), `firstName` the index of
/// the first segment's name (p_1, or s_1 for the spline's pieces).
template <class S> QString bezierTable(const std::vector<BezierSegment<S>>& segments, const QString& name, int firstName)
{
    std::vector<QStringList> rows;
    const int count = static_cast<int>(segments.size());
    const int shown = std::min(count, CatmullRomReport::kMaxListedSegments);
    for (int i = 0; i < shown; ++i) {
        const auto& b = segments[static_cast<std::size_t>(i)];
        rows.push_back({ExactPanel::subscripted(name, i + firstName), shownPoint(b[0]), shownPoint(b[1]), shownPoint(b[2]),
                        shownPoint(b[3])});
    }
    QString html = ExactPanel::table(
        {QString(), ExactPanel::subscripted(QStringLiteral("b"), 0), ExactPanel::subscripted(QStringLiteral("b"), 1),
         ExactPanel::subscripted(QStringLiteral("b"), 2), ExactPanel::subscripted(QStringLiteral("b"), 3)},
        rows);
    if (count > shown)
        html += ExactPanel::note(CatmullRomReport::tr("… and %n more segments.", nullptr, count - shown));
    return html;
}

QString orderText(const char* letter, int order)
{
    return order < 0 ? CatmullRomReport::tr("broken").toHtmlEscaped()
                     : esc(QStringLiteral("%1^%2").arg(QLatin1String(letter)).arg(order));
}

/// One row per knot: its C and G order (knot_continuity.h), the jump of the first derivative
/// in the knot parameter that differs (p″ at a C¹ knot), and κ on both sides where the knot
/// is not G². `knotName(k)` names the point at the knot.
template <class S, class Name> QString continuityTable(const std::vector<KnotContinuity<S>>& knots, const Name& knotName)
{
    if (knots.empty())
        return para(CatmullRomReport::tr("no interior knot").toHtmlEscaped());
    int lowestC = 2, lowestG = 2;
    for (const auto& k : knots) {
        lowestC = std::min(lowestC, k.parametricOrder());
        lowestG = std::min(lowestG, k.geometricOrder());
    }
    QString html;
    if (lowestC >= 0)
        html += para(esc(
            CatmullRomReport::tr("At every knot at least C^%1 and G^%2 (of %n knots).", nullptr, static_cast<int>(knots.size()))
                .arg(lowestC)
                .arg(lowestG)));
    std::vector<QStringList> rows;
    const int count = static_cast<int>(knots.size());
    const int shown = std::min(count, CatmullRomReport::kMaxListedSegments);
    const auto number = [](double v) { return displaySignificant(v, 6).toHtmlEscaped(); };
    for (int i = 0; i < shown; ++i) {
        const auto& k = knots[static_cast<std::size_t>(i)];
        const int c = k.parametricOrder(), g = k.geometricOrder();
        QString jump = QStringLiteral("—");
        if (c >= 0 && c < 2) {
            const char* name = c == 0 ? "p′" : "p″";
            jump = QStringLiteral("Δ%1 = %2").arg(QString::fromUtf8(name), shownPoint(k.jump(c + 1)));
        }
        QString kappa = QStringLiteral("—");
        if (g >= 0 && g < 2) {
            if (k.curvatureLeft && k.curvatureRight)
                kappa = QStringLiteral("%1 → %2 (Δκ = %3)")
                            .arg(number(*k.curvatureLeft), number(*k.curvatureRight),
                                 number(*k.curvatureRight - *k.curvatureLeft));
            else
                kappa = CatmullRomReport::tr("undefined: p′ = 0").toHtmlEscaped();
            if (g == 0 && k.tangentTurn)
                kappa += QStringLiteral("; ") + CatmullRomReport::tr("the tangent turns by %1°")
                                                    .arg(displaySignificant(*k.tangentTurn * 180.0 / kPi, 4))
                                                    .toHtmlEscaped();
        } else if (g == 2 && k.curvatureLeft) {
            kappa = QStringLiteral("κ = %1").arg(number(*k.curvatureLeft));
        }
        rows.push_back({knotName(k), orderText("C", c), orderText("G", g), jump, kappa});
    }
    html += ExactPanel::table({CatmullRomReport::tr("knot"), CatmullRomReport::tr("C order"), CatmullRomReport::tr("G order"),
                               CatmullRomReport::tr("jump"), CatmullRomReport::tr("curvature κ left → right")},
                              rows);
    if (count > shown)
        html += ExactPanel::note(CatmullRomReport::tr("… and %n more knots.", nullptr, count - shown));
    return html;
}

/// §2.3 knot by knot for the selected τ (and the spline): its cubic Bézier segments and the
/// continuity at every knot, exactly when the segment polynomials are exact.
QString bezierSection(const std::vector<Point>& points, const CatmullRomSettings& settings, const CatmullRomScene& scene,
                      const CatmullRomAnalysis& analysis)
{
    const int selected = settings.selectedTau;
    if (selected < 0 || selected >= static_cast<int>(settings.taus.size()))
        return {};
    const Rational& tau = settings.taus[static_cast<std::size_t>(selected)];
    const CatmullRomEnds ends = settings.ends;
    const bool closed = ends == CatmullRomEnds::Closed;
    const int count = static_cast<int>(points.size());
    QString html = ExactPanel::heading(CatmullRomReport::tr("Bézier segments and the knots (§2.3)"));
    html += para(CatmullRomReport::tr("Each segment as a cubic Bézier curve: b0 = p(0), b1 = b0 + p′(0)/3, "
                                      "b2 = b3 − p′(1)/3, b3 = p(1); for Def 2.8, b1 = p1 + τ(p2 − p0)/3 and "
                                      "b2 = p2 − τ(p3 − p1)/3. Cᵏ: equal derivatives up to order k at the knot; "
                                      "Gᵏ: the same tangent direction (G¹) and curvature (G²).")
                     .toHtmlEscaped());
    if (settings.spacing != CatmullRomSpacing::Uniform)
        html += ExactPanel::note(CatmullRomReport::tr("Centripetal and chordal spacing: the derivatives are taken in "
                                                      "the knot parameter u, in which segment i has length "
                                                      "hᵢ = |qᵢ₊₁ − qᵢ|ᵅ. There the curve is C¹; in the local "
                                                      "parameters the tangents are only parallel (G¹)."));
    const auto knotName = [&](int fromSegment, int offset) {
        return ExactPanel::subscripted(QStringLiteral("q"), (fromSegment + offset + 1) % std::max(count, 1));
    };
    html += para(QStringLiteral("<b>τ = %1</b>, %2").arg(tauText(tau), CatmullRomReport::endsName(ends).toHtmlEscaped()));
    const int offset = firstSegmentStart(ends);
    if (analysis.exactCurves) {
        const auto& segs = analysis.ends.front().curves[static_cast<std::size_t>(selected)].segments;
        if (!segs)
            return html + ExactPanel::note(translatedError(segs.error(), ends));
        html += bezierTable(analysis.selectedBezier, QStringLiteral("p"), 1 + offset);
        html += continuityTable(analysis.selectedKnots,
                                [&](const KnotContinuity<Rational>& k) { return knotName(k.fromSegment, offset); });
    } else if (selected < static_cast<int>(scene.curves.size())) {
        const CatmullRomCurve& c = scene.curves[static_cast<std::size_t>(selected)];
        if (!c.error.isEmpty())
            return html + ExactPanel::note(c.error);
        html += bezierTable(c.bezier, QStringLiteral("p"), 1 + offset);
        html += continuityTable(knotContinuity(c.segments, c.intervals, closed, kTolerance),
                                [&](const KnotContinuity<double>& k) { return knotName(k.fromSegment, offset); });
    }
    if (settings.spline && scene.splineError.isEmpty()) {
        html += para(QStringLiteral("<b>%1</b>").arg(CatmullRomReport::tr("Cubic spline C² (Def 2.3)").toHtmlEscaped()));
        html += para(CatmullRomReport::tr("Its graph (x, s(x)) piece by piece, x = xᵢ + hᵢ u, u ∈ [0, 1]; the "
                                          "derivatives in x.")
                         .toHtmlEscaped());
        const auto splineKnot = [&](int fromSegment) { return ExactPanel::subscripted(QStringLiteral("q"), fromSegment + 1); };
        if (analysis.spline && *analysis.spline) {
            html += bezierTable(analysis.splineBezier, QStringLiteral("s"), 1);
            html += continuityTable(analysis.splineKnots,
                                    [&](const KnotContinuity<Rational>& k) { return splineKnot(k.fromSegment); });
        } else if (!scene.splineSegments.empty()) {
            html += bezierTable(scene.splineBezier, QStringLiteral("s"), 1);
            html += continuityTable(knotContinuity(scene.splineSegments, scene.splineIntervals, false, kTolerance),
                                    [&](const KnotContinuity<double>& k) { return splineKnot(k.fromSegment); });
        }
    }
    return html;
}

QString matrixSection(const CatmullRomSettings& settings)
{
    QString html = ExactPanel::heading(CatmullRomReport::tr("Matrix form (Lemma 2.3)"));
    html += para(QStringLiteral("p(t) = [1 t t<sup>2</sup> t<sup>3</sup>] M(τ) [p<sub>0</sub> p<sub>1</sub> "
                                "p<sub>2</sub> p<sub>3</sub>]<sup>T</sup>"));
    for (const Rational& tau : settings.taus) {
        const Matrix4<Rational> m = catmullRomMatrix(tau);
        std::vector<std::vector<std::string>> entries;
        for (const auto& row : m) {
            std::vector<std::string> r;
            for (const Rational& e : row)
                r.push_back(toString(e));
            entries.push_back(r);
        }
        html += ExactPanel::matrix(QStringLiteral("M(τ = %1)").arg(tauText(tau)), entries);
    }
    return html;
}

QString blendingSection(const CatmullRomSettings& settings)
{
    QString html = ExactPanel::heading(CatmullRomReport::tr("Blending functions wⱼ(t, τ) (Def 2.9, Cor 2.1)"));
    for (const Rational& tau : settings.taus) {
        const auto w = blendingFunctions(tau);
        std::vector<QStringList> rows;
        for (int j = 0; j < 4; ++j)
            rows.push_back(
                {ExactPanel::subscripted(QStringLiteral("w"), j) + QStringLiteral("(t)"), poly(w[static_cast<std::size_t>(j)])});
        html += para(QStringLiteral("<b>τ = %1</b>").arg(tauText(tau))) + ExactPanel::table({}, rows);
    }
    return html;
}

QString processingSection(const CatmullRomSettings& settings)
{
    QString html = ExactPanel::heading(CatmullRomReport::tr("Processing's curveTightness"));
    html += para(CatmullRomReport::tr("Processing draws the same curves with curveTightness(s), τ = (1 − s)/2: "
                                      "s = 0 (its default) is τ = 1/2.")
                     .toHtmlEscaped());
    std::vector<QStringList> rows;
    for (const Rational& tau : settings.taus) {
        const Rational s = Rational(1) - Rational(2) * tau; // tauToCurveTightness, exactly
        rows.push_back({QStringLiteral("τ = %1").arg(tauText(tau)), QStringLiteral("curveTightness(%1)").arg(tauText(s))});
    }
    return html + ExactPanel::table({}, rows);
}

/// Ex 2.1's spline as printed, checked; the constant its s₂ lacks; the corrected pieces checked.
QString example21Section(const std::vector<RPoint>& data, SplineEnds ends)
{
    const WorkedExample* ex = findWorkedExample("2.1");
    if (!ex || ex->points != data)
        return {};
    const Json* printedJson = ex->data.find("pieces_as_printed");
    if (!printedJson || !printedJson->asArray())
        return {};
    PiecewisePolynomial<Rational> printed;
    for (const RPoint& p : data)
        printed.knots.push_back(p.x);
    for (const Json& item : *printedJson->asArray()) {
        const auto pieceText = item.asString();
        const auto piece = pieceText ? parsePolynomial(*pieceText, 'x') : std::nullopt;
        if (!piece)
            return {};
        printed.pieces.push_back(*piece);
    }
    if (!printed.isValid())
        return {};
    QString html = ExactPanel::heading(CatmullRomReport::tr("Ex 2.1 as printed in the thesis"));
    std::vector<QStringList> rows;
    for (int i = 0; i < printed.pieceCount(); ++i)
        rows.push_back({ExactPanel::subscripted(QStringLiteral("s"), i + 1) + QStringLiteral("(x)"),
                        poly(printed.pieces[static_cast<std::size_t>(i)], "x")});
    html += ExactPanel::table({}, rows);
    const auto report = checkContinuity(printed, 2, data);
    html += para(CatmullRomReport::tr("The check of Def 2.3 on the printed pieces:").toHtmlEscaped());
    html += continuitySummary(report, 2);
    const auto fix = correctConstantOffsets(printed, data);
    for (const auto& c : fix.corrections) {
        const QString name = QStringLiteral("s_%1").arg(c.piece + 1);
        const QString offset = (c.offset > 0 ? QStringLiteral("+") : QString()) + tauText(c.offset);
        html += para(CatmullRomReport::tr("%1 as printed misses both of its points by the same constant: it lacks %2.")
                         .arg(name, offset)
                         .toHtmlEscaped());
        html += para(CatmullRomReport::tr("Correct %1:").arg(name).toHtmlEscaped() + QStringLiteral(" ") +
                     ExactPanel::subscripted(QStringLiteral("s"), c.piece + 1) + QStringLiteral("(x) = ") +
                     poly(fix.corrected.pieces[static_cast<std::size_t>(c.piece)], "x"));
    }
    if (!fix.corrections.empty()) {
        html += para(CatmullRomReport::tr("The corrected spline:").toHtmlEscaped());
        html += continuitySummary(checkContinuity(fix.corrected, 2, data), 2);
        html += ExactPanel::note(
            ends == SplineEnds::AsEx21
                ? CatmullRomReport::tr("With Ex 2.1's ends — s₁‴ = 0 (s₁ is a parabola) and no x² term in s₃ — the "
                                       "pieces above are exactly the corrected ones (docs/thesis-errata.md, “Ex 2.1”).")
                : CatmullRomReport::tr("Ex 2.1's spline is a cubic spline (Def 2.3) but not the natural one: s″ ≠ 0 at its "
                                       "ends, so its pieces differ from those above. Choose the ends “As Ex 2.1” to get "
                                       "them (docs/thesis-errata.md, “Ex 2.1”)."));
    }
    return html;
}

QString splineSection(const std::vector<Point>& points, const std::optional<std::vector<RPoint>>& rational,
                      const CatmullRomSettings& settings, const CatmullRomScene& scene, const CatmullRomAnalysis& analysis)
{
    QString html = ExactPanel::heading(
        CatmullRomReport::tr("Cubic spline C² (Def 2.3), %1").arg(CatmullRomReport::splineEndsName(settings.splineEnds)));
    if (!scene.splineError.isEmpty())
        return html + ExactPanel::note(scene.splineError);
    if (rational && analysis.spline) {
        const auto& spline = *analysis.spline;
        if (!spline)
            return html + ExactPanel::note(translatedError(spline.error(), CatmullRomEnds::Open));
        std::vector<QStringList> rows;
        const int shown = std::min(spline->pieceCount(), CatmullRomReport::kMaxListedSegments);
        for (int i = 0; i < shown; ++i)
            rows.push_back({ExactPanel::subscripted(QStringLiteral("s"), i + 1) + QStringLiteral("(x)"),
                            QStringLiteral("[%1, %2]")
                                .arg(tauText(spline->knots[static_cast<std::size_t>(i)]),
                                     tauText(spline->knots[static_cast<std::size_t>(i) + 1])),
                            poly(spline->pieces[static_cast<std::size_t>(i)], "x")});
        html += ExactPanel::table({}, rows);
        html += continuitySummary(analysis.splineCheck, 2) + knotTable(*spline, analysis.splineCheck);
        html += example21Section(*rational, settings.splineEnds);
    } else if (const auto& spline = scene.splinePieces) {
        html += para(CatmullRomReport::tr("In decimals, each piece in powers of u = x − xᵢ:").toHtmlEscaped());
        std::vector<QStringList> rows;
        const int shown = std::min(spline->pieceCount(), CatmullRomReport::kMaxListedSegments);
        for (int i = 0; i < shown; ++i)
            rows.push_back({ExactPanel::subscripted(QStringLiteral("s"), i + 1), poly(spline->localPiece(i), "u")});
        html += ExactPanel::table({}, rows);
        const auto report = checkContinuity(*spline, kSplineCheckedOrder, points, kTolerance);
        html += continuitySummary(report, 2) + knotTable(*spline, report);
    }
    return html;
}

} // namespace

QString CatmullRomReport::splineEndsName(SplineEnds ends)
{
    switch (ends) {
    case SplineEnds::Natural: return tr("natural ends");
    case SplineEnds::Clamped: return tr("clamped ends");
    case SplineEnds::NotAKnot: return tr("not-a-knot ends");
    case SplineEnds::AsEx21: return tr("the ends of Ex 2.1");
    }
    return {};
}

QString CatmullRomReport::endsName(CatmullRomEnds ends)
{
    switch (ends) {
    case CatmullRomEnds::Open: return tr("open");
    case CatmullRomEnds::Cyclic: return tr("cyclic");
    case CatmullRomEnds::Closed: return tr("closed");
    case CatmullRomEnds::Segment: return tr("single segment");
    }
    return {};
}

QString CatmullRomReport::html(const std::vector<Point>& points, const CatmullRomSettings& settings, const CatmullRomScene& scene,
                               const CatmullRomAnalysis& analysis)
{
    const auto& rational = analysis.points;
    const bool uniform = settings.spacing == CatmullRomSpacing::Uniform;
    const bool exact = analysis.exactCurves;
    const int count = static_cast<int>(points.size());
    QString html;
    if (settings.spline)
        html += splineSection(points, rational, settings, scene, analysis);

    // Segments (Def 2.10), the current mode and, for Ex 2.13, the other one.
    std::vector<CatmullRomEnds> modes{settings.ends};
    if (settings.compareEnds)
        modes.push_back(comparedEnds(settings.ends));
    for (std::size_t m = 0; m < modes.size(); ++m) {
        const CatmullRomEnds ends = modes[m];
        html += ExactPanel::heading(tr("Segments, t ∈ [0, 1]: %1").arg(endsName(ends)));
        if (!exact)
            html += ExactPanel::note(!uniform ? tr("Centripetal and chordal spacing: coefficients in decimals.")
                                              : tr("The points are not small fractions: coefficients in decimals."));
        const auto& curves = m == 0 ? scene.curves : scene.otherEnds;
        for (std::size_t i = 0; i < settings.taus.size(); ++i) {
            const Rational& tau = settings.taus[i];
            html += para(QStringLiteral("<b>τ = %1</b>").arg(tauText(tau)));
            if (exact) {
                const auto& segs = analysis.ends[m].curves[i].segments;
                html += segs ? segmentTable(*segs, ends) : ExactPanel::note(translatedError(segs.error(), ends));
            } else if (i < curves.size()) {
                html += curves[i].error.isEmpty() ? segmentTable(curves[i].segments, ends) : ExactPanel::note(curves[i].error);
            }
        }
    }

    // Prop 2.3, knot by knot for the selected τ.
    html += ExactPanel::heading(tr("Tangents at the knots (Prop 2.3)"));
    html += para(tr("Catmull-Rom curves are C¹: at every knot cᵢ′(1) = cᵢ₊₁′(0) = τ(qᵢ₊₁ − qᵢ₋₁).").toHtmlEscaped());
    // The lowest C order over the knots (2 when there are none: one polynomial, checked up to C²).
    const auto lowestOrder = [](const std::vector<KnotContinuity<double>>& knots) {
        int order = 2;
        for (const auto& k : knots)
            order = std::min(order, k.parametricOrder());
        return order;
    };
    int selectedOrder = -1;
    for (std::size_t i = 0; i < settings.taus.size(); ++i) {
        const Rational& tau = settings.taus[i];
        const bool table = static_cast<int>(i) == settings.selectedTau;
        const bool closed = settings.ends == CatmullRomEnds::Closed;
        if (exact) {
            const auto& segs = analysis.ends.front().curves[i].segments;
            if (!segs)
                continue;
            html += tangentSection(*segs, tau, settings.ends, count, true, table);
            if (table)
                selectedOrder = analysis.selectedOrder();
        } else if (i < scene.curves.size() && scene.curves[i].error.isEmpty()) {
            html += tangentSection(scene.curves[i].segments, tau, settings.ends, count, uniform, table);
            if (table) // in the knot parameter, as the knot table above: centripetal and chordal curves are C¹
                selectedOrder = lowestOrder(
                    knotContinuity(scene.curves[i].segments, scene.curves[i].intervals, closed, kTolerance));
        }
    }

    // §2.3 knot by knot: Bézier segments, C and G orders, the jumps.
    html += bezierSection(points, settings, scene, analysis);

    // §2.3: what each kind of curve guarantees.
    if (settings.bezier || settings.spline) {
        html += ExactPanel::heading(tr("Smoothness compared (§2.3)"));
        std::vector<QStringList> rows;
        if (settings.bezier)
            rows.push_back(
                {tr("Bézier, degree %1").arg(count - 1), esc(tr("C^∞: one polynomial")), tr("only q0 and q%1").arg(count - 1)});
        if (settings.selectedTau >= 0 && settings.selectedTau < static_cast<int>(settings.taus.size()))
            rows.push_back({tr("Catmull-Rom, τ = %1").arg(tauText(settings.taus[static_cast<std::size_t>(settings.selectedTau)])),
                            selectedOrder >= 0 ? esc(tr("C^%1 at the joins (checked)").arg(std::min(selectedOrder, 2)))
                                               : tr("not C¹ at the joins (checked)"),
                            tr("every point")});
        if (settings.spline)
            rows.push_back({tr("Cubic spline"), scene.splineError.isEmpty() ? tr("C² (checked above)") : tr("not defined"),
                            scene.splineError.isEmpty() ? tr("every point") : QStringLiteral("—")});
        html += ExactPanel::table({tr("curve"), tr("smoothness"), tr("passes through")}, rows);
        if (settings.bezier)
            html += para(tr("The Bézier curve only approaches the inner points: Catmull-Rom passes through all of "
                            "them, which is why the thesis chose it for the frog (§2.3, §4.12).")
                             .toHtmlEscaped());
    }

    html += matrixSection(settings);
    html += blendingSection(settings);
    html += processingSection(settings);
    return html;
}

} // namespace granota::ui
