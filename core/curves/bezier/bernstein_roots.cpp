#include "core/base/math_constants.h"
#include "core/curves/bezier/bernstein_roots.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <limits>

namespace granota {

namespace {

/// Deepest halving: 2⁻¹⁰⁰ is below the spacing of doubles anywhere but right next to 0.
constexpr int kMaxRootDepth = 100;
/// Above this degree C(n, i) could overflow in the Horner-like scheme: De Casteljau instead.
constexpr int kHornerMaxDegree = 500;

int signOf(double v) { return (v > 0) - (v < 0); }

/// Descartes' rule for the Bernstein form: sign changes of b_0 … b_n, zeros skipped.
int signChanges(const double* b, int n)
{
    int changes = 0;
    int last = 0;
    for (int i = 0; i <= n; ++i) {
        const int s = signOf(b[i]);
        if (s == 0)
            continue;
        if (last != 0 && s != last)
            ++changes;
        last = s;
    }
    return changes;
}

/// Rows C(k, 0) … C(k, k) of binomialRow(k) for k ≤ kTabledDegree, computed once: the
/// evaluations below look them up instead of forming C(k, i) by a division per term.
constexpr int kTabledDegree = 64;

const double* tabledBinomials(int k)
{
    struct Table {
        double c[(kTabledDegree + 1) * (kTabledDegree + 2) / 2];
        Table()
        {
            for (int row = 0; row <= kTabledDegree; ++row) {
                double* r = c + row * (row + 1) / 2;
                r[0] = 1.0;
                for (int i = 1; i <= row; ++i) // the recurrence of binomialRow, so the same values
                    r[i] = r[i - 1] * static_cast<double>(row - i + 1) / static_cast<double>(i);
            }
        }
    };
    assert(k >= 0 && k <= kTabledDegree);
    static const Table table;
    return table.c + k * (k + 1) / 2;
}

/// Σ b_i B_i^n(t) by Volk–Schumaker's scheme: Horner in s = 1 − t with the powers of t and
/// the binomials carried along; only products of nonnegative factors besides the b_i.
/// `binomial` is the row C(n, ·), or null to form it on the way.
double hornerValue(const double* b, int n, double t, const double* binomial)
{
    if (n == 0)
        return b[0];
    const double s = 1.0 - t;
    double tn = 1.0;
    double sum = b[0] * s;
    if (binomial) {
        for (int i = 1; i < n; ++i) {
            tn *= t;
            sum = (sum + tn * binomial[i] * b[i]) * s;
        }
    } else {
        double c = 1.0;
        for (int i = 1; i < n; ++i) {
            tn *= t;
            c = c * static_cast<double>(n - i + 1) / static_cast<double>(i);
            sum = (sum + tn * c * b[i]) * s;
        }
    }
    return sum + tn * t * b[n];
}

double deCasteljauValue(const double* b, int n, double t)
{
    std::vector<double> w(b, b + n + 1);
    for (int r = 1; r <= n; ++r)
        for (int i = 0; i <= n - r; ++i)
            w[static_cast<std::size_t>(i)] = (1.0 - t) * w[static_cast<std::size_t>(i)] + t * w[static_cast<std::size_t>(i + 1)];
    return w[0];
}

double value(const double* b, int n, double t)
{
    if (n > kHornerMaxDegree)
        return deCasteljauValue(b, n, t);
    return hornerValue(b, n, t, n <= kTabledDegree ? tabledBinomials(n) : nullptr);
}

/// p′(t) = n Σ (b_{i+1} − b_i) B_i^{n−1}(t), the differences formed on the fly.
double derivative(const double* b, int n, double t)
{
    if (n == 0)
        return 0.0;
    const int m = n - 1;
    if (m > kHornerMaxDegree) {
        std::vector<double> d(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i)
            d[static_cast<std::size_t>(i)] = b[i + 1] - b[i];
        return n * deCasteljauValue(d.data(), m, t);
    }
    if (m == 0)
        return n * (b[1] - b[0]);
    const double s = 1.0 - t;
    double tn = 1.0;
    double sum = (b[1] - b[0]) * s;
    if (m <= kTabledDegree) {
        const double* binomial = tabledBinomials(m);
        for (int i = 1; i < m; ++i) {
            tn *= t;
            sum = (sum + tn * binomial[i] * (b[i + 1] - b[i])) * s;
        }
    } else {
        double c = 1.0;
        for (int i = 1; i < m; ++i) {
            tn *= t;
            c = c * static_cast<double>(m - i + 1) / static_cast<double>(i);
            sum = (sum + tn * c * (b[i + 1] - b[i])) * s;
        }
    }
    return n * (sum + tn * t * (b[m + 1] - b[m]));
}

/// p(t) and p′(t) together (Newton's step needs both): the two Horner chains of value() and
/// derivative() in one loop, the same operations in the same order, so the same results.
void valueAndDerivative(const double* b, int n, double t, double& f, double& d)
{
    if (n < 2 || n > kTabledDegree) {
        f = value(b, n, t);
        d = derivative(b, n, t);
        return;
    }
    const int m = n - 1;
    const double* cn = tabledBinomials(n);
    const double* cm = tabledBinomials(m);
    const double s = 1.0 - t;
    double tn = 1.0;
    double sum = b[0] * s;
    double dsum = (b[1] - b[0]) * s;
    for (int i = 1; i < m; ++i) {
        tn *= t;
        sum = (sum + tn * cn[i] * b[i]) * s;
        dsum = (dsum + tn * cm[i] * (b[i + 1] - b[i])) * s;
    }
    // i = m: the last step of p's chain, the closing term of p′'s.
    const double tm = tn * t;
    d = n * (dsum + tm * (b[m + 1] - b[m]));
    f = (sum + tm * cn[m] * b[m]) * s + tm * t * b[n];
}

/// The one root in (0, 1) of the local polynomial b (degree n) of an interval [a, a + w],
/// where p has sign `leftSign` just right of 0 and the opposite sign just left of 1:
/// Newton steps, each replaced by a bisection when it leaves the bracket, until the step
/// is below the spacing of doubles at the global parameter a + u w.
double polishRoot(const double* b, int n, double a, double w, int leftSign)
{
    double lo = 0.0;
    double hi = 1.0;
    // Start from the secant of the end values (regula falsi), a good guess for a short
    // interval where p is nearly linear.
    double u = 0.5;
    if (b[0] != 0.0 && b[n] != 0.0) {
        const double guess = b[0] / (b[0] - b[n]);
        if (guess > 0.0 && guess < 1.0)
            u = guess;
    }
    double previousStep = std::numeric_limits<double>::infinity();
    for (int iteration = 0; iteration < 200; ++iteration) {
        double f = 0.0, d = 0.0;
        valueAndDerivative(b, n, u, f, d);
        if (f == 0.0)
            return a + u * w;
        if (signOf(f) == leftSign)
            lo = u;
        else
            hi = u;
        const double t = a + u * w;
        const double spacing = kMachineEpsilon * std::max(std::fabs(t), std::numeric_limits<double>::min());
        if (d != 0.0) {
            const double newton = u - f / d;
            const double step = std::fabs(newton - u) * w;
            // Converged: the correction is below the spacing of doubles at t.
            if (step <= 2.0 * spacing)
                return a + std::min(std::max(newton, lo), hi) * w;
            // Newton converges quadratically: a step near rounding noise that does not
            // shrink the one before is that noise (it could wander by ulps for ever).
            if (step >= previousStep && step <= 64.0 * spacing)
                return t;
            previousStep = step;
            if (newton > lo && newton < hi) {
                u = newton;
                continue;
            }
        }
        if ((hi - lo) * w <= 2.0 * spacing)
            return a + 0.5 * (lo + hi) * w;
        u = 0.5 * (lo + hi);
    }
    return a + u * w;
}

struct FoundRoot {
    double t = 0;
    double uncertainty = 0; ///< how far the true root may be (for merging)
    bool crossing = false;
    bool known = false; ///< crossing is known without looking (the ends: no other side)
    /// Which of two reports of one root is the better position: 4 an end, 3 a bracketed
    /// simple root, 2 the zero of p′ at a touching zero, 1 a halving point, 0 a midpoint.
    int rank = 0;
    /// Found alone in an interval whose end values have opposite signs well above rounding:
    /// p changes sign there, so crossing is known too unless another report merges with it.
    bool bracketed = false;
    bool merged = false; ///< another report of the same root was merged into this one
};

class Solver {
public:
    Solver(const std::vector<double>& original, std::vector<double>& scratch, std::vector<FoundRoot>& found)
        : found(found), original_(original), n_(static_cast<int>(original.size()) - 1), scratch_(scratch)
    {
        double maxAbs = 0.0;
        for (double c : original)
            maxAbs = std::max(maxAbs, std::fabs(c));
        globalTolerance_ = toleranceFor(maxAbs);
    }

