#pragma once
/// \file polygon_geometry.h
/// The geometry of a polygon that every soft-body solver needs, in one place: its area by
/// the trapezoid rule of §4.5, whether a point lies inside it by the crossing test of §4.6,
/// the mean of its vertices and its bounding box.
///
/// Area (§4.5): walk the vertices in order and add, for each edge v_i → v_{i+1}, the
/// trapezoid between the edge and the x axis, (x_i − x_{i+1}) (y_i + y_{i+1}) / 2, signed
/// by the direction of travel. The sum is the signed area (the shoelace formula in
/// disguise); its absolute value is the area.
///
/// Point in polygon (§4.6): start "outside", walk the edges, and flip each time the point
/// lies between the x of an edge's ends and on one side (above, in screen coordinates) of
/// that edge. Unlike the seed's `estadins`, the x interval is half-open, [min x, max x),
/// so that a vertical line through a vertex counts the two edges meeting there once, not
/// twice, and vertical edges are skipped: the answer is then right for every point not on
/// the boundary. Works for any simple polygon, convex or not, in either orientation.
///
/// Each computation has two forms, and they differ on purpose, each kept bit for bit as its
/// callers have always had it: a std::vector form (the §4.5 sum for any scalar, the §4.6
/// test with a division), and a flat-array form for the stable solver's inner loops (the
/// area relative to the first vertex, the crossing test without a division or a branch).
/// The seed solver keeps its own area loop (SeedBody::area, Annex II's calculaarea in its
/// float lanes and its order of operations) so that it reproduces the thesis's program.

#include "core/base/aabb.h"
#include "core/base/vec2.h"

#include <vector>

namespace granota {

/// §4.5, signed, closing the polygon from the last vertex back to the first. With the
/// thesis's screen coordinates (y down) a polygon built as in §4.1 comes out positive.
template <class S> S trapezoidArea(const std::vector<Vec2<S>>& polygon)
{
    S area(0);
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2<S>& a = polygon[i];
        const Vec2<S>& b = polygon[(i + 1) % n];
        area += S(S(a.x - b.x) * S(a.y + b.y));
    }
    return S(area / S(2));
}

/// |trapezoidArea|, as §4.5 takes it "to avoid problems".
inline double polygonArea(const std::vector<Point>& polygon)
{
    const double a = trapezoidArea(polygon);
    return a < 0 ? -a : a;
}

/// Signed shoelace area ½ Σ xᵢ × xᵢ₊₁ of n points — the trapezoid sum of §4.5 rewritten,
/// positive for regularPolygon's order in screen coordinates. Taken relative to x[0], so
/// that a small polygon far from the origin loses no digits; 0 for fewer than 3 points.
double signedArea(const Point* x, int n);

/// The sign of Σ xⱼ × xᵢ over the edges j → i (absolute coordinates): +1 for
/// regularPolygon's order on screen, and for a degenerate polygon.
double signedAreaSign(const Point* poly, int n);

/// §4.6 for a point and a polygon (see the file comment).
bool pointInPolygon(const Point& p, const std::vector<Point>& polygon);

/// §4.6 on a flat array, the same half-open rule, "p lies above the edge" tested without a
/// division: (p.y − a.y)(b.x − a.x) ≤ (p.x − a.x)(b.y − a.y), flipped when b.x < a.x.
bool pointInPolygon(const Point* poly, int n, const Point& p);
/// The same, also giving the crossed edge nearest to p along the test's ray (−1 if none):
/// a good first guess for nearestBoundaryPoint (xpbd_collisions.h).
bool pointInPolygon(const Point* poly, int n, const Point& p, int* nearestCrossing);

/// Mean of n points (the centre of mass of equal masses); the origin for none.
Point vertexCentroid(const Point* x, int n);

} // namespace granota
