#pragma once
/// \file closest_point.h
/// The point of a Bézier curve (Def 2.6) closest to a given point p, globally over
/// t ∈ [0, 1]. Beyond the thesis: at an interior minimum of |c(t) − p|² its derivative
/// 2 (c(t) − p)·c′(t) is 0, a polynomial of degree 2n − 1 whose Bernstein coefficients are
/// the product of those of c − p (degree n) and of the hodograph c′ (degree n − 1,
/// hodograph.h); all its roots in [0, 1] (bernstein_roots.h) and both ends are the only
/// candidates (Pomax, "A Primer on Bézier Curves", § "Projecting a point onto a Bézier
/// curve", does this with a look-up table instead; Chen et al., "Computing the minimum
/// distance between a point and a NURBS curve", CAD 40, 2008, use the same polynomial).

#include "core/base/vec2.h"

#include <vector>

namespace granota {

struct ClosestPoint {
    double t = 0;
    Point point;
    double distance = 0;
};

/// The global minimum of |c(t) − p| over [0, 1], ends included; on a tie (distances equal
/// within 10⁻¹² of the curve's size) the smallest t. P must not be empty; a single point
/// gives t = 0.
ClosestPoint closestPoint(const std::vector<Point>& P, Point p);

/// The Bernstein coefficients (degree 2n − 1) of (c(t) − p)·c′(t); empty for n = 0.
std::vector<double> projectionPolynomial(const std::vector<Point>& P, Point p);

} // namespace granota
