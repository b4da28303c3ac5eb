#include "ui/bsplines/bspline_report.h"

#include "core/curves/bsplines/bspline_basis.h"
#include "core/curves/bsplines/circle_arcs.h"
#include "core/curves/bsplines/knot_vector.h"
#include "ui/common/exact_panel.h"
#include "ui/common/number_text.h"

#include <QCoreApplication>

namespace granota::ui {

namespace {

constexpr int kSupportRowsUpTo = 24;   ///< the supports are listed up to this many points
constexpr int kKnotRowsAtEachEnd = 12; ///< beyond twice this many distinct knots, the first and last ones around "…"

} // namespace

QString bsplineReportHtml(const BSplineScene& scene)
{
    if (!scene.valid())
        return ExactPanel::note(
            QCoreApplication::translate("granota::ui::BSplineTab", "This B-spline cannot be drawn: %1").arg(scene.error));
    const int p = scene.degree(), k = scene.span(), n = scene.curve.pointCount() - 1;
    const bool exact = scene.exactNet.has_value();
    QString html;

    // de Boor's net (de Boor 1972; Piegl & Tiller A3.1).
    html += ExactPanel::heading(
        QCoreApplication::translate("granota::ui::BSplineTab", "de Boor's algorithm at u = %1").arg(rationalText(scene.u)));
    html += QStringLiteral("<p>") +
            QCoreApplication::translate(
                "granota::ui::BSplineTab",
                "Span k = %1: u<sub>%1</sub> ≤ u &lt; u<sub>%2</sub>. Only P<sub>%3</sub>…P<sub>%1</sub> act here "
                "(local support); level r interpolates level r − 1 with α = (u − u<sub>j</sub>)/(u<sub>j+p+1−r</sub> − "
                "u<sub>j</sub>).")
                .arg(k)
                .arg(k + 1)
                .arg(k - p) +
            QStringLiteral("</p>");
    std::vector<QStringList> rows;
    for (int r = 0; r <= p; ++r) {
        QStringList cells;
        const auto& level = scene.net.levels[static_cast<std::size_t>(r)];
        for (std::size_t i = 0; i < level.size(); ++i)
            cells << (exact ? panelPointText(scene.exactNet->levels[static_cast<std::size_t>(r)][i]) : panelPointText(level[i]));
        rows.push_back({QString::number(r), cells.join(QStringLiteral("&nbsp;&nbsp;"))});
    }
    html += ExactPanel::table({QCoreApplication::translate("granota::ui::BSplineTab", "level r"),
                               QCoreApplication::translate("granota::ui::BSplineTab", "points P<sub>j</sub><sup>r</sup>")},
                              rows);
    html += QStringLiteral("<p>c(u) = %1</p>")
                .arg(exact ? panelPointText(scene.exactNet->point()) : panelPointText(scene.net.point()));
    if (!exact)
        html += ExactPanel::note(QCoreApplication::translate(
            "granota::ui::BSplineTab", "A point has no exact form (dragged freely): the net is shown in doubles."));

    // The basis at u, exactly (the knots and u are always exact).
    const std::vector<Rational> N = basisFunctions(scene.exact.knots, p, k, scene.u);
    Rational sum(0);
    rows.clear();
    for (int j = 0; j <= p; ++j) {
        sum += N[static_cast<std::size_t>(j)];
        rows.push_back({ExactPanel::subscripted(QStringLiteral("N"), k - p + j), rationalText(N[static_cast<std::size_t>(j)])});
    }
    html += ExactPanel::heading(
        QCoreApplication::translate("granota::ui::BSplineTab", "Basis functions at u (degree p = %1)").arg(p));
    html += ExactPanel::table({QString(), QCoreApplication::translate("granota::ui::BSplineTab", "value")}, rows);
    html += QStringLiteral("<p>%1 %2</p>")
                .arg(QCoreApplication::translate("granota::ui::BSplineTab", "Σ N<sub>i,p</sub>(u) = %1: partition of unity")
                         .arg(rationalText(sum)),
                     ExactPanel::checkMark(sum == 1));

    // Supports.
    const auto& knots = scene.exact.knots;
    if (n + 1 <= kSupportRowsUpTo) {
        rows.clear();
        for (int i = 0; i <= n; ++i)
            rows.push_back({ExactPanel::subscripted(QStringLiteral("N"), i),
                            QStringLiteral("[%1, %2)")
                                .arg(rationalText(knots[static_cast<std::size_t>(i)]),
                                     rationalText(knots[static_cast<std::size_t>(i + p + 1)]))});
        html += ExactPanel::heading(QCoreApplication::translate("granota::ui::BSplineTab", "Supports [uᵢ, uᵢ₊ₚ₊₁)"));
        html += ExactPanel::table({QString(), QCoreApplication::translate("granota::ui::BSplineTab", "non-zero on")}, rows);
    }

    // Knots, multiplicities and continuity.
    rows.clear();
    for (std::size_t i = 0; i < knots.size();) {
        std::size_t j = i;
        while (j < knots.size() && knots[j] == knots[i])
            ++j;
        const int m = static_cast<int>(j - i);
        const bool inside = knots[i] > scene.exact.domainStart() && knots[i] < scene.exact.domainEnd();
        rows.push_back({rationalText(knots[i]), QString::number(m),
                        inside ? (p - m >= 0 ? QStringLiteral("C<sup>%1</sup>").arg(p - m)
                                             : QCoreApplication::translate("granota::ui::BSplineTab", "broken"))
                               : QCoreApplication::translate("granota::ui::BSplineTab", "outside or at an end")});
        i = j;
    }
    // A thousand points give a thousand rows that no one reads and that cost a drag its frame
    // (the panel lays the table out again at every move): the ends, and the ruler shows the rest.
    if (rows.size() > 2 * kKnotRowsAtEachEnd) {
        const auto end = static_cast<std::ptrdiff_t>(kKnotRowsAtEachEnd);
        rows.erase(rows.begin() + end, rows.end() - end);
        const QString more = QStringLiteral("…");
        rows.insert(rows.begin() + end, QStringList{more, more, more});
    }
    html += ExactPanel::heading(QCoreApplication::translate("granota::ui::BSplineTab", "Knots"));
    html += ExactPanel::table({QCoreApplication::translate("granota::ui::BSplineTab", "knot"),
                               QCoreApplication::translate("granota::ui::BSplineTab", "multiplicity m"),
                               QCoreApplication::translate("granota::ui::BSplineTab", "continuity C<sup>p−m</sup>")},
                              rows);
    if (!scene.cubicCircle.empty())
        html += ExactPanel::note(
            QCoreApplication::translate("granota::ui::BSplineTab",
                                        "Dashed red: the cubic Bézier quarter circle (1, 0), (1, k), (k, 1), (0, 1), "
                                        "k = 4(√2 − 1)/3 ≈ %1: its radius is off by up to %2; the rational quarter "
                                        "circle's by nothing (x² + y² = 1 exactly at every rational u).")
                .arg(displayNumber(cubicCircleHandle()), displaySignificant(scene.cubicCircleError, 2)));
    if (scene.curve.rational()) {
        QStringList w;
        for (const Rational& q : scene.exact.weights)
            w << rationalText(q);
        html += QStringLiteral("<p>%1</p>")
                    .arg(QCoreApplication::translate("granota::ui::BSplineTab", "Weights: %1").arg(w.join(QStringLiteral(", "))));
    }
    return html;
}

} // namespace granota::ui
