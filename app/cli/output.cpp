#include "app/cli/command.h"

#include "core/base/number_format.h"

namespace granota::cli {

Json number(const Rational& q, bool exact) { return exact ? Json(toString(q)) : Json(toDouble(q)); }
Json number(double d) { return Json(d); }

Json point(const RPoint& p, bool exact)
{
    Json a = Json::array();
    a.push(number(p.x, exact));
    a.push(number(p.y, exact));
    return a;
}

Json point(const Point& p)
{
    Json a = Json::array();
    a.push(p.x);
    a.push(p.y);
    return a;
}

std::string text(const RPoint& p) { return "(" + toString(p.x) + ", " + toString(p.y) + ")"; }
std::string text(const Point& p) { return "(" + formatDouble(p.x) + ", " + formatDouble(p.y) + ")"; }

} // namespace granota::cli
