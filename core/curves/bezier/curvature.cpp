#include "core/curves/bezier/curvature.h"

#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bezier/exact_hodograph.h"
#include "core/curves/bezier/hodograph.h"
#include "core/exact/square_root.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace granota {

namespace {

bool finite(double v) { return std::isfinite(v); }

/// κ, and the osculating circle of radius r on the side κ's sign gives (along the normal),
/// kept only where the radius and the centre are finite doubles.
void setOsculatingCircle(CurvatureAt& out, double k, double r)
{
    out.curvature = k;
    if (!finite(r))
        return;
    out.radius = r;
    const double s = k > 0 ? r : -r;
    const Point centre(out.point.x + s * out.normal->x, out.point.y + s * out.normal->y);
    if (isFinite(centre))
        out.center = centre;
    else
        out.radius.reset();
}

/// q = m · 2^e with 0.5 ≤ |m| < 1 (m = 0 for q = 0): a rational of any size as a double's
/// mantissa and an exponent beyond a double's range.
struct Binary {
    double m = 0;
    long e = 0;
};

Binary binary(const Rational& q)
{
    if (q == 0)
        return {};
    long en = 0, ed = 0;
    const double mn = mpz_get_d_2exp(&en, q.get_num_mpz_t()), md = mpz_get_d_2exp(&ed, q.get_den_mpz_t());
    int e = 0;
    const double m = std::frexp(mn / md, &e);
    return {m, en - ed + e};
}

/// ldexp for an exponent that may be beyond int: ±inf or 0 there.
double scaled(double m, long e)
{
    const long clamped = std::clamp(e, -2200L, 2200L);
    return std::ldexp(m, static_cast<int>(clamped));
}

/// κ and the rest from c′(t) = v and c″(t) = a exactly, v ≠ 0: when the doubles cannot tell
/// c′(t) from 0 (exact_hodograph.h).
void fromExact(CurvatureAt& out, const RPoint& v, const RPoint& a)
{
    out.exact = true;
    out.tangent = Point(toDouble(v.x), toDouble(v.y));
    // The unit tangent from v scaled by a power of two into the range of doubles.
    const Binary bx = binary(v.x), by = binary(v.y);
    const long e = std::max(bx.m != 0 ? bx.e : by.e, by.m != 0 ? by.e : bx.e);
    const Point w(scaled(bx.m, bx.e - e), scaled(by.m, by.e - e));
    const double length = norm(w);
    const Point unit(w.x / length, w.y / length);
    out.normal = Point(-unit.y, unit.x);
    const Rational c = v.x * a.y - v.y * a.x;
    if (c == 0) {
        out.curvature = 0.0; // straight here (exactly): radius and centre infinite
        return;
    }
    // κ = c / |v|³ = (m_c 2^e_c) / (m_s 2^e_s)^{3/2}, |v|² = m_s 2^e_s with e_s made even.
    const Binary bc = binary(c);
    Binary bs = binary(v.x * v.x + v.y * v.y);
    if (bs.e % 2 != 0) {
        bs.m *= 2;
        bs.e -= 1;
    }
    const double k = scaled(bc.m / (bs.m * std::sqrt(bs.m)), bc.e - 3 * bs.e / 2);
    if (!finite(k) || k == 0.0) {
        out.normal.reset(); // beyond the range of doubles, as below
        return;
    }
    setOsculatingCircle(out, k, 1.0 / std::abs(k));
}

} // namespace

