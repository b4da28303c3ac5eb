#pragma once
/// \file spline_modes.h
/// The two other answers of `granota-cli spline` (spline_command.cpp dispatches to them):
/// `--parametric`, the C² spline through points of the plane (parametric_spline.h), and
/// `--monotone`, monotone interpolation of function data (monotone_spline.h); and the
/// pieces' output that the function spline and the monotone one share.

#include "app/cli/command.h"

#include "core/base/number_format.h"
#include "core/curves/splines/piecewise_polynomial.h"
#include "core/exact/polynomial_text.h"

#include <sstream>
#include <type_traits>

namespace granota::cli {

Expected<CommandOutput> runParametricSpline(const Arguments& args);
Expected<CommandOutput> runMonotoneSpline(const Arguments& args);

template <class S> Json knotNumber(const S& x, bool exact)
{
    if constexpr (std::is_same_v<S, Rational>)
        return number(x, exact);
    else
        return number(x);
}

template <class S> std::string knotText(const S& x)
{
    if constexpr (std::is_same_v<S, Rational>)
        return toString(x);
    else
        return formatDouble(x);
}

/// The pieces s_1 … s_k (Def 2.3's numbering) in powers of x, as JSON ("pieces") and as text.
template <class S>
void describePieces(const PiecewisePolynomial<S>& spline, bool exact, CommandOutput& out, std::ostringstream& txt)
{
    Json pieces = Json::array();
    for (int i = 0; i < spline.pieceCount(); ++i) {
        const Polynomial<S> global = spline.globalPiece(i);
        const auto& from = spline.knots[static_cast<std::size_t>(i)];
        const auto& to = spline.knots[static_cast<std::size_t>(i) + 1];
        Json piece = Json::object();
        piece.set("from", knotNumber(from, exact)).set("to", knotNumber(to, exact)).set("poly", cubicCoefficients(global, exact));
        pieces.push(std::move(piece));
        txt << "  s_" << i + 1 << "(x) = " << toText(global, "x") << "   x ∈ [" << knotText(from) << ", " << knotText(to)
            << (i + 1 < spline.pieceCount() ? ")" : "]") << "\n";
    }
    out.json.set("pieces", std::move(pieces));
}

} // namespace granota::cli
