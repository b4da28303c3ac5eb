#include "ui/fit/fit_exact_view.h"

#include "core/exact/moore_penrose.h"
#include "ui/common/number_text.h"

#include "core/curves/bezier/power_basis.h"
#include "core/exact/polynomial_text.h"
#include "core/exact/radical_sum.h"
#include "core/exact/rounding_residue.h"
#include "core/exact/square_root.h"
#include "core/io/worked_examples.h"
#include "ui/common/exact_panel.h"

#include <QStringList>

#include <algorithm>
#include <cstddef>
#include <optional>

namespace granota::ui {

namespace {

/// Decimals for the panel: six significant digits read well and are enough to compare.
QString decimal(double v, int digits = 6)
{
    if (v == 0)
        v = 0; // no "-0"
    return displaySignificant(v, digits);
}

std::string decimalText(double v, int digits = 6) { return decimal(v, digits).toStdString(); }

/// A polynomial of doubles rounded to `digits` significant digits, for display only.
Polynomial<double> rounded(const Polynomial<double>& p, int digits = 6)
{
    std::vector<double> c;
    for (double a : p.coefficients())
        c.push_back(QString::fromStdString(formatSignificant(a, digits)).toDouble());
    return Polynomial<double>(std::move(c));
}

std::vector<std::vector<std::string>> entries(const RationalMatrix& m)
{
    std::vector<std::vector<std::string>> e(static_cast<std::size_t>(m.rows()));
    for (int r = 0; r < m.rows(); ++r)
        for (int c = 0; c < m.cols(); ++c)
            e[static_cast<std::size_t>(r)].push_back(toString(m(r, c)));
    return e;
}

QString line(const QString& html) { return QStringLiteral("%1<br>").arg(html); }


/// Whether the data are the thesis's Q_0..Q_4 of Ex 2.7–2.10.
bool isThesisData(const std::optional<std::vector<RPoint>>& rational)
{
    const WorkedExample* example = findWorkedExample("2.7");
    return rational && example && *rational == example->points;
}

/// The chord-length (or Annex III) t_i in radicals with their decimals; for the thesis's
/// data of Ex 2.9/2.10, beside them the t_i the thesis prints (from its d_4 = √85) and
/// printed − right.
QString radicalParametersHtml(const std::vector<RadicalQuotient>& t, const std::vector<RadicalSum>* printed)
{
    QString html = ExactPanel::heading(FitExactView::tr("Parameters tᵢ in radicals"));
    QStringList header{QString(), FitExactView::tr("in radicals"), FitExactView::tr("decimal")};
    if (printed)
        header << FitExactView::tr("the thesis prints") << FitExactView::tr("printed − right");
    std::vector<QStringList> rows;
    bool allRationalised = true;
    for (std::size_t i = 0; i < t.size(); ++i) {
        allRationalised = allRationalised && t[i].rationalised();
        QStringList row{ExactPanel::subscripted(QStringLiteral("t"), static_cast<int>(i)),
                        QString::fromStdString(toString(t[i])).toHtmlEscaped(), decimal(t[i].toDouble())};
        if (printed) {
            const RadicalSum& p = (*printed)[i];
            // Exactly when t_i is rationalised, so that only the last step rounds.
            const double d = t[i].rationalised() ? (p - t[i].numerator).toDouble() : p.toDouble() - t[i].toDouble();
            row << decimal(p.toDouble()) << (d > 0 ? QStringLiteral("+") : QString()) + decimal(d, 3);
        }
        rows.push_back(row);
    }
    html += ExactPanel::table(header, rows);
    if (!allRationalised)
        html += QStringLiteral("<p>%1</p>")
                    .arg(FitExactView::tr("A quotient whose denominator has more than %1 coprime radicands is left "
                                          "as it stands, not rationalised.")
                             .arg(kMaxRadicalGenerators)
                             .toHtmlEscaped());
    if (printed) {
        QStringList asPrinted;
        for (std::size_t i = 1; i + 1 < printed->size(); ++i)
            asPrinted << QStringLiteral("t_%1 = %2").arg(i).arg(QString::fromStdString(toString((*printed)[i])));
        html += ExactPanel::note(FitExactView::tr("Ex 2.9 and Ex 2.10 print tᵢ rationalised from their d₄ = √85: %1. "
                                                  "Each is too large by the difference above (docs/thesis-errata.md, "
                                                  "“Ex 2.9 and 2.10”).")
                                     .arg(asPrinted.join(QStringLiteral(", "))));
    }
    return html;
}

QString curveHtml(const std::string& x, const std::string& y)
{
    return line(QStringLiteral("x(t) = ") + ExactPanel::polynomialHtml(x)) +
           line(QStringLiteral("y(t) = ") + ExactPanel::polynomialHtml(y));
}

} // namespace

QString FitExactView::html(const Input& in)
{
    const std::vector<Point>& q = *in.points;
    const int count = static_cast<int>(q.size());
    const int n = in.degree;
    QString html;

    std::optional<std::vector<RPoint>> rational;
    if (count <= kMaxListedPoints)
        rational = in.exact;
    const bool thesisData = isThesisData(rational);
    const bool byDistance = in.parametrization != Parametrization::Uniform;

    // Chord lengths d_j = |Q_j − Q_{j−1}| (§2.1.3), in simplest radical form (Ex 2.9).
    if (byDistance && rational && count >= 2) {
        // Annex III's BezParamProp measures each point before from the origin instead.
        const bool annex = in.parametrization == Parametrization::AnnexIII;
        html += ExactPanel::heading(annex ? tr("Annex III's distances dᵢ = |Qᵢ₋₁| (BezParamProp)")
                                          : tr("Chord lengths dᵢ = dist(Qᵢ₋₁, Qᵢ)"));
        std::vector<std::optional<SimplifiedSquareRoot>> d;
        if (annex)
            for (std::size_t j = 0; j + 1 < rational->size(); ++j)
                d.push_back(
                    simplifySquareRoot(Rational((*rational)[j].x * (*rational)[j].x + (*rational)[j].y * (*rational)[j].y)));
        else
            d = exactChordLengths(*rational);
        for (std::size_t j = 0; j < d.size(); ++j) {
            const Point a = q[j], b = q[j + 1];
            const double approx = annex ? norm(a) : norm(b - a);
            const QString value = d[j] ? QString::fromStdString(toString(*d[j])) : decimal(approx);
            const bool isRational = d[j] && d[j]->radicand == 1;
            html += line(
                isRational
                    ? QStringLiteral("%1 = %2").arg(ExactPanel::subscripted(QStringLiteral("d"), static_cast<int>(j) + 1), value)
                    : QStringLiteral("%1 = %2 ≈ %3")
                          .arg(ExactPanel::subscripted(QStringLiteral("d"), static_cast<int>(j) + 1), value, decimal(approx)));
        }
        if (thesisData && in.parametrization == Parametrization::ChordLength)
            html += ExactPanel::note(tr("The thesis (Ex 2.9) writes d₄ = √85, from (1 − 7)² + (5 + 2)²; but Q₃ has "
                                        "x = 8, so d₄ = √(49 + 49) = 7√2, which is used here "
                                        "(docs/thesis-errata.md, “Ex 2.9 and 2.10”)."));
        if (in.parametrization == Parametrization::AnnexIII)
            html += QStringLiteral("<p>%1</p>")
                        .arg(tr("Annex III's BezParamProp, as the thesis's Matlab computes it: dᵢ = |Qᵢ₋₁|, the "
                                "distance of the point before from the origin, not from its neighbour — Figs 2.7 and 2.8 "
                                "were drawn with these parameters (docs/thesis-errata.md, “Annex III”).")
                                 .toHtmlEscaped());
        if (in.parametrization == Parametrization::Centripetal)
            html += QStringLiteral("<p>%1</p>")
                        .arg(tr("Centripetal parameters (beyond the thesis) use √dᵢ instead of dᵢ.").toHtmlEscaped());
    }

    if (!in.fit)
        return html;
    const FitResult& fit = *in.fit;

    // The exact fit of Ex 2.7 and Ex 2.8: every matrix as fractions.
    std::optional<ExactFit> exact;
    QString whyNotExact;
    if (in.correctParameters)
        whyNotExact = tr("Parameter correction moves the tᵢ to where the points project onto the curve: the "
                         "results are shown in decimals.");
    else if (count > kMaxExactPoints)
        whyNotExact = tr("Exact fractions are shown for up to %1 data points; these %2 are shown in decimals.")
                          .arg(kMaxExactPoints)
                          .arg(count);
    else if (!rational)
        whyNotExact = tr("The data are not small fractions: the results are shown in decimals.");
    else {
        Expected<ExactFit> e = fitBezierExact(*rational, n, in.parametrization, in.exactBudget);
        if (e)
            exact = std::move(e).value();
        else if (e.error().code == ErrorCode::NotRational)
            whyNotExact = tr("These parameters are irrational (square roots of the distances), so M cannot be "
                             "written in fractions: the results are shown in decimals, as the thesis does with "
                             "Matlab in Ex 2.9 and Ex 2.10.");
        else if (e.error().code == ErrorCode::OutOfRange) // refused before any matrix was built
            whyNotExact = tr("The exact fractions of this fit would take too long to compute (their digits grow "
                             "with the degree and the number of points): the results are shown in decimals.");
        else
            whyNotExact = tr("MᵀM is singular for these parameters (coincident points): the control points shown "
                             "are the minimum-norm least-squares solution, in decimals.");
    }

    if (exact) {
        html += ExactPanel::heading(tr("Parameters tᵢ"));
        QStringList ts;
        for (std::size_t i = 0; i < exact->params.size(); ++i)
            ts << QStringLiteral("%1 = %2").arg(ExactPanel::subscripted(QStringLiteral("t"), static_cast<int>(i)),
                                                QString::fromStdString(toString(exact->params[i])));
        html += QStringLiteral("<p>%1</p>").arg(ts.join(QStringLiteral(", ")));
        if (in.showMatrices) {
            html += ExactPanel::heading(tr("Matrices (Lemma 2.2, Note 2.2)"));
            html += ExactPanel::matrix(QStringLiteral("M"), entries(exact->M));
            html += ExactPanel::matrix(QStringLiteral("MᵀM"), entries(exact->MtM));
            html += ExactPanel::matrix(QStringLiteral("(MᵀM)⁻¹"), entries(exact->MtMinv));
            html += ExactPanel::matrix(QStringLiteral("M⁺ = (MᵀM)⁻¹Mᵀ"), entries(exact->Mplus));
            // §2.1.3 checked on these matrices: M⁺ meets the four Penrose conditions, and the
            // Hessian 2MᵀM of Prop 2.2 is positive definite (core/exact/moore_penrose.h).
            const std::array<bool, 4> penrose = penroseConditions(exact->M, exact->Mplus);
            const QString conditions = QStringLiteral("MM⁺M = M %1, M⁺MM⁺ = M⁺ %2, (MM⁺)ᵀ = MM⁺ %3, (M⁺M)ᵀ = M⁺M %4")
                                           .arg(ExactPanel::checkMark(penrose[0]), ExactPanel::checkMark(penrose[1]),
                                                ExactPanel::checkMark(penrose[2]), ExactPanel::checkMark(penrose[3]));
            html += line(tr("The Penrose conditions of M⁺ (§2.1.3), checked exactly: %1").arg(conditions));
            const RationalMatrix hessian = leastSquaresHessian(exact->M);
            html += ExactPanel::matrix(tr("Hessian 2MᵀM (Prop 2.2)"), entries(hessian));
            const std::vector<double> values = symmetricEigenvalues(hessian);
            QStringList eigenvalues;
            for (double v : values)
                eigenvalues << displaySignificant(v, 6);
            html += line(!values.empty() && values.front() > 0
                             ? tr("Its eigenvalues 2σᵢ²: %1 — all positive, so the error's critical point is its minimum.")
                                   .arg(eigenvalues.join(QStringLiteral("; ")))
                             : tr("Its eigenvalues 2σᵢ²: %1.").arg(eigenvalues.join(QStringLiteral("; "))));
        }
        html += ExactPanel::heading(tr("Control points P = M⁺Q"));
        std::vector<RPoint> P;
        for (int j = 0; j < exact->P.rows(); ++j) {
            P.emplace_back(exact->P(j, 0), exact->P(j, 1));
            html += line(QStringLiteral("%1 = (%2, %3)")
                             .arg(ExactPanel::subscripted(QStringLiteral("P"), j),
                                  QString::fromStdString(toString(exact->P(j, 0))),
                                  QString::fromStdString(toString(exact->P(j, 1)))));
        }
        html += ExactPanel::heading(tr("Fitted curve α(t) = Σ Bⱼⁿ(t) Pⱼ"));
        const Vec2<Polynomial<Rational>> alpha = bezierToPowerBasis(P);
        html += curveHtml(toText(alpha.x), toText(alpha.y));
        html += QStringLiteral("<p>Σ‖Q<sub>i</sub> − α(t<sub>i</sub>)‖² = %1 ≈ %2</p>")
                    .arg(QString::fromStdString(toString(exact->sse)), decimal(exact->sse.get_d()));
        if (thesisData && in.parametrization == Parametrization::Uniform && n == 2)
            html += ExactPanel::note(tr("Ex 2.7: the thesis prints α(t) = (−8/7 + 726/35 t − 600/35 t², 46/35 − 130/35 t + "
                                        "200/35 t²), the same curve with unreduced fractions (600/35 = 120/7, "
                                        "130/35 = 26/7, 200/35 = 40/7); its sum runs k = 0…4 where n = 2 has three "
                                        "control points (docs/thesis-errata.md, “Ex 2.7 and 2.8”)."));
        if (thesisData && in.parametrization == Parametrization::Uniform && n == 3)
            html += ExactPanel::note(tr("Ex 2.8: the thesis prints −1636/105 as the coefficient of t in x(t). It is "
                                        "3(P₁ − P₀) = 3(−3371/630 − 11/70) = −347/21 = −1735/105, shown here "
                                        "(docs/thesis-errata.md, “Ex 2.8”). Its sum also runs k = 0…4, with Bₖ², "
                                        "where n = 3 (“Ex 2.7 and 2.8”)."));
        return html;
    }

    // Decimals: the chord-length examples (Ex 2.9, Ex 2.10), drawn data, large data sets.
    if (!whyNotExact.isEmpty())
        html += QStringLiteral("<p>%1</p>").arg(whyNotExact.toHtmlEscaped());
    // Chord-length parameters of rational data are quotients of sums of square roots: in
    // radicals (Ex 2.9/2.10's t_i, as the thesis prints them), unless corrected numerically.
    const std::optional<std::vector<RadicalQuotient>> radicals = rational && !in.correctParameters
                                                                     ? radicalParameters(*rational, in.parametrization)
                                                                     : std::nullopt;
    const WorkedExample* ex29 = findWorkedExample("2.9");
    const bool printedToo = radicals && thesisData && in.parametrization == Parametrization::ChordLength && ex29 &&
                            ex29->printedParameters.size() == radicals->size();
    if (radicals) {
        html += radicalParametersHtml(*radicals, printedToo ? &ex29->printedParameters : nullptr);
    } else if (count <= kMaxListedPoints) {
        html += ExactPanel::heading(tr("Parameters tᵢ"));
        QStringList ts;
        for (std::size_t i = 0; i < fit.params.size(); ++i)
            ts << QStringLiteral("%1 = %2").arg(ExactPanel::subscripted(QStringLiteral("t"), static_cast<int>(i)),
                                                decimal(fit.params[i]));
        html += QStringLiteral("<p>%1</p>").arg(ts.join(QStringLiteral(", ")));
    }
    if (in.showMatrices) {
        // M is (k + 1) × (n + 1): beyond kMaxListedPoints rows (or columns) only its top-left
        // corner is shown, and the note says how large it is — never nothing.
        html += ExactPanel::heading(tr("Matrix M (Lemma 2.2), in decimals"));
        const std::size_t allRows = fit.params.size();
        const int allCols = n + 1;
        const bool whole = allRows <= std::size_t(kMaxListedPoints) && allCols <= kMaxListedPoints;
        const std::size_t rows = whole ? allRows : std::min<std::size_t>(allRows, kMatrixCorner);
        const int cols = whole ? allCols : std::min(allCols, kMatrixCorner);
        // Only the rows shown are computed: the data may have a million points.
        const std::vector<double> shownParams(fit.params.begin(), fit.params.begin() + static_cast<std::ptrdiff_t>(rows));
        const Eigen::MatrixXd M = bernsteinMatrix(shownParams, n);
        if (rows < allRows || cols < allCols)
            html += ExactPanel::note(tr("M has %1 × %2 entries (a row per data point, a column per control point); "
                                        "the first %3 rows and %4 columns are shown.")
                                         .arg(allRows)
                                         .arg(allCols)
                                         .arg(rows)
                                         .arg(cols));
        std::vector<std::vector<std::string>> e(rows);
        for (std::size_t r = 0; r < rows; ++r)
            for (int c = 0; c < cols; ++c)
                e[r].push_back(decimalText(M(static_cast<Eigen::Index>(r), c), 4));
        html += ExactPanel::matrix(QStringLiteral("M"), e);
    }
    html += ExactPanel::heading(tr("Control points P"));
    for (std::size_t j = 0; j < fit.controlPoints.size(); ++j)
        html += line(
            QStringLiteral("%1 = %2").arg(ExactPanel::subscripted(QStringLiteral("P"), static_cast<int>(j)),
                                          displayPair(decimal(fit.controlPoints[j].x), decimal(fit.controlPoints[j].y))));
    constexpr int kMaxPowerDegree = 12;
    if (n <= kMaxPowerDegree) {
        html += ExactPanel::heading(tr("Fitted curve α(t) = Σ Bⱼⁿ(t) Pⱼ"));
        const Vec2<Polynomial<double>> alpha = bezierToPowerBasis(fit.controlPoints);
        // Rounding residue dropped (rounding_residue.h), then 6 significant digits.
        const double residue = fitResidueRelative(n, fit.cond);
        html += curveHtml(toText(rounded(withoutResidue(alpha.x, residue))), toText(rounded(withoutResidue(alpha.y, residue))));
    } else {
        html += QStringLiteral("<p>%1</p>")
                    .arg(tr("α(t) in powers of t is not shown beyond degree %1: its coefficients "
                            "grow like C(n, k) and cancel each other.")
                             .arg(kMaxPowerDegree)
                             .toHtmlEscaped());
    }
    return html;
}

} // namespace granota::ui
