#pragma once
/// \file molding.h
/// Dragging the curve itself ("molding", beyond the thesis; Farin, "Curves and Surfaces for
/// CAGD", §3.6 on direct manipulation, and Pomax, "A Primer on Bézier Curves", §"Moulding"):
/// move the curve's point c(t) to `target` by the smallest change of the control points.
/// The constraint Σ_i B_i^n(t) ΔP_i = Δ, Δ = target − c(t) (Def 2.6), has the minimum-norm
/// solution (least Σ|ΔP_i|², the pseudo-inverse of the row (B_0^n(t) … B_n^n(t)))
///   ΔP_i = B_i^n(t) Δ / Σ_j B_j^n(t)²,
/// so control points far from t, whose B_i^n(t) is small, barely move. Exact for Rational:
/// afterwards c(t) = target exactly.

#include "core/base/vec2.h"
#include "core/curves/bezier/bernstein.h"

#include <cassert>
#include <vector>

namespace granota {

template <class S> std::vector<Vec2<S>> moldCurve(const std::vector<Vec2<S>>& P, const S& t, const Vec2<S>& target)
{
    assert(!P.empty());
    const std::vector<S> b = bernsteinAll(static_cast<int>(P.size()) - 1, t);
    const Vec2<S> delta = target - bezierBernstein(P, t);
    S sum(0);
    for (const S& bi : b)
        sum += S(bi * bi);
    // Σ B_j² ≥ (Σ B_j)²/(n+1) = 1/(n+1) > 0 for t in [0, 1] (Lemma 2.1's partition of unity).
    std::vector<Vec2<S>> out(P);
    for (std::size_t i = 0; i < P.size(); ++i)
        out[i] += S(b[i] / sum) * delta;
    return out;
}

} // namespace granota