    /// The rounding error of a value of p formed from coefficients at most `magnitude`:
    /// n + 1 roundings per level of De Casteljau, with a safety factor 4.
    double toleranceFor(double magnitude) const { return 4.0 * (n_ + 1) * kMachineEpsilon * magnitude; }

    void run(double* b, double a, double w, int depth)
    {
        const int n = n_;
        for (;;) {
            const int v = signChanges(b, n);
            if (v == 0)
                return;
            if (v == 1) {
                int left = 0;
                for (int i = 0; i <= n && left == 0; ++i)
                    left = signOf(b[i]);
                // The end values b_0 = p(a), b_n = p(a + w) carry the rounding of `depth`
                // halvings, each at most n + 1 roundings of values ≤ max |b_i|: far below
                // 32 × globalTolerance_ for depth ≤ kMaxRootDepth.
                const double clear = 32.0 * globalTolerance_;
                const bool bracketed = b[0] * b[n] < 0.0 && std::fabs(b[0]) > clear && std::fabs(b[n]) > clear;
                found.push_back({polishRoot(b, n, a, w, left), 0.0, true, false, 3, bracketed});
                return;
            }
            double maxAbs = 0.0;
            for (int i = 0; i <= n; ++i)
                maxAbs = std::max(maxAbs, std::fabs(b[i]));
            const double mid = a + 0.5 * w;
            if ((maxAbs <= globalTolerance_ && maxAbs <= localTolerance(a, a + w)) || depth >= kMaxRootDepth ||
                !(mid > a && mid < a + w)) {
                tangentialRoot(b, a, w);
                return;
            }
            // De Casteljau at 1/2 in place (Def 2.4): b becomes the right half
            // P_0^n, P_1^{n−1}, …, P_n^0 and `left` receives P_0^0, …, P_0^n.
            double* left = b + (n + 1);
            left[0] = b[0];
            for (int r = 1; r <= n; ++r) {
                for (int i = 0; i <= n - r; ++i)
                    b[i] = 0.5 * (b[i] + b[i + 1]);
                left[r] = b[0];
            }
            // p(mid) is the coefficient both halves share. When it is 0 within rounding,
            // mid is a root (to the precision the coefficients allow) and is made exactly 0
            // in both halves: otherwise its rounding could put a simple root just inside one
            // half, where Descartes' count would no longer see the root next to it.
            const double pm = b[0];
            if (pm == 0.0 || (std::fabs(pm) <= globalTolerance_ && std::fabs(pm) <= localTolerance(mid, mid))) {
                left[n] = 0.0;
                b[0] = 0.0;
                run(left, a, 0.5 * w, depth + 1);
                found.push_back({nearbySimpleRoot(mid, 0.5 * w), 0.0, false, false, 1});
            } else {
                run(left, a, 0.5 * w, depth + 1);
            }
            a = mid;
            w *= 0.5;
            ++depth;
        }
    }

