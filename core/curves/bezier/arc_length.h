#pragma once
/// \file arc_length.h
/// Arc length s(t) = ∫_0^t |c′(u)| du of a Bézier curve, its total L = s(1), and the inverse
/// t(s) for moving along the curve at constant speed (beyond the thesis; the method: Davis &
/// Rabinowitz, "Methods of Numerical Integration", §6.2 adaptive Gauss–Legendre, and Pomax,
/// "A Primer on Bézier Curves", §"Arc length", which uses one fixed 24-point rule instead).
///
/// |c′| is the length of the hodograph (hodograph.h), evaluated in O(n) by the nested
/// (Horner-like) form of the Bernstein sum, at the 16 nodes of a panel at once (four per
/// instruction where the processor has AVX2, chosen at run time; the same operations, so
/// the same lengths to the bit as without). The integral is a composite 16-point
/// Gauss–Legendre rule, halving each panel until the two halves agree with the whole to the
/// requested share of relative tolerance × L, and split first at the zeros of |c′| (cusps),
/// where the integrand has a kink that would slow the rule down. t(s) is Newton's method on
/// s(t) − s inside one panel, safeguarded by bisection. The curve is scaled by a power of two
/// for the computation, so huge and tiny coordinates give finite lengths. No allocation for
/// degree ≤ 63 in arcLength(); ArcLengthParametrization allocates once, when it is built.

#include "core/base/vec2.h"

#include <vector>

namespace granota {

/// ∫_{t0}^{t1} |c′(t)| dt (negative when t1 < t0; t0, t1 are clamped to [0, 1]), to about
/// relativeTolerance of the length of that piece (at least 1e-15). P must not be empty;
/// a single point (or all points equal) has length 0.
double arcLength(const std::vector<Point>& P, double t0 = 0, double t1 = 1, double relativeTolerance = 1e-13);

/// The panels of the adaptive rule, kept: s(t) and t(s) on them at the cost of one 16-point
/// rule (plus a few Newton steps for t(s)).
class ArcLengthParametrization {
public:
    explicit ArcLengthParametrization(const std::vector<Point>& P, double relativeTolerance = 1e-13);
    double total() const { return m_total; }                    ///< L
    double lengthAt(double t) const;                            ///< s(t), t clamped to [0, 1]
    double parameterAt(double s) const;                         ///< t(s), s clamped to [0, L]; the smallest t on a
                                                                ///< stretch of zero speed (a repeated point)
    int panels() const { return static_cast<int>(m_a.size()); } ///< how many the rule needed

private:
    double panelLength(std::size_t k, double t) const; // scaled ∫_{a_k}^{t}
    double speed(double t) const;                      // scaled |c′(t)|

    std::vector<Point> m_w;  // C(m,i) · (scaled hodograph point i)
    std::vector<double> m_a; // panel starts, ascending; panel k is [m_a[k], m_a[k+1]] (last ends at 1)
    std::vector<double> m_s; // scaled s(m_a[k])
    double m_scale = 1;      // lengths of the scaled curve times m_scale are lengths of c
    double m_total = 0;
};

} // namespace granota
