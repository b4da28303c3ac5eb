#include "core/exact/radical_sum.h"

#include <algorithm>
#include <cmath>

namespace granota {

RadicalSum::RadicalSum(const Rational& q) { add(q, mpz_class(1)); }

RadicalSum::RadicalSum(const SimplifiedSquareRoot& root) { add(root.coefficient, root.radicand); }

void RadicalSum::add(const Rational& coefficient, const mpz_class& radicand)
{
    if (coefficient == 0)
        return;
    const auto at = std::lower_bound(m_terms.begin(), m_terms.end(), radicand,
                                     [](const RadicalTerm& t, const mpz_class& r) { return t.radicand < r; });
    if (at != m_terms.end() && at->radicand == radicand) {
        at->coefficient += coefficient;
        at->coefficient.canonicalize();
        if (at->coefficient == 0)
            m_terms.erase(at);
    } else {
        m_terms.insert(at, RadicalTerm{coefficient, radicand});
    }
}

std::optional<Rational> RadicalSum::rational() const
{
    if (m_terms.empty())
        return Rational(0);
    if (m_terms.size() == 1 && m_terms.front().radicand == 1)
        return m_terms.front().coefficient;
    return std::nullopt;
}

double RadicalSum::toDouble() const
{
    // Summed in long double: the printed t_i of Ex 2.9 cancel about one digit.
    long double sum = 0;
    for (const RadicalTerm& t : m_terms)
        sum += static_cast<long double>(t.coefficient.get_d()) * std::sqrt(static_cast<long double>(t.radicand.get_d()));
    return static_cast<double>(sum);
}

RadicalSum& RadicalSum::operator+=(const RadicalSum& other)
{
    for (const RadicalTerm& t : other.m_terms)
        add(t.coefficient, t.radicand);
    return *this;
}

RadicalSum operator-(const RadicalSum& a, const RadicalSum& b)
{
    RadicalSum r = a;
    for (const RadicalTerm& t : b.m_terms)
        r.add(Rational(-t.coefficient), t.radicand);
    return r;
}

RadicalSum operator*(const RadicalSum& a, const RadicalSum& b)
{
    // √p·√q = g·√((p/g)(q/g)) with g = gcd(p, q); the product of the coprime square-free
    // p/g and q/g is square-free again.
    RadicalSum r;
    for (const RadicalTerm& s : a.m_terms)
        for (const RadicalTerm& t : b.m_terms) {
            mpz_class g;
            mpz_gcd(g.get_mpz_t(), s.radicand.get_mpz_t(), t.radicand.get_mpz_t());
            const mpz_class radicand = (s.radicand / g) * (t.radicand / g);
            r.add(Rational(s.coefficient * t.coefficient * Rational(g)), radicand);
        }
    return r;
}

bool operator==(const RadicalSum& a, const RadicalSum& b)
{
    return a.m_terms.size() == b.m_terms.size() &&
           std::equal(a.m_terms.begin(), a.m_terms.end(), b.m_terms.begin(), [](const RadicalTerm& s, const RadicalTerm& t) {
               return s.radicand == t.radicand && s.coefficient == t.coefficient;
           });
}

namespace {

/// Pairwise coprime factors (> 1) of which every radicand is a product: gcd refinement.
std::vector<mpz_class> coprimeFactors(const RadicalSum& s)
{
    std::vector<mpz_class> f;
    for (const RadicalTerm& t : s.terms())
        if (t.radicand != 1)
            f.push_back(t.radicand);
    for (bool changed = true; changed;) {
        changed = false;
        std::sort(f.begin(), f.end());
        f.erase(std::unique(f.begin(), f.end()), f.end());
        for (std::size_t i = 0; i < f.size() && !changed; ++i)
            for (std::size_t j = i + 1; j < f.size() && !changed; ++j) {
                mpz_class g;
                mpz_gcd(g.get_mpz_t(), f[i].get_mpz_t(), f[j].get_mpz_t());
                if (g == 1)
                    continue;
                const mpz_class a = f[i] / g, b = f[j] / g;
                f.erase(f.begin() + static_cast<std::ptrdiff_t>(j));
                f.erase(f.begin() + static_cast<std::ptrdiff_t>(i));
                for (const mpz_class& x : {g, a, b})
                    if (x != 1)
                        f.push_back(x);
                changed = true;
            }
    }
    return f;
}

/// The conjugate A − B√g of s = A + B√g, where B√g gathers the terms whose radicand g divides.
RadicalSum conjugate(const RadicalSum& s, const mpz_class& g)
{
    RadicalSum c;
    for (const RadicalTerm& t : s.terms()) {
        const bool hasG = mpz_divisible_p(t.radicand.get_mpz_t(), g.get_mpz_t()) != 0;
        c += RadicalSum(SimplifiedSquareRoot{hasG ? Rational(-t.coefficient) : t.coefficient, t.radicand});
    }
    return c;
}

/// "11√5", "√5", "10": |c|√r with an integer c (the sign is written by the caller).
std::string magnitude(const mpz_class& c, const mpz_class& radicand)
{
    const mpz_class a = abs(c);
    if (radicand == 1)
        return a.get_str();
    return (a == 1 ? std::string() : a.get_str()) + "√" + radicand.get_str();
}

const char* const kMinus = "\u2212";

} // namespace

std::optional<RadicalQuotient> divide(const RadicalSum& n, const RadicalSum& d)
{
    if (d.isZero())
        return std::nullopt;
    if (n.isZero() || n == d) // t_0 = 0 and t_k = 1 whatever the denominator
        return RadicalQuotient{n.isZero() ? RadicalSum() : RadicalSum(Rational(1)), RadicalSum(Rational(1))};
    const std::vector<mpz_class> factors = coprimeFactors(d);
    if (static_cast<int>(factors.size()) > kMaxRadicalGenerators)
        return RadicalQuotient{n, d};
    RadicalSum num = n, den = d;
    for (const mpz_class& g : factors) {
        const RadicalSum c = conjugate(den, g);
        num = num * c;
        den = den * c;
    }
    const std::optional<Rational> q = den.rational();
    if (!q || *q == 0) // cannot happen: the conjugates of a nonzero D are nonzero
        return RadicalQuotient{n, d};
    return RadicalQuotient{num * RadicalSum(Rational(1 / *q)), RadicalSum(Rational(1))};
}

std::string toString(const RadicalSum& s)
{
    if (s.isZero())
        return "0";
    mpz_class common = 1;
    for (const RadicalTerm& t : s.terms())
        mpz_lcm(common.get_mpz_t(), common.get_mpz_t(), t.coefficient.get_den_mpz_t());
    // Radical terms by increasing radicand, the rational one (radicand 1, first in terms()) last.
    std::vector<const RadicalTerm*> order;
    for (const RadicalTerm& t : s.terms())
        if (t.radicand != 1)
            order.push_back(&t);
    if (s.terms().front().radicand == 1)
        order.push_back(&s.terms().front());
    std::string text;
    for (const RadicalTerm* t : order) {
        const mpz_class c = Rational(t->coefficient * Rational(common)).get_num();
        if (text.empty())
            text = (c < 0 ? std::string(kMinus) : std::string()) + magnitude(c, t->radicand);
        else
            text += (c < 0 ? std::string(" ") + kMinus + " " : std::string(" + ")) + magnitude(c, t->radicand);
    }
    if (common == 1)
        return text;
    return (order.size() > 1 ? "(" + text + ")" : text) + "/" + common.get_str();
}

std::string toString(const RadicalQuotient& q)
{
    if (q.rationalised())
        return toString(q.numerator);
    const auto wrapped = [](const RadicalSum& s) {
        const std::string t = toString(s);
        return s.terms().size() > 1 || t.find('/') != std::string::npos ? "(" + t + ")" : t;
    };
    return wrapped(q.numerator) + "/" + wrapped(q.denominator);
}

} // namespace granota