    std::vector<FoundRoot>& found;

private:
    /// Newton steps on the original polynomial from t, where p(t) is 0 within rounding: a
    /// simple root next to it to full precision; t itself for a multiple root (p′ ≈ 0, the
    /// step would leave the neighbourhood `reach`).
    double nearbySimpleRoot(double t, double reach) const
    {
        const double* b = original_.data();
        double x = t;
        for (int i = 0; i < 3; ++i) {
            double f = 0.0, d = 0.0;
            valueAndDerivative(b, n_, x, f, d);
            if (f == 0.0 || d == 0.0)
                break;
            const double next = x - f / d;
            if (!(std::fabs(next - t) <= 1e-3 * reach) || next < 0.0 || next > 1.0)
                break;
            if (next == x)
                break;
            x = next;
        }
        return x;
    }

    /// The largest rounding error of p on [t0, t1]: the Bernstein coefficients of
    /// Σ |b_i| B_i^n restricted to the interval (all positive: no cancellation).
    double localTolerance(double t0, double t1)
    {
        const int n = n_;
        scratch_.resize(static_cast<std::size_t>(n + 1));
        double* m = scratch_.data();
        for (int i = 0; i <= n; ++i)
            m[i] = std::fabs(original_[static_cast<std::size_t>(i)]);
        if (t1 <= t0)
            return toleranceFor(value(m, n, t0));
        // Right part from t0: after the in-place pass m[k] = P_k^{n−k}(t0).
        for (int r = 1; r <= n; ++r)
            for (int i = 0; i <= n - r; ++i)
                m[i] = (1.0 - t0) * m[i] + t0 * m[i + 1];
        // Left part up to s = (t1 − t0)/(1 − t0) of that: keep P_0^r at each level.
        const double s = t0 < 1.0 ? std::min(1.0, (t1 - t0) / (1.0 - t0)) : 1.0;
        double largest = m[0];
        for (int r = 1; r <= n; ++r) {
            for (int i = n; i >= r; --i)
                m[i] = (1.0 - s) * m[i - 1] + s * m[i];
            largest = std::max(largest, m[r]);
        }
        return toleranceFor(largest);
    }

