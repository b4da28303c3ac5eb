// granota-cli demo: Ex 2.2 of the thesis, the whole De Casteljau triangle as polynomials
// in t — what `granota` shows first, for machines without a display.
#include "app/cli/command.h"

#include "core/curves/bezier/de_casteljau.h"
#include "core/exact/polynomial_text.h"

#include <sstream>

namespace granota::cli {

namespace {

Expected<CommandOutput> run(const Arguments&)
{
    using P = Polynomial<Rational>;
    const int coords[][2] = {{2, 3}, {-1, 8}, {-5, -3}, {3, 0}, {-7, -2}}; // Ex 2.2
    std::vector<Vec2<P>> points;
    for (const auto& c : coords)
        points.emplace_back(P(Rational(c[0])), P(Rational(c[1])));
    const auto table = deCasteljau(points, P::identity());

    CommandOutput out;
    std::ostringstream txt;
    txt << "Granota — Ex 2.2: the Bézier curve of P0 = (2, 3), P1 = (-1, 8), P2 = (-5, -3), P3 = (3, 0), P4 = (-7, -2)\n"
        << "De Casteljau's triangle (Def 2.4), every P_i^r(t) as a polynomial in t:\n";
    Json levels = Json::array();
    for (int r = 0; r <= table.degree(); ++r) {
        Json level = Json::array();
        for (std::size_t i = 0; i < table.levels[r].size(); ++i) {
            const std::string s = toText(table.levels[r][i]);
            txt << "  P_" << i << "^" << r << "(t) = " << s << "\n";
            level.push(s);
        }
        levels.push(std::move(level));
    }
    txt << "c(t) = P_0^4(t) = " << toText(table.point()) << "\n";
    txt << "Run `granota` on a desktop to drag the points, or `granota-cli --help` for every command.\n";
    out.json.set("example", "2.2").set("levels", std::move(levels)).set("curve", toText(table.point()));
    out.text = txt.str();
    return out;
}

} // namespace

Command demoCommand()
{
    return {"demo", "[--json]", "Ex 2.2 of the thesis: De Casteljau's triangle as polynomials", {{}, {"json"}, {}}, &run};
}

} // namespace granota::cli
