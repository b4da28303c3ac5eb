#pragma once
/// \file xpbd_collisions.h
/// Contacts of the stable solver, solved as constraints inside each substep (Müller et al.
/// 2020, "Detailed rigid body simulation with extended position based dynamics", §3.5):
/// the frame's walls (§4.2), fixed
/// obstacles — thick segments and polygons, convex or not (§5.2.1) — and other bodies
/// (§5.2.2). A contact is an inequality C ≥ 0 with compliance 0; friction is the
/// position-based Coulomb model of Macklin et al. 2014 ("Unified particle physics for
/// real-time applications", eq. 24): the tangential displacement of the substep is undone
/// up to μ times the normal correction.
///
/// Surfaces have a thin skin (`margin`): a vertex closer than that is pushed out to it, so
/// that a body at rest stays in contact (and in friction) instead of falling in and being
/// thrown out every substep.

#include "core/softbody/xpbd/xpbd_broad_phase.h"
#include "core/base/vec2.h"

namespace granota {

/// A fixed obstacle: a thick segment (capsule) or a closed polygon; its points live in a
/// flat array of the world, [first, first + count).
struct XpbdObstacle {
    enum class Shape { Segment, Polygon };
    Shape shape = Shape::Segment;
    int first = 0;
    int count = 0;
    double radius = 0; ///< half thickness of a segment, px
    Aabb box;          ///< bounding box, grown by the radius
};

/// The nearest point of a closed polygon's boundary to p.
struct BoundaryPoint {
    int edge = -1;   ///< edge from vertex edge to vertex edge + 1 (mod n)
    double s = 0;    ///< position on that edge, [0, 1]
    Point q;         ///< the point
    double dist = 0; ///< |p − q|
};
/// `hint`, an edge likely to be nearest, is tried first so that the others can be
/// rejected by their boxes; the answer does not depend on it.
BoundaryPoint nearestBoundaryPoint(const Point* poly, int n, const Point& p, int hint = -1);

/// Nearest point to p on segment ab, and its parameter in [0, 1].
inline Point closestOnSegment(const Point& a, const Point& b, const Point& p, double* s = nullptr)
{
    const Point ab = b - a;
    const double l2 = dot(ab, ab);
    double t = l2 > 0 ? dot(p - a, ab) / l2 : 0.0;
    t = t < 0 ? 0.0 : (t > 1 ? 1.0 : t);
    if (s)
        *s = t;
    return {a.x + t * ab.x, a.y + t * ab.y};
}

/// Do the segments pq and ab cross (properly)?
bool segmentsCross(const Point& p, const Point& q, const Point& a, const Point& b);

/// Keeps every particle with w > 0 in [0, width − 1] × [0, height − 1] (Annex II's `fita`),
/// with friction against the wall. Sets contactNormal[i] for the particles it touched.
void solveWalls(Point* x, const Point* xPrev, const double* w, Point* contactNormal, int n, double width, double height,
                double friction);

/// Pushes particle x (with position xPrev at the substep's start) out of an obstacle.
/// Returns true on contact, with the normal; the obstacle does not move (infinite mass).
bool solveObstacle(const XpbdObstacle& o, const Point* obstaclePoints, Point& x, const Point& xPrev, double margin,
                   double friction, Point* normal);

/// A contact of a point with the edge e0–e1 of a body, at s along the edge: the point
/// had to move along n, relative to the edge, and the constraint's multiplier was λ.
struct BodyContact {
    int p = -1; ///< particle, or −1 for an obstacle's corner
    int e0 = 0;
    int e1 = 0;
    double s = 0;
    Point n;
    double lambda = 0;   ///< mass·px: the normal impulse of the substep is λ/h
    double friction = 0; ///< μ of this contact
};

/// A point p (particle index, or −1 with position `fixedPoint` for an obstacle's vertex)
/// against the polygon body [first, first + count): if p is inside or closer than margin,
/// p and the nearest edge are pushed apart, by inverse masses. `orientation` is the sign of
/// the polygon's signed area (for the normal when p lies on an edge). Returns true on
/// contact and describes it in *contact, for friction. `edgeHint`, when given, holds the
/// edge (0 … count − 1) found nearest last time, or −1: it is tried first, which lets the
/// search reject the other edges by their boxes, and receives the edge found nearest now
/// (touching or not); the answer does not depend on it.
bool solvePointInBody(Point* x, const double* w, int p, const Point& fixedPoint, int first, int count, double orientation,
                      double margin, BodyContact* contact, int* edgeHint = nullptr);

/// The same contact kept from the last substep (contact persistence, as contacts found once
/// and re-solved in every substep in Macklin et al. 2019, §4): p against the line of the
/// edge e0 → e1 of a body of orientation `orientation`, solved as solvePointInBody would
/// when that edge is the nearest. Only when p lies within the edge's span and behind it
/// (deeper than −margin); returns false — and does nothing — otherwise, and the caller then
/// asks solvePointInBody for the exact answer. Costs one edge instead of every edge twice.
bool solvePointAgainstEdge(Point* x, const double* w, int p, int e0, int e1, double orientation, double margin,
                           BodyContact* contact);

/// Coulomb friction of a body contact at the velocity level, after the substep's velocity
/// update: the relative tangential velocity of p and the edge point is reduced by at most
/// μ times the normal impulse (Müller et al. 2020, eq. 30). Between soft bodies this is
/// safer than friction on positions, which fights the bodies' own constraint corrections
/// and can feed energy into fine, stretched outlines.
void applyContactFriction(const BodyContact& contact, Point* v, const double* w, double friction, double h);

} // namespace granota
