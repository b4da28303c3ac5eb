#include "ui/catmull_rom/family_report.h"

#include "core/curves/splines/cardinal_spline.h"
#include "core/curves/splines/catmull_rom_ends.h"
#include "core/curves/splines/continuity_check.h"
#include "core/curves/splines/hermite_segment.h"
#include "core/curves/splines/kochanek_bartels.h"
#include "core/curves/splines/parametric_spline.h"
#include "core/exact/polynomial_text.h"
#include "core/exact/rational_approximation.h"
#include "ui/catmull_rom/curve_family.h"
#include "ui/catmull_rom/catmull_rom_report.h"
#include "ui/catmull_rom/family_curves.h"
#include "ui/common/exact_panel.h"
#include "ui/common/number_text.h"

#include <algorithm>

namespace granota::ui {

namespace {

/// A point or a tangent as the panel shows it: exact fractions, or six significant digits.
QString familyReportVec(const Vec2<Rational>& v) { return displayText(detail::scalarText(v)).toHtmlEscaped(); }
QString familyReportVec(const Vec2<double>& v)
{
    return displayPair(displaySignificant(v.x, 6), displaySignificant(v.y, 6)).toHtmlEscaped();
}
QString familyReportNumber(const Rational& r) { return displayText(toString(r)).toHtmlEscaped(); }

QString familyReportPoint(std::size_t i) { return ExactPanel::subscripted(QStringLiteral("q"), static_cast<int>(i)); }

/// The tangents at every point: in and out (with T, C, B) for Kochanek–Bartels, one tangent
/// where the family's in and out are equal by construction.
template <class S> QString familyReportTangents(const std::vector<KbTangents<S>>& tangents, const CatmullRomSettings& settings)
{
    const bool kb = settings.family == CurveFamily::KochanekBartels;
    std::vector<QStringList> rows;
    const std::size_t shown = std::min<std::size_t>(tangents.size(), CatmullRomSettings::kMaxPoints);
    for (std::size_t i = 0; i < shown; ++i) {
        const auto& t = tangents[i];
        if (kb) {
            const TcbKnot<Rational> k = tcbAt(settings, i);
            rows.push_back({familyReportPoint(i),
                            QStringLiteral("%1, %2, %3")
                                .arg(familyReportNumber(k.tension), familyReportNumber(k.continuity), familyReportNumber(k.bias)),
                            familyReportVec(t.in), familyReportVec(t.out)});
        } else {
            rows.push_back({familyReportPoint(i), familyReportVec(t.out)});
        }
    }
    if (kb)
        return ExactPanel::table({QString(), QStringLiteral("T, C, B"), FamilyReport::tr("in"), FamilyReport::tr("out")}, rows);
    return ExactPanel::table({QString(), FamilyReport::tr("tangent")}, rows);
}

/// Each segment as Def 2.8 builds it (its two points and two tangents) and as a cubic Bézier
/// curve (hermite_segment.h: b₁ = p(0) + p′(0)/3, b₂ = p(1) − p′(1)/3).
template <class S> QString familyReportSegments(const std::vector<HermiteSegment<S>>& segments, std::size_t n, int first)
{
    std::vector<QStringList> hermite, bezier;
    const int count = static_cast<int>(segments.size());
    const int shown = std::min(count, 24);
    for (int k = 0; k < shown && n > 0; ++k) {
        const auto& s = segments[static_cast<std::size_t>(k)];
        const std::size_t a = (static_cast<std::size_t>(first) + static_cast<std::size_t>(k)) % n, b = (a + 1) % n;
        const QString name = familyReportPoint(a) + QStringLiteral(" → ") + familyReportPoint(b);
        hermite.push_back({name, familyReportVec(s.m0), familyReportVec(s.m1)});
        const auto c = hermiteToBezier(s);
        bezier.push_back({name, familyReportVec(c[0]), familyReportVec(c[1]), familyReportVec(c[2]), familyReportVec(c[3])});
    }
    QString html = ExactPanel::heading(FamilyReport::tr("Segments as Hermite data (Def 2.8)"));
    html += ExactPanel::table({FamilyReport::tr("segment"), QStringLiteral("p′(0)"), QStringLiteral("p′(1)")}, hermite);
    html += ExactPanel::heading(FamilyReport::tr("Segments as cubic Bézier curves"));
    html += ExactPanel::table({FamilyReport::tr("segment"), ExactPanel::subscripted(QStringLiteral("b"), 0),
                               ExactPanel::subscripted(QStringLiteral("b"), 1), ExactPanel::subscripted(QStringLiteral("b"), 2),
                               ExactPanel::subscripted(QStringLiteral("b"), 3)},
                              bezier);
    if (count > shown)
        html += ExactPanel::note(FamilyReport::tr("… and %n more segments.", nullptr, count - shown));
    return html;
}

/// The Hermite family's segments exactly, when every coordinate (the points' and the student's
/// tangents') is a small fraction; nullopt otherwise.
std::optional<std::vector<HermiteSegment<Rational>>> familyReportExactHermite(const std::vector<HermiteSegment<double>>& segs)
{
    std::vector<HermiteSegment<Rational>> out;
    for (const auto& s : segs) {
        HermiteSegment<Rational> r;
        for (const auto& [from, to] :
             {std::pair{&s.p0, &r.p0}, std::pair{&s.p1, &r.p1}, std::pair{&s.m0, &r.m0}, std::pair{&s.m1, &r.m1}}) {
            const auto x = smallRational(from->x), y = smallRational(from->y);
            if (!x || !y)
                return std::nullopt;
            *to = Vec2<Rational>(*x, *y);
        }
        out.push_back(r);
    }
    return out;
}

template <class S>
QString familyReportBody(const std::vector<HermiteSegment<S>>& segments, const std::vector<KbTangents<S>>& tangents,
                         const CatmullRomSettings& settings, std::size_t n)
{
    QString html = ExactPanel::heading(FamilyReport::tr("Tangents at the points"));
    html += familyReportTangents(tangents, settings);
    html += familyReportSegments(segments, n, firstSegmentStart(settings.ends));
    return html;
}

/// The C² spline in the plane (Def 2.1) through exact points with uniform parameters, solved
/// again in Rational by the core: its segments pᵢ(s) in powers of the local s ∈ [0, 1], or an
/// empty text when it has no exact form here (chord or centripetal parameters, points without
/// an exact form, the core's refusal: the canvas says why).
QString familyReportPlaneSpline(const std::optional<std::vector<RPoint>>& exact, std::size_t n, const PlaneSplineSettings& plane)
{
    if (!exact || exact->size() != n || plane.parameters != SplineParameters::Uniform)
        return QString();
    const bool clamped = plane.ends == ParametricEnds::Clamped;
    const auto spline = parametricSpline(*exact, plane.ends, SplineParameters::Uniform,
                                         clamped ? std::optional<RPoint>(plane.startTangent) : std::nullopt,
                                         clamped ? std::optional<RPoint>(plane.endTangent) : std::nullopt);
    if (!spline)
        return QString();
    const auto pieces = parametricSplinePolynomials(*spline);
    std::vector<QStringList> rows;
    const std::size_t shown = std::min<std::size_t>(pieces.size(), CatmullRomReport::kMaxListedSegments);
    for (std::size_t i = 0; i < shown; ++i)
        rows.push_back({ExactPanel::subscripted(QStringLiteral("p"), static_cast<int>(i)) + QStringLiteral("(s)"),
                        ExactPanel::polynomialHtml(toText(pieces[i].x, "s")),
                        ExactPanel::polynomialHtml(toText(pieces[i].y, "s"))});
    QString html = ExactPanel::table({QString(), QStringLiteral("x(s)"), QStringLiteral("y(s)")}, rows);
    if (pieces.size() > shown)
        html += ExactPanel::note(FamilyReport::tr("… and %n more segments.", nullptr, static_cast<int>(pieces.size() - shown)));
    return html;
}

} // namespace

QString FamilyReport::html(const std::vector<Point>& points, const std::optional<std::vector<RPoint>>& exact,
                           const CatmullRomSettings& settings, const CatmullRomScene& scene)
{
    const CurveFamily family = settings.family;
    QString html = ExactPanel::heading(curveFamilyName(family));
    switch (family) {
    case CurveFamily::CatmullRom: return QString(); // catmull_rom_report.h
    case CurveFamily::Cardinal:
        html += ExactPanel::note(tr("The tangent at qᵢ is τ(qᵢ₊₁ − qᵢ₋₁) with τ = (1 − c)/2 = %1 (c = %2).")
                                     .arg(displayText(toString(cardinalTau(settings.cardinalTension))),
                                          displayText(toString(settings.cardinalTension)))
                                     .toHtmlEscaped());
        break;
    case CurveFamily::KochanekBartels:
        html += ExactPanel::note(tr("Each point has two tangents (Kochanek and Bartels 1984): in ends the segment arriving, "
                                    "out starts the segment leaving; they differ when C ≠ 0, and the curve is then not C¹ there.")
                                     .toHtmlEscaped());
        break;
    case CurveFamily::Hermite:
        html += ExactPanel::note(
            tr("Def 2.8 with the tangents you set: drag the handle at the end of each tangent.").toHtmlEscaped());
        break;
    case CurveFamily::PlaneSpline: {
        const QString segments = familyReportPlaneSpline(exact, points.size(), settings.planeSpline);
        if (!segments.isEmpty())
            return html +
                   ExactPanel::note(tr("Def 2.1 in the plane: each segment pᵢ(s) from qᵢ to qᵢ₊₁, s ∈ [0, 1], in powers of "
                                       "s, solved exactly; the curve is C² at every knot (the Knots tab).")
                                        .toHtmlEscaped()) +
                   segments;
        return html + ExactPanel::note(tr("The C² spline in the plane (Def 2.1) solves for its tangents: its end conditions and "
                                          "parameters are in its panel, the continuity at every knot in the Knots tab. This "
                                          "panel lists the exact tangents and segments of the cardinal, Kochanek–Bartels and "
                                          "Hermite families.")
                                           .toHtmlEscaped());
    }
    case CurveFamily::FunctionData:
        return html +
               ExactPanel::note(tr("Function data y(x): the natural spline, Catmull-Rom, Fritsch–Carlson and Steffen on the "
                                   "same data, their overshoot shaded on the canvas and measured in their panel. This "
                                   "panel lists the exact tangents and segments of the cardinal, Kochanek–Bartels and "
                                   "Hermite families.")
                                    .toHtmlEscaped());
    }
    if (!scene.family.error.isEmpty())
        return html + ExactPanel::note(scene.family.error.toHtmlEscaped());

    const std::size_t n = points.size();
    const bool uniform = settings.spacing == CatmullRomSpacing::Uniform;
    const CatmullRomMode mode = coreMode(settings.ends);
    if (exact && uniform && exact->size() == n) {
        // Computed again in Rational by the core (the scene's curve is in doubles).
        if (family == CurveFamily::Cardinal) {
            if (auto segs = cardinalHermiteSegments(*exact, settings.cardinalTension, mode)) {
                auto shown = familyShownSegments(std::move(*segs), settings.ends);
                const auto tangents = familyTangentsOf(shown, n, firstSegmentStart(settings.ends));
                return html + familyReportBody(shown, tangents, settings, n);
            }
        } else if (family == CurveFamily::KochanekBartels) {
            std::vector<TcbKnot<Rational>> tcb;
            for (std::size_t i = 0; i < n; ++i)
                tcb.push_back(tcbAt(settings, i));
            if (auto kb = kochanekBartels(*exact, tcb, mode)) {
                auto shown = familyShownSegments(std::move(kb->segments), settings.ends);
                return html + familyReportBody(shown, kb->tangents, settings, n);
            }
        } else if (const auto segs = familyReportExactHermite(scene.family.hermite)) {
            const auto tangents = familyTangentsOf(*segs, n, firstSegmentStart(settings.ends));
            return html + familyReportBody(*segs, tangents, settings, n);
        }
    }
    html += ExactPanel::note(!uniform ? tr("Centripetal and chordal spacing: values in decimals.")
                                      : tr("The points or the tangents are not small fractions: values in decimals."));
    return html + familyReportBody(scene.family.hermite, scene.family.tangents, settings, n);
}

} // namespace granota::ui
