#include "core/exact/round_step.h"

#include <algorithm>
#include <cmath>

namespace granota {

namespace {

constexpr int kMaxStepExponent = 300;

int decade(double limit)
{
    if (!(limit > 0) || !std::isfinite(limit))
        return 0;
    return std::clamp(static_cast<int>(std::floor(std::log10(limit))), -kMaxStepExponent, kMaxStepExponent);
}

bool usable(double limit) { return limit > 0 && std::isfinite(limit); }

} // namespace

Rational RoundStep::exact() const
{
    mpz_class power;
    mpz_ui_pow_ui(power.get_mpz_t(), 10, static_cast<unsigned long>(std::abs(exponent)));
    if (exponent >= 0)
        return Rational(mpz_class(mantissa * power));
    Rational q(mpz_class(mantissa), power);
    q.canonicalize();
    return q;
}

double RoundStep::value() const { return toDouble(exact()); }

// log10 may be one off near a power of ten: the decades around it are tried, in order.
RoundStep roundStepAtMost(double limit)
{
    if (!usable(limit))
        return {};
    const int e = decade(limit);
    for (int k = std::min(e + 1, kMaxStepExponent); k >= e - 1; --k)
        for (int m : {5, 2, 1})
            if (RoundStep{m, k}.value() <= limit)
                return {m, k};
    return {1, e - 1};
}

RoundStep roundStepAtLeast(double limit)
{
    if (!usable(limit))
        return {};
    const int e = decade(limit);
    for (int k = std::max(e - 1, -kMaxStepExponent); k <= e + 1; ++k)
        for (int m : {1, 2, 5})
            if (RoundStep{m, k}.value() >= limit)
                return {m, k};
    return {1, e + 1};
}

Rational nextMultiple(const Rational& v, const Rational& step, int sign)
{
    const Rational q = v / step;
    mpz_class k;
    if (sign > 0) {
        mpz_fdiv_q(k.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
        k += 1;
    } else {
        mpz_cdiv_q(k.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
        k -= 1;
    }
    return Rational(k) * step;
}

Rational nearestMultiple(const Rational& v, const Rational& step)
{
    const Rational q = v / step + Rational(1, 2);
    mpz_class k;
    mpz_fdiv_q(k.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
    return Rational(k) * step;
}

} // namespace granota
