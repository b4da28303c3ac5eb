#pragma once
/// \file command.h
/// A granota-cli command: its syntax, its usage line and what it computes. A command
/// returns both forms of its answer, the JSON object of docs/cli.md and the text for people;
/// main() prints one of them.

#include "app/cli/arguments.h"
#include "core/exact/polynomial.h"
#include "core/io/json.h"

#include <string>
#include <type_traits>

namespace granota::cli {

using granota::Json;

struct CommandOutput {
    Json json = Json::object();
    std::string text;
};

struct Command {
    const char* name;
    std::string usage;   ///< one line: the options
    const char* summary; ///< one line: what it does
    CommandSyntax syntax;
    Expected<CommandOutput> (*run)(const Arguments&);
};

// One per file, named for the command.
Command bezierCommand();
Command bernsteinCommand();
Command fitCommand();
Command catmullRomCommand();
Command kochanekBartelsCommand();
Command simulateCommand();
Command benchCommand();
Command demoCommand();
Command reportCommand();
Command projectCommand();
Command analyzeCommand();
Command splineCommand();
Command bsplineCommand();

/// Number output: exact "p/q" strings with --exact, doubles otherwise (docs/cli.md).
Json number(const Rational& q, bool exact);
Json number(double d);
Json point(const RPoint& p, bool exact);
Json point(const Point& p);
/// A cubic's coefficients c0…c3 in powers of its variable: exact strings when `exact`
/// (Rational only), doubles otherwise (the segments of catmull-rom, the pieces of spline).
template <class S> Json cubicCoefficients(const Polynomial<S>& p, bool exact)
{
    Json a = Json::array();
    for (const S& c : p.coefficients(3)) {
        if constexpr (std::is_same_v<S, Rational>)
            a.push(number(c, exact));
        else
            a.push(number(c));
    }
    return a;
}
std::string text(const RPoint& p);
std::string text(const Point& p);
/// Highest degree bezier and bernstein accept: beyond it the O(n²) triangle and the exact
/// tables stop being something anyone reads, and a typo must not hang. fit has its own,
/// lower maximum, the core's kMaxFitDegree.
constexpr int kMaxDegree = 200;

/// The control points of --points/--points-file for the curve commands (bezier, analyze,
/// project): at most kMaxDegree + 1 of them.
Expected<std::vector<RPoint>> controlPoints(const Arguments& args);

} // namespace granota::cli