CurvatureAt curvatureAt(const std::vector<Point>& P, double t)
{
    assert(!P.empty());
    CurvatureAt out;
    t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
    out.t = t;
    out.point = deCasteljauPoint(P, t);
    const int n = static_cast<int>(P.size()) - 1;
    if (n == 0)
        return out; // a single point: c′ ≡ 0, nothing is defined

    // Scale by a power of two (exact) so that every coordinate is at most 1 in magnitude.
    double m = 0;
    for (const Point& p : P)
        m = std::max({m, std::abs(p.x), std::abs(p.y)});
    int e = 0;
    if (m > 0 && finite(m))
        std::frexp(m, &e);
    std::vector<Point> Q(P);
    for (Point& q : Q)
        q = Point(std::ldexp(q.x, -e), std::ldexp(q.y, -e));
    double h = 0; // largest coordinate difference between control points (scaled)
    {
        double xmin = Q[0].x, xmax = Q[0].x, ymin = Q[0].y, ymax = Q[0].y;
        for (const Point& q : Q) {
            xmin = std::min(xmin, q.x), xmax = std::max(xmax, q.x);
            ymin = std::min(ymin, q.y), ymax = std::max(ymax, q.y);
        }
        h = std::max(xmax - xmin, ymax - ymin);
    }
    const std::vector<Point> d1 = hodograph(Q);
    const std::vector<Point> d2 = hodograph(d1);
    const Point v = deCasteljauPoint(d1, t);
    const Point a = deCasteljauPoint(d2, t);
    out.tangent = Point(std::ldexp(v.x, e), std::ldexp(v.y, e));
    const double speed = norm(v);
    if (!(speed > 1e-12 * n * h)) {
        // c′ = 0 relative to the curve's size, as far as doubles tell. The control points
        // taken exactly decide (exact_hodograph.h): near ±1e308 a c′ of (21/4, 0) is below
        // the doubles' rounding.
        const std::optional<ExactDerivatives> exact = exactDerivativesAt(P, t);
        if (exact && (exact->first.x != 0 || exact->first.y != 0))
            fromExact(out, exact->first, exact->second);
        return out; // otherwise c′ = 0: κ undefined
    }
    const Point unit(v.x / speed, v.y / speed);
    out.normal = Point(-unit.y, unit.x);
    const double c = cross(v, a);
    const double roundoff = 4.0 * (n + 1) * std::numeric_limits<double>::epsilon() * speed * norm(a);
    if (std::abs(c) <= roundoff) {
        out.curvature = 0.0; // straight here: radius and centre infinite
        return out;
    }
    // κ of the scaled curve, then of the curve itself: κ scales as 1/length.
    const double kScaled = c / (speed * speed * speed);
    const double k = std::ldexp(kScaled, -e);
    if (!finite(k) || k == 0.0) {
        // Beyond the range of doubles (|κ| > 1e308 or < 1e-308): say "undefined" rather than
        // a false infinity or a false zero.
        out.normal.reset();
        return out;
    }
    setOsculatingCircle(out, k, std::ldexp(1.0 / std::abs(kScaled), e));
    return out;
}

ExactCurvature exactCurvatureAt(const std::vector<RPoint>& P, const Rational& t)
{
    assert(!P.empty());
    const std::vector<RPoint> d1 = hodograph(P);
    const std::vector<RPoint> d2 = hodograph(d1);
    const RPoint v = deCasteljauPoint(d1, t);
    const RPoint a = deCasteljauPoint(d2, t);
    ExactCurvature k;
    k.numerator = v.x * a.y - v.y * a.x;
    k.speedSquared = v.x * v.x + v.y * v.y;
    return k;
}

std::optional<std::string> exactCurvatureText(const ExactCurvature& k)
{
    if (k.speedSquared == 0)
        return std::nullopt;
    if (k.numerator == 0)
        return std::string("0");
    // κ = N / (D √D) with √D = a√b:  κ = N / (D a √b) = (N / (D a b)) √b.
    const auto root = simplifySquareRoot(k.speedSquared);
    if (!root)
        return toString(k.numerator) + "/" + toString(k.speedSquared) + "^(3/2)";
    Rational q = k.numerator / (k.speedSquared * root->coefficient * Rational(root->radicand));
    const bool negative = q < 0;
    if (negative)
        q = -q;
    return (negative ? "-" : "") + toString(SimplifiedSquareRoot{q, root->radicand});
}

} // namespace granota
