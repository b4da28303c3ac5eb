#include "core/softbody/xpbd/xpbd_constraints.h"
#include "core/base/math_constants.h"

namespace granota {

void solveEdgeRing(DistanceConstraint* e, int n, Point* x, const Point* xPrev, const double* w, double alphaTildePerLength,
                   double dampingRatio, double* dampingLambda, Point* delta)
{
    constexpr double omega = 0.5; // each vertex lies on two edges: apply their mean
    for (int k = 0; k < n; ++k) {
        DistanceConstraint& c = e[k];
        const Point d = x[c.a] - x[c.b];
        const double len = std::sqrt(dot(d, d));
        const double mobility = w[c.a] + w[c.b];
        const double alpha = alphaTildePerLength * c.complianceScale;
        double denom = mobility + omega * alpha;
        if (len < 1e-12 || !(denom > 0)) {
            c.lambda = 0;
            continue;
        }
        // Soft limit: ω Δλ ≈ −ω C h²/(ω α) = −C h²/α, the spring's own force.
        double pull = -(len - c.rest);
        if (dampingLambda)
            dampingLambda[k] = 0;
        if (dampingRatio > 0 && alpha > 0 && mobility > 0) {
            // A dashpot along the edge (Macklin et al. 2016, eq. 26): γ = α̃ β̃ / h with
            // β̃ = h² b and b = 2ζ √(k m) (k = 1/α, m = 1/(w_a + w_b)): γ = 2ζ √(α̃ (w_a + w_b)) / (w_a + w_b).
            const double gamma = 2 * dampingRatio * std::sqrt(alpha / mobility);
            const Point moved = (x[c.a] - xPrev[c.a]) - (x[c.b] - xPrev[c.b]);
            const double damping = -gamma * dot(d, moved) / len;
            pull += damping;
            denom += gamma * mobility;
            if (dampingLambda)
                dampingLambda[k] = omega * (damping / denom);
        }
        const double applied = omega * (pull / denom);
        c.lambda = applied;
        const Point n(d.x / len * applied, d.y / len * applied);
        delta[c.a] += Point(w[c.a] * n.x, w[c.a] * n.y);
        delta[c.b] -= Point(w[c.b] * n.x, w[c.b] * n.y);
    }
    for (int k = 0; k < n; ++k) {
        const int i = e[k].a;
        x[i] += delta[i];
        delta[i] = Point();
    }
}

double edgeDashpotLoss(const DistanceConstraint* e, const double* dampingLambda, int n, const Point* x, const Point* xPrev,
                       double h)
{
    // The dashpot's force λ_d/h² along the edge, against how far the edge stretched in the
    // substep: −λ_d ΔC / h² (λ_d opposes the stretching, so the work it takes is > 0).
    double loss = 0;
    for (int k = 0; k < n; ++k) {
        const DistanceConstraint& c = e[k];
        if (dampingLambda[k] == 0)
            continue;
        const Point d = x[c.a] - x[c.b];
        const double len = std::sqrt(dot(d, d));
        if (!(len > 1e-12))
            continue;
        const Point moved = (x[c.a] - xPrev[c.a]) - (x[c.b] - xPrev[c.b]);
        loss -= dampingLambda[k] * (dot(d, moved) / len) / (h * h);
    }
    return loss;
}

double solveArea(Point* x, const double* w, int n, double target, double alphaTilde)
{
    if (n < 3)
        return 0;
    const double c = signedArea(x, n) - target;
    double denom = alphaTilde;
    for (int i = 0; i < n; ++i) {
        const Point g = areaGradient(x[i == 0 ? n - 1 : i - 1], x[i + 1 == n ? 0 : i + 1]);
        denom += w[i] * dot(g, g);
    }
    if (!(denom > 1e-300)) // every vertex on one point and α = 0: no direction to grow in
        return 0;
    const double dLambda = -c / denom; // Macklin et al. 2016, eq. 18 (λ = 0 at the substep's start)
    // Δxᵢ = wᵢ ∇ᵢC Δλ (eq. 17) with ∇ᵢC at the old positions: keep the old x[i−1] and x[0]
    // while moving the vertices in place.
    const Point first = x[0];
    Point prevOld = x[n - 1];
    for (int i = 0; i < n; ++i) {
        const Point cur = x[i];
        const Point next = i + 1 < n ? x[i + 1] : first;
        const Point g = areaGradient(prevOld, next);
        const double s = w[i] * dLambda;
        x[i] += Point(s * g.x, s * g.y);
        prevOld = cur;
    }
    return dLambda;
}

double solveAnchoredDistance(AnchoredDistanceConstraint& c, Point* x, const double* w, double alphaTilde)
{
    const double t = c.t;
    const Point p = x[c.a] + Point(t * (x[c.b].x - x[c.a].x), t * (x[c.b].y - x[c.a].y));
    const Point d = x[c.joint] - p;
    const double len = std::sqrt(dot(d, d));
    // C = |d| − rest: ∇_joint = n, ∇_a = −(1 − t) n, ∇_b = −t n (n = d/|d|); when a = b the
    // two body terms are one, of weight 1.
    const double wBody = c.a == c.b ? w[c.a] : (1 - t) * (1 - t) * w[c.a] + t * t * w[c.b];
    const double denom = w[c.joint] + wBody + alphaTilde;
    if (len < 1e-12 || !(denom > 0))
        return 0;
    const double dLambda = (-(len - c.rest) - alphaTilde * c.lambda) / denom; // Macklin et al. 2016, eq. 18
    c.lambda += dLambda;
    const Point n(d.x / len * dLambda, d.y / len * dLambda);
    x[c.joint] += Point(w[c.joint] * n.x, w[c.joint] * n.y);
    if (c.a == c.b) {
        x[c.a] -= Point(w[c.a] * n.x, w[c.a] * n.y);
    } else {
        x[c.a] -= Point((1 - t) * w[c.a] * n.x, (1 - t) * w[c.a] * n.y);
        x[c.b] -= Point(t * w[c.b] * n.x, t * w[c.b] * n.y);
    }
    return dLambda;
}

namespace {

/// ∇ of seedAngle(d) with respect to d: (−d.y, d.x)/|d|².
Point angleGradient(const Point& d)
{
    const double l2 = dot(d, d);
    return {-d.y / l2, d.x / l2};
}

} // namespace

namespace {

/// The reference direction of c: segment a0→a1, or straight down (seed angle 0) without one.
Point referenceDirection(const AngleConstraint& c, const Point* x) { return c.a0 < 0 ? Point(0, 1) : x[c.a1] - x[c.a0]; }

/// θ of c from its two directions.
double angleBetween(const AngleConstraint& c, const Point& da, const Point& db)
{
    // seedAngle(b) − seedAngle(a) is the turn from a to b, which one atan2 of their cross
    // and dot products gives directly, already in (−π, π]: half the trigonometry of taking
    // both angles (the seed's measure is the usual one turned by a constant, which cancels).
    return wrapAngle(std::atan2(cross(da, db), dot(da, db)) - c.offset);
}

/// Is θ strictly inside a limit range [lo, hi] (lo < hi)? Without any trigonometry: θ lies
/// in the arc [lo, hi] exactly when cos(θ − mid) > cos(half), mid and half the arc's middle
/// and half width, and cos(θ − mid)·|da||db| is a dot product of db with da turned by
/// offset + mid. A limb inside its limits — the common case — then costs no atan2.
bool strictlyWithinLimits(AngleConstraint& c, const Point& da, const Point& db)
{
    if (!(c.windowLo == c.lo && c.windowHi == c.hi && c.windowOffset == c.offset)) {
        const double mid = c.offset + 0.5 * (c.lo + c.hi);
        c.windowCos = std::cos(mid);
        c.windowSin = std::sin(mid);
        c.windowCosHalf = std::cos(0.5 * (c.hi - c.lo));
        c.windowLo = c.lo, c.windowHi = c.hi, c.windowOffset = c.offset;
    }
    const double along = c.windowCos * dot(da, db) + c.windowSin * cross(da, db);
    return along > c.windowCosHalf * std::sqrt(dot(da, da) * dot(db, db));
}

} // namespace

double constraintAngle(const AngleConstraint& c, const Point* x)
{
    return angleBetween(c, referenceDirection(c, x), x[c.b1] - x[c.b0]);
}

namespace {

/// The XPBD step of an angle constraint: Δλ and the gradients of the (up to four)
/// distinct particles it moves. Returns false when there is nothing to do.
struct AngleStep {
    int idx[4] = {-1, -1, -1, -1};
    Point grad[4];
    int count = 0;
    double dLambda = 0;
};

bool angleStep(AngleConstraint& c, const Point* x, const double* w, double alphaTilde, AngleStep& out)
{
    const Point db = x[c.b1] - x[c.b0];
    const Point da = referenceDirection(c, x);
    if (dot(db, db) < 1e-18 || dot(da, da) < 1e-18)
        return false;
    if (c.lo < c.hi && strictlyWithinLimits(c, da, db))
        return false; // an inactive limit (inside, value 0 below): nothing to do
    const double theta = angleBetween(c, da, db);
    double value = 0;
    if (theta < c.lo || theta > c.hi) {
        // Outside the limits: measure the violation to the nearer limit around the circle,
        // so that a range like [0, π] is left the short way. Inside, the limit is inactive.
        const double toLo = wrapAngle(theta - c.lo);
        const double toHi = wrapAngle(theta - c.hi);
        value = std::abs(toLo) < std::abs(toHi) ? toLo : toHi;
    }
    if (value == 0)
        return false;
    // θ = angle(b1 − b0) − angle(a1 − a0) − offset: ∇_b1 = g_b, ∇_b0 = −g_b, ∇_a1 = −g_a,
    // ∇_a0 = g_a. Particles may be shared (consecutive links share a joint): merge them.
    out.idx[0] = c.b1, out.idx[1] = c.b0, out.idx[2] = c.a1, out.idx[3] = c.a0;
    const Point gb = angleGradient(db);
    out.grad[0] = gb;
    out.grad[1] = -gb;
    out.count = 2;
    if (c.a0 >= 0) {
        const Point ga = angleGradient(da);
        out.grad[2] = -ga;
        out.grad[3] = ga;
        out.count = 4;
    }
    for (int i = 0; i < out.count; ++i)
        for (int j = i + 1; j < out.count; ++j)
            if (out.idx[j] == out.idx[i] && out.idx[i] >= 0) {
                out.grad[i] += out.grad[j];
                out.grad[j] = Point();
                out.idx[j] = -1;
            }
    double denom = alphaTilde;
    for (int i = 0; i < out.count; ++i)
        if (out.idx[i] >= 0)
            denom += w[out.idx[i]] * dot(out.grad[i], out.grad[i]);
    if (!(denom > 1e-300))
        return false;
    out.dLambda = (-value - alphaTilde * c.lambda) / denom; // Macklin et al. 2016, eq. 18
    return true;
}

} // namespace

double solveAngle(AngleConstraint& c, Point* x, const double* w, double alphaTilde)
{
    AngleStep st;
    if (!angleStep(c, x, w, alphaTilde, st))
        return 0;
    for (int i = 0; i < st.count; ++i)
        if (st.idx[i] >= 0) {
            const double s = w[st.idx[i]] * st.dLambda;
            x[st.idx[i]] += Point(s * st.grad[i].x, s * st.grad[i].y);
        }
    c.lambda += st.dLambda;
    return st.dLambda;
}

void solveBendingRing(AngleConstraint* a, int n, Point* x, const double* w, double alphaTilde, Point* delta)
{
    constexpr double omega = 1.0 / 3; // each vertex takes part in three turns: apply their mean
    for (int k = 0; k < n; ++k) {
        AngleStep st;
        a[k].lambda = 0;
        if (!angleStep(a[k], x, w, omega * alphaTilde, st))
            continue;
        const double applied = omega * st.dLambda;
        a[k].lambda = applied;
        for (int i = 0; i < st.count; ++i)
            if (st.idx[i] >= 0) {
                const double s = w[st.idx[i]] * applied;
                delta[st.idx[i]] += Point(s * st.grad[i].x, s * st.grad[i].y);
            }
    }
    for (int k = 0; k < n; ++k) { // the constraint of vertex k is centred on it (b0 = vertex k)
        const int i = a[k].b0;
        x[i] += delta[i];
        delta[i] = Point();
    }
}

} // namespace granota
