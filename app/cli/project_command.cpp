// granota-cli project: the point of a Bézier curve closest to a given point, globally over
// t ∈ [0, 1] (core/curves/bezier/closest_point.h; beyond the thesis).
#include "app/cli/command.h"
#include "app/cli/finite_doubles.h"

#include "core/base/number_format.h"
#include "core/curves/bezier/closest_point.h"
#include "core/io/point_list.h"

#include <sstream>

namespace granota::cli {

namespace {

Expected<CommandOutput> run(const Arguments& args)
{
    auto points = controlPoints(args);
    if (!points)
        return points.error();
    const auto atText = args.value("at");
    if (!atText)
        return makeError(ErrorCode::InvalidInput, "--at x,y is required (the point to project)");
    auto at = parsePointList(*atText);
    if (!at)
        return makeError(ErrorCode::InvalidInput, "--at: " + at.error().message);
    if (at->size() != 1)
        return makeError(ErrorCode::InvalidInput, "--at takes one point x,y, not " + std::to_string(at->size()));
    auto P = finiteDoubles(*points, false);
    if (!P)
        return P.error();
    auto p = finiteDoubles(*at, false);
    if (!p)
        return makeError(ErrorCode::InvalidInput, "--at: " + p.error().message);

    const ClosestPoint c = closestPoint(*P, p->front());
    CommandOutput out;
    out.json.set("t", c.t).set("point", point(c.point)).set("distance", c.distance);
    std::ostringstream txt;
    txt << "Closest point of the degree-" << (P->size() - 1) << " Bézier curve to " << text(p->front()) << "\n"
        << "  t = " << formatDouble(c.t) << "\n"
        << "  c(t) = " << text(c.point) << "\n"
        << "  distance = " << formatDouble(c.distance) << "\n";
    out.text = txt.str();
    return out;
}

} // namespace

Command projectCommand()
{
    return {"project",
            "--points P | --points-file F  --at x,y  [--json]",
            "the closest point of the curve to (x, y): global over [0, 1], ends included, smallest t on a tie",
            {{"points", "points-file", "at"}, {"json"}, {}},
            &run};
}

} // namespace granota::cli
