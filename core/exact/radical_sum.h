#pragma once
/// \file radical_sum.h
/// Sums of square roots Σ a_j √b_j (a_j rational, b_j square-free integers) and quotients of
/// two of them, for the chord-length parameters of §2.1.3 in radicals: in Ex 2.9 and 2.10
/// t_1 = √10 / (2√10 + 11√2) = (11√5 − 10)/101 (the thesis prints a value from its d_4 = √85;
/// docs/thesis-errata.md, “Ex 2.9 and 2.10”).
///
/// A quotient N/D is rationalised by conjugation: the radicands are split into pairwise
/// coprime factors g_1 … g_m (gcd refinement, no factoring), D = A + B√g with A and B free
/// of g is multiplied by its conjugate A − B√g, which leaves A² − gB², free of g; after m
/// steps D is rational. Each step can double the terms of N, so only up to
/// kMaxRadicalGenerators factors are tried; beyond that the quotient is kept as N/D.

#include "core/exact/exact_cost.h"
#include "core/exact/rational.h"
#include "core/exact/square_root.h"

#include <optional>
#include <string>
#include <vector>

namespace granota {

/// a·√b with a ≠ 0 and b ≥ 1 square-free (b = 1: a rational term).
struct RadicalTerm {
    Rational coefficient;
    mpz_class radicand;
};

/// Σ a_j √b_j with distinct radicands, sorted by radicand, no zero coefficient (0 is empty).
class RadicalSum {
public:
    RadicalSum() = default;
    explicit RadicalSum(const Rational& q);
    explicit RadicalSum(const SimplifiedSquareRoot& root);

    const std::vector<RadicalTerm>& terms() const { return m_terms; }
    bool isZero() const { return m_terms.empty(); }
    /// The value when it is rational (no radicand but 1), else nullopt.
    std::optional<Rational> rational() const;
    double toDouble() const;

    RadicalSum& operator+=(const RadicalSum& other);
    friend RadicalSum operator+(RadicalSum a, const RadicalSum& b) { return a += b; }
    friend RadicalSum operator-(const RadicalSum& a, const RadicalSum& b);
    friend RadicalSum operator*(const RadicalSum& a, const RadicalSum& b);
    friend bool operator==(const RadicalSum& a, const RadicalSum& b);
    friend bool operator!=(const RadicalSum& a, const RadicalSum& b) { return !(a == b); }

private:
    void add(const Rational& coefficient, const mpz_class& radicand);
    std::vector<RadicalTerm> m_terms;
};

/// N/D; rationalised when `denominator` is 1.
struct RadicalQuotient {
    RadicalSum numerator;
    RadicalSum denominator{Rational(1)};

    bool rationalised() const { return denominator == RadicalSum(Rational(1)); }
    double toDouble() const { return numerator.toDouble() / denominator.toDouble(); }
};

/// n/d with a rational denominator when the radicands of d have at most
/// kMaxRadicalGenerators coprime factors (exact_cost.h), else n/d as given; nullopt when d
/// is zero.
std::optional<RadicalQuotient> divide(const RadicalSum& n, const RadicalSum& d);

/// "(11√5 − 10)/101", "√10/2", "7√2", "−3", "0": over the least common denominator, the
/// radical terms by increasing radicand first, the rational term last, minus as "−".
std::string toString(const RadicalSum& s);
/// toString of the numerator when rationalised, else "(N)/(D)" ("√10/(2√10 + 11√2)").
std::string toString(const RadicalQuotient& q);

} // namespace granota
