// granota-cli fit: least-squares Bézier fitting (§2.1.3, Lemma 2.2, Prop 2.2).
// --exact reproduces the matrices of Ex 2.7 and Ex 2.8 as fractions, and the chord-length
// t_i of Ex 2.9 and Ex 2.10 in radicals beside the ones the thesis prints.
#include "app/cli/command.h"
#include "app/cli/finite_doubles.h"

#include "core/curves/fitting/least_squares_fit.h"
#include "core/exact/moore_penrose.h"
#include "core/base/number_format.h"
#include "core/io/worked_examples.h"

#include <optional>
#include <sstream>

namespace granota::cli {

namespace {

Json matrixJson(const RationalMatrix& m)
{
    Json rows = Json::array();
    for (int r = 0; r < m.rows(); ++r) {
        Json row = Json::array();
        for (int c = 0; c < m.cols(); ++c)
            row.push(toString(m(r, c)));
        rows.push(std::move(row));
    }
    return rows;
}

void matrixText(std::ostringstream& txt, const char* name, const RationalMatrix& m)
{
    std::vector<std::size_t> width(static_cast<std::size_t>(m.cols()), 0);
    for (int r = 0; r < m.rows(); ++r)
        for (int c = 0; c < m.cols(); ++c)
            width[static_cast<std::size_t>(c)] = std::max(width[static_cast<std::size_t>(c)], toString(m(r, c)).size());
    txt << name << " =\n";
    for (int r = 0; r < m.rows(); ++r) {
        txt << "  [";
        for (int c = 0; c < m.cols(); ++c) {
            const std::string s = toString(m(r, c));
            txt << std::string(width[static_cast<std::size_t>(c)] - s.size() + 1, ' ') << s;
        }
        txt << " ]\n";
    }
}

/// With --exact and distance parameters: the t_i in radicals ("t_radicals"), and for the
/// thesis's data of Ex 2.9/2.10 the t_i it prints from its d_4 = √85 ("t_printed") and
/// printed − right ("t_printed_difference"); docs/thesis-errata.md, “Ex 2.9 and 2.10”.
void addRadicalParameters(const std::vector<RPoint>& points, Parametrization param, CommandOutput& out, std::ostringstream& txt)
{
    const auto radicals = radicalParameters(points, param);
    if (!radicals)
        return;
    Json strings = Json::array();
    txt << "t_i in radicals:\n";
    for (std::size_t i = 0; i < radicals->size(); ++i) {
        const RadicalQuotient& t = (*radicals)[i];
        strings.push(toString(t));
        txt << "  t_" << i << " = " << toString(t) << " ≈ " << formatSignificant(t.toDouble(), 6) << "\n";
    }
    out.json.set("t_radicals", std::move(strings));
    const WorkedExample* ex = findWorkedExample("2.9");
    if (param != Parametrization::ChordLength || !ex || ex->points != points || ex->printedParameters.size() != radicals->size())
        return;
    Json printed = Json::array(), difference = Json::array();
    txt << "as the thesis prints them (Ex 2.9, Ex 2.10, from its d_4 = √85), and printed − right:\n";
    for (std::size_t i = 0; i < radicals->size(); ++i) {
        const RadicalSum& p = ex->printedParameters[i];
        const RadicalQuotient& t = (*radicals)[i];
        // Exactly when the right t_i is rationalised, so that only the last step rounds.
        const double d = t.rationalised() ? (p - t.numerator).toDouble() : p.toDouble() - t.toDouble();
        printed.push(toString(p));
        difference.push(d);
        txt << "  t_" << i << " = " << toString(p) << " ≈ " << formatSignificant(p.toDouble(), 6) << "   "
            << formatSignificant(d, 3) << "\n";
    }
    out.json.set("t_printed", std::move(printed)).set("t_printed_difference", std::move(difference));
}

Expected<CommandOutput> run(const Arguments& args)
{
    auto points = args.points();
    if (!points)
        return points.error();
    auto degree = args.integer("degree", 0, kMaxFitDegree, std::nullopt);
    if (!degree)
        return degree.error();
    auto paramName = args.choice("param", {"uniform", "chord", "centripetal", "annex-iii"}, std::string("uniform"));
    if (!paramName)
        return paramName.error();
    auto solverName = args.choice("solver", {"qr", "normal", "svd"}, std::string("qr"));
    if (!solverName)
        return solverName.error();
    const Parametrization param = *parseParametrization(*paramName);
    const bool exact = args.flag("exact");
    const bool iterate = args.flag("iterate");
    if (exact && iterate)
        return makeError(ErrorCode::InvalidInput, "--iterate projects points onto the curve numerically; it cannot be --exact");

    FitOptions options;
    options.degree = *degree;
    options.parametrization = param;
    options.solver = *parseLeastSquaresSolver(*solverName);
    options.correctParameters = iterate;
    // The numerical fit always runs: it gives cond₂(M), and validates the input the same
    // way with or without --exact.
    // cond₂(M) is a double, so even --exact needs the points as doubles.
    auto doublePoints = finiteDoubles(*points, false);
    if (!doublePoints)
        return doublePoints.error();
    // The corrections project every point and refit, up to maxCorrections times: bounded,
    // so that a large --iterate is refused at once rather than run for hours.
    if (const double work = fitWork(doublePoints->size(), *degree, iterate, options.maxCorrections);
        iterate && work > kMaxCliFitWork)
        return makeError(ErrorCode::OutOfRange, "--iterate on " + std::to_string(doublePoints->size()) + " points at degree " +
                                                    std::to_string(*degree) + " is too much work: (1 + " +
                                                    std::to_string(options.maxCorrections) +
                                                    " corrections) × points × (degree + 1)² = " + formatSignificant(work, 3) +
                                                    ", more than " + formatSignificant(kMaxCliFitWork, 2) +
                                                    "; lower the degree or the number of points, or leave out --iterate");
    auto fit = fitBezier(*doublePoints, options);
    if (!fit)
        return fit.error();

    std::optional<Expected<ExactFit>> exactFit;
    if (exact) {
        exactFit = fitBezierExact(*points, *degree, param);
        // Irrational distance parameters: the fit is the floating-point one, and the t_i are
        // given in radicals after it; without radicals to give, --exact refuses as before.
        if (!*exactFit && !((*exactFit).error().code == ErrorCode::NotRational && radicalParameters(*points, param)))
            return (*exactFit).error();
    }
    const bool exactDone = exactFit && *exactFit;

    CommandOutput out;
    std::ostringstream txt;
    txt << "Least-squares Bézier fit (§2.1.3): " << points->size() << " points, degree " << *degree << ", " << *paramName
        << " parameters, solver " << (exactDone ? "exact rational" : *solverName) << "\n";
    if (exact && !exactDone)
        txt << "not exact: " << (*exactFit).error().message << "; the fit is in floating point, the t_i follow in radicals\n";
    Json control = Json::array(), params = Json::array();
    if (exactDone) {
        const auto& e = *exactFit;
        for (int j = 0; j < e->P.rows(); ++j)
            control.push(point(RPoint(e->P(j, 0), e->P(j, 1)), true));
        for (const Rational& t : e->params)
            params.push(toString(t));
        out.json.set("control_points", std::move(control))
            .set("params", std::move(params))
            .set("sse", toString(e->sse))
            .set("cond", fit->cond)
            .set("M", matrixJson(e->M))
            .set("MtM", matrixJson(e->MtM))
            .set("MtM_inv", matrixJson(e->MtMinv))
            .set("M_pinv", matrixJson(e->Mplus));
        // §2.1.3 checked: the four Penrose conditions of M⁺ (the thesis's order), and
        // Prop 2.2's Hessian 2MᵀM with its eigenvalues 2σ_i², all positive (a minimum).
        const std::array<bool, 4> penrose = penroseConditions(e->M, e->Mplus);
        const RationalMatrix hessian = leastSquaresHessian(e->M);
        const std::vector<double> eigenvalues = symmetricEigenvalues(hessian);
        Json penroseJson = Json::array(), eigenJson = Json::array();
        for (bool holds : penrose)
            penroseJson.push(Json(holds));
        for (double v : eigenvalues)
            eigenJson.push(v);
        out.json.set("penrose", std::move(penroseJson))
            .set("hessian", matrixJson(hessian))
            .set("hessian_eigenvalues", std::move(eigenJson));
        txt << "t_i: ";
        for (const Rational& t : e->params)
            txt << " " << toString(t);
        txt << "\n";
        matrixText(txt, "M", e->M);
        matrixText(txt, "MᵀM", e->MtM);
        matrixText(txt, "(MᵀM)⁻¹", e->MtMinv);
        matrixText(txt, "M⁺ = (MᵀM)⁻¹Mᵀ", e->Mplus);
        txt << "control points P = M⁺Q:\n";
        for (int j = 0; j < e->P.rows(); ++j)
            txt << "  P_" << j << " = " << text(RPoint(e->P(j, 0), e->P(j, 1))) << "\n";
        txt << "Σ‖Q_i − α(t_i)‖² = " << toString(e->sse) << "\n";
        txt << "Penrose conditions of M⁺: MM⁺M = M " << (penrose[0] ? "✓" : "✗") << ", M⁺MM⁺ = M⁺ " << (penrose[1] ? "✓" : "✗")
            << ", (MM⁺)ᵀ = MM⁺ " << (penrose[2] ? "✓" : "✗") << ", (M⁺M)ᵀ = M⁺M " << (penrose[3] ? "✓" : "✗") << "\n";
        matrixText(txt, "Hessian 2MᵀM (Prop 2.2)", hessian);
        txt << "its eigenvalues 2σ_i²:";
        for (double v : eigenvalues)
            txt << " " << formatSignificant(v, 6); // decimals from doubles: six digits, no rounding noise
        txt << (!eigenvalues.empty() && eigenvalues.front() > 0 ? "  (all positive: the critical point is a minimum)\n" : "\n");
    } else {
        for (const Point& p : fit->controlPoints)
            control.push(point(p));
        for (double t : fit->params)
            params.push(t);
        out.json.set("control_points", std::move(control))
            .set("params", std::move(params))
            .set("sse", fit->sse)
            .set("cond", fit->cond)
            .set("rms", fit->rms)
            .set("max_error", fit->maxError)
            .set("corrections", fit->corrections);
        txt << "t_i:";
        for (double t : fit->params)
            txt << " " << formatDouble(t);
        txt << "\ncontrol points:\n";
        for (std::size_t j = 0; j < fit->controlPoints.size(); ++j)
            txt << "  P_" << j << " = " << text(fit->controlPoints[j]) << "\n";
        txt << "Σ‖Q_i − α(t_i)‖² = " << formatDouble(fit->sse) << "   RMS " << formatDouble(fit->rms) << "   max "
            << formatDouble(fit->maxError) << "\n";
        if (iterate)
            txt << "parameter corrections: " << fit->corrections << "\n";
    }
    if (exact)
        addRadicalParameters(*points, param, out, txt);
    txt << "cond₂(M) = " << formatDouble(fit->cond) << "\n";
    Json warnings = Json::array();
    for (const std::string& w : fit->warnings) {
        warnings.push(w);
        txt << "warning: " << w << "\n";
    }
    out.json.set("warnings", std::move(warnings));
    out.text = txt.str();
    return out;
}

} // namespace

Command fitCommand()
{
    return {"fit",
            "--points Q | --points-file F  --degree n (0 to " + std::to_string(kMaxFitDegree) +
                ")  [--param uniform|chord|centripetal|annex-iii] [--solver qr|normal|svd] "
                "[--iterate] [--exact] [--json]",
            "least-squares Bézier fit: control points, t_i, Σ‖Q_i − α(t_i)‖², cond₂(M); --exact adds M, MᵀM, (MᵀM)⁻¹, M⁺",
            {{"points", "points-file", "degree", "param", "solver"}, {"exact", "json", "iterate"}, {}},
            &run};
}

} // namespace granota::cli
