#include "core/exact/square_root.h"

namespace granota {

namespace {

constexpr unsigned long kTrialLimit = 1000000; ///< trial division up to 10^6 covers integers up to 10^12 fully

/// n = s² · f with f square-free, by trial division; false when n is too large to finish.
bool splitSquare(const mpz_class& n, mpz_class& s, mpz_class& f)
{
    static const mpz_class kLargest("1000000000000000000"); // 10^18
    if (n > kLargest)
        return false;
    mpz_class rest = n;
    s = 1;
    f = 1;
    for (unsigned long p = 2; p <= kTrialLimit && mpz_class(p) * p <= rest; ++p) {
        int power = 0;
        while (mpz_divisible_ui_p(rest.get_mpz_t(), p) != 0) {
            mpz_divexact_ui(rest.get_mpz_t(), rest.get_mpz_t(), p);
            ++power;
        }
        for (int i = 0; i + 1 < power; i += 2)
            s *= p;
        if (power % 2 == 1)
            f *= p;
    }
    if (mpz_class(kTrialLimit) * kTrialLimit < rest) {
        // An unfactored rest: it is square-free unless it is a perfect square of a prime.
        if (mpz_perfect_square_p(rest.get_mpz_t()) != 0) {
            mpz_class root;
            mpz_sqrt(root.get_mpz_t(), rest.get_mpz_t());
            s *= root;
            return true;
        }
    }
    f *= rest; // what is left is 1 or a prime
    return true;
}

} // namespace

std::optional<SimplifiedSquareRoot> simplifySquareRoot(const Rational& q)
{
    if (q < 0)
        return std::nullopt;
    if (q == 0)
        return SimplifiedSquareRoot{Rational(0), mpz_class(1)};
    // √(p/r) = √(p·r)/r: one integer to split.
    const mpz_class num = q.get_num(), den = q.get_den();
    mpz_class s, f;
    if (!splitSquare(num * den, s, f))
        return std::nullopt;
    Rational coefficient(s, den);
    coefficient.canonicalize();
    return SimplifiedSquareRoot{coefficient, f};
}

std::string toString(const SimplifiedSquareRoot& r)
{
    if (r.coefficient == 0)
        return "0";
    if (r.radicand == 1)
        return toString(r.coefficient);
    const std::string root = "√" + r.radicand.get_str();
    const mpz_class num = r.coefficient.get_num(), den = r.coefficient.get_den();
    std::string text = num == 1 ? root : num.get_str() + root;
    if (den != 1)
        text += "/" + den.get_str();
    return text;
}

std::vector<std::optional<SimplifiedSquareRoot>> exactChordLengths(const std::vector<RPoint>& q)
{
    std::vector<std::optional<SimplifiedSquareRoot>> d;
    for (std::size_t j = 1; j < q.size(); ++j) {
        const Rational dx = Rational(q[j].x - q[j - 1].x), dy = Rational(q[j].y - q[j - 1].y);
        d.push_back(simplifySquareRoot(Rational(dx * dx + dy * dy)));
    }
    return d;
}

} // namespace granota
