#pragma once
/// \file bspline_sampling.h
/// c(u) at many parameters, as a curve is sampled for drawing: bsplinePoint's arithmetic (the same
/// values to the bit), with each parameter's span found by stepping on from the previous one's
/// instead of a bisection of all the knots. When the parameters increase that costs a step or
/// two (a bisection of 10⁴ knots is about fourteen unpredictable branches, half the time of a
/// cubic's point); scipy's BSpline.__call__ keeps the same hint. Any order is accepted: a
/// parameter behind the last span, or far ahead of it, is found by bisection.

#include "core/curves/bsplines/de_boor.h"
#include "core/curves/bsplines/knot_vector.h"

#include <cassert>
#include <cstddef>
#include <vector>

namespace granota {

/// out[i] = bsplinePoint(c, us[i]) for every i (out is resized). Same preconditions as
/// bsplinePoint: c passes checkBSpline, every u in the domain.
template <class S> void bsplinePoints(const BSplineCurve<S>& c, const std::vector<S>& us, std::vector<Vec2<S>>& out)
{
    out.resize(us.size());
    if (us.empty())
        return;
    const int p = c.degree, n = c.pointCount() - 1;
    const auto K = [&](int i) -> const S& { return c.knots[static_cast<std::size_t>(i)]; };
    constexpr int kMaxSteps = 4; // beyond this many knots ahead a bisection is cheaper
    int k = findSpan(c.knots, p, n + 1, us.front());
    for (std::size_t i = 0; i < us.size(); ++i) {
        const S& u = us[i];
        // findSpan's k is the last one with u_k ≤ u, for u in [u_p, u_{n+1}); walking on from a
        // k with u_k ≤ u while u_{k+1} ≤ u reaches the same one.
        if (K(k) <= u && u < K(n + 1)) {
            int steps = 0;
            while (steps < kMaxSteps && K(k + 1) <= u) {
                ++k;
                ++steps;
            }
            if (K(k + 1) <= u)
                k = findSpan(c.knots, p, n + 1, u);
        } else {
            k = findSpan(c.knots, p, n + 1, u);
        }
        assert(k == findSpan(c.knots, p, n + 1, u));
        out[i] = bsplinePointInSpan(c, u, k);
    }
}

} // namespace granota
