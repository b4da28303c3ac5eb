#include "core/softbody/xpbd/xpbd_collisions.h"

#include "core/softbody/polygon_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace granota {

BoundaryPoint nearestBoundaryPoint(const Point* poly, int n, const Point& p, int hint)
{
    BoundaryPoint best;
    double best2 = std::numeric_limits<double>::infinity();
    const auto consider = [&](int i) {
        const Point& a = poly[i];
        const Point& b = poly[i + 1 == n ? 0 : i + 1];
        double s = 0;
        const Point q = closestOnSegment(a, b, p, &s);
        const Point d = p - q;
        const double d2 = dot(d, d);
        if (d2 < best2) {
            best.edge = i;
            best.s = s;
            best.q = q;
            best2 = d2;
        }
    };
    if (hint >= 0 && hint < n)
        consider(hint);
    for (int i = 0; i < n; ++i) {
        const Point& a = poly[i];
        const Point& b = poly[i + 1 == n ? 0 : i + 1];
        // An edge whose box is farther than the best so far cannot be nearer: skip it
        // before the division. With a good hint, most edges end here. (Plain max/min of
        // two: they compile to max/min instructions, not to branches on the data.)
        const double gx = std::max(std::max(std::min(a.x, b.x) - p.x, p.x - std::max(a.x, b.x)), 0.0);
        const double gy = std::max(std::max(std::min(a.y, b.y) - p.y, p.y - std::max(a.y, b.y)), 0.0);
        if (gx * gx + gy * gy < best2 && i != hint)
            consider(i);
    }
    if (best.edge < 0) { // no edge at a finite distance (NaN input): the first vertex
        best.edge = 0;
        best.q = n > 0 ? poly[0] : p;
    }
    best.dist = std::sqrt(dot(p - best.q, p - best.q));
    return best;
}

