// granota-cli bernstein: the values B_i^N(T) and the polynomials of Ex 2.4 (Def 2.5).
#include "app/cli/command.h"
#include "app/cli/finite_doubles.h"

#include "core/curves/bezier/bernstein.h"
#include "core/exact/exact_cost.h"
#include "core/exact/polynomial_text.h"

#include <sstream>

namespace granota::cli {

namespace {

Expected<CommandOutput> run(const Arguments& args)
{
    auto n = args.integer("degree", 0, kMaxDegree, std::nullopt);
    if (!n)
        return n.error();
    auto t = args.rational("t", std::nullopt);
    if (!t)
        return t.error();
    const bool exact = args.flag("exact");
    double doubleT = 0;
    if (exact) {
        const double work = bernsteinExactWork(*n, bitLength(*t));
        if (!exactWorkAllowed(work))
            return makeError(ErrorCode::OutOfRange, exactWorkRefusal("Bernstein values", work, "--degree or the digits of --t"));
    } else {
        auto d = finiteDouble(*t, "--t " + valueText(*t), true);
        if (!d)
            return d.error();
        doubleT = *d;
    }

    CommandOutput out;
    std::ostringstream txt;
    txt << "Bernstein polynomials of degree " << *n << " (Def 2.5) at t = " << toString(*t) << "\n";
    Json values = Json::array(), polys = Json::array();
    // Values through the recursion of Lemma 2.1: exact, or in double (stable on [0,1]).
    const std::vector<Rational> exactValues = exact ? bernsteinAll(*n, *t) : std::vector<Rational>{};
    const std::vector<double> doubleValues = exact ? std::vector<double>{} : bernsteinAll(*n, doubleT);
    for (int i = 0; i <= *n; ++i) {
        const Polynomial<Rational> b = bernsteinPolynomial(i, *n);
        Json coefficients = Json::array();
        for (const Rational& c : b.coefficients(*n))
            coefficients.push(number(c, exact));
        polys.push(std::move(coefficients));
        const std::string value = exact ? toString(exactValues[static_cast<std::size_t>(i)])
                                        : formatDouble(doubleValues[static_cast<std::size_t>(i)]);
        values.push(exact ? Json(value) : Json(doubleValues[static_cast<std::size_t>(i)]));
        txt << "  B_" << i << "^" << *n << "(t) = " << toText(b) << "   = " << value << "\n";
    }
    out.json.set("values", std::move(values)).set("poly", std::move(polys)).set("degree", *n);
    out.text = txt.str();
    return out;
}

} // namespace

Command bernsteinCommand()
{
    return {"bernstein",
            "--degree N  --t T  [--exact] [--json]",
            "the Bernstein polynomials B_i^N in powers of t and their values at T",
            {{"degree", "t"}, {"exact", "json"}, {}},
            &run};
}

} // namespace granota::cli
