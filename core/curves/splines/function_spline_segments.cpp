#include "core/curves/splines/function_spline_segments.h"

#include <cassert>
#include <cstddef>

namespace granota {

template <class S> FunctionSplineSegments<S> functionSplineSegments(const PiecewisePolynomial<S>& pp)
{
    assert(pp.isValid());
    FunctionSplineSegments<S> out;
    out.segments.reserve(pp.pieces.size());
    out.intervals.reserve(pp.pieces.size());
    for (int i = 0; i < pp.pieceCount(); ++i) {
        const auto ui = static_cast<std::size_t>(i);
        const S& x0 = pp.knots[ui];
        const S h = S(pp.knots[ui + 1] - x0);
        // s_i in powers of v = x − x_i, then v = h·u: c_k ↦ c_k h^k.
        const Polynomial<S> local = pp.localOrigin ? pp.pieces[ui] : pp.pieces[ui].shifted(x0);
        std::vector<S> c = local.coefficients();
        S power(1);
        for (S& ck : c) {
            ck = S(ck * power);
            power = S(power * h);
        }
        out.segments.emplace_back(Polynomial<S>({x0, h}), Polynomial<S>(std::move(c)));
        out.intervals.push_back(h);
    }
    return out;
}

template FunctionSplineSegments<double> functionSplineSegments(const PiecewisePolynomial<double>&);
template FunctionSplineSegments<Rational> functionSplineSegments(const PiecewisePolynomial<Rational>&);

} // namespace granota