    /// p is 0 within rounding on all of [a, a + w] (or the interval cannot be halved): one
    /// root here, at the sign change of p if its ends differ in sign, else at the zero of
    /// p′ (the bottom of the touching zero), else in the middle.
    void tangentialRoot(const double* b, double a, double w)
    {
        const int n = n_;
        const int s0 = signOf(b[0]);
        const int sn = signOf(b[n]);
        if (s0 * sn < 0) {
            found.push_back({polishRoot(b, n, a, w, s0), w, false, false, 2}); // end signs are noise here
            return;
        }
        if (n >= 2) {
            const double d0 = b[1] - b[0];
            const double dn = b[n] - b[n - 1];
            if (signOf(d0) * signOf(dn) < 0) {
                scratch_.resize(static_cast<std::size_t>(n));
                for (int i = 0; i < n; ++i)
                    scratch_[static_cast<std::size_t>(i)] = b[i + 1] - b[i];
                found.push_back({polishRoot(scratch_.data(), n - 1, a, w, signOf(d0)), w, false, false, 2});
                return;
            }
        }
        found.push_back({a + 0.5 * w, 0.5 * w, false, false, 0});
    }

    const std::vector<double>& original_;
    int n_;
    std::vector<double>& scratch_;
    double globalTolerance_ = 0;
};

} // namespace

double bernsteinValue(const std::vector<double>& coefficients, double t)
{
    return value(coefficients.data(), static_cast<int>(coefficients.size()) - 1, t);
}

std::vector<double> binomialRow(int k)
{
    std::vector<double> c(static_cast<std::size_t>(k + 1), 1.0);
    for (int i = 1; i <= k; ++i)
        c[static_cast<std::size_t>(i)] = c[static_cast<std::size_t>(i - 1)] * static_cast<double>(k - i + 1) /
                                         static_cast<double>(i);
    return c;
}

std::vector<double> bernsteinProduct(const std::vector<double>& a, const std::vector<double>& b)
{
    if (a.empty() || b.empty())
        return {};
    const int m = static_cast<int>(a.size()) - 1;
    const int n = static_cast<int>(b.size()) - 1;
    const std::vector<double> cm = binomialRow(m), cn = binomialRow(n), cmn = binomialRow(m + n);
    std::vector<double> c(static_cast<std::size_t>(m + n + 1), 0.0);
    for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= n; ++j)
            c[static_cast<std::size_t>(i + j)] += cm[static_cast<std::size_t>(i)] * cn[static_cast<std::size_t>(j)] *
                                                  a[static_cast<std::size_t>(i)] * b[static_cast<std::size_t>(j)];
    for (int k = 0; k <= m + n; ++k)
        c[static_cast<std::size_t>(k)] /= cmn[static_cast<std::size_t>(k)];
    return c;
}