bool segmentsCross(const Point& p, const Point& q, const Point& a, const Point& b)
{
    const double d1 = cross(b - a, p - a);
    const double d2 = cross(b - a, q - a);
    const double d3 = cross(q - p, a - p);
    const double d4 = cross(q - p, b - p);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

namespace {

/// Position-based Coulomb friction against a fixed surface of normal n after a normal
/// correction of `depth`: the tangential move of the substep is undone entirely while it
/// is below μ·depth (sticking), by μ·depth otherwise (sliding). Macklin et al. 2014, eq. 24.
void staticSurfaceFriction(Point& x, const Point& xPrev, const Point& n, double depth, double mu)
{
    const Point d = x - xPrev;
    const double dn = dot(d, n);
    const Point t(d.x - dn * n.x, d.y - dn * n.y);
    const double lt = std::sqrt(dot(t, t));
    if (lt < 1e-15)
        return;
    const double limit = mu * depth;
    const double k = lt <= limit ? 1.0 : limit / lt;
    x -= Point(k * t.x, k * t.y);
}

/// The unit vector along `d`; straight up (−y) for a zero vector.
Point unitOrUp(const Point& d)
{
    const double l = std::sqrt(dot(d, d));
    return l > 0 ? Point(d.x / l, d.y / l) : Point(0, -1);
}

} // namespace

void solveWalls(Point* x, const Point* xPrev, const double* w, Point* contactNormal, int n, double width, double height,
                double friction)
{
    const double maxX = width - 1;
    const double maxY = height - 1;
    for (int i = 0; i < n; ++i) {
        if (!(w[i] > 0))
            continue;
        Point p = x[i];
        if (!isFinite(p)) { // never let a NaN through: fall back to the substep's start
            p = isFinite(xPrev[i]) ? xPrev[i] : Point(0.5 * maxX, 0.5 * maxY);
        }
        double dx = 0;
        double dy = 0;
        if (p.x < 0)
            dx = -p.x;
        else if (p.x > maxX)
            dx = maxX - p.x;
        if (p.y < 0)
            dy = -p.y;
        else if (p.y > maxY)
            dy = maxY - p.y;
        if (dx == 0 && dy == 0) {
            x[i] = p;
            continue;
        }
        p.x += dx;
        p.y += dy;
        // A wall that pushed in x brakes the motion in y, and the other way round.
        if (dx != 0 && dy == 0) {
            const double t = p.y - xPrev[i].y;
            const double limit = friction * std::abs(dx);
            p.y = std::abs(t) <= limit ? xPrev[i].y : p.y - std::copysign(limit, t);
        } else if (dy != 0 && dx == 0) {
            const double t = p.x - xPrev[i].x;
            const double limit = friction * std::abs(dy);
            p.x = std::abs(t) <= limit ? xPrev[i].x : p.x - std::copysign(limit, t);
        }
        p.x = std::clamp(p.x, 0.0, maxX);
        p.y = std::clamp(p.y, 0.0, maxY);
        x[i] = p;
        contactNormal[i] = unitOrUp(Point(dx == 0 ? 0.0 : std::copysign(1.0, dx), dy == 0 ? 0.0 : std::copysign(1.0, dy)));
    }
}

bool solveObstacle(const XpbdObstacle& o, const Point* pts, Point& x, const Point& xPrev, double margin, double friction,
                   Point* normal)
{
    // §5.2.1: the cheap box test first, the exact test only when it passes.
    Aabb path;
    path.minX = std::min(x.x, xPrev.x);
    path.maxX = std::max(x.x, xPrev.x);
    path.minY = std::min(x.y, xPrev.y);
    path.maxY = std::max(x.y, xPrev.y);
    Aabb grown = o.box;
    grown.minX -= margin, grown.minY -= margin, grown.maxX += margin, grown.maxY += margin;
    if (!path.overlaps(grown))
        return false;

    Point target;
    Point n;
    if (o.shape == XpbdObstacle::Shape::Segment) {
        const Point a = pts[o.first];
        const Point b = pts[o.first + 1];
        // At least a hair's breadth: a particle left exactly on a zero-thickness segment
        // would not "cross" it next substep (the test is strict) and could fall through.
        const double reach = std::max(o.radius + margin, 1e-3);
        const Point q = closestOnSegment(a, b, x);
        const Point d = x - q;
        const double dist = std::sqrt(dot(d, d));
        if (segmentsCross(xPrev, x, a, b)) {
            // Went through the core line within one substep: back to the side it came from.
            const Point t = b - a;
            n = unitOrUp(Point(t.y, -t.x));
            if (dot(n, xPrev - a) < 0)
                n = -n;
        } else if (dist < reach) {
            if (dist > 1e-12) {
                n = Point(d.x / dist, d.y / dist);
            } else { // on the core line: the side of the substep's start, else up
                const Point t = b - a;
                n = unitOrUp(Point(t.y, -t.x));
                if (dot(n, xPrev - a) < 0)
                    n = -n;
            }
        } else {
            return false;
        }
        target = q + Point(reach * n.x, reach * n.y);
    } else {
        const Point* poly = pts + o.first;
        const bool inside = pointInPolygon(poly, o.count, x);
        if (!inside && !(margin > 0))
            return false;
        const BoundaryPoint bp = nearestBoundaryPoint(poly, o.count, x);
        if (!inside && bp.dist >= margin)
            return false;
        if (bp.dist > 1e-12) {
            const Point d((x.x - bp.q.x) / bp.dist, (x.y - bp.q.y) / bp.dist);
            n = inside ? -d : d;
        } else { // on the boundary: the edge's outward normal
            const Point t = poly[bp.edge + 1 == o.count ? 0 : bp.edge + 1] - poly[bp.edge];
            const double sign = signedAreaSign(poly, o.count);
            n = unitOrUp(Point(sign * t.y, -sign * t.x));
        }
        target = bp.q + Point(margin * n.x, margin * n.y);
    }
    const double depth = dot(target - x, n);
    x = target;
    staticSurfaceFriction(x, xPrev, n, std::max(depth, 0.0), friction);
    if (normal)
        *normal = n;
    return true;
}

bool solvePointInBody(Point* x, const double* w, int p, const Point& fixedPoint, int first, int count, double orientation,
                      double margin, BodyContact* contact, int* edgeHint)
{
    const Point pp = p >= 0 ? x[p] : fixedPoint;
    const Point* poly = x + first;
    // A first guess for the nearest edge: the caller's (last substep's nearest: contacts
    // move little between substeps), else the edge the upward ray crossed first.
    const bool known = edgeHint && *edgeHint >= 0 && *edgeHint < count;
    int hint = known ? *edgeHint : -1;
    const bool inside = pointInPolygon(poly, count, pp, known ? nullptr : &hint);
    if (!inside && !(margin > 0)) // the common case: near the box, outside the polygon
        return false;
    const BoundaryPoint bp = nearestBoundaryPoint(poly, count, pp, hint);
    if (edgeHint)
        *edgeHint = bp.edge;
    if (!inside && bp.dist >= margin)
        return false;
    const int e0 = first + bp.edge;
    const int e1 = first + (bp.edge + 1 == count ? 0 : bp.edge + 1);
    Point n; // direction p must move relative to the edge
    double depth = 0;
    if (bp.dist > 1e-12) {
        const Point d((pp.x - bp.q.x) / bp.dist, (pp.y - bp.q.y) / bp.dist);
        n = inside ? -d : d;
        depth = inside ? bp.dist + margin : margin - bp.dist;
    } else {
        const Point t = x[e1] - x[e0];
        n = unitOrUp(Point(orientation * t.y, -orientation * t.x));
        depth = margin;
    }
    const double s = bp.s;
    const double wp = p >= 0 ? w[p] : 0.0;
    const double w0 = (1 - s) * w[e0];
    const double w1 = s * w[e1];
    // C = n·(p − q) − margin ≥ 0 with q = (1 − s) x_e0 + s x_e1: ∇_p = n, ∇_e0 = −(1 − s) n,
    // ∇_e1 = −s n; α = 0 (Macklin et al. 2016, eq. 18 with α̃ = 0).
    const double wsum = wp + (1 - s) * w0 + s * w1;
    if (!(wsum > 0))
        return false;
    const double dl = depth / wsum;
    if (p >= 0)
        x[p] += Point(wp * dl * n.x, wp * dl * n.y);
    x[e0] -= Point(w0 * dl * n.x, w0 * dl * n.y);
    x[e1] -= Point(w1 * dl * n.x, w1 * dl * n.y);
    if (contact)
        *contact = BodyContact{p, e0, e1, s, n, dl};
    return true;
}

bool solvePointAgainstEdge(Point* x, const double* w, int p, int e0, int e1, double orientation, double margin,
                           BodyContact* contact)
{
    const Point a = x[e0];
    const Point t = x[e1] - a;
    const double l2 = dot(t, t);
    if (!(l2 > 1e-24)) // a collapsed edge has no normal: the exact test decides
        return false;
    const Point ap = x[p] - a;
    const double along = dot(ap, t);
    if (!(along >= 0 && along <= l2)) // slid past an end: a corner, where another edge may be nearer
        return false;
    const double len = std::sqrt(l2);
    const Point n(orientation * t.y / len, -orientation * t.x / len); // outward, as solvePointInBody's
    const double depth = margin - dot(ap, n);
    if (!(depth > 0)) // in front of the edge: perhaps leaving, perhaps past a corner
        return false;
    const double s = along / l2;
    const double wp = w[p];
    const double w0 = (1 - s) * w[e0];
    const double w1 = s * w[e1];
    const double wsum = wp + (1 - s) * w0 + s * w1;
    if (!(wsum > 0))
        return false;
    const double dl = depth / wsum; // C = n·(p − q) − margin ≥ 0, α = 0, as in solvePointInBody
    x[p] += Point(wp * dl * n.x, wp * dl * n.y);
    x[e0] -= Point(w0 * dl * n.x, w0 * dl * n.y);
    x[e1] -= Point(w1 * dl * n.x, w1 * dl * n.y);
    *contact = BodyContact{p, e0, e1, s, n, dl};
    return true;
}

void applyContactFriction(const BodyContact& c, Point* v, const double* w, double friction, double h)
{
    const double s = c.s;
    const double wp = c.p >= 0 ? w[c.p] : 0.0;
    const double w0 = (1 - s) * w[c.e0];
    const double w1 = s * w[c.e1];
    const double wsum = wp + (1 - s) * w0 + s * w1;
    if (!(wsum > 0))
        return;
    const Point vp = c.p >= 0 ? v[c.p] : Point();
    const Point ve((1 - s) * v[c.e0].x + s * v[c.e1].x, (1 - s) * v[c.e0].y + s * v[c.e1].y);
    const Point rel = vp - ve;
    const double rn = dot(rel, c.n);
    const Point t(rel.x - rn * c.n.x, rel.y - rn * c.n.y);
    const double lt = std::sqrt(dot(t, t));
    if (lt < 1e-15)
        return;
    // The normal impulse of the contact was λ/h; friction may take at most μ times that,
    // and never more than stops the sliding (Müller et al. 2020, eq. 30).
    const double impulse = std::min(lt / wsum, friction * c.lambda / h);
    const Point j(impulse * t.x / lt, impulse * t.y / lt);
    if (c.p >= 0)
        v[c.p] -= Point(wp * j.x, wp * j.y);
    v[c.e0] += Point(w0 * j.x, w0 * j.y);
    v[c.e1] += Point(w1 * j.x, w1 * j.y);
}

} // namespace granota
