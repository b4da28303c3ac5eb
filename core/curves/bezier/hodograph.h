#pragma once
/// \file hodograph.h
/// The hodograph: the derivative of a Bézier curve of degree n is itself a Bézier curve of
/// degree n − 1 over the Bernstein polynomials of Def 2.5,
///   c′(t) = Σ_{i=0}^{n−1} B_i^{n−1}(t) · n (P_{i+1} − P_i)
/// (beyond the thesis: Farin, "Curves and Surfaces for CAGD", §5.3). Applying it twice gives
/// c″. Exact for Rational.

#include "core/base/vec2.h"

#include <cassert>
#include <vector>

namespace granota {

/// n (P_{i+1} − P_i), i = 0..n−1: the control points of c′. A single point (degree 0, c′ ≡ 0)
/// gives {(0,0)}, so that hodograph(hodograph(P)) is defined for every P.
template <class S> std::vector<Vec2<S>> hodograph(const std::vector<Vec2<S>>& P)
{
    assert(!P.empty());
    if (P.size() < 2)
        return {Vec2<S>(S(0), S(0))};
    const S n(static_cast<int>(P.size()) - 1);
    std::vector<Vec2<S>> d;
    d.reserve(P.size() - 1);
    for (std::size_t i = 0; i + 1 < P.size(); ++i)
        d.push_back(n * (P[i + 1] - P[i]));
    return d;
}

} // namespace granota