BernsteinRoots bernsteinRoots(const std::vector<double>& coefficients)
{
    BernsteinRoots result;
    if (std::all_of(coefficients.begin(), coefficients.end(), [](double c) { return c == 0.0; })) {
        result.identicallyZero = true;
        return result;
    }
    if (!std::all_of(coefficients.begin(), coefficients.end(), [](double c) { return std::isfinite(c); }))
        return result;
    const int n = static_cast<int>(coefficients.size()) - 1;

    // No sign change and no zero at an end: no root at all (Descartes), nothing to subdivide.
    if (coefficients.front() != 0.0 && coefficients.back() != 0.0 && signChanges(coefficients.data(), n) == 0)
        return result;

    // One slot of n + 1 coefficients per level of halving, and the reports, reused from call
    // to call.
    thread_local std::vector<double> work;
    thread_local std::vector<double> scratch;
    thread_local std::vector<FoundRoot> found;
    thread_local std::vector<FoundRoot> merged;
    thread_local std::vector<double> magnitude;
    found.clear();
    merged.clear();
    magnitude.clear();
    const std::size_t need = static_cast<std::size_t>(kMaxRootDepth + 2) * static_cast<std::size_t>(n + 1);
    if (work.size() < need)
        work.resize(need);
    std::copy(coefficients.begin(), coefficients.end(), work.begin());

    Solver solver(coefficients, scratch, found);
    if (coefficients.front() == 0.0)
        solver.found.push_back({0.0, 0.0, false, true, 4});
    solver.run(work.data(), 0.0, 1.0, 0);
    if (n > 0 && coefficients.back() == 0.0)
        solver.found.push_back({1.0, 0.0, false, true, 4});

    std::sort(found.begin(), found.end(), [](const FoundRoot& x, const FoundRoot& y) { return x.t < y.t; });
    // One root where two reports are not separated: p does not rise above its rounding
    // error (the magnitude Σ |b_i| B_i^n scaled as in toleranceFor) between them (a touching
    // zero met from a halving point and from its own interval, a cluster too tight for
    // doubles). The better placed report stays.
    for (const FoundRoot& r : found) {
        if (!merged.empty()) {
            FoundRoot& last = merged.back();
            const double gap = r.t - last.t;
            bool same = gap <= std::max(r.uncertainty, last.uncertainty) + 4.0 * kMachineEpsilon * std::max(1e-300, r.t);
            // Only close neighbours (a touching zero is blurred over about √ε, not more): a wide
            // stretch where p is below rounding must not swallow the roots beyond it.
            if (!same && !(last.known && r.known) && gap <= 1e-5) {
                const double between = 0.5 * (last.t + r.t);
                if (magnitude.empty())
                    for (double c : coefficients)
                        magnitude.push_back(std::fabs(c));
                same = std::fabs(bernsteinValue(coefficients, between)) <=
                       solver.toleranceFor(bernsteinValue(magnitude, between));
            }
            if (same) {
                if (r.rank > last.rank)
                    last = r;
                last.merged = true;
                continue;
            }
        }
        merged.push_back(r);
    }

    // Whether p changes sign at the roots found without a bracket: compare p on either side,
    // stepping out until both values are above rounding (and staying short of the neighbours).
    double maxAbs = 0.0;
    for (double c : coefficients)
        maxAbs = std::max(maxAbs, std::fabs(c));
    const double tolerance = 4.0 * (n + 1) * kMachineEpsilon * maxAbs;
    for (std::size_t k = 0; k < merged.size(); ++k) {
        FoundRoot& r = merged[k];
        if (r.known)
            continue;
        if (r.t <= 0.0 || r.t >= 1.0) {
            r.crossing = false;
            continue;
        }
        if (r.bracketed && !r.merged)
            continue; // crossing: p has opposite signs at the ends of its interval
        const double leftRoom = k > 0 ? 0.5 * (r.t - merged[k - 1].t) : r.t;
        const double rightRoom = k + 1 < merged.size() ? 0.5 * (merged[k + 1].t - r.t) : 1.0 - r.t;
        const double room = std::min(leftRoom, rightRoom);
        for (double h = std::max(2.0 * r.uncertainty, 64.0 * kMachineEpsilon * std::max(r.t, 1e-300)); h <= room; h *= 4.0) {
            const double fl = bernsteinValue(coefficients, r.t - h);
            const double fr = bernsteinValue(coefficients, r.t + h);
            if (std::fabs(fl) > tolerance && std::fabs(fr) > tolerance) {
                r.crossing = signOf(fl) != signOf(fr);
                break;
            }
        }
    }
    result.roots.reserve(merged.size());
    result.crossing.reserve(merged.size());
    for (const FoundRoot& r : merged) {
        result.roots.push_back(r.t);
        result.crossing.push_back(r.crossing);
    }
    return result;
}

} // namespace granota
