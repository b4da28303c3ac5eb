#include "core/curves/bezier/arc_length.h"

#include "core/curves/bezier/curve_features.h"
#include "core/curves/bezier/gauss_legendre.h"
#include "core/curves/bezier/hodograph.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

namespace granota {

namespace {

constexpr int kGaussPoints = 16;
constexpr int kMaxDepth = 48;
constexpr std::size_t kFixedHodograph = 64; // arcLength() allocates nothing up to degree 63

/// The positive half of the 16-point Gauss–Legendre rule's nodes, and their weights, as doubles.
struct GaussLegendre {
    std::array<double, kGaussPoints / 2> x{}, w{};
    GaussLegendre()
    {
        const GaussLegendreRule rule = gaussLegendreRule(kGaussPoints);
        for (std::size_t i = 0; i < x.size(); ++i) {
            x[i] = static_cast<double>(rule.nodes[i]);
            w[i] = static_cast<double>(rule.weights[i]);
        }
    }
};

const GaussLegendre& gauss()
{
    static const GaussLegendre g;
    return g;
}

/// |Σ_i w_i t^i (1−t)^{m−i}| with w_i = C(m,i) D_i: the nested form of the Bernstein sum
/// (Schumaker & Volk, 1986), O(m), all weights positive, so as accurate as De Casteljau.
struct Speed {
    const Point* w = nullptr;
    int m = 0;
    double operator()(double t) const
    {
        const double u = 1 - t;
        if (m == 0)
            return std::sqrt(w[0].x * w[0].x + w[0].y * w[0].y);
        double tn = 1, x = w[0].x * u, y = w[0].y * u;
        for (int i = 1; i < m; ++i) {
            tn *= t;
            x = (x + tn * w[i].x) * u;
            y = (y + tn * w[i].y) * u;
        }
        tn *= t;
        x += tn * w[m].x;
        y += tn * w[m].y;
        return std::sqrt(x * x + y * y); // no overflow: the curve is scaled to coordinates ≤ 1
    }
};

/// The 16-point rule on [a, b]. The 16 speeds are evaluated in lockstep (one nested loop
/// over the control points, the nodes innermost) so that the compiler can vectorise them:
/// one Horner chain alone is latency-bound.
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
inline double
gaussRuleBody(const Speed& f, double a, double b)
{
    const GaussLegendre& g = gauss();
    const double h = 0.5 * (b - a), c = 0.5 * (a + b);
    constexpr int K = kGaussPoints, H = kGaussPoints / 2;
    double t[K], u[K], tn[K], x[K], y[K];
    for (int j = 0; j < H; ++j) {
        t[j] = c - h * g.x[static_cast<std::size_t>(j)];
        t[K - 1 - j] = c + h * g.x[static_cast<std::size_t>(j)];
    }
    const Point* w = f.w;
    const int m = f.m;
    for (int j = 0; j < K; ++j) {
        u[j] = 1 - t[j];
        tn[j] = 1;
        x[j] = w[0].x;
        y[j] = w[0].y;
    }
    for (int i = 1; i <= m; ++i) {
        const double wx = w[i].x, wy = w[i].y;
        for (int j = 0; j < K; ++j) {
            tn[j] *= t[j];
            x[j] = x[j] * u[j] + tn[j] * wx;
            y[j] = y[j] * u[j] + tn[j] * wy;
        }
    }
    double sum = 0;
    for (int j = 0; j < H; ++j)
        sum += g.w[static_cast<std::size_t>(j)] *
               (std::sqrt(x[j] * x[j] + y[j] * y[j]) + std::sqrt(x[K - 1 - j] * x[K - 1 - j] + y[K - 1 - j] * y[K - 1 - j]));
    return h * sum;
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
/// The same rule compiled for AVX2 (four nodes per instruction instead of two), chosen at
/// run time where the processor has it. Only AVX2, not FMA: every product and sum is the
/// same IEEE operation as in the plain build, so both give the same length to the bit.
__attribute__((target("avx2"))) double gaussRuleAvx2(const Speed& f, double a, double b) { return gaussRuleBody(f, a, b); }

bool hasAvx2()
{
    static const bool yes = (__builtin_cpu_init(), __builtin_cpu_supports("avx2"));
    return yes;
}

double gaussRule(const Speed& f, double a, double b) { return hasAvx2() ? gaussRuleAvx2(f, a, b) : gaussRuleBody(f, a, b); }
#else
double gaussRule(const Speed& f, double a, double b) { return gaussRuleBody(f, a, b); }
#endif

/// The largest |coordinate| rounded up to a power of two: dividing by it is exact.
int scaleExponent(const std::vector<Point>& P)
{
    double m = 0;
    for (const Point& p : P)
        m = std::max({m, std::abs(p.x), std::abs(p.y)});
    int e = 0;
    if (m > 0 && std::isfinite(m))
        std::frexp(m, &e);
    return e;
}

/// C(m,i) · m (Q_{i+1} − Q_i) with Q = P / 2^e: the weights of the nested form.
template <class Out> void speedWeights(const std::vector<Point>& P, int e, Out& w)
{
    const std::size_t n = P.size() - 1;
    if (n == 0) {
        w[0] = Point(0, 0);
        return;
    }
    const std::size_t m = n - 1;
    // 2^−e as a normal double multiplies exactly as ldexp scales (both round the exact
    // product once), at a fraction of the cost; ldexp beyond that range.
    const bool normal = e >= -1022 && e <= 1022;
    const double f = normal ? std::ldexp(1.0, -e) : 1.0;
    auto scaled = [&](double v) { return normal ? v * f : std::ldexp(v, -e); };
    double binom = 1;
    for (std::size_t i = 0; i <= m; ++i) {
        const Point d(scaled(P[i + 1].x) - scaled(P[i].x), scaled(P[i + 1].y) - scaled(P[i].y));
        const double k = binom * static_cast<double>(n);
        w[i] = Point(k * d.x, k * d.y);
        binom = binom * static_cast<double>(m - i) / static_cast<double>(i + 1);
    }
}

/// True when the hodograph's control points lie in an open half-plane through the origin:
/// then c′ ≠ 0 on [0, 1] (c′(t) is a convex combination of positive multiples of them), and
/// there is no cusp to look for. O(m): the cone of their directions grows while it is narrower
/// than a half-turn.
bool hodographAvoidsZero(const Point* w, int m)
{
    Point lo = w[0], hi = w[0];
    if (lo.x == 0 && lo.y == 0)
        return false;
    for (int i = 1; i <= m; ++i) {
        const Point d = w[i];
        if (d.x == 0 && d.y == 0)
            return false;
        const double a = cross(lo, d), b = cross(d, hi);
        if (a >= 0 && b >= 0 && (a > 0 || dot(lo, d) > 0) && (b > 0 || dot(d, hi) > 0))
            continue; // inside the cone (not opposite to one of its edges)
        if (cross(hi, d) > 0 && cross(lo, d) > 0)
            hi = d;
        else if (cross(d, lo) > 0 && cross(d, hi) > 0)
            lo = d;
        else
            return false;
    }
    return true;
}

/// c′ ≠ 0 on the piece whose hodograph control points are d[0..m], tried on that piece and,
/// failing that, on its halves (De Casteljau at 1/2) down to `depth` more levels.
bool hodographPieceAvoidsZero(const Point* d, int m, int depth)
{
    if (hodographAvoidsZero(d, m))
        return true;
    if (depth == 0)
        return false;
    std::array<Point, kFixedHodograph> left, right;
    std::copy(d, d + m + 1, right.begin());
    for (int r = 0; r <= m; ++r) {
        left[static_cast<std::size_t>(r)] = right[0];
        for (int i = 0; i + r < m; ++i)
            right[static_cast<std::size_t>(i)] = Point(
                0.5 * (right[static_cast<std::size_t>(i)].x + right[static_cast<std::size_t>(i + 1)].x),
                0.5 * (right[static_cast<std::size_t>(i)].y + right[static_cast<std::size_t>(i + 1)].y));
    }
    // right[0..m] now holds the right half's points P_0^m, P_1^{m−1}, …, P_m^0.
    return hodographPieceAvoidsZero(left.data(), m, depth - 1) && hodographPieceAvoidsZero(right.data(), m, depth - 1);
}

/// Where to split before integrating: the zeros of |c′| (cusps, curve_features.h), where
/// |c′| has a kink |t − t_c|·|c″(t_c)| that no polynomial rule integrates fast. Looked for only
/// when the hodograph's control polygon (on [0, 1], its halves or its quarters) does not rule
/// them out: cheaply, with no allocation, for nearly every curve.
int splitPoints(const std::vector<Point>& P, const Point* w, std::array<double, kFixedHodograph>& out)
{
    const int m = static_cast<int>(P.size()) - 2;
    if (m < 1 || hodographAvoidsZero(w, m))
        return 0;
    if (m + 1 <= static_cast<int>(kFixedHodograph)) {
        std::array<Point, kFixedHodograph> d;
        for (int i = 0; i <= m; ++i) // directions only: halves avoid overflow
            d[static_cast<std::size_t>(i)] = Point(
                0.5 * P[static_cast<std::size_t>(i + 1)].x - 0.5 * P[static_cast<std::size_t>(i)].x,
                0.5 * P[static_cast<std::size_t>(i + 1)].y - 0.5 * P[static_cast<std::size_t>(i)].y);
        if (hodographPieceAvoidsZero(d.data(), m, 3))
            return 0;
    }
    const std::vector<double> cusps = cuspParameters(P);
    int k = 0;
    for (double t : cusps)
        if (k < static_cast<int>(out.size()))
            out[static_cast<std::size_t>(k++)] = t;
    return k;
}

/// The adaptive composite rule on [a, b] to an absolute tolerance `tol` for the whole of
/// [a, b]; each accepted panel [l, r] is reported as panel(l, value). A panel is halved until
/// the 16-point rule on it agrees with the sum over its two halves to its share of `tol`; the
/// halves are kept, which are much better still. (Estimating the halves' error from the
/// convergence ratio one level up would save a panel or two, but it fails where a zero of |c′|²
/// lies near [0, 1] in the complex plane: the rule is not yet converging geometrically there.)
/// `whole` is the 16-point rule on [a, b], already formed for the first estimate of L.
template <class Panel> double adaptive(const Speed& f, double a, double b, double whole, double tol, Panel&& panel)
{
    struct Item {
        double a, b, g;
        int depth;
    };
    std::array<Item, kMaxDepth + 2> stack;
    std::size_t top = 0;
    stack[top++] = {a, b, whole, 0};
    double total = 0;
    const double width = b - a;
    while (top > 0) {
        const Item it = stack[--top];
        const double mid = 0.5 * (it.a + it.b);
        const double gl = gaussRule(f, it.a, mid), gr = gaussRule(f, mid, it.b);
        const double diff = std::abs(gl + gr - it.g);
        if (diff <= tol * (it.b - it.a) / width || it.depth >= kMaxDepth || !(it.a < mid && mid < it.b)) {
            panel(it.a, gl);
            panel(mid, gr);
            total += gl + gr;
            continue;
        }
        stack[top++] = {mid, it.b, gr, it.depth + 1}; // right below left: left first
        stack[top++] = {it.a, mid, gl, it.depth + 1};
    }
    return total;
}

double clampedTolerance(double relativeTolerance)
{
    if (!(relativeTolerance >= 1e-15))
        return 1e-15;
    return std::min(relativeTolerance, 0.1);
}

/// The whole computation on [t0, t1] ⊂ [0, 1] (t0 ≤ t1), split at the cusps inside.
template <class Panel>
double integrate(const std::vector<Point>& P, const Speed& f, double t0, double t1, double rel, Panel&& panel)
{
    std::array<double, kFixedHodograph + 2> cuts{};
    std::size_t count = 0;
    cuts[count++] = t0;
    std::array<double, kFixedHodograph> cusps{};
    const int k = splitPoints(P, f.w, cusps);
    for (int i = 0; i < k; ++i)
        if (cusps[static_cast<std::size_t>(i)] > t0 && cusps[static_cast<std::size_t>(i)] < t1)
            cuts[count++] = cusps[static_cast<std::size_t>(i)];
    cuts[count++] = t1;
    std::array<double, kFixedHodograph + 1> whole{};
    double estimate = 0;
    for (std::size_t i = 0; i + 1 < count; ++i)
        estimate += whole[i] = gaussRule(f, cuts[i], cuts[i + 1]);
    if (!(estimate > 0))
        return 0; // a single point, or a piece of zero length
    double total = 0;
    for (std::size_t i = 0; i + 1 < count; ++i)
        total += adaptive(f, cuts[i], cuts[i + 1], whole[i], rel * estimate * (cuts[i + 1] - cuts[i]) / (t1 - t0), panel);
    return total;
}

double clampT(double t) { return std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0; }

} // namespace

double arcLength(const std::vector<Point>& P, double t0, double t1, double relativeTolerance)
{
    assert(!P.empty());
    t0 = clampT(t0), t1 = clampT(t1);
    if (t1 < t0)
        return -arcLength(P, t1, t0, relativeTolerance);
    if (P.size() < 2 || t0 == t1)
        return 0;
    const int e = scaleExponent(P);
    const double rel = clampedTolerance(relativeTolerance);
    auto run = [&](Point* w) {
        speedWeights(P, e, w);
        const Speed f{w, static_cast<int>(P.size()) - 2};
        return integrate(P, f, t0, t1, rel, [](double, double) {});
    };
    double scaled = 0;
    if (P.size() - 1 <= kFixedHodograph) {
        std::array<Point, kFixedHodograph> w;
        scaled = run(w.data());
    } else {
        std::vector<Point> w(P.size() - 1);
        scaled = run(w.data());
    }
    return std::ldexp(scaled, e);
}

ArcLengthParametrization::ArcLengthParametrization(const std::vector<Point>& P, double relativeTolerance)
{
    assert(!P.empty());
    const int e = scaleExponent(P);
    m_scale = std::ldexp(1.0, e);
    m_w.resize(std::max<std::size_t>(1, P.size() - 1));
    speedWeights(P, e, m_w);
    const Speed f{m_w.data(), static_cast<int>(m_w.size()) - 1};
    double s = 0;
    const double scaled = P.size() < 2 ? 0.0
                                       : integrate(P, f, 0.0, 1.0, clampedTolerance(relativeTolerance), [&](double a, double g) {
                                             m_a.push_back(a);
                                             m_s.push_back(s);
                                             s += g;
                                         });
    if (m_a.empty()) { // length 0: one panel [0, 1] of zero length
        m_a.push_back(0);
        m_s.push_back(0);
    }
    m_total = std::ldexp(scaled, e);
}

double ArcLengthParametrization::speed(double t) const { return Speed{m_w.data(), static_cast<int>(m_w.size()) - 1}(t); }

double ArcLengthParametrization::panelLength(std::size_t k, double t) const
{
    return gaussRule(Speed{m_w.data(), static_cast<int>(m_w.size()) - 1}, m_a[k], t);
}

double ArcLengthParametrization::lengthAt(double t) const
{
    t = clampT(t);
    if (m_total == 0)
        return 0;
    if (t == 1)
        return m_total;
    const auto it = std::upper_bound(m_a.begin(), m_a.end(), t);
    const std::size_t k = static_cast<std::size_t>(it - m_a.begin()) - 1;
    return std::min(m_total, (m_s[k] + panelLength(k, t)) * m_scale);
}

double ArcLengthParametrization::parameterAt(double s) const
{
    if (!(s > 0) || m_total == 0)
        return 0;
    if (s >= m_total)
        return 1;
    const double target = s / m_scale;
    const auto it = std::upper_bound(m_s.begin(), m_s.end(), target);
    const std::size_t k = static_cast<std::size_t>(it - m_s.begin()) - 1;
    double lo = m_a[k], hi = k + 1 < m_a.size() ? m_a[k + 1] : 1.0;
    const double want = target - m_s[k];
    const double whole = (k + 1 < m_s.size() ? m_s[k + 1] : m_total / m_scale) - m_s[k];
    double t = whole > 0 ? lo + (hi - lo) * std::clamp(want / whole, 0.0, 1.0) : lo;
    for (int iteration = 0; iteration < 60; ++iteration) {
        const double r = panelLength(k, t) - want;
        if (r > 0)
            hi = t;
        else
            lo = t;
        const double v = speed(t);
        double next = v > 0 ? t - r / v : 0.5 * (lo + hi);
        if (!(next > lo && next < hi))
            next = 0.5 * (lo + hi);
        if (std::abs(next - t) <= 2 * std::numeric_limits<double>::epsilon() * std::max(t, 1e-300) || hi - lo <= 0) {
            t = next;
            break;
        }
        t = next;
    }
    return std::clamp(t, 0.0, 1.0);
}

} // namespace granota
