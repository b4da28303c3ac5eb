#include "core/exact/exact_cost.h"

#include <algorithm>
#include <cmath>

namespace granota {

long bitLength(const Rational& q)
{
    return static_cast<long>(mpz_sizeinbase(q.get_num_mpz_t(), 2) + mpz_sizeinbase(q.get_den_mpz_t(), 2));
}

long maxBitLength(const std::vector<RPoint>& points)
{
    long bits = 0;
    for (const RPoint& p : points)
        bits = std::max({bits, bitLength(p.x), bitLength(p.y)});
    return bits;
}

double deCasteljauExactWork(int degree, long pointBits, long tBits)
{
    // Σ_{r=0}^{n} 2(n − r + 1)(b_P + r·b_t), in closed form (Def 2.4: level r from level r − 1),
    // twice: once to compute every level and once to write it (the CLI and the GUI show
    // the whole triangle; writing a b-bit number in decimal costs about what computing it did).
    const double n = std::max(0, degree), bp = static_cast<double>(pointBits), bt = static_cast<double>(tBits);
    const double entries = (n + 1) * (n + 2) / 2;      // Σ (n − r + 1)
    const double weighted = n * (n + 1) * (n + 2) / 6; // Σ (n − r + 1)·r
    return 2 * 2 * (entries * bp + weighted * bt);
}

double rationalDeCasteljauExactWork(int degree, long pointBits, long weightBits, long tBits)
{
    // Three coordinates instead of two (× 3/2), and the projected points P_i^r = p_i^r / w_i^r
    // have numerators and denominators of the homogeneous bits each (× 2).
    return 3 * deCasteljauExactWork(degree, pointBits + weightBits, tBits);
}

double bernsteinExactWork(int degree, long tBits)
{
    // Lemma 2.1: B_i^r = (1 − t)·B_i^{r−1} + t·B_{i−1}^{r−1}, the same triangle as De
    // Casteljau's with one coordinate of 1 bit at the top.
    // Only the n + 1 values of the last level are written.
    return deCasteljauExactWork(degree, 1, tBits) / 4;
}

double fitExactWork(int degree, const std::vector<Rational>& params, long pointBits)
{
    // The t_i over one denominator L (Lemma 2.2's M then has rows B_j^n(a_i / L)).
    mpz_class lcm = 1;
    for (const Rational& t : params) {
        mpz_lcm(lcm.get_mpz_t(), lcm.get_mpz_t(), t.get_den_mpz_t());
        if (mpz_sizeinbase(lcm.get_mpz_t(), 2) > 1000000) // already far beyond any budget
            break;
    }
    const double m = static_cast<double>(params.size()), n1 = std::max(0, degree) + 1.0;
    const double bL = static_cast<double>(mpz_sizeinbase(lcm.get_mpz_t(), 2));
    const double entryM = (n1 - 1) * (bL + 1) + 1; // E_M: C(n, j) a^j (L − a)^{n−j} / L^n
    const double entry = 2 * entryM + std::log2(std::max(1.0, m)) + static_cast<double>(pointBits); // E
    const double gram = m * n1 * n1 * entry;                                                        // MᵀM
    // Gauss–Jordan: (n + 1)³ operations on numbers that grow to (n + 1)·E bits, half that on
    // average; M⁺ = (MᵀM)⁻¹Mᵀ (Nota 2.2) and its writing: m(n + 1)² on entries of the inverse.
    const double inverse = n1 * n1 * n1 * n1 * entry / 2;
    const double pseudoInverse = m * n1 * n1 * n1 * entry / 2;
    return gram + inverse + pseudoInverse;
}

double catmullRomExactWork(std::size_t segments, long pointBits, long tauBits, int samples)
{
    // Lemma 2.3: each coefficient c_r = Σ_j M(τ)_{rj} p_j is four products of a coordinate by
    // an entry of M(τ) (a few bits more than τ): 4 × 4 × 2 operations, and the Bézier control
    // points (bezier_segments.h) as many again.
    const double coefficientBits = static_cast<double>(pointBits) + static_cast<double>(tauBits) + 2;
    const double sBits = samples > 1 ? 2 * std::log2(static_cast<double>(samples)) : 0;
    const double perSegment = 64 * coefficientBits + 6.0 * samples * (coefficientBits + 3 * sBits);
    // Twice: computed, then written in decimal (as deCasteljauExactWork).
    return 2 * static_cast<double>(segments) * perSegment;
}

namespace {

/// "3.2e11": two significant digits, no locale.
std::string roughly(double v)
{
    if (!(v >= 1) || !std::isfinite(v))
        return v >= 1 ? "1e308" : "1";
    int e = static_cast<int>(std::floor(std::log10(v)));
    long tenths = std::lround(v / std::pow(10.0, e) * 10);
    if (tenths >= 100) {
        tenths /= 10;
        ++e;
    }
    return std::to_string(tenths / 10) + (tenths % 10 ? "." + std::to_string(tenths % 10) : "") + "e" + std::to_string(e);
}

} // namespace

std::string exactWorkRefusal(const std::string& what, double work, const std::string& lower)
{
    return "the exact " + what + " would take about " + roughly(work) + " bit operations, more than " + roughly(kMaxExactWork) +
           " (minutes, and memory growing): lower " + lower + ", or leave out --exact";
}

double cubicSplineExactWork(int pieces, long xBits, long yBits)
{
    // The M_i are ratios of determinants of the k × k tridiagonal matrix, whose entries are
    // the steps h_i: their numbers hold about S = k·(b_x + 2) + b_y bits, and each of the
    // k rows does a few products and reductions of them (S log S each). Fitted on the
    // measured times of docs/exact-cost.md (about 5·10⁻⁹ s a unit).
    const double k = std::max(1, pieces);
    const double size = k * (static_cast<double>(xBits) + 2.0) + static_cast<double>(yBits) + 1.0;
    return k * size * std::log2(size + 1.0);
}

} // namespace granota
