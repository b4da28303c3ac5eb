#pragma once
/// \file bernstein_roots.h
/// All real roots in [0, 1] of a polynomial written in the Bernstein basis,
/// p(t) = Σ_{i=0}^{n} b_i B_i^n(t) (Def 2.5), of any degree. Beyond the thesis: the
/// extrema, bounding box, inflections, cusps and closest point of a Bézier curve
/// (curve_features.h, closest_point.h) are all roots of such polynomials.
///
/// The method is recursive subdivision with Descartes' rule of signs for the Bernstein
/// form (Lane & Riesenfeld, "Bounds on a polynomial", BIT 21, 1981; the same bound that
/// drives Sederberg & Nishita's Bézier clipping, CAD 22(9), 1990): the number of roots in
/// (0, 1), counted with multiplicity, is at most the number V of sign changes of
/// b_0 … b_n and has the parity of V. So V = 0 means no root, V = 1 exactly one; otherwise
/// the interval is halved by De Casteljau (Def 2.4), which gives the Bernstein
/// coefficients of both halves. A single root is polished by Newton steps kept inside its
/// bracket (bisection when a step leaves it) to full double precision. A multiple root
/// (tangential zero such as (t − 1/2)²) never separates into V = 1: it is recognised when
/// every coefficient of a small interval is below the rounding error of the evaluation,
/// and is reported once, at the zero of p′ there (or of p for an odd multiplicity).

#include <vector>

namespace granota {

struct BernsteinRoots {
    /// The roots in [0, 1], ascending, each once (a double root once); 0 and 1 are
    /// included when b_0 = 0 resp. b_n = 0 exactly.
    std::vector<double> roots;
    /// crossing[k]: p changes sign at roots[k] (odd multiplicity); false for a tangential
    /// zero (even multiplicity) and for a root at 0 or 1 (no other side to compare).
    std::vector<bool> crossing;
    /// Every coefficient is 0 (or there are none): p ≡ 0, and roots is empty.
    bool identicallyZero = false;
};

/// All roots in [0, 1] of Σ b_i B_i^n(t), n = coefficients.size() − 1. A non-finite
/// coefficient gives no roots (nothing can be said). Two roots closer than the
/// precision allows (their polynomial's values between them below the rounding error,
/// about n·2⁻⁵²·max|b_i|) are one root.
BernsteinRoots bernsteinRoots(const std::vector<double>& coefficients);

/// p(t) for t in [0, 1] in O(n) (Volk–Schumaker's Horner-like scheme; De Casteljau for
/// n > 1000, where binomial coefficients would overflow). coefficients must not be empty.
double bernsteinValue(const std::vector<double>& coefficients, double t);

/// The Bernstein coefficients (degree m + n) of the product of two polynomials of degrees
/// m and n given in Bernstein form: c_k = Σ_{i+j=k} C(m,i) C(n,j) / C(m+n,k) a_i b_j
/// (Farouki & Rajan, "Algorithms for polynomials in Bernstein form", CAGD 5, 1988, §3;
/// no degree elevation needed). Empty if either is empty.
std::vector<double> bernsteinProduct(const std::vector<double>& a, const std::vector<double>& b);

/// C(k, 0) … C(k, k) as doubles: exact up to 2⁵³, then correctly rounded to ~1e-16 relative
/// (C(400, 200) ≈ 1e119 is far from overflow).
std::vector<double> binomialRow(int k);

} // namespace granota
